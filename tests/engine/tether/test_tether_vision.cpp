// Synthetic camera and Gauss-Newton shape estimator: noiseless projections of the catenary are
// fitted exactly, noisy ones within the noise, and degenerate views hold the previous estimate without NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tether/tether_vision.hpp"

namespace maris::tether {
namespace {

// Attachment at (0, 0.10, 0.20) m in the camera frame: camera 0.2 m behind and 0.1 m above P2.
struct VisionRig {
  TetherRig rig;
  CameraModel camera;
  RobotPose leader{{2.0, 0.0, -0.5}, 0.0};
  VisionRig() { camera.position_in_body = rig.follower_attachment + Eigen::Vector3d(-0.2, 0.0, 0.1); }

  std::vector<ImagePoint> image(double a, double b, std::mt19937_64* noise = nullptr) const {
    const RobotPose follower = followerPoseFromFeatures(rig, leader, Features{a, b, 0.5, 0.0});
    const TetherState state = tetherState(rig, follower, leader);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 60; ++i) points.push_back(tetherPointAtArcLength(state, rig.length * (i + 0.5) / 60.0));
    return projectTether(camera, follower, points, noise);
  }
};

TEST(TetherVision, AttachmentSitsBehindAndAboveTheFollowersTetherPoint) {
  const VisionRig s;
  EXPECT_LE((attachmentInCamera(s.rig, s.camera) - Eigen::Vector3d(0.0, 0.10, 0.20)).norm(), 1e-15);
}

TEST(TetherVision, NoiselessProjectionsAreFittedExactly) {
  // D1: from (0.5, 0.3), true (a, b) recovered to 1e-8 in <= 30 iterations (an independent implementation needed 12-13). The model and
  // the synthetic image share only the catenary; the projection is generic in both.
  const VisionRig s;
  for (const auto& truth : {std::pair{0.5, 0.5}, std::pair{0.3, 0.2}, std::pair{0.8, 0.6}}) {
    const auto image = s.image(truth.first, truth.second);
    ASSERT_GE(image.size(), 20u);
    ShapeEstimate start;
    start.a = 0.5;
    start.b = 0.3;
    const ShapeEstimate est = estimateShape(s.rig, s.camera, image, 0.0, start);
    EXPECT_FALSE(est.held);
    EXPECT_NEAR(est.a, truth.first, 1e-8);
    EXPECT_NEAR(est.b, truth.second, 1e-8);
    EXPECT_LE(est.iterations, 30);
  }
}

TEST(TetherVision, NoisyProjectionsAreFittedWithinTheNoise) {
  // D2: sigma = 1e-3 normalised units: |a_hat - a|, |b_hat - b| <= 5e-3 (an independent implementation measured <= 1e-4).
  VisionRig s;
  s.camera.noise = 1e-3;
  std::mt19937_64 rng(7);
  const auto image = s.image(0.5, 0.5, &rng);
  ShapeEstimate start;
  start.a = 0.5;
  start.b = 0.3;
  const ShapeEstimate est = estimateShape(s.rig, s.camera, image, 0.0, start);
  EXPECT_NEAR(est.a, 0.5, 5e-3);
  EXPECT_NEAR(est.b, 0.5, 5e-3);
  // The ordinate residual y - y(x) also carries the abscissa noise times the curve's slope, so its rms exceeds
  // sigma near the steep ends; it stays at the noise level's order.
  EXPECT_LT(est.rms_residual, 20e-3);
}

TEST(TetherVision, DegenerateViewHoldsThePreviousEstimate) {
  // D3: alpha = 0 with the attachment on the optical axis: the tether plane contains the camera centre and the
  // image is a vertical line; the estimator holds and returns the previous (finite) estimate.
  VisionRig s;
  s.camera.position_in_body = s.rig.follower_attachment + Eigen::Vector3d(-0.2, 0.0, 0.0);
  const auto image = s.image(0.5, 0.0);
  ShapeEstimate previous;
  previous.a = 0.42;
  previous.b = 0.1;
  const ShapeEstimate est = estimateShape(s.rig, s.camera, image, 0.0, previous);
  EXPECT_TRUE(est.held);
  EXPECT_EQ(est.a, 0.42);
  EXPECT_EQ(est.b, 0.1);
  EXPECT_TRUE(estimateShape(s.rig, s.camera, {}, 0.0, previous).held);  // nothing visible
}

TEST(TetherVision, PointsOutsideTheModelTetherAreNotResiduals) {
  // D4: abscissas that back-project beyond the tether are rejected instead of overflowing cosh.
  const VisionRig s;
  double y = 0.0;
  const Eigen::Vector3d p2c = attachmentInCamera(s.rig, s.camera);
  EXPECT_FALSE(modelOrdinate(s.rig, p2c, 0.0, 0.5, 0.5, 5.0, y));   // far right of the plane's image
  EXPECT_FALSE(modelOrdinate(s.rig, p2c, 0.0, 0.5, 0.5, -0.9, y));  // beyond P1
  EXPECT_TRUE(modelOrdinate(s.rig, p2c, 0.0, 0.5, 0.5, -0.2, y));
  EXPECT_TRUE(std::isfinite(y));
}

}  // namespace
}  // namespace maris::tether
