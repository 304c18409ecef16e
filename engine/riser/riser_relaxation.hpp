// Dynamic relaxation: the way to static equilibrium when Newton's method cannot find it from the initial
// shape (riser_statics). The chain moves under its own loads with a mass-proportional damper added,
// integrated by generalized-α in joint coordinates with the O(n) Newton matrix of riser_joint_newton, so each
// step is O(n) and a chain far from equilibrium (a slack cable started on an arc) follows a physical path
// instead of Newton's linearisation. Statics then finishes by Newton from the shape the motion reaches.
#pragma once

#include <functional>

#include <Eigen/Core>

#include "core/run_context.hpp"
#include "riser/riser_charted_alpha.hpp"
#include "riser/riser_model.hpp"

namespace maris::riser {

class DampedRelaxation {
 public:
  // `at_rest`: the model with its top held still (riser_statics' atRest); any formulation (joint is used).
  // The damper c = 2√(g/L) [1/s] is critical for a pendulum of the chain's length; the step is a 40th of that
  // pendulum's period; generalized-α's numerical damping (ρ∞ = 0.8) takes the modes far above it.
  explicit DampedRelaxation(const RiserModel& at_rest);
  DampedRelaxation(const DampedRelaxation&) = delete;  // the integrator refers to m_
  DampedRelaxation& operator=(const DampedRelaxation&) = delete;

  // Advances the joint state y (riser_dynamics layout of the joint model) by `duration` s of damped motion;
  // `progress` (may be empty) sees the fraction of `duration` done. Throws SolverError if the motion fails
  // (naming time, step and quantity). Stops early, with exhausted() true and y at the last chunk's end, once the
  // steps of all calls reach the limit (limitSteps).
  // `watch` (may be empty) sees the state every eighth of a period inside the chunks (interpolated; not at their
  // ends, where the caller sees y) and returns true to stop there: advance then returns with y at that state,
  // time() at its time and stopped() true, and the relaxation cannot go on.
  using Watch = std::function<bool(double t, const Eigen::VectorXd& y)>;
  void advance(Eigen::VectorXd& y, double duration, RunContext& context, const RunContext::ProgressFn& progress = {},
               const Watch& watch = {});
  bool stopped() const { return stopped_; }

  // At most `max_steps` accepted steps over all calls (a chunk cut into fresh charts may pass it by one piece's
  // worth). Without a limit the steps are bounded by the core integrator's own max_steps only.
  void limitSteps(long max_steps) { max_steps_ = max_steps; }
  bool exhausted() const { return exhausted_; }
  // [s] mean step of the chunk the limit stopped (0 before): far below the nominal step, the motion is stiff or
  // discontinuous there (a load that jumps, such as buoyancy at the water line, makes the error control halve it).
  double stalledStep() const { return stalled_step_; }
  double stalledTime() const { return stalled_time_; }  // [s] where the limit stopped it (y stays at time())
  double nominalStep() const { return step_; }

  const RiserModel& model() const { return m_; }  // the joint model with the damper
  double period() const { return period_; }       // [s] 2π√(L/g)
  double time() const { return time_; }           // [s] damped motion so far
  long steps() const { return integrator_.steps(); }

 private:
  // In this order: each is made from the ones above it.
  RiserModel m_;
  double period_ = 0.0, step_ = 0.0;
  ChartedGeneralizedAlpha integrator_;  // refers to m_
  double time_ = 0.0;
  long max_steps_ = 0;  // 0: no limit of its own
  bool exhausted_ = false, stopped_ = false;
  double stalled_step_ = 0.0, stalled_time_ = 0.0;
};

}  // namespace maris::riser
