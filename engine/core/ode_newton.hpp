// Newton iteration for the acceleration of a second-order system at one time (used by the
// generalized-α integrator; internal, not part of the public API). The unknown q̈ moves q and v along
// the step as q = q_base + dq·q̈, v = v_base + dv·q̈; the iteration matrix is
// S = ∂r/∂q̈ + dv·∂r/∂v + dq·∂r/∂q, from the caller's solver, or by finite differences: dense with
// PartialPivLU, or banded (SecondOrderSystem bandwidths) with grouped columns and BandedLu.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/banded_lu.hpp"
#include "core/ode_second_order.hpp"
#include "core/ode_types.hpp"
#include "core/run_context.hpp"

namespace maris::ode_detail {

class NewtonSolver {
 public:
  NewtonSolver(const SecondOrderSystem& system, const OdeOptions& options, int max_iterations, OdeStats& stats,
               RunContext& ctx);

  // Solves r(t, q_base + dq·acc, v_base + dv·acc, acc) = 0 for acc, starting from `acc`. Returns true on
  // convergence (acc, q(), v() then hold the solution), false on divergence, a non-finite residual, a
  // singular matrix or too many iterations. Throws RunCancelled (checked between residual calls).
  bool solve(double t, const Eigen::VectorXd& q_base, const Eigen::VectorXd& v_base, double dq, double dv,
             Eigen::VectorXd& acc);

  const Eigen::VectorXd& q() const { return q_; }
  const Eigen::VectorXd& v() const { return v_; }
  const Eigen::VectorXd& lastCorrection() const { return delta_; }
  void invalidateMatrix() { have_matrix_ = false; }
  bool matrixIsFresh() const { return matrix_fresh_; }  // refreshed during the last solve()

 private:
  bool solveLinear(double t, const Eigen::VectorXd& acc, double dq, double dv, bool refresh);
  bool formDifferenceMatrix(double t, const Eigen::VectorXd& acc, double dq, double dv);
  void perturbedResidual(double t, const Eigen::VectorXd& acc, double dq, double dv);
  double correctionNorm(double dq, double dv, const Eigen::VectorXd& q_base, const Eigen::VectorXd& v_base,
                        const Eigen::VectorXd& acc) const;

  const SecondOrderSystem& system_;
  const OdeOptions& options_;
  int max_iterations_;
  OdeStats& stats_;
  RunContext& ctx_;
  Eigen::Index n_;
  bool banded_;
  Eigen::VectorXd q_, v_, r_, delta_, solution_, r_pert_, acc_pert_, q_pert_, v_pert_, eps_;
  Eigen::MatrixXd dense_;                     // S (dense path)
  Eigen::PartialPivLU<Eigen::MatrixXd> dense_lu_;
  BandedLu banded_lu_;                        // S (banded path)
  bool have_matrix_ = false, matrix_fresh_ = false, slow_ = false;
  double matrix_dq_ = -1.0, matrix_dv_ = -1.0;
};

}  // namespace maris::ode_detail
