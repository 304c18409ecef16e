// Linear hydrodynamic coefficients of one float in surge (x) and heave (z).
//
// Conventions (fixed for the whole wec scene):
//   * complex amplitudes use the e^{+iωt} time factor (as WAMIT): q(t) = Re{q̂ e^{+iωt}};
//     Capytaine/NEMOH use e^{−iωt}; toEMinusIwt/fromEMinusIwt convert (complex conjugation);
//   * the incident wave travelling along +x is η(x, t) = Re{a e^{i(ωt − kx)}}, a = H/2 [m];
//   * excitation X̂ [N/m] is the force per unit wave amplitude on a body centred at x = 0, so its
//     phase is the lead of the force over η(0, t); a body at x_f gets the factor e^{−ikx_f};
//   * radiation: F = −A(ω) q̈ − B(ω) q̇ per mode; A∞ = A(ω → ∞).
// Surge–heave coupling is zero for an axisymmetric body (WAMIT sphere: |A13|/A11 ~ 1e-6).
#pragma once

#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "core/monotone_cubic.hpp"

namespace maris::wec {

using Complex = std::complex<double>;

// Hulme (1982), "The wave forces acting on a floating hemisphere undergoing forced periodic oscillations",
// J. Fluid Mech. 121, 443–463, Tables 1 (heave) and 2 (surge); deep water. Nondimensional:
//   μ = A / (ρV), λ = B / (ρVω), V = (2/3)πa³, argument ka = ω²a/g.
// Between nodes: PCHIP; ka → 0 and ka → ∞ tend to the exact limits (μ33: 0.8310 / 0.5,
// μ11: 0.5 / 0.2732; λ → 0 at both ends, with a power-law tail fitted to the last two nodes).
// Surge damping beyond Hulme's ka = 1.4 comes from the WAMIT hemisphere run (a = 5 m, h = 50 m,
// capytaine pytest/Bemio_verification_cases/sphere.out), deep-water there since kh > 3.
double hulmeHeaveAddedMass(double ka);  // μ33
double hulmeHeaveDamping(double ka);    // λ33
double hulmeSurgeAddedMass(double ka);  // μ11
double hulmeSurgeDamping(double ka);    // λ11
struct HulmeLimits {
  static constexpr double heave_added_mass_zero = 0.8310;
  static constexpr double heave_added_mass_infinity = 0.5;
  static constexpr double surge_added_mass_zero = 0.5;
  static constexpr double surge_added_mass_infinity = 0.2732;
};

// Excitation phase [rad] (e^{+iωt}, lead over η at the centre) of a floating hemisphere in deep water,
// interpolated in ka from the WAMIT BEM run above (integer-degree output, ±0.5°), tending to the exact
// long-wave limits 0 (heave) and +π/2 (surge) as ka → 0. Held constant beyond ka = 5, where the
// excitation magnitude is below 1 % of its peak.
double hemisphereHeavePhase(double ka);
double hemisphereSurgePhase(double ka);

// Hydrodynamic coefficients of one float at one frequency (per mode: x = surge, z = heave).
struct ModeHydro {
  double added_mass = 0.0;  // [kg] A(ω)
  double damping = 0.0;     // [N·s/m] B(ω)
  Complex excitation;       // [N/m] X̂(ω) per unit wave amplitude, float centred at x = 0
};
struct FloatHydro {
  ModeHydro surge, heave;
};

// Source of coefficients for a float: the analytic hemisphere or a table imported from a BEM code.
class HydroDatabase {
 public:
  virtual ~HydroDatabase() = default;
  virtual FloatHydro at(double omega) const = 0;           // omega > 0 [rad/s]
  virtual double addedMassInfinitySurge() const = 0;       // [kg]
  virtual double addedMassInfinityHeave() const = 0;       // [kg]
  virtual double maxFrequency() const = 0;                 // [rad/s] beyond it damping is treated as 0
  virtual std::string describe() const = 0;
};

// Deep-water floating hemisphere of radius a (Hulme tables, Haskind excitation magnitudes,
// WAMIT-derived phases). Haskind–Newman for an axisymmetric body in deep water:
//   |X3|² = 2ρg³B33/ω³,  |X1|² = 4ρg³B11/ω³   (Newman, Marine Hydrodynamics, §6.18).
class HemisphereHydro : public HydroDatabase {
 public:
  HemisphereHydro(double radius, double density, double gravity);
  FloatHydro at(double omega) const override;
  double addedMassInfinitySurge() const override;
  double addedMassInfinityHeave() const override;
  double maxFrequency() const override;
  std::string describe() const override;
  double displacedVolume() const;  // [m³] (2/3)πa³

 private:
  double radius_, density_, gravity_;
};

// Coefficients tabulated at frequencies (e.g. from WAMIT .1/.3), interpolated with PCHIP in ω
// (real and imaginary parts of X̂ separately). Outside the table: end values for A, damping
// and excitation tapering linearly to 0 at ω = 0 and held at the last value up to maxFrequency.
class TabulatedHydro : public HydroDatabase {
 public:
  struct Row {
    double omega;  // [rad/s]
    FloatHydro hydro;
  };
  TabulatedHydro(std::vector<Row> rows, double a_inf_surge, double a_inf_heave, std::string source);
  FloatHydro at(double omega) const override;
  double addedMassInfinitySurge() const override { return a_inf_surge_; }
  double addedMassInfinityHeave() const override { return a_inf_heave_; }
  double maxFrequency() const override;
  std::string describe() const override { return source_; }
  const std::vector<Row>& rows() const { return rows_; }

 private:
  std::vector<Row> rows_;
  double a_inf_surge_, a_inf_heave_;
  std::string source_;
  MonotoneCubic a_x_, a_z_, b_x_, b_z_, xr_x_, xi_x_, xr_z_, xi_z_;
};

// Phase-convention conversion: an amplitude in e^{−iωt} convention is the conjugate of the e^{+iωt} one.
inline Complex toEMinusIwt(Complex e_plus) { return std::conj(e_plus); }
inline Complex fromEMinusIwt(Complex e_minus) { return std::conj(e_minus); }

}  // namespace maris::wec
