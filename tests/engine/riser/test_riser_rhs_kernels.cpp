// The right-hand side's cheaper kernels against the formulas they replace, written out here as the equations state
// them: the spring couple -R_{i-1} G(Δφ)^{-T} M̄ with M̄ = C Δφ + B G(Δφ)^{-1} R_{i-1}ᵀ(ω_i − ω_{i-1}) by LU
// solves with G = zyxRateMatrix (addSpringMoments reads G's sines and cosines off the relative rotation and solves
// in closed form), and Morison drag in the global frame at each Gauss point (addDrag sums in the segment's frame).
// Same equations, so they agree to rounding: tolerance 1e-12 relative (measured: couples 3.4e-16 of the largest,
// drag 6e-16, powers 2e-16 and 7e-16).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "riser/riser_loads.hpp"
#include "riser/riser_model.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

// The peer riser at n = 8, every joint damped, in a pose bent by more than 57° between some neighbours (the rate
// matrix is far from the identity there) with every segment turning and moving.
struct BentPose {
  RiserModel model;
  RiserPose pose;
};

BentPose bentPose() {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_peer_tensioned.json");
  p.segment_count = 8;
  BentPose b{buildRiserModel(p), {}};
  RiserModel& m = b.model;
  for (int i = 1; i <= m.n; ++i) m.joints[i].damping = 0.3 * m.joints[i].stiffness;
  b.pose.resize(m.segmentCount());
  Vec3 r(0.0, 0.0, -5.0);
  for (int i = 0; i <= m.n; ++i) {
    const double a = i;
    const Eigen::Quaterniond q = Eigen::AngleAxisd(0.17 * a * a, Vec3(std::sin(a), std::cos(0.7 * a), 0.4).normalized()) *
                                 Eigen::AngleAxisd(-1.4, Vec3::UnitY());
    b.pose.rotation[i] = q.toRotationMatrix();
    b.pose.omega[i] = Vec3(0.3 * std::sin(1.1 * a), 0.2 * std::cos(a), -0.25 * std::sin(0.5 * a));
    b.pose.velocity[i] = Vec3(0.8 * std::cos(0.3 * a), -0.4, 0.2 * std::sin(a));
    b.pose.position[i] = r;
    r += m.segments[i].length * b.pose.rotation[i].col(0);
  }
  b.pose.end_position = r;
  return b;
}

double largestAngleBetweenNeighbours(const BentPose& b) {
  double largest = 0.0;
  for (int i = 1; i <= b.model.n; ++i)
    largest = std::max(largest, std::acos(std::clamp(b.pose.tangent(i - 1).dot(b.pose.tangent(i)), -1.0, 1.0)));
  return largest;
}

TEST(RiserRhsKernels, SpringCoupleInClosedFormMatchesTheRateMatrixSolves) {
  const BentPose b = bentPose();
  const RiserModel& m = b.model;
  ASSERT_GT(largestAngleBetweenNeighbours(b), 1.0);  // bends of more than 57°: G far from the identity
  SegmentLoads fast;
  fast.resize(m.segmentCount());
  addSpringMoments(m, b.pose, fast);
  std::vector<Vec3> moment(m.segmentCount(), Vec3::Zero());
  double power = 0.0, scale = 0.0;
  for (int i = 1; i <= m.n; ++i) {
    const Mat3& ra = b.pose.rotation[i - 1];
    const Vec3 angles = zyxAngles(ra.transpose() * b.pose.rotation[i]);
    const Mat3 g = zyxRateMatrix(angles);
    const Vec3 rates = g.lu().solve(ra.transpose() * (b.pose.omega[i] - b.pose.omega[i - 1]));
    const Vec3 mbar = m.joints[i].stiffness.cwiseProduct(angles) + m.joints[i].damping.cwiseProduct(rates);
    const Vec3 couple = ra * g.transpose().lu().solve(mbar);
    moment[i] -= couple;
    moment[i - 1] += couple;
    power -= rates.dot(m.joints[i].damping.cwiseProduct(rates));
    scale = std::max(scale, couple.norm());
  }
  ASSERT_GT(scale, 0.0);
  for (int i = 0; i <= m.n; ++i)
    EXPECT_LT((fast.moment[i] - moment[i]).norm(), 1e-12 * scale) << "segment " << i;
  EXPECT_NEAR(fast.power_damping, power, 1e-12 * std::abs(power));
}

TEST(RiserRhsKernels, DragInTheSegmentFrameMatchesTheGlobalFrameAtEachGaussPoint) {
  const BentPose b = bentPose();
  const RiserModel& m = b.model;
  SegmentLoads fast;
  fast.resize(m.segmentCount());
  addDrag(m, b.pose, 0.7, fast);
  double power = 0.0, scale = 0.0;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& s = m.segments[i];
    const Mat3& r = b.pose.rotation[i];
    const Vec3 t = r.col(0);
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    for (int q = 0; q < 3; ++q) {
      const double xi = kGaussX[q] * s.length, w = kGaussW[q] * s.length;
      const Vec3 p = b.pose.position[i] + xi * t;
      if (p.z() > m.water_level) continue;
      const Vec3 v = b.pose.velocity[i] + b.pose.omega[i].cross(xi * t);
      const Vec3 local = r.transpose() * (v - m.currentAt(p.z()));
      const double vn = std::hypot(local.y(), local.z());
      const Vec3 f = 0.7 * w * (r * Vec3(-s.tangential_drag * std::abs(local.x()) * local.x(),
                                         -s.normal_drag * vn * local.y(), -s.normal_drag * vn * local.z()));
      force += f;
      moment += (xi * t).cross(f);
      power += f.dot(v);
    }
    scale = std::max(scale, force.norm());
    EXPECT_LT((fast.force[i] - force).norm(), 1e-12 * std::max(force.norm(), 1.0)) << "segment " << i;
    EXPECT_LT((fast.moment[i] - moment).norm(), 1e-12 * std::max(moment.norm(), 1.0)) << "segment " << i;
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_NEAR(fast.power_drag, power, 1e-12 * std::abs(power));
}

}  // namespace
}  // namespace maris::riser
