// The riser scene's solver entry point: parameters -> model -> statics -> time integration -> Results.
#pragma once

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

// Runs a validated parameter set. Throws SolverError (diverging run, no static equilibrium) or RunCancelled.
Results solveRiser(const RiserParameters& p, RunContext& context);

}  // namespace maris::riser
