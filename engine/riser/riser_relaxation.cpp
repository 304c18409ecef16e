#include "riser/riser_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace maris::riser {

DampedRelaxation::DampedRelaxation(const RiserModel& at_rest) : m_(at_rest) {
  m_.formulation = Formulation::Joint;
  const double g = m_.gravity > 0 ? m_.gravity : 9.81;
  const double rate = std::sqrt(g / std::max(m_.length, 1e-6));  // [rad/s] pendulum of the chain's length
  m_.relaxation_damping = 2 * rate;
  period_ = 2 * std::numbers::pi / rate;
  step_ = period_ / 40;
  integrator_ = std::make_unique<ChartedGeneralizedAlpha>(m_, 1.0 / step_);  // Baumgarte rate as the dynamics
}

void DampedRelaxation::advance(Eigen::VectorXd& y, double duration, RunContext& context) {
  OdeOptions options;
  options.rtol = options.atol = 1e-6;
  options.step = step_;
  options.min_step = step_ * 1e-6;
  options.output_interval = period_;
  GeneralizedAlphaOptions alpha;
  alpha.startup_halvings = time_ == 0.0 ? 6 : 0;  // the shape starts at rest far from equilibrium
  // One chart per period: rotations within it stay well inside the chart's limit.
  const double end = time_ + duration;
  while (time_ < end - 1e-9 * period_) {
    options.t0 = time_;
    options.t1 = std::min(end, time_ + period_);
    integrator_->advance(y, options, alpha, context);
    time_ = options.t1;
    alpha.startup_halvings = 0;
  }
}

}  // namespace maris::riser
