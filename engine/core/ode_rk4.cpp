// Classical fixed-step Runge–Kutta 4 (see core/ode.hpp for the contract).
#include <cmath>

#include "core/checked_count.hpp"
#include "core/errors.hpp"
#include "core/ode.hpp"
#include "core/ode_internal.hpp"
#include "core/text_format.hpp"

namespace maris {

OdeStats integrateRk4(const OdeRhs& rhs, Eigen::VectorXd& y, const OdeOptions& options, RunContext& ctx,
                      const OdeObserver& observer) {
  using namespace ode_detail;
  checkOptions(options, "integrateRk4", true);
  OdeStats stats;
  const Eigen::Index n = y.size();
  const double h_nominal = options.step;
  const double span = options.t1 - options.t0;
  // Number of steps: the last one is shortened to end at t1 (a remainder below 1e-9 h is absorbed).
  const double ratio = span / h_nominal;
  // Compared as doubles first: a count beyond max_steps (or beyond any integer) is never converted.
  if (span > 0 && !(std::ceil(ratio - 1e-9) <= static_cast<double>(options.max_steps)))
    throw SolverError("time", options.t0, 0,
                      formatText("needs %.6g steps, more than max_steps = %ld", std::ceil(ratio - 1e-9), options.max_steps));
  const long step_count =
      span > 0 ? std::max(1L, checkedCount(ratio, options.max_steps, "time step h", "RK4 steps over the time span")) : 0;

  // Work vectors, sized once.
  Eigen::VectorXd k1(n), k2(n), k3(n), k4(n), k5(n), stage(n), y_new(n), dense(n);
  OutputSchedule schedule(options);
  ProgressTicker ticker(ctx, options);

  throwIfNotFinite(y, options.t0, 0, options.state_name);
  if (observer) observer(options.t0, y);
  if (step_count == 0) return stats;

  rhs(options.t0, y, k1);
  ++stats.rhs_evaluations;
  if (!k1.allFinite()) throwNonFiniteStep({&k1}, y, options.t0, 0, options);
  double t = options.t0;
  for (long k = 1; k <= step_count; ++k) {
    ctx.throwIfCancelled();
    const double t_new = k == step_count ? options.t1 : options.t0 + static_cast<double>(k) * h_nominal;
    const double h = t_new - t;

    // The four classical stages (k1 is carried over from the previous step: FSAL).
    stage = y + (0.5 * h) * k1;
    rhs(t + 0.5 * h, stage, k2);
    stage = y + (0.5 * h) * k2;
    rhs(t + 0.5 * h, stage, k3);
    stage = y + h * k3;
    rhs(t_new, stage, k4);
    y_new = y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (!y_new.allFinite()) throwNonFiniteStep({&k1, &k2, &k3, &k4}, y_new, t_new, k, options);
    if (options.after_step) {
      options.after_step(t_new, y_new);
      throwIfNotFinite(y_new, t_new, k, options.state_name);
    }
    // k5 = F(t_new, y_new): the 3rd-order embedded estimate, the Hermite end slope and the next k1.
    rhs(t_new, y_new, k5);
    stats.rhs_evaluations += 4;
    if (!k5.allFinite()) throwNonFiniteStep({&k5}, y_new, t_new, k, options);
    stats.error_estimate += relativeLocalError((h / 6.0) * (k4 - k5), y_new, options.atol);

    // Interior outputs from the step's cubic Hermite interpolant.
    for (double t_out = schedule.next(); t_out <= t_new; t_out = schedule.next()) {
      hermiteCubic((t_out - t) / h, h, y, k1, y_new, k5, dense);
      if (observer) observer(t_out, dense);
      schedule.advance();
    }
    y.swap(y_new);
    k1.swap(k5);
    t = t_new;
    ++stats.steps;
    if (k < step_count || step_count == 1) stats.last_step = h;
    if (observer && (schedule.everyStep() || k == step_count)) observer(t, y);
    ticker.tick(t);
  }
  ticker.finish();
  return stats;
}

}  // namespace maris
