// Equations of motion of the segment chain in joint (J) or absolute (A) coordinates, O(n) per
// right-hand side.
//
// Both formulations use the same Newton-Euler block of each segment about its origin A_i
// (derived from the paper's definitions; equivalent to its A_i, h_A,i of eqs 12-15) and the same joint reactions
// F_j (eq 53: F_j acts on segment j at A_j, -F_{j+1} at its far end):
//     M_i x_i = E F_i - D'_i F_{i+1} + b_i,   x_i = (a_{A_i}, α_i),  E = [I; 0],  D'_i = [I; [d_i]x]
// The continuity conditions a_{A_{i+1}} = a_{A_i} + α_i × d_i + ω_i × (ω_i × d_i), with the end
// conditions, give a symmetric block-tridiagonal system for the reactions (3×3 blocks, the Schur
// complement D_Aᵀ M_A⁻¹ D_A of eq 54), solved by a block-Thomas sweep: O(n), no dense matrix.
//   J: state = top point + orientation/angular velocity of each segment; positions follow by the
//      recursion r_{i+1} = r_i + l_i t_i (eq 7), so continuity holds exactly; only the bottom
//      constraint (pinned/clamped) needs Baumgarte feedback.
//   A: state = position/velocity of each A_i + orientation/angular velocity; the 3(n+2)
//      constraints (eq 55) are kept by Baumgarte stabilisation Φ̈ + 2αΦ̇ + α²Φ = 0; the drift
//      |Φ| is reported.
// State layout (both): [r_top(3), v_top(3)], then per dynamic segment J: [q(4), ω(3)],
// A: [r(3), q(4), v(3), ω(3)], then [W_drag, W_damping, W_boundary, W_flow] (work integrals, J).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "riser/riser_loads.hpp"

