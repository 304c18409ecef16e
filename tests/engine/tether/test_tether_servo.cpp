// Closed-loop behaviour of the servo law with exact features and a kinematic follower at 30 Hz:
// the discrete error decays as (1 - lambda dt)^k, leader-velocity compensation removes the tracking error of a
// moving leader, and L Lhat+ keeps eigenvalues with positive real parts under 40 % model errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tether/tether_servo.hpp"

namespace maris::tether {
namespace {

constexpr double kDt = 1.0 / 30.0;  // [s] control period of the paper's simulations

ServoSettings unsaturated(double lambda, bool four_features) {
  ServoSettings s;
  s.use_leader_feature = four_features;
  s.proportional_gain = Vector4::Constant(lambda);
  s.max_linear_speed = 1e9;
  s.max_yaw_rate = 1e9;
  return s;
}

struct LoopTrace {
  std::vector<double> error_norm;
  RobotPose follower;
};

// Runs k ticks: measure exact features, command, move the follower (and the leader with `leader_twist(t)`).
template <class LeaderTwist>
LoopTrace runLoop(const TetherRig& rig, const ServoSettings& settings, RobotPose follower, RobotPose leader,
                  const Features& target, int ticks, LeaderTwist leader_twist) {
  TetherServo servo(rig, settings);
  LoopTrace trace;
  for (int k = 0; k <= ticks; ++k) {
    const Features s = featuresOf(rig, tetherState(rig, follower, leader));
    const Vector4 v1 = leader_twist(k * kDt);
    const ServoCommand cmd = servo.update(s, s, target, v1);
    trace.error_norm.push_back(cmd.error.norm());
    follower = integratePose(follower, cmd.twist, kDt);
    leader = integratePose(leader, v1, kDt);
  }
  trace.follower = follower;
  return trace;
}

const auto kStaticLeader = [](double) { return Vector4::Zero(); };

TEST(TetherServo, ErrorDecaysGeometricallyAtOneMinusLambdaDt) {
  // C1: s0 ~ (0.855, 0.131, 0.45) -> s* = (0.5, 0.5, 0.5), lambda = 1; ratio within 1 % of (1 - lambda dt)^k
  // (the residual is the second-order error of the Euler step on the nonlinear feature map).
  const TetherRig rig;
  const RobotPose leader{{2.0, 0.0, -1.0}, 0.0};
  const RobotPose follower = followerPoseFromFeatures(rig, leader, Features{0.855, 0.131, 0.45, 0.0});
  const auto trace = runLoop(rig, unsaturated(1.0, false), follower, leader, Features{0.5, 0.5, 0.5, 0.0}, 300,
                             kStaticLeader);
  for (int k : {30, 80, 120, 240, 300}) {
    const double expected = std::pow(1.0 - kDt, k);
    EXPECT_NEAR(trace.error_norm[k] / trace.error_norm[0], expected, 0.01 * expected) << "k = " << k;
  }
}

TEST(TetherServo, FourFeatureLawConvergesToTheUniquePose) {
  // C2: (s2, b1) with lambda = 0.5 fixes the follower pose; three starts, one with b2 < 0. ||e|| never grows,
  // the ratio after 600 ticks is (1 - lambda dt)^600 = 4.18e-5 within 1 %, and the final pose equals the pose
  // that realises the target exactly (1e-4 m / rad, i.e. ~2 e_600 scaled).
  const TetherRig rig;
  const RobotPose leader{{0.0, 0.0, -1.0}, 0.4};
  const Features target{0.5, 0.5, 0.5, std::sin(20.0 * std::numbers::pi / 180.0)};
  const RobotPose goal = followerPoseFromFeatures(rig, leader, target);
  for (const Features start : {Features{0.8, 0.1, 0.45, 0.0}, Features{0.3, -0.3, 0.6, 0.2},
                               Features{0.65, 0.7, 0.5, -0.2}}) {
    const auto trace = runLoop(rig, unsaturated(0.5, true), followerPoseFromFeatures(rig, leader, start), leader,
                               target, 600, kStaticLeader);
    for (std::size_t k = 1; k < trace.error_norm.size(); ++k)
      ASSERT_LE(trace.error_norm[k], trace.error_norm[k - 1] * (1 + 1e-12)) << "k = " << k;
    const double expected = std::pow(1.0 - 0.5 * kDt, 600);
    EXPECT_NEAR(trace.error_norm[600] / trace.error_norm[0], expected, 0.01 * expected);
    EXPECT_LE((trace.follower.position - goal.position).norm(), 1e-4);
    EXPECT_LE(std::abs(std::remainder(trace.follower.yaw - goal.yaw, 2 * std::numbers::pi)), 1e-4);
  }
}

TEST(TetherServo, LeaderCompensationRemovesTrackingError) {
  // C3: leader at 0.1 m/s forward with lateral 0.05 sin(0.5 t) and vertical 0.03 cos(0.3 t), lambda = 2.
  // With compensation the remaining error is what a twist held over one tick cannot cancel (an independent
  // implementation measured 1.9e-8); without it the error stays of the order of |L1 v1|/lambda (measured there 7.6e-2).
  const TetherRig rig;
  const RobotPose leader{{0.0, 0.0, -1.0}, 0.0};
  const Features target{0.5, 0.2, 0.5, 0.0};
  // Start on the target so that the error after k = 100 is tracking error, not the transient (1 - 2 dt)^100.
  const RobotPose follower = followerPoseFromFeatures(rig, leader, target);
  const auto moving = [](double t) { return Vector4(0.1, 0.05 * std::sin(0.5 * t), 0.03 * std::cos(0.3 * t), 0.0); };
  for (auto compensation : {LeaderCompensation::MinimumNorm, LeaderCompensation::Rigid, LeaderCompensation::None}) {
    ServoSettings settings = unsaturated(2.0, false);
    settings.compensation = compensation;
    const auto trace = runLoop(rig, settings, follower, leader, target, 900, moving);
    double worst = 0.0;
    for (std::size_t k = 100; k < trace.error_norm.size(); ++k) worst = std::max(worst, trace.error_norm[k]);
    if (compensation == LeaderCompensation::None) {
      EXPECT_GE(worst, 1e-2);
      EXPECT_LE(worst, 0.5);
    } else if (compensation == LeaderCompensation::Rigid) {
      // Moving rigidly with the held leader twist leaves the relative pose, hence the features, unchanged.
      EXPECT_LE(worst, 1e-6);
    } else {
      // -L+ L1 v1 cancels the leader-induced change to first order in dt only: the held-twist residual
      // ~ |v1|^2 dt^2 |d2s/dx2| per tick, divided by lambda dt, is ~1e-5 here.
      EXPECT_LE(worst, 1e-4);
    }
  }
}

TEST(TetherServo, ClosedLoopStaysStableUnderFortyPercentModelError) {
  // C4 (paper §6, eqs. 56-58): eigenvalues of L(s*) Lhat+ for relative errors up to 40 % on a and b, attachment
  // 0 to 0.5 m ahead of the follower centre: all real parts > 0; the d eigenvalue is exactly 1; all are 1 at zero
  // error (L L+ = I for full row rank).
  const Features truth{0.5, 0.5, 0.5, 0.0};
  double min_real = 1e9;
  for (double offset : {0.0, 0.25, 0.5}) {
    TetherRig rig;
    rig.follower_attachment = {offset, 0.0, 0.0};
    const ServoSettings settings = unsaturated(1.0, false);
    const Eigen::VectorXcd exact = closedLoopEigenvalues(rig, settings, truth, truth);
    for (Eigen::Index i = 0; i < exact.size(); ++i) EXPECT_NEAR(std::abs(exact[i] - 1.0), 0.0, 1e-12);
    for (double ea = -0.4; ea <= 0.401; ea += 0.1)
      for (double eb = -0.4; eb <= 0.401; eb += 0.1) {
        const Features model{truth.a * (1 + ea), truth.b * (1 + eb), truth.d, 0.0};
        const Eigen::VectorXcd values = closedLoopEigenvalues(rig, settings, truth, model);
        bool has_one = false;
        for (Eigen::Index i = 0; i < values.size(); ++i) {
          min_real = std::min(min_real, values[i].real());
          has_one = has_one || std::abs(values[i] - 1.0) < 1e-12;
        }
        EXPECT_TRUE(has_one) << ea << " " << eb;
      }
  }
  EXPECT_GT(min_real, 0.0);
  EXPECT_LT(min_real, 1.0);  // errors do move the spectrum (independent implementation: minimum 0.562)
}

TEST(TetherServo, SaturationKeepsDirectionAndHoldNearSingularity) {
  const TetherRig rig;
  ServoSettings settings;
  settings.max_linear_speed = 0.01;
  TetherServo servo(rig, settings);
  const Features s{0.9, 0.1, 0.45, 0.0}, target{0.5, 0.5, 0.5, 0.0};
  const ServoCommand cmd = servo.update(s, s, target, Vector4::Zero());
  EXPECT_TRUE(cmd.saturated);
  EXPECT_LE(cmd.twist.head<3>().cwiseAbs().maxCoeff(), 0.01 + 1e-15);
  TetherServo free(rig, unsaturated(1.0, false));
  const ServoCommand unsat = free.update(s, s, target, Vector4::Zero());
  EXPECT_NEAR(std::abs(cmd.twist.normalized().dot(unsat.twist.normalized())), 1.0, 1e-12);
  const ServoCommand held = servo.update(Features{0.5, 0.995, 0.5, 0.0}, Features{0.5, 0.995, 0.5, 0.0}, target,
                                         Vector4::Zero());
  EXPECT_TRUE(held.held);
  EXPECT_EQ(held.twist.norm(), 0.0);
}

TEST(TetherServo, DampedInverseIsPseudoInverseAwayFromRankLoss) {
  Eigen::MatrixXd m(2, 3);
  m << 1, 2, 0, 0, 1, 3;
  const DampedInverse inv = dampedPseudoInverse(m, 1e-3, 0.1);
  EXPECT_EQ(inv.damping, 0.0);
  EXPECT_LE((m * inv.inverse - Eigen::MatrixXd::Identity(2, 2)).norm(), 1e-14);
  Eigen::MatrixXd singular(2, 3);
  singular << 1, 2, 0, 1, 2, 1e-9;
  const DampedInverse damped = dampedPseudoInverse(singular, 1e-2, 0.1);
  EXPECT_GT(damped.damping, 0.09);
  EXPECT_LT(damped.inverse.norm(), 20.0);  // bounded by 1/(2 mu) per direction instead of 1e9
}

}  // namespace
}  // namespace maris::tether
