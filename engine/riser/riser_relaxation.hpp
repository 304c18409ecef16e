// Dynamic relaxation: the way to static equilibrium when Newton's method cannot find it from the initial
// shape (riser_statics). The chain moves under its own loads with a mass-proportional damper added,
// integrated by generalized-α in joint coordinates with the O(n) Newton matrix of riser_joint_newton, so each
// step is O(n) and a chain far from equilibrium (a slack cable started on an arc) follows a physical path
// instead of Newton's linearisation. Statics then finishes by Newton from the shape the motion reaches.
#pragma once

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
  // (naming time, step and quantity).
  void advance(Eigen::VectorXd& y, double duration, RunContext& context, const RunContext::ProgressFn& progress = {});

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
};

}  // namespace maris::riser