namespace maris::riser {

// Constraint violations Φ and Φ̇ per row of the reaction system (row 0: top hold, k: joint A_{f+k},
// last: bottom hold; zero where the force is known). Joint coordinates satisfy the inner rows exactly.
struct ConstraintViolation {
  std::vector<Vec3> position;  // [m] Φ_k
  std::vector<Vec3> velocity;  // [m/s] Φ̇_k
  double largest = 0.0;        // [m] max |Φ_k| (infinity norm)
};

// Scratch space of evaluateRhs, sized once by makeWorkspace (nothing allocates per call).
struct RiserWorkspace {
  RiserPose pose;                 // written by poseFromState
  SegmentLoads loads;             // written by computeLoads
  std::vector<Mat6> inverse_mass; // W_i in the global frame (n+1)
  std::vector<Vec6> bias;         // b_i: external loads minus velocity terms (n+1)
  std::vector<Mat3> lower, diag, upper, pivot_upper;  // block-tridiagonal system (n+2)
  std::vector<Vec3> rhs, reaction;                    // right side and F_j (n+2, index j)
  std::vector<Vec6> acceleration;                     // x_i = (a_{A_i}, α_i) (n+1)
  ConstraintViolation constraint_violation;           // Φ, Φ̇ of the last evaluation (joint: end rows only)
  double stabilisation_rate = 0.0;  // [1/s] Baumgarte α (= β)
  double constraint_drift = 0.0;    // [m] max |Φ| at the last evaluation
  VesselMotionCache vessel_motion;  // the top's vessel motion at the last time (RiserModel::topAt)
};

RiserWorkspace makeWorkspace(const RiserModel& m, double stabilisation_rate);

inline constexpr int kWorkIntegrals = 4;  // W_drag, W_damping, W_boundary (top + point loads), W_flow [J]
int stateSize(const RiserModel& m);
// Index of the first state entry of dynamic segment i (layout in the file comment).
Eigen::Index segmentStateOffset(const RiserModel& m, int i);
// Index of dynamic segment i's orientation quaternion (w, x, y, z) and of its angular velocity ω [rad/s].
Eigen::Index orientationStateOffset(const RiserModel& m, int i);
Eigen::Index angularVelocityStateOffset(const RiserModel& m, int i);
// Index of dynamic segment i's origin velocity [m/s]: absolute coordinates only (J has no such entry; its
// position is segmentStateOffset).
Eigen::Index velocityStateOffset(const RiserModel& m, int i);
// Index of the first work integral in the state.
Eigen::Index workIntegralOffset(const RiserModel& m);
// Name of state component k for error messages ("segment 17 angular velocity z").
std::string stateComponentName(const RiserModel& m, Eigen::Index k);

// State of a pose at rest: orientations `orientation` (n+1), top at `top`, zero velocities and work.
Eigen::VectorXd restState(const RiserModel& m, const std::vector<Eigen::Quaterniond>& orientation, const Vec3& top);

// Known force on the top's component c (topForceKnown): the tensioner's pull, zero for a free top, or the axial
// spring k (H − z) + β k (Ḣ − ż) + W/2 between the prescribed point H(t) and the chain's top (position, velocity),
// its weight share W/2 scaled by `load_factor` (statics' load continuation).
double knownTopForce(const RiserModel& m, int c, double t, const Vec3& top_position, const Vec3& top_velocity,
                     double load_factor = 1.0);

// Fills pose (positions, orientations, velocities of all segments) from the state at time t.
void poseFromState(const RiserModel& m, double t, const Eigen::VectorXd& y, RiserPose& pose);

// dy/dt at (t, y). Leaves pose, loads, reactions and accelerations in the workspace.
void evaluateRhs(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy);

// The three steps of evaluateRhs, exposed for the implicit integrator's Newton matrix (riser_newton):
// pose, loads, inverse masses W_i and biases b_i of the dynamic segments at (t, y).
void prepareSegments(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y);

ConstraintViolation constraintViolation(const RiserModel& m, const RiserPose& pose, double t);

// Residuals of the unreduced equations at the pose prepared in ws, for given accelerations x_i = (a_{A_i}, α_i)
// and reactions F_j (indices as in ws.acceleration / ws.reaction):
//   segment i:  x_i − W_i (E F_i − D'_i F_{i+1} + b_i)
//   row k:      the acceleration-level constraint with Baumgarte terms (or F − known for known forces).
// Both vanish at the solution of evaluateRhs. The force-space Newton matrix of riser_newton differentiates them.
void balanceResidual(const RiserModel& m, const RiserWorkspace& ws, double t, const std::vector<Vec6>& x,
                     const std::vector<Vec3>& reaction, std::vector<Vec6>& segment_residual,
                     std::vector<Vec3>& row_residual);

// Absolute coordinates: projects the positions of y back onto the constraints, O(n). The joints are closed by
// translating the segments down the chain from the top's held coordinates, orientations kept; a held bottom's
// remaining mismatch is then spread over small turns of all segments, weighted by their rotational inertia
// (`iterations` sweeps). Velocities are left to the Baumgarte term (riser_dynamics.cpp says why).
// Returns the largest |Φ| [m] after the projection. Joint coordinates: no-op, returns 0.
double projectConstraints(const RiserModel& m, RiserWorkspace& ws, double t, Eigen::VectorXd& y, int iterations = 2);

// Renormalises the quaternions of y (after a step) and, without torsion, removes spin about the axes.
void normaliseState(const RiserModel& m, Eigen::VectorXd& y);

// Total mechanical energy T + V_springs + V_gravity + V_anchor of the pose [J].
double totalEnergy(const RiserModel& m, const RiserPose& pose);

// Estimated highest natural frequency [rad/s] (bending 9√(EI/μ)/Δ², torsion 2√(GJ/ι)/Δ, tension
// 4√(T/μ)/Δ, discrete-spectrum bounds; times β ω when the spring dampers are overdamped), for the automatic RK4 step.
double highestFrequencyEstimate(const RiserModel& m);

}  // namespace maris::riser
