// Converged limit cycle of the FIV model at one operating point: time-marches the 6-state system
// (fiv_model.hpp) with fixed-step RK4 until the cycle amplitude stops changing, then averages the
// response over the last whole cycles.
//
// Why a dedicated RK4 loop rather than core/ode.hpp: the loop needs per-step event logic (zero
// up-crossings with interpolated times and energies, refined peaks, convergence test, stop) on a
// fixed-size 6-state array with an inlined right-hand side. The general integrators take
// std::function callbacks on Eigen::VectorXd, which costs several times more per step here, and the
// 2 s budget for 500 limit cycles (5 h* × 50 speeds × up/down) leaves ≈ 4 ms per cycle
// (bench/fiv_sweep.cpp measures both).
#pragma once

#include <vector>

#include "core/run_context.hpp"
#include "fiv/fiv_model.hpp"

namespace maris::fiv {

struct LimitCycleSettings {
  int steps_per_period = 40;     // [-] RK4 steps per shortest period (structure or shedding)
  double tolerance = 1e-3;       // [-] converged when estimated remaining amplitude change / A is below
  int max_cycles = 150;          // [-] structural periods simulated at most
  int min_cycles = 6;            // [-] whole cycles before convergence is tested
  int average_cycles = 4;        // [-] cycles averaged for A, f and P
  double rest_amplitude = 1e-7;  // [m] below this (and shrinking) the cylinder counts as at rest
};

// Response averaged over the last whole cycles.
struct LimitCycle {
  double amplitude = 0.0;       // [m] A, mean half peak-to-peak of y per cycle
  double frequency = 0.0;       // [Hz] f, from zero up-crossings of y
  double power_damper = 0.0;    // [W] P = ⟨c ẏ²⟩ (paper eq 13)
  double power_fluid = 0.0;     // [W] ⟨F ẏ⟩ (paper eq 8), equal to P on an exact cycle
  double residual = 0.0;        // [-] estimated relative error of A (remaining drift or cycle-to-cycle spread)
  double y_max = 0.0;           // [m] largest upward displacement over the averaged cycles
  double y_min = 0.0;           // [m] largest downward displacement (negative)
  double max_tan_alpha = 0.0;   // [-] largest |ẏ|/U over the averaged cycles
  int cycles = 0;               // whole cycles completed
  long steps = 0;               // RK4 steps taken (all attempts)
  double step = 0.0;            // [s] RK4 step used
  bool converged = false;       // residual below tolerance
  bool at_rest = false;         // decayed to rest (A = 0)
};

// Samples recorded after convergence (every RK4 step), for histories, spectra and animation.
struct History {
  std::vector<double> time;            // [s] from the start of the recording
  std::vector<double> displacement;    // [m] y
  std::vector<double> velocity;        // [m/s] ẏ
  std::vector<double> wake;            // [-] q
  std::vector<double> force_galloping; // [N]
  std::vector<double> force_vortex;    // [N]
};

// Marches `state` (in/out: the continuation state) at the point of `rhs` to a limit cycle.
// If `record` is given, afterwards records `record_cycles` more response periods into it.
// Retries with a halved step (up to 3 times) when the state turns non-finite; then throws
// SolverError naming U, h*, the time and the quantity. Honours cancellation (RunCancelled).
LimitCycle runToLimitCycle(const FivRhs& rhs, State& state, const LimitCycleSettings& settings,
                           RunContext* context = nullptr, History* record = nullptr, int record_cycles = 0);

}  // namespace maris::fiv
