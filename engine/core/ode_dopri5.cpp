// Adaptive Dormand–Prince 5(4) with FSAL, PI step control and dense output (contract in core/ode.hpp).
// Coefficients: Dormand & Prince (1980), J. Comput. Appl. Math. 6:19–26; dense-output weights from
// Hairer, Nørsett & Wanner, Solving Ordinary Differential Equations I, 2nd ed., §II.6.
#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/ode.hpp"
#include "core/ode_internal.hpp"

namespace maris {
namespace {

// Butcher tableau (c, a) and the 5th-order weights b (= the last row, so the 7th stage is FSAL).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
// e = b − b̂ (5th minus 4th order weights), over the stages 1, 3, 4, 5, 6, 7.
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
// Weights of the 4th-order continuous extension's last coefficient.
constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                 d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                 d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;

// PI controller (Hairer et al. §IV.2): exponents, safety factor and step-ratio limits.
constexpr double kAlpha = 0.17, kBeta = 0.04, kSafety = 0.9, kMinFactor = 0.2, kMaxFactor = 10.0;

double weightedRms(const Eigen::VectorXd& v, const Eigen::VectorXd& scale) {
  if (v.size() == 0) return 0.0;
  return std::sqrt((v.array() / scale.array()).square().mean());
}

// Starting step from the scales of y0, F(y0) and a finite-difference second derivative
// (Hairer et al. §II.4, "starting step size").
double initialStep(const OdeRhs& rhs, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0, const OdeOptions& o,
                   OdeStats& stats) {
  const Eigen::VectorXd scale = (o.atol + o.rtol * y0.array().abs()).matrix();
  const double d0 = weightedRms(y0, scale), d1n = weightedRms(f0, scale);
  double h0 = (d0 < 1e-5 || d1n < 1e-5) ? 1e-6 : 0.01 * d0 / d1n;
  h0 = std::min(h0, o.t1 - o.t0);
  const Eigen::VectorXd y1 = y0 + h0 * f0;
  Eigen::VectorXd f1(y0.size());
  rhs(o.t0 + h0, y1, f1);
  ++stats.rhs_evaluations;
  const double d2 = f1.allFinite() ? weightedRms(f1 - f0, scale) / h0 : 0.0;
  const double dmax = std::max(d1n, d2);
  const double h1 = dmax <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / dmax, 1.0 / 5.0);
  return std::min(100.0 * h0, h1);
}

}  // namespace

OdeStats integrateDopri5(const OdeRhs& rhs, Eigen::VectorXd& y, const OdeOptions& options, RunContext& ctx,
                         const OdeObserver& observer) {
  using namespace ode_detail;
  checkOptions(options, "integrateDopri5", false);
  OdeStats stats;
  const Eigen::Index n = y.size();
  const double t1 = options.t1;

  // Work vectors, sized once.
  Eigen::VectorXd k1(n), k2(n), k3(n), k4(n), k5(n), k6(n), k7(n), stage(n), y_new(n), err(n), scale(n);
  Eigen::VectorXd r_diff(n), r_start(n), r_end(n), r_mid(n), dense(n);
  OutputSchedule schedule(options);
  ProgressTicker ticker(ctx, options);

  throwIfNotFinite(y, options.t0, 0, options.state_name);
  if (observer) observer(options.t0, y);
  if (t1 == options.t0) return stats;

  rhs(options.t0, y, k1);
  ++stats.rhs_evaluations;
  if (!k1.allFinite()) throwNonFiniteStep({&k1}, y, options.t0, 0, options);
  double h = options.step > 0.0 ? options.step : initialStep(rhs, y, k1, options, stats);
  h = std::min({h, options.max_step, t1 - options.t0});
  double t = options.t0;
  double err_prev = 1e-4;
  bool previous_rejected = false;

  while (t < t1) {
    ctx.throwIfCancelled();
    if (stats.steps >= options.max_steps)
      throw SolverError("time", t, stats.steps,
                        "needs more than max_steps = " + std::to_string(options.max_steps) + " steps");
    // Stretch (≤ 1 %) or shorten the step to land exactly on t1.
    const bool last = t + 1.01 * h >= t1;
    if (last) h = t1 - t;
    const double t_new = last ? t1 : t + h;

    // The six stages; the seventh (at t_new, y_new) is the next step's first (FSAL).
    stage = y + h * a21 * k1;
    rhs(t + c2 * h, stage, k2);
    stage = y + h * (a31 * k1 + a32 * k2);
    rhs(t + c3 * h, stage, k3);
    stage = y + h * (a41 * k1 + a42 * k2 + a43 * k3);
    rhs(t + c4 * h, stage, k4);
    stage = y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
    rhs(t + c5 * h, stage, k5);
    stage = y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
    rhs(t_new, stage, k6);
    y_new = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    rhs(t_new, y_new, k7);
    stats.rhs_evaluations += 6;

    // Weighted RMS of the embedded error estimate.
    err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    scale = (options.atol + options.rtol * y.array().abs().max(y_new.array().abs())).matrix();
    const double err_norm = weightedRms(err, scale);

    if (std::isfinite(err_norm) && err_norm <= 1.0) {
      stats.error_estimate += relativeLocalError(err, y_new, options.atol);
      // Interior outputs from the continuous extension (coefficients formed only when needed).
      if (schedule.next() <= t_new) {
        r_diff = y_new - y;
        r_start = h * k1 - r_diff;
        r_end = r_diff - h * k7 - r_start;
        r_mid = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
      }
      for (double t_out = schedule.next(); t_out <= t_new; t_out = schedule.next()) {
        const double theta = (t_out - t) / h, theta1 = 1.0 - theta;
        dense = y + theta * (r_diff + theta1 * (r_start + theta * (r_end + theta1 * r_mid)));
        if (observer) observer(t_out, dense);
        schedule.advance();
      }
      y.swap(y_new);
      k1.swap(k7);
      t = t_new;
      ++stats.steps;
      if (!last || stats.steps == 1) stats.last_step = h;
      if (observer && (schedule.everyStep() || last)) observer(t, y);
      ticker.tick(t);

      // PI step-size update; no growth right after a rejection.
      double factor = kSafety * std::pow(std::max(err_norm, 1e-10), -kAlpha) * std::pow(err_prev, kBeta);
      factor = std::clamp(factor, kMinFactor, previous_rejected ? 1.0 : kMaxFactor);
      err_prev = std::max(err_norm, 1e-4);
      previous_rejected = false;
      h = std::min(h * factor, options.max_step);
      continue;
    }

    // Rejected: shrink (by the largest allowed factor if the estimate is not even finite).
    ++stats.rejected_steps;
    previous_rejected = true;
    const double factor =
        std::isfinite(err_norm) ? std::max(kMinFactor, kSafety * std::pow(err_norm, -kAlpha)) : kMinFactor;
    h *= factor;
    if (h < options.min_step) {
      if (!std::isfinite(err_norm)) throwNonFiniteStep({&k1, &k2, &k3, &k4, &k5, &k6, &k7}, y_new, t_new,
                                                       stats.steps, options);
      Eigen::Index worst = 0;
      (err.array() / scale.array()).abs().maxCoeff(&worst);
      throw SolverError(componentName(options, worst), t, stats.steps,
                        "has the largest local error when the step size collapsed below min_step = " +
                            std::to_string(options.min_step) + " s (weighted error " +
                            std::to_string(err_norm) + ")");
    }
  }
  ticker.finish();
  return stats;
}

}  // namespace maris
