// Amplitude envelopes along the riser (paper §8.3, Fig 17): largest displacement from the static
// shape and largest curvature at each node over the stored frames of the second half of a run.
#pragma once

#include "core/results.hpp"
#include "riser/riser_model.hpp"

namespace maris::riser {

// Reads table "node_positions" (every stored frame) and adds table "envelope" (arc_length,
// displacement_amplitude [m], curvature_amplitude [1/m]) with a plot, using frames with
// t ≥ t_end/2 (the steady response of a forced run). The displacement is measured from the first
// frame (the static shape); the curvature at a joint is the change of the angle between the chords
// to its neighbours, divided by Δ. The frames sample the motion, so with k frames per period an amplitude is
// underestimated by at most 1 − cos(π/k). Does nothing when there are fewer than 3 frames.
void addEnvelope(const RiserModel& model, Results& results);

}  // namespace maris::riser
