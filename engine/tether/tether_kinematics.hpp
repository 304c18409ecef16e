// Robot poses, tether features and the catenary interaction matrices of the leader/follower pair.
//
// Frames (written once for the scene):
//   - world: z up, x/y horizontal, origin arbitrary; robots stay level (roll and pitch held by a low-level
//     controller), so a pose is (x, y, z, yaw) with yaw about +z, counter-clockwise seen from above;
//   - robot body frames FLU: x forward, y left, z up. Twists are body-frame (nu_x, nu_y, nu_z, omega_z);
//   - P2 is the follower's tether attachment (normally at its front), P1 the leader's (normally at its rear);
//   - bearing theta = atan2 of the horizontal vector P2 -> P1; follower angle alpha2 = theta - yaw2; leader angle
//     alpha1 = theta - yaw1 (measured from the leader's rear axis to the direction towards P2; this makes the
//     relative yaw yaw1 - yaw2 = alpha2 - alpha1, the paper's ^{r2}R_{r1} = R_z(alpha2 - alpha1)).
// Features (paper eqs. 14, 22): a = H/H_max, b = sin(alpha2), d = (dH + dH_max)/(2 dH_max), b1 = sin(alpha1),
// with H the sag at P2 and dH = z(P1) - z(P2). b may be negative (the paper's mirror image) so that the controller
// sees the side of the tether. The interaction matrices follow the paper's eqs. (25)-(45) in this z-up/FLU
// convention, signs (lost in the available text) derived from the catenary model and checked by finite differences.
#pragma once

#include <Eigen/Core>

#include "tether/tether_catenary.hpp"

namespace maris::tether {

using Vector4 = Eigen::Vector4d;  // a body twist (nu_x [m/s], nu_y [m/s], nu_z [m/s], omega_z [rad/s]) or features
using Matrix4 = Eigen::Matrix4d;

struct RobotPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m] world, z up
  double yaw = 0.0;                                     // [rad] about +z
};

// The constant geometry of the pair: tether length, feature normalisation and attachment points.
struct TetherRig {
  double length = 1.5;          // [m] L
  double sag_max = 0.7;         // [m] H_max
  double rise_max = 0.5;        // [m] dH_max
  Eigen::Vector3d follower_attachment{0.2, 0.0, 0.0};  // [m] P2 in the follower body frame
  Eigen::Vector3d leader_attachment{-0.2, 0.0, 0.0};   // [m] P1 in the leader body frame
};

// Moves a pose by a constant body twist for dt seconds (exact: the horizontal path is a circular arc).
RobotPose integratePose(const RobotPose& pose, const Vector4& body_twist, double dt);

Eigen::Vector3d attachmentPoint(const RobotPose& pose, const Eigen::Vector3d& body_offset);

// The tether between the two robots: attachment points, span, rise, angles and the catenary through them.
struct TetherState {
  Eigen::Vector3d follower_point = Eigen::Vector3d::Zero();  // [m] P2, world
  Eigen::Vector3d leader_point = Eigen::Vector3d::Zero();    // [m] P1, world
  double span = 0.0;            // [m] horizontal |P1 - P2|
  double rise = 0.0;            // [m] z(P1) - z(P2)
  double bearing = 0.0;         // [rad] theta
  double follower_angle = 0.0;  // [rad] alpha2 in (-pi, pi]
  double leader_angle = 0.0;    // [rad] alpha1 in (-pi, pi]
  Catenary catenary;
};
TetherState tetherState(const TetherRig& rig, const RobotPose& follower, const RobotPose& leader);

// World point of the catenary at arc length sigma from P2.
Eigen::Vector3d tetherPointAtArcLength(const TetherState& state, double arc_length);

struct Features {
  double a = 0.0;   // [-] H / H_max
  double b = 0.0;   // [-] sin(alpha2)
  double d = 0.0;   // [-] (dH + dH_max) / (2 dH_max)
  double b1 = 0.0;  // [-] sin(alpha1)
  Vector4 vector() const { return {a, b, d, b1}; }
  static Features fromVector(const Vector4& v) { return {v[0], v[1], v[2], v[3]}; }
};

// Features of the current tether. Precondition: state.catenary.has_geometry.
Features featuresOf(const TetherRig& rig, const TetherState& state);

// Why a feature vector cannot be a shape of the paper's model ("" if it can): sag and rise inside the feasible box
// max(0, -dH) <= H < (L - dH)/2 (lowest point between the ends), |b|, |b1| < 1, catenary regime Regular or NearlyTaut.
std::string featureInfeasibility(const TetherRig& rig, const Features& s);

// The follower pose that realises features s (a, b, d, b1) behind a given leader. Throws InputError (path
// "features") when s is infeasible.
RobotPose followerPoseFromFeatures(const TetherRig& rig, const RobotPose& leader, const Features& s);

// Analytic Jacobians of the features with respect to the robots' body twists, from the features alone
// (paper eqs. 35-45 and the b1 row of eq. 51). Rows: a, b, d, b1. Columns: nu_x, nu_y, nu_z, omega_z.
struct InteractionMatrices {
  Matrix4 follower = Matrix4::Zero();  // ds/dt per follower twist (top 3x4 block: the paper's L^2_{r2})
  Matrix4 leader = Matrix4::Zero();    // ds/dt per leader twist
  Eigen::Matrix3d shape_jacobian = Eigen::Matrix3d::Zero();  // M: d(a, b, d)/d(^2P1) (eq. 37)
  double span = 0.0;                   // [m] S at the features
  double span_per_sag = 0.0;           // [-] U + P = dS/dH (eq. 34), negative
  double span_per_rise = 0.0;          // [-] V + Q = dS/d(dH)
  Eigen::Vector3d leader_centre_in_follower = Eigen::Vector3d::Zero();  // [m] ^{r2}c1, leader origin
  double relative_yaw = 0.0;           // [rad] yaw1 - yaw2 = alpha2 - alpha1
};
// Precondition: featureInfeasibility(rig, s) is empty and a > 0.
InteractionMatrices interactionMatrices(const TetherRig& rig, const Features& s);

}  // namespace maris::tether
