#include "riser/riser_charted_alpha.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace maris::riser {

ChartedGeneralizedAlpha::ChartedGeneralizedAlpha(const RiserModel& m, double stabilisation_rate)
    : m_(m), chart_(m, stabilisation_rate), projection_ws_(makeWorkspace(m, 0.0)) {
  system_.size = chart_.size();
  if (m.sea) chart_.workspace().pose.step_waves = &step_waves_;
  // The O(n) Newton matrices give the work-integral rows the identity (the powers feed back into nothing), so
  // their corrections lag one iteration behind; as passive coordinates they are left out of the convergence
  // test. Counted in, they failed steps whose motion had converged: the top's work has an absolute tolerance at
  // the start of a run (W ≈ 0) and its power carries the stiff top reaction (case 5, A3, n = 400, h = 50 ms:
  // 12 rejected steps in the first 0.15 s). The motion is the same either way; the work integrals agree to
  // 1e-16 relative with those of an exact completion of their rows.
  system_.passive_coordinates = kWorkIntegrals;  // the chart's last coordinates (riser_implicit.hpp)
  system_.residual = [this](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                            Eigen::VectorXd& r) {
    context_->throwIfCancelled();
    if (m_.sea && t != step_time_) beginStepAt(t);
    chart_.residual(t, q, v, acc, r);
  };
  if (m.formulation == Formulation::Joint) {
    joint_newton_.emplace(m, chart_, stabilisation_rate);
    if (m.sea) joint_newton_->holdTwinWaveKinematics(&twin_step_waves_);
    system_.solve_iteration_matrix = [this](const IterationMatrixRequest& request, Eigen::VectorXd& rhs) {
      context_->throwIfCancelled();
      return joint_newton_->solve(request, rhs);
    };
  } else {
    newton_.emplace(m, chart_);
    system_.solve_iteration_matrix = [this](const IterationMatrixRequest& request, Eigen::VectorXd& rhs) {
      context_->throwIfCancelled();
      return newton_->solve(request, rhs);
    };
    // The joints are projected back together after every step (closed by translation down the chain, a held
    // bottom's mismatch spread over turns of all segments), so Baumgarte only has to hold the remainder within
    // a step and the top's velocity.
    system_.project_step = [this](double t, Eigen::VectorXd& q, Eigen::VectorXd& v) {
      chart_.toState(q, v, projected_);
      projectConstraints(m_, projection_ws_, t, projected_, 1);
      chart_.fromState(projected_, q, v);
    };
  }
}

void ChartedGeneralizedAlpha::beginStepAt(double t) {
  step_time_ = t;
  step_waves_.beginStep();
  twin_step_waves_.beginStep();
}

namespace {

// [rad/s] the largest angular speed of the segments in first-order state y.
double largestAngularSpeed(const RiserModel& m, const Eigen::VectorXd& y) {
  double largest = 0.0;
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i)
    largest = std::max(largest, y.segment<3>(angularVelocityStateOffset(m, i)).norm());
  return largest;
}

// A chart is used for at most the time a segment takes to turn this far at the speed of the chart's start, so
// that a fast segment (a whipping free end) stays well inside the chart's reach (riser_implicit: a swing of
// 2.8 rad without torsion) even if it speeds up twofold.
constexpr double kChartTurn = 1.0;  // [rad]

}  // namespace

OdeStats ChartedGeneralizedAlpha::advance(Eigen::VectorXd& y, OdeOptions options, const GeneralizedAlphaOptions& alpha,
                                          RunContext& context, const RunContext::ProgressFn& progress,
                                          const StateObserver& observer) {
  const double t0 = options.t0, t1 = options.t1;
  const double tol = 1e-9 * std::max(std::abs(t1), t1 - t0);
  OdeStats total;
  GeneralizedAlphaOptions piece_alpha = alpha;  // the start-up ramp belongs to the chunk's start, not each piece's
  for (double t = t0; t < t1 - tol;) {
    // A new chart where the segments turn fast; the last piece not shorter than half a reach. The pieces end on
    // the chunk's output grid (the core counts output times from each call's start), at least one interval on.
    const double speed = largestAngularSpeed(m_, y);
    const double reach = speed > 0 ? kChartTurn / speed : t1 - t;
    double end = t1;
    if (t1 - t > 1.5 * reach) {
      end = t + reach;
      if (const double every = options.output_interval; every > 0) {
        const double at = std::round((t - t0) / every);
        end = t0 + std::max(at + 1, std::floor((end - t0) / every)) * every;
      }
      if (end >= t1 - tol) end = t1;
    }
    options.t0 = t;
    options.t1 = end;
    RunContext::ProgressFn piece_progress;
    if (progress)
      piece_progress = [&](double f, const std::string& stage) {
        progress((t - t0 + f * (end - t)) / (t1 - t0), stage);
      };
    const OdeStats s = advanceChart(y, options, piece_alpha, context, piece_progress, observer, t1);
    piece_alpha.startup_halvings = 0;
    total.steps += s.steps;
    total.rejected_steps += s.rejected_steps;
    total.rhs_evaluations += s.rhs_evaluations;
    total.jacobian_evaluations += s.jacobian_evaluations;
    total.error_estimate += s.error_estimate;
    if (s.last_step > 0) total.last_step = s.last_step;
    t = end;
  }
  return total;
}

OdeStats ChartedGeneralizedAlpha::advanceChart(Eigen::VectorXd& y, OdeOptions options,
                                               const GeneralizedAlphaOptions& alpha, RunContext& context,
                                               const RunContext::ProgressFn& progress, const StateObserver& observer,
                                               double chunk_end) {
  context_ = &context;
  if (carried_.acceleration.size() > 0) {
    chart_.rebaseAccelerations(q_, v_, carried_.acceleration);
    chart_.rebaseAccelerations(q_, v_, carried_.pseudo_acceleration);
  }
  chart_.reset(y, q_, v_);
  options.state_name = [this](Eigen::Index k) { return chart_.name(k); };
  // The observer sees the output times after the piece's start (the previous piece's end, seen there) and
  // before the chunk's end (the caller's); a piece's own end inside the chunk is on the output grid.
  const double t0 = options.t0;
  const double tol = 1e-9 * std::max(std::abs(chunk_end), chunk_end - t0);
  SecondOrderObserver inner;
  if (observer)
    inner = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd&) {
      if (t <= t0 + tol || t >= chunk_end - tol) return;
      chart_.toState(q, v, state_);
      observer(t, state_);
    };
  RunContext chunk(progress, nullptr);  // cancellation is checked on `context` in every residual
  OdeStats stats;
  try {
    stats = integrateGeneralizedAlpha(system_, q_, v_, options, alpha, chunk, inner, &carried_);
  } catch (const SolverError& e) {
    // The core only sees the NaN residual of an iterate beyond the chart; name that as the quantity.
    const auto& overflow = chart_.chartOverflow();
    const bool off_chart = overflow.t == e.time();
    throw SolverError(off_chart ? overflow.quantity : e.quantity(), e.time(), steps_ + std::max(e.step(), 0L),
                      off_chart ? overflow.detail + " in every Newton iteration down to the smallest step (" +
                                      e.detail() + "); shorten the chunks (raise output.frame_count) or the step"
                                : e.detail());
  }
  steps_ += stats.steps;
  chart_.toState(q_, v_, y);
  normaliseState(m_, y);
  return stats;
}

}  // namespace maris::riser
