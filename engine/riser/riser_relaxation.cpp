#include "riser/riser_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/ode.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_joint_newton.hpp"

namespace maris::riser {

DampedRelaxation::DampedRelaxation(const RiserModel& at_rest) : m_(at_rest) {
  m_.formulation = Formulation::Joint;
  const double g = m_.gravity > 0 ? m_.gravity : 9.81;
  const double rate = std::sqrt(g / std::max(m_.length, 1e-6));  // [rad/s] pendulum of the chain's length
  m_.relaxation_damping = 2 * rate;
  period_ = 2 * std::numbers::pi / rate;
  step_ = period_ / 40;
}

void DampedRelaxation::advance(Eigen::VectorXd& y, double duration, RunContext& context) {
  const double stabilisation = 1.0 / step_;  // the bottom's Baumgarte rate, as the implicit dynamics use
  RotationVectorChart chart(m_, stabilisation);
  JointNewtonMatrix newton(m_, chart, stabilisation);
  SecondOrderSystem system;
  system.size = chart.size();
  system.passive_coordinates = kWorkIntegrals;
  system.residual = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                        Eigen::VectorXd& r) {
    context.throwIfCancelled();
    chart.residual(t, q, v, acc, r);
  };
  system.solve_iteration_matrix = [&](const IterationMatrixRequest& request, Eigen::VectorXd& rhs) {
    context.throwIfCancelled();
    return newton.solve(request, rhs);
  };
  OdeOptions options;
  options.state_name = [&](Eigen::Index k) { return chart.name(k); };
  options.rtol = options.atol = 1e-6;
  options.step = step_;
  options.min_step = step_ * 1e-6;
  options.output_interval = duration;
  GeneralizedAlphaOptions alpha;
  alpha.startup_halvings = time_ == 0.0 ? 6 : 0;  // the shape starts at rest far from equilibrium
  // One chart per period: rotations within it stay well inside the chart's limit.
  GeneralizedAlphaState carried;
  Eigen::VectorXd q, v;
  const double end = time_ + duration;
  while (time_ < end - 1e-9 * period_) {
    const double chunk_end = std::min(end, time_ + period_);
    if (carried.acceleration.size() > 0) {
      chart.rebaseAccelerations(q, v, carried.acceleration);
      chart.rebaseAccelerations(q, v, carried.pseudo_acceleration);
    }
    chart.reset(y, q, v);
    options.t0 = time_;
    options.t1 = chunk_end;
    RunContext quiet;
    const OdeStats st = integrateGeneralizedAlpha(system, q, v, options, alpha, quiet, nullptr, &carried);
    steps_ += st.steps;
    chart.toState(q, v, y);
    normaliseState(m_, y);
    time_ = chunk_end;
    alpha.startup_halvings = 0;
  }
}

}  // namespace maris::riser
