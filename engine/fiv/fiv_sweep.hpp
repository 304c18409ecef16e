// Sweeps of the FIV model over current speed for several submergence ratios, with continuation:
// each speed starts from the previous speed's final state, first upwards from a small seed, then
// back down from the top, so that coexisting branches (hysteresis) show.
#pragma once

#include <functional>
#include <vector>

#include "core/run_context.hpp"
#include "fiv/fiv_limit_cycle.hpp"
#include "fiv/fiv_model.hpp"

namespace maris::fiv {

struct SweepSettings {
  std::vector<double> speeds;              // [m/s] ascending
  std::vector<double> submergence_ratios;  // [-] h*; kDeep for no free surface
  bool sweep_down = true;
  bool up_from_rest = false;               // up-sweep: every speed from the seed (no continuation)
  double seed_amplitude_ratio = 0.05;      // [-] A/D of the seed and floor on the way up
  double onset_amplitude_ratio = 1.0;      // [-] A/D that counts as galloping for onset detection
  LimitCycleSettings cycle;
};

SweepSettings sweepSettingsFrom(const FivParameters& p);

// The response along one h* (index-aligned with SweepSettings::speeds).
struct SweepBranch {
  double submergence_ratio = kDeep;   // [-]
  double clearance = 0.0;             // [m] h − D/2, room above the cylinder top (∞ for deep)
  std::vector<LimitCycle> up;         // up-sweep
  std::vector<LimitCycle> down;       // down-sweep (empty unless sweep_down)
  double linear_onset_speed = 0.0;    // [m/s] 2c/(ρDLκ_g A1), ∞ if κ_g A1 <= 0
  double onset_speed = -1.0;          // [m/s] lowest up-sweep speed from which A/D >= onset ratio; -1 if none
  bool clearanceExceeded(const LimitCycle& c) const { return c.y_max > clearance; }
};

struct SweepResult {
  std::vector<double> speeds;
  std::vector<SweepBranch> branches;
  long steps = 0;               // RK4 steps over the whole sweep
  double worst_residual = 0.0;  // [-] largest limit-cycle residual
  int unconverged = 0;          // responses still drifting at max_cycles (ResponseKind::Drifting)
  int stationary = 0;           // quasi-periodic or chaotic responses found stationary (ResponseKind::Stationary)
};

// Seeds a state with a small displacement and wake variable (the rest state plus a perturbation).
State seedState(const FivModel& model, double amplitude_ratio);

// Sees the sweep so far, for partial results: while the first h* climbs, its up-sweep over the
// speeds done (speeds truncated to them); later, every finished h* over all speeds (a branch in
// progress and an unfinished down-sweep are left out). Called only when the context wants partial
// results (throttled), so building Results from it costs little.
using SweepObserver = std::function<void(const SweepResult& so_far)>;

// Runs the sweep. Throws SolverError (non-finite state) or RunCancelled.
SweepResult runSweep(const FivModel& model, const SweepSettings& settings, RunContext& context,
                     const SweepObserver& observe = {});

}  // namespace maris::fiv
