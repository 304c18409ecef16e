// Steady-state time-domain response in regular waves, extracted for comparison with the frequency domain:
// a ramped run of ramp + settling + `periods` whole periods with a time step that divides the period,
// then single-frequency DFTs (harmonicAmplitude) of θ − θ0, the hinge forces and the energy flows.
#pragma once

#include <vector>

#include "core/run_context.hpp"
#include "wec/wec_time.hpp"

namespace maris::wec {

struct SteadyResponse {
  double omega = 0.0;           // [rad/s]
  double time_step = 0.0;       // [s] the step actually used (period / integer)
  double duration = 0.0;        // [s]
  std::vector<Complex> pitch;   // [rad/m] per float, per unit wave amplitude
  std::vector<Complex> hinge_fx, hinge_fz;  // [N/m]
  std::vector<double> pto_power;        // [W] mean over the last periods
  std::vector<double> excitation_power; // [W] mean
  std::vector<double> radiated_power;   // [W] mean
  double max_position_drift = 0.0;      // [m] augmented only
};

// Settling time after the ramp [s]: 7 e-folds of the slowest free decay, σ = (B_PTO + B_θ)/(2J) at the
// pitch natural frequency (at least 20 s, at most 600 s).
double settlingTime(const WecModel& model);

// Runs regular waves of height H at ω and extracts the steady response (wave amplitude a = H/2).
SteadyResponse steadyResponse(const WecModel& model, double omega, double height, double ramp,
                              const TimeDomainOptions& base, int periods, RunContext* context);

}  // namespace maris::wec
