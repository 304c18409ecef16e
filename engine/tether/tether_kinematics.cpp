#include "tether/tether_kinematics.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/errors.hpp"
#include "core/text_format.hpp"

namespace maris::tether {

namespace {

double wrapAngle(double angle) { return std::remainder(angle, 2.0 * std::numbers::pi); }

Eigen::Matrix3d yawRotation(double yaw) { return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

double sinc(double x) { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

}  // namespace

RobotPose integratePose(const RobotPose& pose, const Vector4& twist, double dt) {
  // The horizontal velocity turns with the yaw at a constant rate: the displacement is the chord of the arc,
  // dt sinc(w dt/2) R(yaw + w dt/2) nu.
  const double turn = twist[3] * dt;
  const double mid_yaw = pose.yaw + 0.5 * turn;
  const double chord = dt * sinc(0.5 * turn);
  RobotPose next;
  next.position.x() = pose.position.x() + chord * (std::cos(mid_yaw) * twist[0] - std::sin(mid_yaw) * twist[1]);
  next.position.y() = pose.position.y() + chord * (std::sin(mid_yaw) * twist[0] + std::cos(mid_yaw) * twist[1]);
  next.position.z() = pose.position.z() + dt * twist[2];
  next.yaw = wrapAngle(pose.yaw + turn);
  return next;
}

Eigen::Vector3d attachmentPoint(const RobotPose& pose, const Eigen::Vector3d& body_offset) {
  return pose.position + yawRotation(pose.yaw) * body_offset;
}

TetherState tetherState(const TetherRig& rig, const RobotPose& follower, const RobotPose& leader) {
  TetherState s;
  s.follower_point = attachmentPoint(follower, rig.follower_attachment);
  s.leader_point = attachmentPoint(leader, rig.leader_attachment);
  const Eigen::Vector3d chord = s.leader_point - s.follower_point;
  s.span = std::hypot(chord.x(), chord.y());
  s.rise = chord.z();
  s.bearing = std::atan2(chord.y(), chord.x());
  s.follower_angle = wrapAngle(s.bearing - follower.yaw);
  s.leader_angle = wrapAngle(s.bearing - leader.yaw);
  s.catenary = catenaryFromSpan(s.span, s.rise, rig.length);
  return s;
}

Eigen::Vector3d tetherPointAtArcLength(const TetherState& state, double arc_length) {
  const PlanePoint p = catenaryPointAtArcLength(state.catenary, arc_length);
  return state.follower_point + Eigen::Vector3d(p.x * std::cos(state.bearing), p.x * std::sin(state.bearing), p.z);
}

Features featuresOf(const TetherRig& rig, const TetherState& state) {
  Features f;
  f.a = state.catenary.sag / rig.sag_max;
  f.b = std::sin(state.follower_angle);
  f.d = (state.rise + rig.rise_max) / (2.0 * rig.rise_max);
  f.b1 = std::sin(state.leader_angle);
  return f;
}

std::string featureInfeasibility(const TetherRig& rig, const Features& s) {
  const double sag = s.a * rig.sag_max;
  const double rise = (2.0 * s.d - 1.0) * rig.rise_max;
  if (!(s.a > 0.0) || !(sag + rise > 0.0) || !(2.0 * sag + rise < rig.length)) {
    return formatText("(a, d) = (%.4g, %.4g) gives sag H = %.4g m and rise dH = %.4g m; the feasible box is "
                      "max(0, -dH) < H < (L - dH)/2 = %.4g m",
                      s.a, s.d, sag, rise, 0.5 * (rig.length - rise));
  }
  if (!(std::abs(s.b) < 1.0) || !(std::abs(s.b1) < 1.0)) {
    return formatText("b = %.4g and b1 = %.4g must lie in (-1, 1) (tether plane not perpendicular to a robot axis)",
                      s.b, s.b1);
  }
  const Catenary c = catenaryFromShape(sag, rise, rig.length);
  if (!c.fitsPaperModel()) return std::string(toString(c.regime)) + ": " + c.message;
  return {};
}

RobotPose followerPoseFromFeatures(const TetherRig& rig, const RobotPose& leader, const Features& s) {
  if (const auto why = featureInfeasibility(rig, s); !why.empty()) throw InputError("features", "", why);
  const double sag = s.a * rig.sag_max;
  const double rise = (2.0 * s.d - 1.0) * rig.rise_max;
  const Catenary c = catenaryFromShape(sag, rise, rig.length);
  const double bearing = leader.yaw + std::asin(s.b1);
  RobotPose follower;
  follower.yaw = wrapAngle(bearing - std::asin(s.b));
  const Eigen::Vector3d p1 = attachmentPoint(leader, rig.leader_attachment);
  const Eigen::Vector3d p2 = p1 - Eigen::Vector3d(c.span * std::cos(bearing), c.span * std::sin(bearing), rise);
  follower.position = p2 - yawRotation(follower.yaw) * rig.follower_attachment;
  return follower;
}

InteractionMatrices interactionMatrices(const TetherRig& rig, const Features& s) {
  InteractionMatrices out;
  const double sag = s.a * rig.sag_max;
  const double rise = (2.0 * s.d - 1.0) * rig.rise_max;
  const Catenary cat = catenaryFromShape(sag, rise, rig.length);
  const double C = cat.constant;
  const auto grad = catenaryConstantGradient(sag, rise, rig.length);

  // Horizontal distances from the vertex and their derivatives (eqs. 32-33): D2 = x0, D1 = S - x0.
  const double d2 = cat.vertex_offset, d1 = cat.span - cat.vertex_offset;
  const double sinh2 = std::sqrt(C * sag * (C * sag + 2.0));                  // sinh(C D2)
  const double sinh1 = std::sqrt(C * (sag + rise) * (C * (sag + rise) + 2.0));  // sinh(C D1)
  const double lever2 = sag - d2 * sinh2, lever1 = (sag + rise) - d1 * sinh1;
  const double P = (C + lever2 * grad.d_sag) / (C * sinh2);
  const double Q = lever2 * grad.d_rise / (C * sinh2);
  const double U = (C + lever1 * grad.d_sag) / (C * sinh1);
  const double V = (C + lever1 * grad.d_rise) / (C * sinh1);
  out.span = cat.span;
  out.span_per_sag = U + P;
  out.span_per_rise = V + Q;

  // M of eq. (37): d(a, b, d)/d(^2P1) in the z-up follower attachment frame.
  const double b = s.b, c = std::sqrt(1.0 - b * b), S = cat.span;
  const double k = out.span_per_sag * rig.sag_max;
  out.shape_jacobian << c / k, b / k, -out.span_per_rise / k,  //
      -b * c / S, c * c / S, 0.0,                              //
      0.0, 0.0, 1.0 / (2.0 * rig.rise_max);

  // ^2P1 rate per follower twist (eq. 64): -nu - omega x ^{r2}p1, and per leader twist: R21 (nu + omega x ^{r1}p1).
  const Eigen::Vector3d p1_in_follower = rig.follower_attachment + Eigen::Vector3d(S * c, S * b, rise);
  Eigen::Matrix<double, 3, 4> follower_rate;
  follower_rate << -1, 0, 0, p1_in_follower.y(),  //
      0, -1, 0, -p1_in_follower.x(),              //
      0, 0, -1, 0;
  out.relative_yaw = std::asin(b) - std::asin(s.b1);
  const Eigen::Matrix3d r21 = yawRotation(out.relative_yaw);
  Eigen::Matrix<double, 3, 4> leader_body;
  leader_body << 1, 0, 0, -rig.leader_attachment.y(),  //
      0, 1, 0, rig.leader_attachment.x(),              //
      0, 0, 1, 0;
  const Eigen::Matrix<double, 3, 4> leader_rate = r21 * leader_body;
  out.leader_centre_in_follower = p1_in_follower - r21 * rig.leader_attachment;

  out.follower.topRows<3>() = out.shape_jacobian * follower_rate;
  out.leader.topRows<3>() = out.shape_jacobian * leader_rate;

  // b1 row: d(alpha1)/dt = d(alpha2)/dt + omega2 - omega1, d(alpha2)/dt = (-b, c, 0) . d(^2P1)/dt / S.
  const Eigen::RowVector3d bearing_rate(-b / S, c / S, 0.0);
  const double c1 = std::sqrt(1.0 - s.b1 * s.b1);
  const Eigen::RowVector4d yaw_rate(0, 0, 0, 1);
  out.follower.row(3) = c1 * (bearing_rate * follower_rate + yaw_rate);
  out.leader.row(3) = c1 * (bearing_rate * leader_rate - yaw_rate);
  return out;
}

}  // namespace maris::tether
