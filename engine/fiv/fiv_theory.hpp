// Closed forms of the FIV model, shared by the solver, the tests and bench/: free decay, power and
// efficiency definitions of the paper, and the quasi-steady galloping theory (linear onset and
// Krylov–Bogoliubov / harmonic-balance limit-cycle amplitudes).
#pragma once

#include <vector>

#include "fiv/fiv_model.hpp"

namespace maris::fiv {

inline constexpr double kBetzLimit = 16.0 / 27.0;  // [-] Betz (1920)

// Logarithmic decrement of free decay, δ = ln(y_k / y_{k+1}) = 2πξ / √(1 − ξ²) (ξ < 1).
double logarithmicDecrement(double damping_ratio);

// Mean damper power of y = A sin(ωt): P = ½ c ω² A² (paper eq 13 on a sine) [W].
double sinusoidDamperPower(double damping, double omega, double amplitude);

// Fluid power through the swept frontal area, P_fluid = ½ ρ U³ L (D + 2A) (paper eq 14) [W].
double sweptFluidPower(double density, double speed, double length, double side, double amplitude);

// Efficiency against the Betz-limited fluid power, η = P / (P_fluid · 16/27) (paper eq 15) [-].
double betzEfficiency(double power, double fluid_power);

// Linear quasi-steady galloping onset, U_cr = 2c / (ρ D L κ A1) [m/s] (Den Hartog / Parkinson;
// A1 = dC_y/d tanα at 0, κ the free-surface factor). Infinite when κA1 <= 0.
double gallopingOnsetSpeed(double damping, double density, double side, double length, double slope_a1,
                           double surface_factor = 1.0);

// Averaged transverse-force coefficient of a harmonic motion with velocity ratio r = Aω/U:
// G(r) = (1/(π r)) ∫₀^{2π} C_y(r sinθ) sinθ dθ; for Parkinson's polynomial
// G = A1 − ¾A3 r² + ⅝A5 r⁴ − 35/64 A7 r⁶ (Parkinson & Smith 1964). Trapezoid rule, exact for polynomials.
double averagedForceCoefficient(const ForceCurve& curve, double velocity_ratio);

// Harmonic-balance limit cycles: roots r of G(r) = S with S = 2c / (ρ D L U κ) = 2ξ / (n_m U'),
// ascending in r, searched in (0, r_max]. Stable roots are those where G decreases.
struct HarmonicBalanceRoot {
  double velocity_ratio = 0.0;  // [-] r = A ω_n / U
  bool stable = false;
};
std::vector<HarmonicBalanceRoot> harmonicBalanceRoots(const ForceCurve& curve, double balance, double r_max = 1.0);

// Limit-cycle amplitudes [m] predicted by harmonic balance for the model at speed U and factor κ_g.
std::vector<HarmonicBalanceRoot> harmonicBalanceAtSpeed(const FivModel& model, double speed, double surface_factor);

}  // namespace maris::fiv
