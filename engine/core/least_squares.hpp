// Nonlinear least squares shared by every scene: Levenberg–Marquardt on cost(x) = ‖r(x)‖²
// (Levenberg 1944; Marquardt 1963; Nocedal & Wright, Numerical Optimization, §10.3).
// Users: tether (camera shape fit), fiv (coefficient calibration), riser (descent steps of the static
// Newton solver when a Newton step fails). docs/numerics.md says how each one sets the options.
#pragma once

#include <functional>
#include <string>

#include <Eigen/Core>

#include "core/run_context.hpp"

namespace maris {

struct LeastSquaresProblem {
  // r(x) into `r` (sized by the callee). False when x lies outside the model's domain; such a trial
  // step is rejected like one that raises the cost, as is one with a non-finite residual.
  std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& r)> residuals;
  // J = ∂r/∂x at x, given r(x). False when J cannot be formed (the solver stops). Empty: forward
  // differences with step difference_step·max(|x_j|, difference_floor) (LeastSquaresOptions).
  std::function<bool(const Eigen::VectorXd& x, const Eigen::VectorXd& r, Eigen::MatrixXd& jacobian)> jacobian;
  // The point actually tried for the step x → x + δ (clamping to bounds, shortening into a feasible
  // region). Empty: x + δ.
  std::function<Eigen::VectorXd(const Eigen::VectorXd& x, const Eigen::VectorXd& step)> trial_point;
};

// How the damping μ enters the step equation (JᵀJ + μ·D) δ = −Jᵀr.
enum class LeastSquaresDamping {
  Marquardt,  // D = diag(JᵀJ) (each entry at least 1e-12): invariant to the scaling of the unknowns
  Levenberg,  // D = max_i (JᵀJ)_ii · I: μ relative to the stiffest direction
};

struct LeastSquaresOptions {
  int max_iterations = 100;         // Jacobian evaluations at most
  int max_trials = 1000;            // rejected steps per iteration at most before stopping
  LeastSquaresDamping damping = LeastSquaresDamping::Marquardt;
  double initial_damping = 1e-3;    // [-] μ at the start
  double damping_decrease = 1.0 / 3.0;  // μ ← max(μ·this, min_damping) after an accepted step
  double damping_increase = 4.0;    // μ ← μ·this after a rejected step
  double min_damping = 1e-12;
  double max_damping = 1e8;         // a rejected step that would push μ above this stops the solver
  double cost_tolerance = 1e-14;    // converged: an accepted step lowers the cost by ≤ this fraction of it
  double step_tolerance = 1e-11;    // converged: an accepted step with ‖δ‖ below this; stop: a rejected one
  double difference_step = 1e-7;    // [-] forward-difference Jacobian (when problem.jacobian is empty)
  double difference_floor = 1.0;    // [x units]
  std::string progress_stage;       // non-empty: ctx->progress(iteration / max_iterations, this)
};

enum class LeastSquaresStop {
  CostConverged,    // relative cost change below cost_tolerance
  StepConverged,    // accepted step below step_tolerance
  NoDescent,        // no trial step lowered the cost up to max_damping / max_trials, or a tiny rejected step
  IterationLimit,   // max_iterations reached
  InvalidStart,     // r(x0) not available
  NoJacobian,       // problem.jacobian (or a forward-difference point) failed
};

struct LeastSquaresReport {
  Eigen::VectorXd x;           // best point found (the start if nothing was accepted)
  Eigen::VectorXd residuals;   // r(x)
  Eigen::MatrixXd jacobian;    // the last Jacobian evaluated (at the start of the last iteration)
  double initial_cost = 0.0;   // ‖r(x0)‖²
  double cost = 0.0;           // ‖r(x)‖²
  int iterations = 0;          // Jacobian evaluations
  long residual_evaluations = 0;  // including any forward-difference columns
  long accepted_steps = 0;
  bool converged = false;      // stop is CostConverged or StepConverged
  LeastSquaresStop stop = LeastSquaresStop::IterationLimit;
};

// Minimises ‖r(x)‖² from x0. Each iteration forms J once, then solves the damped normal equations with
// rising μ until a trial point lowers the cost (accepted: μ falls) or μ exceeds max_damping.
// ctx (optional) is checked for cancellation once per trial step (RunCancelled).
LeastSquaresReport levenbergMarquardt(const LeastSquaresProblem& problem, const Eigen::VectorXd& x0,
                                      const LeastSquaresOptions& options, RunContext* ctx = nullptr);

// One word for the stop reason, for reports ("cost converged", "no descent step", ...).
std::string describe(LeastSquaresStop stop);

}  // namespace maris
