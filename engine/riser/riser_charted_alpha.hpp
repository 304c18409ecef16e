// Generalized-α on the riser over a sequence of chunks of time, each in a fresh chart (riser_implicit) about the
// state at its start (riser_implicit: the chart's reach is limited, so a long run cannot stay in one). Owns the
// chart and the O(n) Newton matrix of the formulation: absolute coordinates the force-space matrix of
// riser_newton, with the joints projected back together after every step; joint coordinates the same through
// an absolute twin (riser_joint_newton). The integrator's accelerations go on from chunk to chunk, rebased to
// the new chart, so a run cut into chunks continues as one call would (restarting each chunk from the exact
// accelerations injects the unresolved fast modes: core/ode_second_order.hpp, GeneralizedAlphaState).
// Used by the implicit dynamics (riser_integration) and by dynamic relaxation (riser_relaxation).
#pragma once

#include <functional>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include "core/ode.hpp"
#include "core/run_context.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_joint_newton.hpp"
#include "riser/riser_newton.hpp"
#include "riser/riser_waves.hpp"

namespace maris::riser {

class ChartedGeneralizedAlpha {
 public:
  // Sees the first-order state at the output times inside a chunk (not at its ends).
  using StateObserver = std::function<void(double t, const Eigen::VectorXd& y)>;

  // Keeps a reference to `m`. stabilisation_rate [1/s]: Baumgarte α of the constraints (bottom, joints).
  ChartedGeneralizedAlpha(const RiserModel& m, double stabilisation_rate);
  ChartedGeneralizedAlpha(const ChartedGeneralizedAlpha&) = delete;
  ChartedGeneralizedAlpha& operator=(const ChartedGeneralizedAlpha&) = delete;

  // Integrates the first-order state y (riser_dynamics layout) from options.t0 to options.t1 as one chunk and
  // leaves it normalised in y. The chunk is cut into pieces, each in a fresh chart, where a segment turns faster
  // than 1 rad per chunk (by the angular speeds at each piece's start): a whipping end stays inside the chart.
  // options.state_name is set here (the chart's coordinate names). `context` is checked for cancellation in
  // every residual; `progress` (may be empty) sees the fraction of this chunk.
  // Throws SolverError (its step counted from the first chunk; an iterate beyond the chart named as such),
  // RunCancelled.
  OdeStats advance(Eigen::VectorXd& y, OdeOptions options, const GeneralizedAlphaOptions& alpha, RunContext& context,
                   const RunContext::ProgressFn& progress = {}, const StateObserver& observer = {});

  long steps() const { return steps_; }  // accepted steps of all chunks so far

 private:
  // In a sea, a step's Newton iterations and Newton-matrix differences reuse the wave kinematics of its first
  // residual (the predictor) in the chart and in the joint formulation's twin: the fluid velocity and acceleration
  // are then off by their gradient times the predictor's position error, O(h²) like the step's own error, and
  // second order is kept (bench_riser_long_sea, docs/riser.md). The core integrator evaluates every residual of
  // a step at its t_{n+1} and each step, or retry after a halving, at a new time: a residual at a new time begins
  // a step.
  void beginStepAt(double t);

  // One piece [options.t0, options.t1] of the chunk ending at chunk_end, in a chart reset at its start.
  OdeStats advanceChart(Eigen::VectorXd& y, OdeOptions options, const GeneralizedAlphaOptions& alpha,
                        RunContext& context, const RunContext::ProgressFn& progress, const StateObserver& observer,
                        double chunk_end);

  const RiserModel& m_;
  OrientationChart chart_;
  std::optional<ForceSpaceNewtonMatrix> newton_;      // absolute coordinates
  std::optional<JointNewtonMatrix> joint_newton_;     // joint coordinates
  RiserWorkspace projection_ws_;
  SecondOrderSystem system_;
  RunContext* context_ = nullptr;                     // of the current advance() (cancellation)
  GeneralizedAlphaState carried_;
  Eigen::VectorXd q_, v_, state_, projected_;
  long steps_ = 0;
  StepWaveKinematics step_waves_, twin_step_waves_;  // held over the step at step_time_ (m.sea only)
  double step_time_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace maris::riser
