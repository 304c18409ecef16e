// Converged limit cycle of the FIV model at one operating point: time-marches the 6-state system
// (fiv_model.hpp) with fixed-step RK4 until the cycle amplitude stops changing, then averages the
// response over the last whole cycles.
//
// Why a dedicated RK4 loop rather than core/ode.hpp: the loop needs per-step event logic (zero
// up-crossings with interpolated times and energies, refined peaks, convergence test, early stop) on a
// fixed-size 6-state array with an inlined right-hand side. integrateRk4 takes a std::function on
// Eigen::VectorXd and has no early stop; on this system it costs 140 ns per step against 92 ns here
// (bench/fiv_sweep.cpp), before any event handling. The budget is 2 s for 500 limit cycles.
#pragma once

#include <cstddef>
#include <vector>

#include "core/run_context.hpp"
#include "fiv/fiv_model.hpp"

namespace maris::fiv {

struct LimitCycleSettings {
  int steps_per_period = 40;     // [-] RK4 steps per shortest period (structure or shedding)
  double tolerance = 1e-3;       // [-] converged when estimated remaining amplitude change / A is below
  int max_cycles = 150;          // [-] structural periods simulated at most
  int min_cycles = 6;            // [-] whole cycles before convergence is tested
  int average_cycles = 4;        // [-] cycles averaged for A, f and P of a periodic response
  int min_window = 8;            // [-] cycles per window, at least, of the stationarity test
  double rest_amplitude = 1e-7;  // [m] below this (and shrinking) the cylinder counts as at rest
};

// What the march ended on.
enum class ResponseKind {
  AtRest = 0,      // decayed to rest (A = 0)
  Periodic = 1,    // converged limit cycle: residual below the tolerance
  Stationary = 2,  // quasi-periodic or chaotic, statistically stationary (compareAmplitudeWindows)
  Drifting = 3,    // neither within max_cycles: still growing, decaying or drifting
};

// Response averaged over whole cycles: the last average_cycles of a periodic one, the two windows of a
// stationary one, the last average_cycles of a drifting one.
struct LimitCycle {
  double amplitude = 0.0;       // [m] A, mean half peak-to-peak of y per cycle
  double amplitude_spread = 0.0;  // [m] standard deviation of the per-cycle half peak-to-peak over those cycles
  double frequency = 0.0;       // [Hz] f, from zero up-crossings of y
  double power_damper = 0.0;    // [W] P = ⟨c ẏ²⟩ (paper eq 13)
  double power_fluid = 0.0;     // [W] ⟨F ẏ⟩ (paper eq 8), equal to P on an exact cycle
  double residual = 0.0;        // [-] estimated relative error of A: remaining drift (periodic), change between
                                //     the two windows' means (stationary), drift or spread (drifting)
  double y_max = 0.0;           // [m] largest upward displacement over the averaged cycles
  double y_min = 0.0;           // [m] largest downward displacement (negative)
  double max_tan_alpha = 0.0;   // [-] largest |ẏ|/U over the averaged cycles
  int cycles = 0;               // whole cycles completed
  long steps = 0;               // RK4 steps taken (all attempts)
  double step = 0.0;            // [s] RK4 step used
  bool converged = false;       // periodic (or at rest) with the residual below the tolerance
  bool at_rest = false;         // decayed to rest (A = 0)
  ResponseKind response = ResponseKind::Drifting;
};

// Stationarity test on per-cycle amplitudes a_k (half peak-to-peak per cycle). The first half of the
// record counts as transient; the second half is split into two windows of W = ⌊n/4⌋ cycles each. The
// response is stationary when the windows' means m1, m2 and standard deviations s1, s2 differ by no more
// than half the pooled standard deviation s = √((s1² + s2²)/2). A drift of any rate that is roughly linear
// over the windows moves the mean by √12 ≈ 3.5 s (the spread it causes itself), so it fails by a factor 7;
// a stationary fluctuation (quasi-periodic beating, chaos) moves it by less the longer the windows, once
// they span its slowest modulation. A period-2 cycle (alternating amplitudes) passes.
// The error of the mean over both windows is estimated twice: by |m2 − m1|, and by the standard error from
// 8 batch means (consecutive batches of 2W/8 cycles; their means are nearly independent once a batch spans
// the response's correlation time, whereas |m2 − m1| alone passes through zero now and then by chance).
struct AmplitudeWindows {
  bool stationary = false;
  std::size_t first = 0;   // index of the first cycle of the two windows
  std::size_t window = 0;  // W, cycles per window (0: record too short, W < max(min_window, 4))
  double mean = 0.0;       // mean of a_k over both windows
  double spread = 0.0;     // standard deviation of a_k over both windows
  double change = 0.0;     // |m2 − m1|
  double standard_error = 0.0;  // std of the 8 batch means / √8 (sample standard deviation)
  double error() const { return change > standard_error ? change : standard_error; }
};
AmplitudeWindows compareAmplitudeWindows(const std::vector<double>& amplitudes, int min_window);

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
