// Newton iteration of the generalized-α integrator (contract in core/ode_newton.hpp).
#include "core/ode_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace maris::ode_detail {

NewtonSolver::NewtonSolver(const SecondOrderSystem& system, const OdeOptions& options, int max_iterations,
                           OdeStats& stats, RunContext& ctx)
    : system_(system), options_(options), max_iterations_(max_iterations), stats_(stats), ctx_(ctx),
      n_(system.size), banded_(system.lower_bandwidth >= 0 && system.upper_bandwidth >= 0),
      q_(n_), v_(n_), r_(n_), delta_(n_), solution_(n_), r_pert_(n_), acc_pert_(n_), q_pert_(n_), v_pert_(n_),
      eps_(n_) {
  if (system_.solve_iteration_matrix) return;
  if (banded_)
    banded_lu_.resize(n_, system.lower_bandwidth, system.upper_bandwidth);
  else
    dense_.resize(n_, n_);
}

bool NewtonSolver::solve(double t, const Eigen::VectorXd& q_base, const Eigen::VectorXd& v_base, double dq,
                         double dv, Eigen::VectorXd& acc) {
  const bool coefficients_changed = dq != matrix_dq_ || dv != matrix_dv_;
  matrix_fresh_ = false;
  double previous_norm = 0.0;
  for (int iteration = 0; iteration < max_iterations_; ++iteration) {
    ctx_.throwIfCancelled();
    q_ = q_base + dq * acc;
    v_ = v_base + dv * acc;
    system_.residual(t, q_, v_, acc, r_);
    ++stats_.rhs_evaluations;
    if (!r_.allFinite()) return false;
    // Refresh the iteration matrix at the first iteration if it is stale, or when convergence is slow.
    const bool refresh = !have_matrix_ || (coefficients_changed && iteration == 0) || slow_;
    delta_ = -r_;
    if (!solveLinear(t, acc, dq, dv, refresh)) return false;
    acc += delta_;
    const double norm = correctionNorm(dq, dv, q_base, v_base, acc);
    if (!std::isfinite(norm)) return false;
    // Converged when the correction is within tolerance, or the contraction rate θ says the remaining
    // error θ/(1−θ)·|Δ| is.
    const double theta = iteration > 0 ? norm / std::max(previous_norm, 1e-300) : 0.0;
    slow_ = theta > 0.5;
    if (norm <= 1.0 || (iteration > 0 && theta < 1.0 && theta / (1.0 - theta) * norm <= 1.0)) {
      q_ = q_base + dq * acc;
      v_ = v_base + dv * acc;
      return true;
    }
    // Diverging. Except once: a matrix formed at the first iterate (the predictor) can be far from the one along
    // the path to the solution; formed again at the second (slow_ is set), it often converges at once: riser,
    // absolute coordinates, slack cable held at both ends at T/25: 85 steps, 11 rejected, without this; 63, none.
    if (iteration > 0 && theta >= 1.0 && !(iteration == 1 && matrix_fresh_)) return false;
    previous_norm = norm;
  }
  slow_ = true;
  return false;
}

// delta_ ← S⁻¹ delta_, through the caller's solver or the finite-difference matrix.
bool NewtonSolver::solveLinear(double t, const Eigen::VectorXd& acc, double dq, double dv, bool refresh) {
  if (refresh) {
    ++stats_.jacobian_evaluations;
    matrix_fresh_ = true;
    matrix_dq_ = dq;
    matrix_dv_ = dv;
    slow_ = false;
  }
  if (system_.solve_iteration_matrix) {
    have_matrix_ = true;
    return system_.solve_iteration_matrix(IterationMatrixRequest{t, q_, v_, acc, dv, dq, refresh}, delta_);
  }
  if (refresh && !formDifferenceMatrix(t, acc, dq, dv)) {
    have_matrix_ = false;
    return false;
  }
  have_matrix_ = true;
  if (banded_) {
    banded_lu_.solve(delta_);
  } else {
    solution_.noalias() = dense_lu_.solve(delta_);
    delta_.swap(solution_);
  }
  return delta_.allFinite();
}

