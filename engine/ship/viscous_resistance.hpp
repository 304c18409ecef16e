// Water properties and the viscous part of the resistance: R_T = R_W + (1 + k) R_F + R_A with
// R_F = C_F ½ρU²S (paper eqs 13–14).
#pragma once

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

}  // namespace maris::ship
