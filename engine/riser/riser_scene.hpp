// The riser scene's solver entry point: parameters -> model -> statics -> time integration -> Results.
#pragma once

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "core/work_estimate.hpp"
#include "riser/riser_modes.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_statics.hpp"

namespace maris::riser {

// Runs a validated parameter set. Throws SolverError (diverging run, no static equilibrium) or RunCancelled.
Results solveRiser(const RiserParameters& p, RunContext& context);

// Steps, unknowns, stored values, memory and the longest uninterruptible stretch (the dense modal solve) of
// solveRiser(p), without solving (the scene's work estimate).
WorkEstimate estimateRiserWork(const RiserParameters& p);

// The parts of solveRiser that a study repeating the run needs:
// the initial shape, static equilibrium when p.solve_statics, else the built-in straight/arc shape;
StaticSolution initialShape(const RiserModel& m, const RiserParameters& p, RunContext& context);
// the time history from it (the recorder's results, `modes` among them when not empty, and the solver statistics;
// live partial results go to `context`'s sink, if it has one).
Results simulateRiser(const RiserModel& m, const RiserParameters& p, const StaticSolution& initial,
                      const RiserModes& modes, RunContext& context);

}  // namespace maris::riser