// r_pert_ ← r at acc + eps_ (q and v moved consistently); eps_ is zero outside the perturbed columns.
void NewtonSolver::perturbedResidual(double t, const Eigen::VectorXd& acc, double dq, double dv) {
  ctx_.throwIfCancelled();
  acc_pert_ = acc + eps_;
  q_pert_ = q_ + dq * eps_;
  v_pert_ = v_ + dv * eps_;
  system_.residual(t, q_pert_, v_pert_, acc_pert_, r_pert_);
  ++stats_.rhs_evaluations;
}

// Forward differences of the residual. Dense: one call per column. Banded: columns j ≡ g mod (kl + ku + 1)
// touch disjoint rows [j − ku, j + kl], so one call per group g serves all of them (Curtis, Powell & Reid
// 1974). Perturbation √eps·max(|acc_j|, |acc|_max, 1) [acceleration units].
bool NewtonSolver::formDifferenceMatrix(double t, const Eigen::VectorXd& acc, double dq, double dv) {
  const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  const double acc_scale = std::max(n_ > 0 ? acc.cwiseAbs().maxCoeff() : 0.0, 1.0);
  auto step_of = [&](Eigen::Index j) { return root_eps * std::max(std::abs(acc[j]), acc_scale); };
  if (!banded_) {
    for (Eigen::Index j = 0; j < n_; ++j) {
      eps_.setZero();
      eps_[j] = step_of(j);
      perturbedResidual(t, acc, dq, dv);
      dense_.col(j) = (r_pert_ - r_) / eps_[j];
    }
    if (!dense_.allFinite()) return false;
    dense_lu_.compute(dense_);
    // PartialPivLU does not report singularity: look at the pivots.
    const Eigen::VectorXd pivots = dense_lu_.matrixLU().diagonal().cwiseAbs();
    return n_ == 0 || pivots.minCoeff() > 1e-14 * pivots.maxCoeff();
  }
  const Eigen::Index kl = banded_lu_.lowerBandwidth(), ku = banded_lu_.upperBandwidth();
  const Eigen::Index groups = std::min(n_, kl + ku + 1);
  banded_lu_.setZero();
  for (Eigen::Index g = 0; g < groups; ++g) {
    eps_.setZero();
    for (Eigen::Index j = g; j < n_; j += kl + ku + 1) eps_[j] = step_of(j);
    perturbedResidual(t, acc, dq, dv);
    for (Eigen::Index j = g; j < n_; j += kl + ku + 1) {
      const Eigen::Index first = std::max<Eigen::Index>(0, j - ku), last = std::min(n_ - 1, j + kl);
      for (Eigen::Index i = first; i <= last; ++i) banded_lu_.at(i, j) = (r_pert_[i] - r_[i]) / eps_[j];
    }
  }
  return banded_lu_.factorize();
}

// Weighted RMS of the corrections to q and v (weights 1/(atol + rtol·|value|)) over the coordinates that are
// not passive; the larger one.
// With dq = dv = 0 (initial acceleration) the acceleration itself is measured.
double NewtonSolver::correctionNorm(double dq, double dv, const Eigen::VectorXd& q_base,
                                    const Eigen::VectorXd& v_base, const Eigen::VectorXd& acc) const {
  const Eigen::Index checked = n_ - std::clamp<Eigen::Index>(system_.passive_coordinates, 0, n_);
  if (checked == 0) return 0.0;
  const double atol = options_.atol, rtol = options_.rtol;
  double sum_q = 0.0, sum_v = 0.0, sum_a = 0.0;
  for (Eigen::Index i = 0; i < checked; ++i) {
    const double eq = dq * delta_[i] / (atol + rtol * std::abs(q_base[i] + dq * acc[i]));
    const double ev = dv * delta_[i] / (atol + rtol * std::abs(v_base[i] + dv * acc[i]));
    const double ea = delta_[i] / (atol + rtol * std::abs(acc[i]));
    sum_q += eq * eq;
    sum_v += ev * ev;
    sum_a += ea * ea;
  }
  const double count = static_cast<double>(checked);
  if (dq == 0.0 && dv == 0.0) return std::sqrt(sum_a / count);
  return std::sqrt(std::max(sum_q, sum_v) / count);
}

}  // namespace maris::ode_detail
