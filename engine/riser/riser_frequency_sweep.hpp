// Frequency sweeps of the paper's Sect. 8.2 (case 3, Tables 5 and 6): the first two bending frequencies
// about the static state for several pretension ratios i_T (T = i_T g m′, m′ the submerged mass of the
// riser and its contents) and for several segment counts n, each a statics solve plus a (gyroscopic,
// with internal flow) eigen solve. Where the riser is a straight, uniform, fully submerged pipe pinned at
// the bottom under a tensioner, every row carries the Galerkin reference of riser_references.hpp (tension
// varying with depth, internal flow with its Coriolis term) and eq (66) (mean tension, no flow).
#pragma once

#include <optional>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_references.hpp"

namespace maris::riser {

// g m′ [N]: weight minus buoyancy of wall and contents over the whole length, Σ (w_i − b_i) l_i.
double submergedWeight(const RiserModel& m);

// The riser as the continuous pipe of conveyingPipeFrequencies, or nothing when it is not one: needs a
// tensioner top over a pinned bottom, no sections rows, no current, no point loads, the bottom straight
// below the top and the same submerged weight per length on every segment (fully submerged or in air).
std::optional<ConveyingPipe> conveyingPipeOf(const RiserParameters& p, const RiserModel& m);

// Lowest two distinct bending frequencies [rad/s] (torsion-dominated modes skipped; in 3D each bending
// frequency comes twice, once per transverse plane). When some linearised modes are unstable (flow past
// divergence, flutter) the lowest stable ones need not be ω₁ and ω₂: check unstable_count. Slowly growing
// modes (a coarse chain with fast flow, docs/riser.md) keep their frequencies.
struct BendingPair {
  double first = 0.0;      // [rad/s] ω₁ (0 when missing)
  double second = 0.0;     // [rad/s] ω₂ (0 when missing)
  int unstable_count = 0;  // [-] linearised modes with Re λ > 1e-3 |λ| (RiserModes)
  int slowly_growing_count = 0;      // [-] RiserModes::slowly_growing_count
  double growth_rate = 0.0;          // [1/s] RiserModes::largest_growth_rate
  double growth_per_radian = 0.0;    // [-] RiserModes::largest_growth_per_radian
};
BendingPair firstTwoBendingFrequencies(const RiserModel& m, RunContext& context);

// Runs the sweeps listed in p.sweep_pretension_ratios and p.sweep_segment_counts (either may be empty)
// and appends tables "frequency_vs_pretension" and "frequency_vs_segments" with their plots and the
// scalar "sweep_max_difference" (largest |ω − ω_ref|/ω_ref over the pretension rows, when a reference
// exists). A row with unstable linearised modes is left out with a warning; a row with slowly growing
// modes is kept, with a warning giving the growth. Reports progress per row
// and honours cancellation between rows; throws SolverError when a statics solve fails (naming the row).
void addFrequencySweeps(const RiserParameters& p, Results& results, RunContext& context);

}  // namespace maris::riser
