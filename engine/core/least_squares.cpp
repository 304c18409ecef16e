#include "core/least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

namespace maris {

namespace {

// r(x) and its cost; +∞ when x is outside the domain or r is not finite.
double evaluate(const LeastSquaresProblem& problem, const Eigen::VectorXd& x, Eigen::VectorXd& r, long& count) {
  ++count;
  if (!problem.residuals(x, r) || !r.allFinite()) return std::numeric_limits<double>::infinity();
  return r.squaredNorm();
}

bool formJacobian(const LeastSquaresProblem& problem, const LeastSquaresOptions& o, const Eigen::VectorXd& x,
                  const Eigen::VectorXd& r, Eigen::MatrixXd& jac, long& count) {
  if (problem.jacobian) return problem.jacobian(x, r, jac) && jac.allFinite();
  jac.resize(r.size(), x.size());
  Eigen::VectorXd shifted = x, r_shifted;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const double h = o.difference_step * std::max(std::abs(x[j]), o.difference_floor);
    shifted[j] = x[j] + h;
    if (!std::isfinite(evaluate(problem, shifted, r_shifted, count)) || r_shifted.size() != r.size()) return false;
    jac.col(j) = (r_shifted - r) / h;
    shifted[j] = x[j];
  }
  return true;
}

}  // namespace

LeastSquaresReport levenbergMarquardt(const LeastSquaresProblem& problem, const Eigen::VectorXd& x0,
                                      const LeastSquaresOptions& o, RunContext* ctx) {
  LeastSquaresReport rep;
  rep.x = x0;
  rep.cost = rep.initial_cost = evaluate(problem, rep.x, rep.residuals, rep.residual_evaluations);
  if (!std::isfinite(rep.cost)) {
    rep.stop = LeastSquaresStop::InvalidStart;
    return rep;
  }
  double mu = o.initial_damping;
  Eigen::VectorXd r_trial;
  while (true) {
    if (rep.iterations == o.max_iterations) {
      rep.stop = LeastSquaresStop::IterationLimit;
      return rep;
    }
    if (ctx && !o.progress_stage.empty())
      ctx->progress(static_cast<double>(rep.iterations) / o.max_iterations, o.progress_stage);
    ++rep.iterations;
    if (!formJacobian(problem, o, rep.x, rep.residuals, rep.jacobian, rep.residual_evaluations)) {
      rep.stop = LeastSquaresStop::NoJacobian;
      return rep;
    }
    const Eigen::MatrixXd normal = rep.jacobian.transpose() * rep.jacobian;
    const Eigen::VectorXd gradient = rep.jacobian.transpose() * rep.residuals;
    const Eigen::VectorXd scale = o.damping == LeastSquaresDamping::Marquardt
                                      ? Eigen::VectorXd(normal.diagonal().cwiseMax(1e-12))
                                      : Eigen::VectorXd::Constant(normal.rows(), normal.diagonal().maxCoeff());
    bool accepted = false;
    for (int trial = 0; trial < o.max_trials && !accepted; ++trial) {
      if (ctx) ctx->throwIfCancelled();
      Eigen::MatrixXd damped = normal;
      damped.diagonal() += mu * scale;
      const Eigen::VectorXd delta = damped.ldlt().solve(-gradient);
      const Eigen::VectorXd x_trial = problem.trial_point ? problem.trial_point(rep.x, delta) : rep.x + delta;
      const double step = (x_trial - rep.x).norm();
      const double cost_trial = evaluate(problem, x_trial, r_trial, rep.residual_evaluations);
      if (cost_trial < rep.cost) {
        accepted = true;
        ++rep.accepted_steps;
        const bool small_change = rep.cost - cost_trial <= o.cost_tolerance * rep.cost;
        rep.x = x_trial;
        rep.residuals = r_trial;
        rep.cost = cost_trial;
        mu = std::max(mu * o.damping_decrease, o.min_damping);
        if (small_change || step < o.step_tolerance) {
          rep.stop = small_change ? LeastSquaresStop::CostConverged : LeastSquaresStop::StepConverged;
          rep.converged = true;
          return rep;
        }
      } else {
        mu *= o.damping_increase;
        if (mu > o.max_damping || step < o.step_tolerance) break;
      }
    }
    if (!accepted) {
      rep.stop = LeastSquaresStop::NoDescent;
      return rep;
    }
  }
}

std::string describe(LeastSquaresStop stop) {
  switch (stop) {
    case LeastSquaresStop::CostConverged: return "cost converged";
    case LeastSquaresStop::StepConverged: return "step converged";
    case LeastSquaresStop::NoDescent: return "no descent step found";
    case LeastSquaresStop::IterationLimit: return "iteration limit reached";
    case LeastSquaresStop::InvalidStart: return "residuals not defined at the start";
    case LeastSquaresStop::NoJacobian: return "Jacobian not available";
  }
  return "unknown";
}

}  // namespace maris
