// The segment's inverse mass turned to the global frame from its tangent (riser_inverse_mass, used by every
// right-hand side) against the full product R W_local Rᵀ it replaces. Same matrix, so they agree to rounding:
// tolerance 1e-13 of the largest entry of each block.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "riser/riser_inverse_mass.hpp"
#include "riser/riser_model.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

double blockError(const Mat3& a, const Mat3& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

void expectRotatedAsTheFullProduct(const RiserModel& m) {
  for (int i = 0; i <= m.n; ++i) {
    const Mat6& local = m.segments[i].inverse_mass_local;
    AxisymmetricInverseMass k;
    ASSERT_TRUE(axisymmetricInverseMass(local, k)) << "segment " << i;
    const double a = i;
    const Mat3 r = Eigen::AngleAxisd(0.3 + 0.9 * a, Vec3(std::sin(a), std::cos(0.7 * a), 0.4).normalized())
                       .toRotationMatrix();
    Mat6 w;
    rotateInverseMass(k, r.col(0), w);
    EXPECT_LT(blockError(w.topLeftCorner<3, 3>(), r * local.topLeftCorner<3, 3>() * r.transpose()), 1e-13);
    EXPECT_LT(blockError(w.topRightCorner<3, 3>(), r * local.topRightCorner<3, 3>() * r.transpose()), 1e-13);
    EXPECT_LT(blockError(w.bottomLeftCorner<3, 3>(), r * local.bottomLeftCorner<3, 3>() * r.transpose()), 1e-13);
    // Without torsion the rotation block is singular (no spin about the axis); its largest entry is still nonzero.
    EXPECT_LT(blockError(w.bottomRightCorner<3, 3>(), r * local.bottomRightCorner<3, 3>() * r.transpose()), 1e-13);
  }
}

TEST(RiserInverseMass, TurnedFromTheTangentAsTheFullProductWithAndWithoutTorsion) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_peer_tensioned.json");
  p.segment_count = 6;
  p.torsion = true;
  expectRotatedAsTheFullProduct(buildRiserModel(p));
  p.torsion = false;
  expectRotatedAsTheFullProduct(buildRiserModel(p));
}

// Buoyancy modules and an axial added mass unlike the normal one change the blocks' coefficients, not their form.
TEST(RiserInverseMass, TurnedFromTheTangentWithModulesAndAxialAddedMass) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_lazy_wave.json");
  p.segment_count = 12;
  p.tangential_added_mass_coefficient = 0.4;
  expectRotatedAsTheFullProduct(buildRiserModel(p));
}

// A matrix not of that form is refused (the check the tests above rely on can fail).
TEST(RiserInverseMass, AMatrixWithoutTheAxisymmetricFormIsRefused) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_peer_tensioned.json");
  p.segment_count = 4;
  Mat6 local = buildRiserModel(p).segments[1].inverse_mass_local;
  local(1, 2) += 1e-6 * local(1, 1);
  AxisymmetricInverseMass k;
  EXPECT_FALSE(axisymmetricInverseMass(local, k));
}

}  // namespace
}  // namespace maris::riser
