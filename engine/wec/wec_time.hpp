// Time-domain simulation of the hinged floats (Cummins equation, paper §2), two formulations:
//
// Classical (paper eqs 8–11, 16–17): one ODE per float in θ,
//   J(θ) θ̈ = r_x F_z − r_z F_x + r_x r_z (A∞z − A∞x) θ̇² − B_PTO θ̇ − k_PTO (θ − θ0),
//   J(θ) = I_cg + m L² + A∞z r_x² + A∞x r_z²,  r = L (cos θ, sin θ),
//   F = excitation − memory − ρ g A_w (z_h + r_z) ê_z, float velocity u̇ = θ̇ (−r_z, r_x);
//   hinge reaction afterwards from F_h = Q_hydro − m ü (paper eqs 14–15).
// Augmented (paper eqs 18–30): q = (x, z, θ), M = diag(m + A∞x, m + A∞z, I_cg) (A∞ in the mass matrix
//   avoids an algebraic loop), hinge constraints C = (x − x_h − L cos θ, z − z_h − L sin θ) = 0,
//   [M C_qᵀ; C_q 0][q̈; λ] = [Q; Q_c − 2αĊ − α²C], solved by a 2×2 Schur complement;
//   the multipliers λ are the hinge reaction on the structure.
//
// Integrator: the shared fixed-step RK4 (core/ode.hpp integrateRk4). Its after_step hook projects the
// augmented formulation's (x, z, ẋ, ż) back onto the constraints after every step (recording the drift it
// removes) and advances the direct convolution's velocity history once per completed step. The radiation
// memory is a modal state-space system integrated with the mechanics (ẇ = p w + u̇), or direct trapezoidal
// convolution over the stored velocity history with the memory force extrapolated linearly across each step
// (second order).
// The augmented formulation can instead use the paper's own scheme (options.newmark; wec_newmark.cpp): explicit
// Newmark-β (β = 0, γ = ½) on θ with an inner Newton–Raphson loop on the position constraints, which satisfies
// the constraints at position, velocity and acceleration level with no drift.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/run_context.hpp"
#include "wec/wec_model.hpp"

namespace maris::wec {

struct TimeDomainOptions {
  bool augmented = false;          // false: classical
  bool state_space = true;         // false: direct convolution
  bool projection = true;          // augmented RK4: project onto the constraints after each step
  bool newmark = false;            // augmented: the paper's Newmark two-loop scheme instead of RK4
  double baumgarte_rate = 10.0;    // [1/s] α
  double time_step = 0.05;         // [s]
  double duration = 100.0;         // [s]
  double initial_offset = 0.0;     // [rad] θ(0) − θ0 for every float
  int output_stride = 1;           // record every n-th step
};

// Time histories of one float (one entry per recorded step).
struct FloatHistory {
  std::vector<double> theta;             // [rad]
  std::vector<double> theta_dt;          // [rad/s]
  std::vector<double> theta_dtdt;        // [rad/s²]
  std::vector<double> hinge_fx;          // [N] reaction on the structure
  std::vector<double> hinge_fz;          // [N]
  std::vector<double> moment_y;          // [N·m] moment of all float loads about the hinge (paper eq 8)
  std::vector<double> pto_power;         // [W] B_PTO θ̇²
  std::vector<double> pto_energy;        // [J] ∫ P_PTO dt (trapezoid over steps)
  std::vector<double> excitation_work;   // [J] ∫ F_exc · u̇ dt
  std::vector<double> radiation_work;    // [J] ∫ F_memory · u̇ dt (energy radiated away)
  std::vector<double> mechanical_energy; // [J] kinetic (incl. A∞) + hydrostatic + PTO spring
};

struct TimeDomainResult {
  std::vector<double> time;                // [s]
  std::vector<double> wave_at_origin;      // [m] η(0, t)
  std::vector<FloatHistory> floats;
  double max_position_drift = 0.0;         // [m] max |C| over the run (before projection)
  double max_velocity_drift = 0.0;         // [m/s] max |C_q q̇|
  double stability_step = 0.0;             // [s] estimated stability limit of the integrator (fastest mode)
  // [rad] RK4: Σ over steps of the local error of θ from the embedded 3rd-order companion, h|k4 − k5|/6 with
  // k5 = the next step's k1 (core/ode.hpp's estimator on the θ components only); an over-estimate of RK4's
  // global error. Newmark: Σ h²/6 |Δθ̈| (wec_newmark.cpp).
  double error_estimate = 0.0;
  double relative_error_estimate = 0.0;    // [-] RK4: OdeStats::error_estimate of the shared integrator (all states)
  int max_newton_iterations = 0;           // Newmark: most position (Newton–Raphson) iterations in one step
  int max_velocity_iterations = 0;         // Newmark: most velocity fixed-point iterations in one step
  long steps = 0;
  long rhs_evaluations = 0;
  std::string method;
};

// Sees the run so far (every history the same length) so a caller can publish partial results.
using TimeDomainObserver = std::function<void(const TimeDomainResult& so_far)>;

// Runs the simulation. Throws SolverError naming float, quantity, time and step if the state becomes
// non-finite, and RunCancelled when the context asks (context may be null). `observe` (optional) is called
// after a recorded step whenever context->wantsPartialResults(); it only reads, so the result does not depend on it.
TimeDomainResult simulateTimeDomain(const WecModel& model, const IncidentWaves& waves, const TimeDomainOptions& options,
                                    RunContext* context, const TimeDomainObserver& observe = {});

// Estimated RK4 stability limit of the linearised system [s]: 2.78/|λ| over the radiation poles,
// the Baumgarte rate (augmented) and the undamped pitch frequency (2.83/ω).
double rk4StabilityStep(const WecModel& model, const TimeDomainOptions& options);

// Complex amplitude of a signal at ω by a single-frequency DFT over the last `periods` whole periods
// (e^{+iωt}: s(t) ≈ Re{ŝ e^{iωt}}); samples at spacing dt with an integer number per period.
Complex harmonicAmplitude(const std::vector<double>& t, const std::vector<double>& s, double omega, int periods);

}  // namespace maris::wec
