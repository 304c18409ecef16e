// Features and interaction matrices: analytic Jacobians against central finite differences of the feature map
// from robot poses, and the reference matrix M at s* = (0.5, 0.5, 0.5) of an independent computation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "tether/tether_kinematics.hpp"

namespace maris::tether {
namespace {

const double kDeg = std::numbers::pi / 180.0;

TetherRig paperRig() { return TetherRig{}; }  // L = 1.5 m, H_max = 0.7 m, dH_max = 0.5 m (paper §7)

Vector4 featuresAt(const TetherRig& rig, const RobotPose& follower, const RobotPose& leader) {
  return featuresOf(rig, tetherState(rig, follower, leader)).vector();
}

// Central differences of s along each body-twist direction; h = 1e-6 gives truncation ~h^2 and round-off
// ~eps/h ~ 2e-10, so 1e-7 is a safe bound (an independent implementation measured <= 5e-10).
void expectJacobiansMatchFiniteDifferences(const TetherRig& rig, const Features& s) {
  const RobotPose leader{{1.0, -0.5, -2.0}, 0.3};
  const RobotPose follower = followerPoseFromFeatures(rig, leader, s);
  ASSERT_NEAR((featuresAt(rig, follower, leader) - s.vector()).norm(), 0.0, 1e-12);  // the inverse map
  const InteractionMatrices im = interactionMatrices(rig, s);
  const double h = 1e-6;
  for (int j = 0; j < 4; ++j) {
    const Vector4 e = Vector4::Unit(j);
    const Vector4 fd_follower = (featuresAt(rig, integratePose(follower, e, h), leader) -
                                 featuresAt(rig, integratePose(follower, e, -h), leader)) / (2 * h);
    const Vector4 fd_leader = (featuresAt(rig, follower, integratePose(leader, e, h)) -
                               featuresAt(rig, follower, integratePose(leader, e, -h))) / (2 * h);
    EXPECT_LE((im.follower.col(j) - fd_follower).cwiseAbs().maxCoeff(), 1e-7)
        << "follower column " << j << " at a=" << s.a << " b=" << s.b << " d=" << s.d << "\n"
        << im.follower.col(j).transpose() << "\n" << fd_follower.transpose();
    EXPECT_LE((im.leader.col(j) - fd_leader).cwiseAbs().maxCoeff(), 1e-7)
        << "leader column " << j << " at a=" << s.a << " b=" << s.b << " d=" << s.d;
  }
}

TEST(TetherKinematics, InteractionMatricesMatchFiniteDifferencesOnGrid) {
  const TetherRig rig = paperRig();
  int checked = 0;
  for (double sag : {0.05, 0.2, 0.35, 0.6})
    for (double rise : {-0.3, -0.1, 0.0, 0.1, 0.3})
      for (double alpha_deg : {-60.0, -25.0, 0.0, 10.0, 45.0, 60.0}) {
        const Features s{sag / rig.sag_max, std::sin(alpha_deg * kDeg), (rise + rig.rise_max) / (2 * rig.rise_max),
                         std::sin((alpha_deg * 0.5 - 10.0) * kDeg)};
        if (!featureInfeasibility(rig, s).empty()) continue;
        expectJacobiansMatchFiniteDifferences(rig, s);
        ++checked;
      }
  EXPECT_GE(checked, 90);  // most of the 120 grid points are feasible shapes
}

TEST(TetherKinematics, ShapeJacobianAtDesiredShapeMatchesReference) {
  // An independent Python implementation (outside this repository) (z-up convention); rel 1e-9.
  const InteractionMatrices im = interactionMatrices(paperRig(), Features{0.5, 0.5, 0.5, 0.0});
  Eigen::Matrix3d ref;
  ref << -0.9023964972, -0.5209988606, -0.7142857143, -0.3404919054, 0.5897492798, 0, 0, 0, 1;
  EXPECT_LE((im.shape_jacobian - ref).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(im.span_per_sag, -1.3709928531, 1e-9);
  EXPECT_NEAR(im.span_per_rise, 0.0762994058 - 0.7617958323, 1e-9);
}

TEST(TetherKinematics, SpanShrinksWithSagEverywhereOnGrid) {
  // The paper's claim U + P < 0 (keeps row a of L finite), on a feasible grid.
  const TetherRig rig = paperRig();
  for (double sag : {1e-3, 0.05, 0.2, 0.35, 0.6, 0.74})
    for (double rise : {-0.3, -0.1, 0.0, 0.1, 0.3, 0.5}) {
      const Features s{sag / rig.sag_max, 0.3, (rise + rig.rise_max) / (2 * rig.rise_max), 0.0};
      if (!featureInfeasibility(rig, s).empty() || sag + rise < 1e-3) continue;
      EXPECT_LT(interactionMatrices(rig, s).span_per_sag, 0.0) << sag << " " << rise;
    }
}

TEST(TetherKinematics, FollowerMatrixLosesRankOnlyWhenTetherPlaneIsPerpendicular) {
  // Eq. 43: det of the top-left 2x2 block = sqrt(1 - b^2)/((U + P) H_max S); rank 3 while |b| < 0.99.
  const TetherRig rig = paperRig();
  for (double b : {-0.95, -0.5, 0.0, 0.3, 0.9, 0.989}) {
    const Features s{0.5, b, 0.6, 0.0};
    const InteractionMatrices im = interactionMatrices(rig, s);
    const double expected = std::sqrt(1 - b * b) / (im.span_per_sag * rig.sag_max * im.span);
    const double det = im.follower.topLeftCorner<2, 2>().determinant();
    EXPECT_NEAR(det, expected, 1e-12 * std::abs(expected) + 1e-15);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(im.follower.topRows<3>()));
    EXPECT_GT(svd.singularValues()[2], 1e-3) << b;
  }
  const double near_one = interactionMatrices(rig, Features{0.5, 0.999999, 0.6, 0.0}).follower.col(0).head<3>().norm();
  EXPECT_LT(near_one, 2e-3);  // column nu_x ~ sqrt(1 - b^2) = 1.4e-3 times O(1)
}

TEST(TetherKinematics, InfeasibleTargetsAreRejectedWithReason) {
  const TetherRig rig = paperRig();
  EXPECT_NE(featureInfeasibility(rig, Features{1.0, 0.0, 1.0, 0.0}), "");  // (a, d) = (1, 1): 2H + dH > L
  EXPECT_NE(featureInfeasibility(rig, Features{0.5, 0.0, 0.0, 0.0}), "");  // (0.5, 0): H + dH < 0
  EXPECT_EQ(featureInfeasibility(rig, Features{1.0, 0.0, 0.5, 0.0}), "");  // lowest point at the follower's end: feasible
  EXPECT_EQ(featureInfeasibility(rig, Features{0.5, 0.0, 1.0, 0.0}), "");
  EXPECT_NE(featureInfeasibility(rig, Features{0.5, 1.0, 0.5, 0.0}), "");
}

}  // namespace
}  // namespace maris::tether
