// O(n) Newton matrix of the implicit integrator in absolute coordinates (no dense N×N
// factorisation at run time).
//
// The chart residual r = q̈ − a(t, q, q̇) of riser_implicit is dense in q, because the accelerations a
// depend on every segment through the reactions. Its iteration matrix S = I − γ'∂a/∂v − β'∂a/∂q is
// therefore never formed. Instead, with x = S⁻¹ b written as δa = x − b, the implicit-function theorem
// applied to the unreduced equations F(q, v, acc, F_j) = 0 of balanceResidual (Newton–Euler rows per
// segment in the form x_i − W_i(...), acceleration-level constraint rows per joint) gives
//     K [x; μ] = [∂F/∂acc · b; 0-padded],   K = ∂F/∂(acc, F_j) along the step (q = q_b + β'acc, v = v_b + γ'acc),
// evaluated at the exact accelerations and reactions of (q, v). Ordered as
// (F_f, segment f, F_{f+1}, segment f+1, ..., F_{last+1}), K is banded: every row involves a segment, its
// reactions and its neighbours (springs ±1; the internal-flow curvature stencil ±2 at the ends), so its
// bandwidth is 9s + 5 with s = 1 or 2. K is formed by grouped (coloured) forward differences of F,
// 2·bandwidth + 1 evaluations of O(n) each, and factorised by BandedLu: O(n) per refresh and per solve.
// The top coordinates (q̈ = 0 in absolute coordinates) and the work integrals (which feed back into
// nothing) get the identity; the work integrals then converge one Newton iteration behind.
#pragma once

#include <vector>

#include "core/banded_lu.hpp"
#include "core/ode_second_order.hpp"
#include "riser/riser_implicit.hpp"

namespace maris::riser {

class ForceSpaceNewtonMatrix {
 public:
  // Absolute coordinates only (throws std::invalid_argument otherwise). Keeps references to both.
  ForceSpaceNewtonMatrix(const RiserModel& m, OrientationChart& chart);

  // Overwrites rhs with S⁻¹ rhs; forms and factorises K when request.refresh, when there is none yet, or when
  // β', γ' changed. Returns false if K is singular. Matches SecondOrderSystem::solve_iteration_matrix.
  bool solve(const IterationMatrixRequest& request, Eigen::VectorXd& rhs);

  // For large β' (statics by pseudo-time, riser_statics): difference steps of the segment columns chosen for
  // the coordinate change β'ε alone (1e-7 m or rad), not at least 1e-6 in acceleration.
  void useCoordinateSteps() { coordinate_steps_ = true; }

  Eigen::Index bandwidth() const { return band_; }
  long refreshes() const { return refreshes_; }
  long balanceEvaluations() const { return evaluations_; }

 private:
  void refresh(const IterationMatrixRequest& request);
  void pack(const std::vector<Vec6>& segment_residual, const std::vector<Vec3>& row_residual, Eigen::VectorXd& out) const;

  const RiserModel& m_;
  OrientationChart& chart_;
  int f_ = 0, segments_ = 0;
  Eigen::Index size_ = 0, band_ = 0;
  BandedLu lu_;
  bool have_ = false;
  bool coordinate_steps_ = false;
  double dq_ = -1.0, dv_ = -1.0;
  long refreshes_ = 0, evaluations_ = 0;
  std::vector<Mat3> turn_;  // R_i J_r(θ_i) at the last refresh (the ∂x/∂θ̈ block)
  std::vector<Vec3> arm_;   // d_i at the last refresh
  std::vector<Vec6> seg_res_;
  std::vector<Vec3> row_res_, reaction_, reaction_pert_;
  Eigen::VectorXd residual_, acc_, q_, v_, acc_pert_, base_, pert_, eps_, z_;
};

}  // namespace maris::riser
