// Turns a tether simulation into Results: scalars, time-series tables with plots, the stability map of the
// closed loop at the target under model errors, and the animated 3D view (robots, camera frusta, catenary with
// tension colouring, lumped-mass cable).
#pragma once

#include "core/results.hpp"
#include "tether/tether_simulation.hpp"

namespace maris::tether {

Results buildTetherResults(const TetherParameters& p, const SimulationOutput& sim, RunContext& context);

}  // namespace maris::tether
