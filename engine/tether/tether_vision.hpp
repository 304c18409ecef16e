// Synthetic follower camera and the shape estimator of the paper's §3 (eqs. 11-21): tether points are projected
// by a pinhole camera (focal length 1, metric image coordinates), and the sag and angle features (a, b) are fitted
// to them by a damped Gauss-Newton (Levenberg-Marquardt) iteration on the image-ordinate residuals.
//
// Camera frame (paper's convention): x right, y down, z forward along the follower's body x axis. The image of the
// tether plane is generated generically (extrinsics, then division by depth), so the fit model and the synthetic
// measurement share no sign convention with the paper's closed forms:
//   the tether-plane point at horizontal distance zeta from P2 along the body direction (cos alpha2, sin alpha2)
//   and height h(zeta) above P2 has camera coordinates (cx2 - zeta sin, cy2 - h, cz2 + zeta cos) = (X, Y, Z); it
//   projects to abscissa x when zeta = (cx2 - x cz2)/(x cos alpha2 + sin alpha2), and then y = Y/Z.
// Modifications of the paper kept: residuals whose back-projection falls outside the tether (zeta outside [0, S]
// or behind the camera) are dropped; iterates are kept inside the feasible box by step halving; a nearly vertical
// image line (standard deviation of the abscissas below a threshold) or too few points gives "hold".
#pragma once

#include <random>
#include <vector>

#include <Eigen/Core>

#include "tether/tether_kinematics.hpp"

namespace maris::tether {

struct CameraModel {
  Eigen::Vector3d position_in_body{0.15, 0.0, 0.05};  // [m] follower front camera in the body frame (FLU)
  double half_field_of_view = 0.7;                    // [rad] half angle, horizontal and vertical
  double noise = 0.0;                                 // [-] std dev of image coordinates (normalised units)
  int sample_count = 60;                              // [-] tether points sampled along the arc
};

struct ImagePoint {
  double x = 0.0, y = 0.0;  // [-] normalised image coordinates (x right, y down)
};

// Projects world points (the tether, catenary or cable) into the follower camera; keeps those in front of the
// camera and inside the field of view; adds Gaussian noise of std dev camera.noise (core's portable standardNormal).
std::vector<ImagePoint> projectTether(const CameraModel& camera, const RobotPose& follower,
                                      const std::vector<Eigen::Vector3d>& world_points, std::mt19937_64* noise);

// Image of the model tether for features (a, b): y at abscissa x, or false when x back-projects outside the tether.
// p2_camera: the follower attachment point in the camera frame; rise: dH from the depth sensors.
bool modelOrdinate(const TetherRig& rig, const Eigen::Vector3d& p2_camera, double rise, double a, double b, double x,
                   double& y);

struct ShapeEstimate {
  double a = 0.0, b = 0.0;  // [-] fitted features
  bool held = false;        // degenerate view or too few points: the previous estimate is returned
  int iterations = 0;       // Levenberg–Marquardt iterations (Jacobian evaluations) of the fit kept
  bool converged = false;   // the fit met its cost or step tolerance (false: stopped without descent or at 50)
  int points_used = 0;
  double rms_residual = 0.0;  // [-] image units
};

// Fits (a, b) to the image points starting from `start`; returns `start` with held = true when the view is
// degenerate (abscissa spread < 1e-3 or fewer than 5 usable points).
ShapeEstimate estimateShape(const TetherRig& rig, const CameraModel& camera, const std::vector<ImagePoint>& image,
                            double rise, const ShapeEstimate& start);

// The follower attachment point in the camera frame.
Eigen::Vector3d attachmentInCamera(const TetherRig& rig, const CameraModel& camera);

}  // namespace maris::tether
