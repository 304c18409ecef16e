// Predicted cost of the riser's integrators, for the `auto` choice of planIntegration.
//
// The unit is one right-hand side (evaluateRhs, O(n): 0.34–0.36 µs per segment measured by bench_riser_auto_cost,
// see docs/riser_work_precision.md), so the prediction does not depend on the machine:
//   RK4:      4 evaluations per step, steps = end_time / h, h = the smaller of half its stability limit
//             2.8/ω_max and the step whose phase error on the top's frequency meets the tolerance;
//   DOPRI5:   stability-bound as well; reported at the measured 2.7 × RK4's evaluations, never chosen;
//   implicit: per step ν Newton iterations of one residual and one banded solve, plus one Newton-matrix refresh
//             (its balance evaluations and banded factorisation) per output chunk; ν from the Newton tolerance;
//   waves:    in a sea every right-hand side of RK4 evaluates the wave kinematics at the 3(n + 1) Gauss points,
//             generalized-α once per step (held over its Newton iterations and matrix differences), both once
//             per history sample; one evaluation costs a measured weight per Gauss point and wave component.
// The same weights turn a run's counts (SolverStats) into evaluations: implicitCostOfRun, explicitCostOfRun.
#pragma once

#include <string>

#include "riser/riser_integration.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

// Newton iterations per implicit step at Newton tolerance `newton_tolerance` (measured, docs/riser.md).
double newtonIterationsPerStep(double newton_tolerance);

// Cost of one evaluation of the wave kinematics at all Gauss points, in right-hand-side evaluations (0 without a
// sea).
double waveEvaluationCost(const RiserModel& m);

// Cost of one banded Newton solve and of one Newton-matrix refresh, in right-hand-side evaluations.
double bandedSolveCost(const RiserModel& m);
double matrixRefreshCost(const RiserModel& m);

// Implicit run: ν residuals + solves per step at the step's Newton tolerance, refreshes per output chunk.
IntegratorCost predictImplicitCost(const RiserModel& m, const RiserParameters& p, double step, double newton_tolerance);
// RK4 at step h.
IntegratorCost predictRk4Cost(const RiserModel& m, const RiserParameters& p, double step);

// The step at which RK4's phase error on the harmonic top motion (ω = 2π/T) over end_time meets the relative
// tolerance: per step RK4 lags a harmonic oscillator's phase by (ωh)⁵/120, so over end_time the error is
// ω end_time (ωh)⁴/120 of the amplitude.
double rk4AccuracyStep(double period, double end_time, double tolerance);

// What a run cost, in the same units: explicit = right-hand sides; implicit = residuals and solves (one each
// per Newton iteration) plus refreshes; both plus `wave_evaluations`, the evaluations of the wave kinematics the
// run counted (the difference of the sea's batch's evaluations() over it).
double implicitCostOfRun(const RiserModel& m, const RiserSolverStats& stats, long wave_evaluations = 0);
double explicitCostOfRun(const RiserModel& m, const RiserSolverStats& stats, long wave_evaluations = 0);

// The method line of auto: "auto → implicit generalized-α: predicted 2 304 steps × 0.42 ms against RK4
// 164 966 steps × 0.22 ms (…)"; per-step times from the per-segment cost of one right-hand side.
std::string explainAutoChoice(const RiserModel& m, bool implicit, const IntegratorCost& implicit_cost,
                              const IntegratorCost& rk4_cost);

}  // namespace maris::riser
