// The catenary visual-servoing controller of the follower (paper §5, eqs. 46-60).
//
//   e = s - s*                                   (3 features a, b, d; or 4 with the leader-camera feature b1)
//   v = -lambda_p o (L+ e) - lambda_i o (L+ sum_{last k_max ticks} e) + v_ff
// with L the follower interaction matrix (3x4, eq. 42; or 4x4, eq. 52), "o" the element-wise product with the
// per-velocity-component gains, and v_ff the leader-velocity compensation:
//   MinimumNorm: v_ff = -L+ L_leader v1          (cancels the leader-induced feature change, eq. 49 derived)
//   Rigid:       v_ff = ^{r2}V_{r1} v1           (move rigidly with the leader, the paper's eq. 49 form)
// L+ is a damped pseudo-inverse: plain Moore-Penrose while the smallest singular value sigma_min >= threshold,
// damped least squares sigma/(sigma^2 + mu^2) with mu^2 = (1 - (sigma_min/threshold)^2) mu_max^2 below it.
// The command is saturated by uniform scaling (direction kept). Twists are in the follower body frame (FLU).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "tether/tether_kinematics.hpp"

namespace maris::tether {

enum class LeaderCompensation { None, MinimumNorm, Rigid };

struct ServoSettings {
  bool use_leader_feature = false;                     // 4x4 law with b1 (both cameras) instead of 3x4
  LeaderCompensation compensation = LeaderCompensation::None;
  Vector4 proportional_gain = Vector4::Constant(1.0);  // [1/s] lambda_p per (nu_x, nu_y, nu_z, omega_z)
  Vector4 integral_gain = Vector4::Zero();             // [1/s] lambda_i per component (per tick, eq. 59)
  int integral_window = 40;                            // [-] k_max: number of past errors summed
  double max_linear_speed = 0.5;                       // [m/s] saturation of |nu| components
  double max_yaw_rate = 1.0;                           // [rad/s] saturation of |omega_z|
  double rank_threshold = 0.05;                        // [1/m] sigma_min below which damping starts
  double max_damping = 0.05;                           // [1/m] mu_max
  double singular_sine = 0.98;                         // [-] hold (zero command) when |b| or |b1| exceeds it
};

// Pseudo-inverse of an m x n matrix (m <= n) with the damping above. Also returns sigma_min and mu.
struct DampedInverse {
  Eigen::MatrixXd inverse;
  double smallest_singular_value = 0.0;
  double damping = 0.0;
};
DampedInverse dampedPseudoInverse(const Eigen::MatrixXd& matrix, double threshold, double max_damping);

struct ServoCommand {
  Vector4 twist = Vector4::Zero();  // [m/s, m/s, m/s, rad/s] follower body twist
  Vector4 error = Vector4::Zero();  // [-] e = s - s* (b1 entry 0 in the 3-feature law)
  double smallest_singular_value = 0.0;
  double damping = 0.0;
  bool saturated = false;
  bool held = false;                // singularity guard: features near |b| = 1, command zeroed
};

// Stateful only through the integral window. Reset() clears it.
class TetherServo {
 public:
  TetherServo(TetherRig rig, ServoSettings settings);

  // One control tick. `measured`: the features the controller sees; `model`: the features its interaction
  // matrix is built from (equal to `measured` unless a model error is studied); leader_twist: the leader's body
  // twist if known (used only with compensation).
  ServoCommand update(const Features& measured, const Features& model, const Features& target,
                      const Vector4& leader_twist);
  void reset();
  const ServoSettings& settings() const { return settings_; }
  int featureCount() const { return settings_.use_leader_feature ? 4 : 3; }

 private:
  TetherRig rig_;
  ServoSettings settings_;
  std::vector<Vector4> window_;  // last k_max errors, ring buffer
  std::size_t next_ = 0;
  Vector4 window_sum_ = Vector4::Zero();
};

// Rigid-motion twist transform ^{r2}V_{r1} v1: the follower twist that keeps its pose fixed relative to the leader.
Vector4 rigidFollowerTwist(const InteractionMatrices& interaction, const Vector4& leader_twist);

// Eigenvalues of the closed-loop matrix L(s) diag(lambda_p) Lhat+ [1/s], where L is built from the true features
// and Lhat from the model's (paper eq. 56-58 with per-axis gains). Sorted by real part.
Eigen::VectorXcd closedLoopEigenvalues(const TetherRig& rig, const ServoSettings& settings, const Features& truth,
                                       const Features& model);

}  // namespace maris::tether
