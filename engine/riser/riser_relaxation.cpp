#include "riser/riser_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace maris::riser {

namespace {

double pendulumRate(const RiserModel& m) {  // [rad/s] of a pendulum of the chain's length
  const double g = m.gravity > 0 ? m.gravity : 9.81;
  return std::sqrt(g / std::max(m.length, 1e-6));
}

RiserModel dampedJointModel(const RiserModel& at_rest) {
  RiserModel m = at_rest;
  m.formulation = Formulation::Joint;
  m.relaxation_damping = 2 * pendulumRate(m);
  return m;
}

}  // namespace

DampedRelaxation::DampedRelaxation(const RiserModel& at_rest)
    : m_(dampedJointModel(at_rest)),
      period_(2 * std::numbers::pi / pendulumRate(m_)),
      step_(period_ / 40),
      integrator_(m_, 1.0 / step_) {}  // Baumgarte rate as the implicit dynamics use

void DampedRelaxation::advance(Eigen::VectorXd& y, double duration, RunContext& context,
                               const RunContext::ProgressFn& progress) {
  OdeOptions options;
  options.rtol = options.atol = 1e-6;
  options.step = step_;
  options.min_step = step_ * 1e-6;
  options.output_interval = period_;
  GeneralizedAlphaOptions alpha;
  alpha.startup_halvings = time_ == 0.0 ? 6 : 0;  // the shape starts at rest far from equilibrium
  // One chart per period: rotations within it stay well inside the chart's limit.
  const double start = time_, end = time_ + duration;
  while (time_ < end - 1e-9 * period_) {
    options.t0 = time_;
    options.t1 = std::min(end, time_ + period_);
    RunContext::ProgressFn chunk;
    if (progress)
      chunk = [&](double f, const std::string& stage) {
        progress((options.t0 - start + f * (options.t1 - options.t0)) / duration, stage);
      };
    integrator_.advance(y, options, alpha, context, chunk);
    time_ = options.t1;
    alpha.startup_halvings = 0;
  }
}

}  // namespace maris::riser
