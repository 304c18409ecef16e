#include "riser/riser_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "riser/riser_dynamics.hpp"

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

struct RelaxationWatchStop {};  // thrown through the integrator by a watch that asks to stop

}  // namespace

DampedRelaxation::DampedRelaxation(const RiserModel& at_rest)
    : m_(dampedJointModel(at_rest)),
      period_(2 * std::numbers::pi / pendulumRate(m_)),
      step_(period_ / 40),
      integrator_(m_, 1.0 / step_) {}  // Baumgarte rate as the implicit dynamics use

void DampedRelaxation::advance(Eigen::VectorXd& y, double duration, RunContext& context,
                               const RunContext::ProgressFn& progress, const Watch& watch) {
  if (stopped_ || exhausted_) return;  // the integrator's carried state ends where the stop threw
  OdeOptions options;
  options.rtol = options.atol = 1e-6;
  options.step = step_;
  options.min_step = step_ * 1e-6;
  options.output_interval = watch ? period_ / 8 : period_;
  ChartedGeneralizedAlpha::StateObserver observer;
  if (watch)
    observer = [&](double t, const Eigen::VectorXd& state) {
      if (!watch(t, state)) return;
      y = state;
      normaliseState(m_, y);
      time_ = t;
      stopped_ = true;
      throw RelaxationWatchStop{};
    };
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
    const long before = integrator_.steps();
    if (max_steps_ > 0) options.max_steps = std::max(1L, max_steps_ - before);
    try {
      integrator_.advance(y, options, alpha, context, chunk, observer);
    } catch (const RelaxationWatchStop&) {
      return;
    } catch (const SolverError& e) {
      // The core counts its steps from each call: the limit reached is the one set here, not a failed motion.
      if (max_steps_ <= 0 || e.step() < max_steps_) throw;
      exhausted_ = true;
      stalled_time_ = e.time();
      stalled_step_ = (e.time() - options.t0) / static_cast<double>(std::max(1L, e.step() - before));
      return;
    }
    time_ = options.t1;
    alpha.startup_halvings = 0;
  }
}

}  // namespace maris::riser
