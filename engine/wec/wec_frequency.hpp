// Linear frequency-domain model of a float pitching about its hinge (derived here from the hinge kinematics; not in the paper,
// kept as the independent check of the time domain). Linearised about θ0 with r_x0 = L cos θ0,
// r_z0 = L sin θ0, the float centre moves by ξ = T δθ, T = (−r_z0, r_x0):
//
//   Z_θ(ω) Θ = X_θ,   Z_θ = −ω² J(ω) + iω (B_PTO + B_θ(ω)) + K_θ
//   J = I_cg + m L² + A_zz r_x0² + A_xx r_z0²,  B_θ = B_zz r_x0² + B_xx r_z0²,
//   K_θ = ρ g A_w r_x0² + k_PTO,               X_θ = r_x0 X_z − r_z0 X_x   (location phase included).
//
// Without multi-body coefficients the floats do not interact and the N-float system is diagonal (solved float by
// float); with them (model.coupled) solveFrequency returns the float's row of the coupled system (wec_coupled.hpp).
// Hinge force (on the structure): F̂_h = Q̂ − m ü, Q̂ = X̂ + (ω² A − iω B) ξ̂ − ρ g A_w ξ̂_z ê_z.
// Mean PTO power P̄ = ½ B_PTO ω² |Θ|²; the passive optimum B_PTO,opt = √(B_θ² + (ωJ − K_θ/ω)²);
// capture width CW = P̄/J_wave, J_wave = ρ g² a²/(4ω) (deep water), bounded by 3λ/(2π) for a body
// moving in combined surge and heave (Newman 1976; Falnes, Ocean Waves and Oscillating Systems §6).
#pragma once

#include <string>
#include <vector>

#include "wec/wec_model.hpp"

namespace maris::wec {

struct FrequencyResponse {
  double omega = 0.0;            // [rad/s]
  Complex pitch;                 // [rad/m] Θ per unit wave amplitude
  Complex hinge_fx, hinge_fz;    // [N/m] hinge reaction on the structure per unit amplitude
  Complex moment_y;              // [N·m/m] moment of all float loads about the hinge (= I θ̈, paper eq 8)
  double power = 0.0;            // [W/m²] mean PTO power per a²
  double capture_width = 0.0;    // [m]
  double capture_width_bound = 0.0;  // [m] 3λ/(2π)
  double optimal_damping = 0.0;  // [N·m·s/rad] passive optimum B_PTO
  double power_bound = 0.0;      // [W/m²] |X_θ|²/(8 B_θ), the optimum with reactive control
  double inertia = 0.0;          // [kg·m²] J(ω)
  double damping = 0.0;          // [N·m·s/rad] B_θ(ω)
  double stiffness = 0.0;        // [N·m/rad] K_θ
  Complex excitation;            // [N·m/m] X_θ
};

// pto_damping < 0: use the float's own B_PTO.
FrequencyResponse solveFrequency(const WecModel& model, const FloatModel& f, double omega, double pto_damping = -1.0);

// Undamped natural frequency: root of K_θ = ω² J(ω) (secant on a bracket from a scan of [0.05, 10] rad/s).
// Returns 0 if there is no root (no restoring).
double naturalFrequency(const WecModel& model, const FloatModel& f);

// Complex free-decay eigenvalue s = −σ + iω_d of the linearised float: root of
//   Z(s) = s² J∞ + s (B_PTO + r_x0² K̂_z(s) + r_z0² K̂_x(s)) + K_θ,  J∞ = I + A∞z r_x0² + A∞x r_z0²,
// with K̂(s) continued off the imaginary axis through the modal fit of K(t) (Newton from s = iω_n).
// On s = iω this is exactly the impedance above. Requires buildRadiation. Returns 0 if Newton fails.
Complex freeDecayEigenvalue(const WecModel& model, const FloatModel& f);

// Linear response of a float in an irregular sea: spectral densities S_q(ω) = |H_q(ω)|² S_η(ω) of the pitch,
// the hinge reactions (on the structure) and the hinge moment on the grid `omega`, and their standard deviations
// σ_q = √m0,q (trapezoid over the grid; significant amplitude 2σ). Cross terms between floats are absent (no
// hydrodynamic interaction), so each float is independent.
struct ResponseSpectra {
  std::vector<double> omega;               // [rad/s] grid (input)
  std::vector<double> wave;                // [m²·s/rad] S_η
  std::vector<double> pitch;               // [rad²·s/rad]
  std::vector<double> hinge_fx, hinge_fz;  // [N²·s/rad]
  std::vector<double> moment_y;            // [(N·m)²·s/rad]
  double sd_pitch = 0.0, sd_fx = 0.0, sd_fz = 0.0, sd_moment = 0.0;  // [rad], [N], [N], [N·m]
};
ResponseSpectra responseSpectra(const WecModel& model, const FloatModel& f, const std::string& spectrum, double hs,
                                double tp, double gamma, const std::vector<double>& omega);

// Relative standard error of a standard deviation measured over a record of `duration` [s] of a stationary Gaussian
// response with one-sided spectrum s(ω) on the grid `omega` (trapezoid): ε = √(π ∫s² dω / (2T)) / ∫s dω. It is half
// the normalised error 1/√(B_s T) of the mean square, B_s = (∫G df)²/∫G² df the statistical bandwidth in Hz
// (J. S. Bendat, A. G. Piersol, Random Data, 4th ed., Wiley 2010, §8.2), for a Gaussian process. A sum of
// components with random amplitudes behaves so when their spacing is below 2π/T; one with fixed amplitudes (the
// scene's seas) scatters less.
double deviationSamplingError(const std::vector<double>& omega, const std::vector<double>& s, double duration);

// Standard deviations of the same quantities for a discrete sea of components a_j at ω_j: σ² = Σ ½|H(ω_j)|² a_j²,
// whatever the phases: the mean over a long record of the linear response's variance (exact over a whole repeat
// period when the frequencies are multiples of one Δω; core's seas have no common period, see ocean::irregularSea).
struct ResponseDeviations {
  double pitch = 0.0, fx = 0.0, fz = 0.0, moment = 0.0;  // [rad], [N], [N], [N·m]
};
ResponseDeviations discreteResponseDeviations(const WecModel& model, const FloatModel& f, const IncidentWaves& waves);

// Mean PTO power in an irregular sea [W]: ∫ B_PTO ω² |Θ(ω)|² S(ω) dω on [0.2, 6]·ω_p (2000 points).
double irregularMeanPower(const WecModel& model, const FloatModel& f, const std::string& spectrum, double hs,
                          double tp, double gamma);

}  // namespace maris::wec
