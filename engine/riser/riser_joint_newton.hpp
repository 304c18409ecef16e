// O(n) Newton matrix of the implicit integrator in joint coordinates (no dense N×N work at run time).
//
// The joint chart residual r_J = q̈_J − a_J(q_J, v_J) has a dense iteration matrix S_J: a segment's position
// depends on every rotation above it, so the loads (buoyancy, current, drag) of segment i depend on all
// θ_j, j ≤ i. The force-space matrix of riser_newton is banded only because absolute coordinates keep the
// positions as unknowns and tie them by local joint rows. So S_J y = b is solved through an absolute twin
// of the model (the same RiserModel with formulation = Absolute, its own chart reset at the joint state):
//   - the joint state P(q_J, v_J) is a consistent absolute state (Φ = Φ̇ = 0), where both formulations have
//     the same accelerations: a_J = Π a_A(P(q_J, v_J)), Π = the joint-chart part (top, θ̈ through M⁻¹, the
//     inverse rate map of the chart);
//   - a joint motion u = T y (T: joint-chart accelerations to absolute-chart ones, O(n) recursion
//     r̈_{i+1} = r̈_i + α_i × d_i) keeps the twin consistent to first order, and the twin's banded system
//     K [u; μ] = ∂F/∂x · T b (riser_newton) enforces the joint rows Φ_q u ≈ 0 itself;
//   - with δx = u − T b the linearised twin equations are exactly those of the joint residual, so
//     y = Π u solves S_J y = b, up to the terms below.
// Neglected (they only make Newton inexact; generalized-α converges with an approximate matrix, and
// test_riser_joint_newton measures the Newton counts against the dense path):
//   - the twin's joint rows are acceleration-level constraints, whose dependence on the coordinates
//     (α × δd, ω × (ω × δd)) lets u leave the joint manifold by O(β'|α|·|δθ|·l);
//   - the curvature of the chart maps away from the joint chart's reference (M(θ_J)⁻¹ varies), O(β'|α||θ_J|);
//   - the change of the joint-point velocities with the rotations at fixed rates and the rate terms Ṁ θ̇,
//     relative size ≈ ω h.
// All vanish at rest on the chart reference (measured defect 2e-6 there); on smooth motions they are
// ≈ 1e-4–1e-3 of S. Large angular accelerations far from the reference (a random twist of 0.03 rad between
// neighbours with stiff torsion: |α| ≈ 1e4 rad/s²) make the solve a poor inverse (defect ≈ 1 of S ≈ 240).
// Cost per refresh: the twin's 2b + 4 balance/residual evaluations (b = 9s + 5, independent of n) and an
// O(n) banded LU; per solve O(n).
#pragma once

#include <vector>

#include "riser/riser_newton.hpp"

namespace maris::riser {

class JointNewtonMatrix {
 public:
  // `joint` must use joint coordinates (throws std::invalid_argument otherwise); keeps references to
  // `joint` and `chart` (the joint chart the integrator iterates in).
  JointNewtonMatrix(const RiserModel& joint, const OrientationChart& chart, double stabilisation_rate);
  JointNewtonMatrix(const JointNewtonMatrix&) = delete;
  JointNewtonMatrix& operator=(const JointNewtonMatrix&) = delete;

  // Overwrites rhs with (approximately) S_J⁻¹ rhs; matches SecondOrderSystem::solve_iteration_matrix.
  bool solve(const IterationMatrixRequest& request, Eigen::VectorXd& rhs);

  // See ForceSpaceNewtonMatrix::useCoordinateSteps (statics by pseudo-time).
  void useCoordinateSteps() { twin_newton_.useCoordinateSteps(); }

  // Points the twin chart's pose at wave kinematics held over a step (riser_charted_alpha, riser_waves.hpp).
  void holdTwinWaveKinematics(StepWaveKinematics* held) { twin_chart_.workspace().pose.step_waves = held; }

  long refreshes() const { return twin_newton_.refreshes(); }
  // Balance/residual evaluations of the twin (each O(n)): the cost of the refreshes.
  long balanceEvaluations() const { return twin_newton_.balanceEvaluations(); }

 private:
  void refresh(const IterationMatrixRequest& request);

  const RiserModel& m_;
  const OrientationChart& chart_;
  RiserModel twin_;                    // absolute twin (declared before the members that refer to it)
  OrientationChart twin_chart_;
  ForceSpaceNewtonMatrix twin_newton_;
  RiserWorkspace pose_ws_;
  int f_ = 0, segments_ = 0;
  bool have_ = false;
  double dq_ = -1.0, dv_ = -1.0;
  // At the last refresh: the chart's rate map M(θ_J,k) (J_r with torsion), its inverse, R_k.
  std::vector<Mat3> rate_map_, rate_map_inverse_, rot_;
  std::vector<Vec3> arm_;              // d_k at the last refresh
  Eigen::VectorXd y_joint_, y_twin_, q_twin_, v_twin_, acc_twin_, rhs_twin_;
};

}  // namespace maris::riser
