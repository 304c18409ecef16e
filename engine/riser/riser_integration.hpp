// Time integration of the riser: chooses an integrator of core/ode.hpp, runs it between sample times
// and feeds the recorder.
//
// The state carries unit quaternions, which no general-purpose integrator keeps on the unit sphere;
// the explicit integrators (RK4, DOPRI5) therefore run from sample to sample (≈ 2000 per run) and the
// state is projected back (quaternions renormalised, spin about the axes removed without torsion) at
// every sample. Between samples the right-hand side uses the normalised quaternion, so the drift of
// the norm never reaches the physics.
//
// The implicit integrator (core generalized-α, second-order form M q̈ = f) needs a vector-space
// configuration: each chunk re-parametrises every segment's orientation by three chart coordinates θ_i about
// its orientation at the chunk start, R_i = R_ref,i E(θ_i) (local re-parametrisation, so no Euler
// singularity; E: the rotation vector with torsion, swing–twist without, riser_implicit ChartKind), with
// velocities θ̇_i. The residual is r = q̈ − a(t, q, q̇), a = the accelerations of the O(n) Newton–Euler/reaction
// solve mapped to θ̈ through the chart's rate map. Work integrals ride
// along as coordinates whose velocity is the work (q̈ = power). The iteration matrix of this residual is
// dense (a depends on every segment through the reactions), so it is never formed: absolute coordinates
// solve with it through the banded unreduced equations (riser_newton), joint coordinates through an
// absolute twin of the model (riser_joint_newton); both O(n) per refresh and per solve.
#pragma once

#include <string>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "riser/riser_results.hpp"

namespace maris::riser {

// Samples of a run's history (the output interval is the simulated time over this); each evaluates the loads.
inline constexpr long kHistorySamples = 2000;

enum class Integrator { Rk4, Dopri5, Implicit };

// Predicted cost of one integrator over a run (riser_integrator_cost), in right-hand-side evaluations.
struct IntegratorCost {
  double step = 0.0;                  // [s]
  double steps = 0.0;                 // over solver.end_time
  double evaluations_per_step = 0.0;  // [right-hand-side evaluations]
  double total() const { return steps * evaluations_per_step; }
};

struct IntegrationPlan {
  Integrator method = Integrator::Rk4;
  double step = 0.0;                // [s] RK4/implicit step; DOPRI5: largest step (0 = unlimited)
  double stabilisation_rate = 0.0;  // [1/s] Baumgarte α of the constraints
  double highest_frequency = 0.0;   // [rad/s] ω_max estimate (bending, torsion, tension)
  std::string reason;               // why this integrator (auto) and step
  double expected_error = 0.0;      // [-] implicit with harmonic top motion or in a sea: probe error / motion
                                    // from implicitErrorModel or kSeaErrorModel (0 if no estimate)
  IntegratorCost rk4_prediction, implicit_prediction;  // auto only: what each would cost at its step
};

// Error model of generalized-α on a riser driven by a harmonic top motion of period T: probe error ≈ C (h/T)²
// of the motion, C measured on case 5 (absolute 22, joint 43: J builds positions from integrated rotations).
double implicitErrorModel(Formulation formulation);

// In a sea (waves, with or without the vessel moving the top) the same form with T_m01, the sea's mean period:
// probe error ≈ C (h/T_m01)² of the motion. C measured against converged references (docs/riser.md, "Error
// estimate in a sea"): 16 (100 m riser, n = 100, 3 hours), 28–58 (the two built-in seas, J and A, 40 s), 41–104
// (a 100 m riser, n = 10, 8 s through its ramp, against RK4); the largest, rounded up.
inline constexpr double kSeaErrorModel = 120.0;

// Whether the top moves harmonically (amplitude set, no time table): the only motion with a period T, the one
// implicitErrorModel is fitted to.
bool hasHarmonicTopMotion(const RiserModel& m);

// The automatic implicit step for a relative tolerance: 0.8 T √(tol/C) (so the expected error is 0.64 tol).
double implicitStepForTolerance(Formulation formulation, double period, double tolerance);

// Chooses integrator, step and stabilisation from solver.integrator, solver.time_step and solver.tolerance.
// "auto": the cheaper of RK4 and generalized-α in predicted right-hand-side evaluations at the asked tolerance
// (riser_integrator_cost; implicit also when RK4 would need more than 2e6 steps): RK4 at half its stability
// limit or the step its phase error on the top motion needs, whichever is smaller; generalized-α at the step
// implicitStepForTolerance (at most T/50; any implicit step without solver.time_step is rounded down to whole
// steps per frame interval). The method line gives both predictions (docs/riser.md: measured costs).
IntegrationPlan planIntegration(const RiserModel& m, const RiserParameters& p);

// The solver statistics with the implicit integrator's Newton-matrix refreshes (for the cost of a run,
// riser_integrator_cost).
struct RiserSolverStats : SolverStats {
  long matrix_refreshes = 0;
};

// Integrates y (at t = 0) to p.end_time, sampling `recorder` at ≈ 2000 history points, p.frame_count frames
// and the stress times. Returns the solver statistics (steps, rejected, RHS evaluations, error estimate).
// Throws SolverError (diverging state, naming time, step and quantity), RunCancelled.
RiserSolverStats integrateRiser(const RiserModel& m, const RiserParameters& p, const IntegrationPlan& plan,
                           Eigen::VectorXd& y, RiserRecorder& recorder, RunContext& context);

// Name of a time for table names: 12.5 -> "12_5".
std::string formatTime(double t);

}  // namespace maris::riser
