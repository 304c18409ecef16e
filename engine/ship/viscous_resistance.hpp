// Water properties and the viscous part of the resistance: R_T = R_W + (1 + k) R_F + R_A with
// R_F = C_F ½ρU²S (paper eqs 13–14).
#pragma once

#include <vector>

namespace maris::ship {

enum class WaterKind { Fresh, Sea };

struct WaterProperties {
  double density = 0;              // [kg/m³]
  double kinematic_viscosity = 0;  // [m²/s]
};

// Density and kinematic viscosity at temperature t [°C], 0 ≤ t ≤ 40, atmospheric pressure.
//   Fresh density: Tanaka et al. (2001), Metrologia 38:301, eq 1 (CIPM formula, SMOW).
//   Sea density (salinity 35 g/kg): UNESCO EOS-80 one-atmosphere equation (Millero & Poisson 1981).
//   Viscosities: ITTC Recommended Procedure 7.5-02-01-03 (2011) fits
//     ν_fresh = ((0.000585 (t−12) − 0.03361)(t−12) + 1.2350)·1e-6,
//     ν_sea   = ((0.000659 (t−1)  − 0.05076)(t−1)  + 1.7688)·1e-6.
WaterProperties waterProperties(WaterKind kind, double temperature_c);

// ITTC-1957 model–ship correlation line C_F = 0.075/(log10 Re − 2)², Re > 100.
double ittc57FrictionCoefficient(double reynolds);

// Prohaska's method (ITTC Recommended Procedure 7.5-02-02-01): at low speed the wave resistance grows like
// Fn⁴, C_T = (1 + k) C_F + c Fn⁴, so C_T/C_F against Fn⁴/C_F is a straight line with intercept 1 + k.
// Least squares over the given measured points (C_F from ITTC-57 at each point's Reynolds number).
struct ProhaskaFit {
  double form_factor = 1;   // [-] 1 + k, the intercept
  double slope = 0;         // [-] c
  int points = 0;           // measured points used
  double rms_residual = 0;  // [-] RMS of C_T/C_F about the line
};
// froude, c_total, c_friction: equal sizes, ≥ 2 points with distinct Fn⁴/C_F (else std::invalid_argument).
ProhaskaFit prohaskaFormFactor(const std::vector<double>& froude, const std::vector<double>& c_total,
                               const std::vector<double>& c_friction);

}  // namespace maris::ship
