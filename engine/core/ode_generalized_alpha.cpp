// Implicit generalized-α for M(t,q) q'' = f(t,q,q') with Newton iterations (contract and equations in
// core/ode_second_order.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/ode_internal.hpp"
#include "core/ode_newton.hpp"
#include "core/ode_second_order.hpp"
#include "core/text_format.hpp"

namespace maris {

GeneralizedAlphaCoefficients generalizedAlphaCoefficients(double rho_inf) {
  if (!(rho_inf >= 0.0 && rho_inf <= 1.0))
    throw std::invalid_argument("generalized-alpha: rho_inf must be in [0, 1], got " + std::to_string(rho_inf));
  GeneralizedAlphaCoefficients c;
  c.alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
  c.alpha_f = rho_inf / (rho_inf + 1.0);
  c.gamma = 0.5 + c.alpha_f - c.alpha_m;
  c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  return c;
}

namespace {

using ode_detail::NewtonSolver;

// The coordinate with the largest last correction among those Newton's convergence test checks (not the
// passive ones, whose lagging corrections would otherwise be named).
std::string newtonFailure(const NewtonSolver& newton, const SecondOrderSystem& system, const OdeOptions& o, double h,
                          Eigen::Index* worst) {
  *worst = 0;
  const Eigen::VectorXd& correction = newton.lastCorrection();
  const Eigen::Index passive = std::clamp<Eigen::Index>(system.passive_coordinates, 0, correction.size());
  const Eigen::Index checked = correction.size() - passive;
  if (checked > 0) correction.head(checked).cwiseAbs().maxCoeff(worst);
  return "has the largest correction when the Newton iteration failed to converge at step h = " +
         numberText(h) + " s (min_step " + numberText(o.min_step) + " s)";
}

}  // namespace

OdeStats integrateGeneralizedAlpha(const SecondOrderSystem& system, Eigen::VectorXd& q, Eigen::VectorXd& v,
                                   const OdeOptions& options, const GeneralizedAlphaOptions& alpha_options,
                                   RunContext& ctx, const SecondOrderObserver& observer,
                                   GeneralizedAlphaState* state) {
  using namespace ode_detail;
  checkOptions(options, "integrateGeneralizedAlpha", true);
  const GeneralizedAlphaCoefficients c = generalizedAlphaCoefficients(alpha_options.rho_inf);
  const Eigen::Index n = system.size;
  if (!system.residual || q.size() != n || v.size() != n)
    throw std::invalid_argument("integrateGeneralizedAlpha: need a residual and q, v of size " + std::to_string(n));
  OdeStats stats;
  NewtonSolver newton(system, options, std::max(1, alpha_options.max_newton_iterations), stats, ctx);
  OutputSchedule schedule(options);
  ProgressTicker ticker(ctx, options);

  // Initial acceleration from M(t0, q0) q̈0 = f(t0, q0, v0) and the pseudo-acceleration equal to it, unless
  // a previous call's are given.
  throwIfNotFinite(q, options.t0, 0, options.state_name);
  throwIfNotFinite(v, options.t0, 0, options.state_name);
  const bool continued = state && state->acceleration.size() == n && state->pseudo_acceleration.size() == n;
  Eigen::VectorXd acc = continued ? state->acceleration : Eigen::VectorXd::Zero(n);
  if (!continued && !newton.solve(options.t0, q, v, 0.0, 0.0, acc)) {
    Eigen::Index worst = 0;
    newtonFailure(newton, system, options, 0.0, &worst);
    throw SolverError(componentName(options, worst), options.t0, 0,
                      "acceleration could not be found at the initial state (singular mass matrix?)");
  }
  if (continued) throwIfNotFinite(acc, options.t0, 0, options.state_name);
  if (observer) observer(options.t0, q, v, acc);
  newton.invalidateMatrix();

  Eigen::VectorXd pseudo = continued ? state->pseudo_acceleration : acc;
  Eigen::VectorXd pseudo_known(n), acc_new(n), q_base(n), v_base(n), q_new(n), v_new(n), q_out(n), v_out(n), a_out(n);
  // Equal steps no longer than options.step over [t0, t1], not full steps and a short last one: a change of step
  // changes β', γ' (a fresh iteration matrix) and, where the iteration matrix is formed at the predictor, fails
  // Newton (riser, slack cable held at both ends in absolute coordinates, 0.25 s output intervals at h = 0.16 s:
  // 247 steps, 92 rejected, with a 0.09 s step closing every interval; in two steps of 0.125 s: 81 and 1).
  const double span = options.t1 - options.t0;
  const double h_nominal = span > 0 ? span / std::ceil(span / options.step - 1e-9) : options.step;
  const int ramp = std::clamp(alpha_options.startup_halvings, 0, 60);
  double h = std::max(std::ldexp(h_nominal, -ramp), options.min_step), t = options.t0;
  bool ramping = ramp > 0;
  int good_steps_since_halving = 0;
  while (t < options.t1) {
    ctx.throwIfCancelled();
    if (stats.steps >= options.max_steps)
      throw SolverError("time", t, stats.steps,
                        "needs more than max_steps = " + std::to_string(options.max_steps) + " steps");
    const bool last = t + h * (1.0 + 1e-9) >= options.t1;
    const double h_step = last ? options.t1 - t : h;
    const double t_new = last ? options.t1 : t + h_step;

    // Predictor-independent parts of q_{n+1}, v_{n+1}; the unknown q̈_{n+1} enters with β', γ'.
    const double w = 1.0 / (1.0 - c.alpha_m);
    const double dq = c.beta * h_step * h_step * (1.0 - c.alpha_f) * w;
    const double dv = c.gamma * h_step * (1.0 - c.alpha_f) * w;
    pseudo_known = (c.alpha_f * acc - c.alpha_m * pseudo) * w;  // a_{n+1} minus its q̈_{n+1} part
    q_base = q + h_step * v + (h_step * h_step) * ((0.5 - c.beta) * pseudo + c.beta * pseudo_known);
    v_base = v + h_step * ((1.0 - c.gamma) * pseudo + c.gamma * pseudo_known);
    acc_new = acc;
    bool converged = newton.solve(t_new, q_base, v_base, dq, dv, acc_new);
    if (!converged && !newton.matrixIsFresh()) {
      newton.invalidateMatrix();  // a stale matrix may be the reason: retry once with a fresh one
      acc_new = acc;
      converged = newton.solve(t_new, q_base, v_base, dq, dv, acc_new);
    }
    if (!converged) {
      ++stats.rejected_steps;
      newton.invalidateMatrix();
      if (alpha_options.halve_on_failure && 0.5 * h_step >= options.min_step) {
        h = 0.5 * h_step;
        good_steps_since_halving = 0;
        ramping = false;
        continue;
      }
      Eigen::Index worst = 0;
      const std::string detail = newtonFailure(newton, system, options, h_step, &worst);
      throw SolverError(componentName(options, worst), t_new, stats.steps + 1, detail);
    }
    q_new = newton.q();
    v_new = newton.v();
    if (!q_new.allFinite()) throwIfNotFinite(q_new, t_new, stats.steps + 1, options.state_name);
    if (!v_new.allFinite()) throwIfNotFinite(v_new, t_new, stats.steps + 1, options.state_name);
    if (system.project_step) system.project_step(t_new, q_new, v_new);
    stats.error_estimate +=
        relativeLocalError((h_step * h_step * std::abs(c.beta - 1.0 / 6.0)) * (acc_new - acc), q_new, options.atol);

    // Interior outputs: Hermite cubics for q (with v) and v (with q̈), linear q̈.
    for (double t_out = schedule.next(); t_out <= t_new; t_out = schedule.next()) {
      const double theta = (t_out - t) / h_step;
      hermiteCubic(theta, h_step, q, v, q_new, v_new, q_out);
      hermiteCubic(theta, h_step, v, acc, v_new, acc_new, v_out);
      a_out = (1.0 - theta) * acc + theta * acc_new;
      if (observer) observer(t_out, q_out, v_out, a_out);
      schedule.advance();
    }
    // Commit: a_{n+1} = pseudo_known + (1−α_f)/(1−α_m) q̈_{n+1}.
    pseudo = pseudo_known + (1.0 - c.alpha_f) * w * acc_new;
    q.swap(q_new);
    v.swap(v_new);
    acc.swap(acc_new);
    t = t_new;
    ++stats.steps;
    if (!last || stats.steps == 1) stats.last_step = h_step;
    if (observer && (schedule.everyStep() || last)) observer(t, q, v, acc);
    ticker.tick(t);

    // Start-up ramp: double every step; after a halving, grow back once Newton copes again.
    if (ramping) {
      h = std::min(2.0 * h, h_nominal);
      ramping = h < h_nominal;
    } else if (h < h_nominal && ++good_steps_since_halving >= 4) {
      h = std::min(2.0 * h, h_nominal);
      good_steps_since_halving = 0;
    }
  }
  ticker.finish();
  if (state) {
    state->acceleration = acc;
    state->pseudo_acceleration = pseudo;
  }
  return stats;
}

}  // namespace maris
