// 3D frames of a tether run: both robots as boxes with a heading line, their cameras' view frusta, the
// quasi-static catenary as a tube coloured by tension, and the lumped-mass cable as a polyline.
#include <cmath>

#include <Eigen/Geometry>

#include "tether/tether_results.hpp"

namespace maris::tether {

namespace {

constexpr double kFrustumDepth = 0.6;       // [m] drawn depth of a camera's view volume
constexpr double kHalfFieldOfView = 0.7;    // [rad] ~40 deg half angle (the paper gives no intrinsics)
const Eigen::Vector3d kRobotSize{0.46, 0.34, 0.25};  // [m] BlueROV-sized box (drawing only)

Eigen::Vector3d bodyToWorld(const RobotPose& pose, const Eigen::Vector3d& body) {
  return pose.position + Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitZ()) * body;
}

Shape3D robotBox(const RobotPose& pose, const std::string& name, const Eigen::Vector3d& color) {
  Shape3D box;
  box.kind = Shape3D::Kind::Box;
  box.name = name;
  box.points = {pose.position};
  // Boxes are axis-aligned: use the footprint's extent in world axes so the robot's volume is covered.
  const double c = std::abs(std::cos(pose.yaw)), s = std::abs(std::sin(pose.yaw));
  box.size = {c * kRobotSize.x() + s * kRobotSize.y(), s * kRobotSize.x() + c * kRobotSize.y(), kRobotSize.z()};
  box.color = color;
  box.opacity = 0.5;
  return box;
}

Shape3D headingLine(const RobotPose& pose, const std::string& name) {
  Shape3D line;
  line.kind = Shape3D::Kind::Polyline;
  line.name = name;
  line.points = {pose.position, bodyToWorld(pose, {0.4, 0.0, 0.0})};
  line.color = {1.0, 1.0, 1.0};
  return line;
}

// Pyramid of a camera at `apex` (body frame) looking along body +x (front) or -x (rear): one polyline, apex
// edges retraced so that a single line draws all eight edges.
Shape3D frustum(const RobotPose& pose, const Eigen::Vector3d& apex, double direction, const std::string& name) {
  const double half = kFrustumDepth * std::tan(kHalfFieldOfView);
  Eigen::Vector3d corner[4];
  const double ys[4] = {half, -half, -half, half}, zs[4] = {half, half, -half, -half};
  for (int i = 0; i < 4; ++i) corner[i] = bodyToWorld(pose, apex + Eigen::Vector3d(direction * kFrustumDepth, ys[i], zs[i]));
  const Eigen::Vector3d a = bodyToWorld(pose, apex);
  Shape3D f;
  f.kind = Shape3D::Kind::Polyline;
  f.name = name;
  f.points = {a, corner[0], corner[1], corner[2], corner[3], corner[0], a, corner[1], a, corner[2], a, corner[3]};
  f.color = {0.9, 0.9, 0.3};
  f.opacity = 0.6;
  return f;
}

}  // namespace

View3D buildTetherView(const TetherParameters& p, const SimulationOutput& sim) {
  View3D view;
  view.scalar_name = "tension";
  view.scalar_unit = "N";
  view.water_level_z = 0.0;
  const double w = wetWeightPerLength(p);
  const bool both = p.law == "both_cameras";
  for (const Snapshot& snap : sim.frames) {
    Frame3D frame;
    frame.time = snap.time;
    frame.shapes.push_back(robotBox(snap.follower, "follower", {0.2, 0.5, 0.9}));
    frame.shapes.push_back(robotBox(snap.leader, "leader", {0.9, 0.4, 0.2}));
    frame.shapes.push_back(headingLine(snap.follower, "follower heading"));
    frame.shapes.push_back(headingLine(snap.leader, "leader heading"));
    frame.shapes.push_back(frustum(snap.follower, {p.follower_attachment_x, 0.0, 0.05}, +1.0, "follower front camera"));
    if (both) frame.shapes.push_back(frustum(snap.leader, {p.leader_attachment_x, 0.0, 0.05}, -1.0, "leader rear camera"));
    if (snap.tether.catenary.has_geometry) {
      Shape3D tube;
      tube.kind = Shape3D::Kind::Tube;
      tube.name = "catenary (quasi-static model)";
      tube.radius = std::max(0.5 * p.diameter, 0.004);  // drawn at least 4 mm thick to stay visible
      for (int i = 0; i <= 60; ++i) {
        const double s = p.length * i / 60.0;
        tube.points.push_back(tetherPointAtArcLength(snap.tether, s));
        tube.scalars.push_back(catenaryTension(snap.tether.catenary, w, s));
      }
      frame.shapes.push_back(std::move(tube));
    }
    if (!snap.cable.empty()) {
      Shape3D cable;
      cable.kind = Shape3D::Kind::Polyline;
      cable.name = "lumped-mass cable";
      cable.points = snap.cable;
      cable.color = {0.1, 0.9, 0.4};
      frame.shapes.push_back(std::move(cable));
    }
    view.frames.push_back(std::move(frame));
  }
  return view;
}

}  // namespace maris::tether
