// The riser's plots grouped by what they show, for front ends that group many plots (a run with waves, a sea bed
// and a stored profile has about 14): histories at the probes, forces and energies at the ends, distributions
// along the riser, and the frequency and convergence sweeps.
#pragma once

#include <vector>

#include "core/scene.hpp"

namespace maris::riser {

std::vector<PlotGroupSpec> riserPlotGroups();

}  // namespace maris::riser
