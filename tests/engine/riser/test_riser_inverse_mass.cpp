// The inverse mass from the tangent (riser_inverse_mass.hpp) against the products it replaces, written out here:
// W = blockdiag(R) W_local blockdiag(R)ᵀ, W D' with D' = [1; [d]×], and D'ᵀ W D', for segments of the peer riser
// (with and without torsion, with a tangential added mass unlike the normal one) turned to orientations far from the
// initial shape. Same algebra, so they agree to rounding: tolerance 1e-13 of the largest entry; 1e-12 for D'ᵀ W D',
// a difference of products about ten times larger than itself (measured up to 2.1e-13 there).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "riser/riser_inverse_mass.hpp"
#include "riser/riser_model.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

Mat6 globalInverseMass(const SegmentInverseMass& w, const Vec3& t) {
  Mat6 g;
  g << w.force.at(t), w.coupling.at(t), w.coupling.transposed().at(t), w.moment.at(t);
  return g;
}

void checkModel(const RiserModel& m) {
  for (int i = 0; i <= m.n; ++i) {
    const Segment& s = m.segments[i];
    const SegmentInverseMass w = segmentInverseMass(s.inverse_mass_local, s.length);
    // The blocks give the local matrix back (tangent e_x).
    EXPECT_LT(relativeDifference(globalInverseMass(w, Vec3::UnitX()), s.inverse_mass_local), 1e-13) << "segment " << i;
    for (int k = 0; k < 4; ++k) {
      const double a = i + 3.0 * k;
      const Mat3 r = (Eigen::AngleAxisd(0.9 * a + 0.3, Vec3(std::sin(a), std::cos(0.7 * a), 0.4).normalized()) *
                      Eigen::AngleAxisd(-1.1 * k, Vec3::UnitY()))
                         .toRotationMatrix();
      Mat6 turn = Mat6::Zero();
      turn.topLeftCorner<3, 3>() = r;
      turn.bottomRightCorner<3, 3>() = r;
      const Mat6 expected = turn * s.inverse_mass_local * turn.transpose();
      const Vec3 t = r.col(0);
      EXPECT_LT(relativeDifference(globalInverseMass(w, t), expected), 1e-13) << "segment " << i << " turn " << k;
      Eigen::Matrix<double, 6, 3> d_prime;
      d_prime << Mat3::Identity(), skew(s.length * t);
      const Eigen::Matrix<double, 6, 3> wd = expected * d_prime;
      EXPECT_LT(relativeDifference(w.far_force.at(t), wd.topRows<3>()), 1e-13);
      EXPECT_LT(relativeDifference(w.far_end.at(t), d_prime.transpose() * wd), 1e-12);
      Vec6 g;
      g << 3e5 * std::sin(a), -2e4, 7e3 * std::cos(a), 1e5 * std::cos(2 * a), 4e4, -9e4 * std::sin(0.3 * a);
      const Vec6 x = expected * g;
      EXPECT_LT((w.apply(t, g) - x).cwiseAbs().maxCoeff(), 1e-13 * x.cwiseAbs().maxCoeff());
    }
  }
}

TEST(RiserInverseMass, BlocksFromTheTangentAreTheTurnedInverseMass) {
  for (const bool torsion : {true, false})
    for (const double axial_added_mass : {0.0, 0.7}) {
      RiserParameters p = test::builtinParameters("scenarios/riser/riser_peer_tensioned.json");
      p.segment_count = 6;
      p.torsion = torsion;
      p.tangential_added_mass_coefficient = axial_added_mass;
      SCOPED_TRACE(torsion ? "torsion" : "no torsion");
      checkModel(buildRiserModel(p));
    }
}

}  // namespace
}  // namespace maris::riser
