// The reaction sweep's written-out 3×3 LU (riser_small_lu.hpp) against Eigen's PartialPivLU<Matrix3d>, whose
// operations it mirrors: the same bits for every solve (vector and 3×3 right sides), on random matrices over
// twelve decades of scale, on matrices with pivot ties, unit rows (known top-force rows of the sweep) and zeros.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include <Eigen/LU>

#include "riser/riser_small_lu.hpp"

namespace maris::riser {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

int differingEntries(const Eigen::Matrix3d& a, const Eigen::Matrix3d& rhs, const Eigen::Vector3d& v) {
  const Eigen::PartialPivLU<Eigen::Matrix3d> eigen(a);
  const SmallLu3 mine(a);
  const Eigen::Matrix3d x = eigen.solve(rhs), y = mine.solve(rhs);
  const Eigen::Vector3d u = eigen.solve(v), w = mine.solve(v);
  int differ = 0;
  for (int i = 0; i < 9; ++i) differ += !sameBits(x.data()[i], y.data()[i]);
  for (int i = 0; i < 3; ++i) differ += !sameBits(u[i], w[i]);
  return differ;
}

TEST(RiserSmallLu, SolvesBitForBitAsEigensPartialPivLu) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> entry(-1.0, 1.0), decade(-6.0, 6.0);
  int cases = 0;
  for (int k = 0; k < 20000; ++k) {
    Eigen::Matrix3d a, rhs;
    Eigen::Vector3d v;
    for (int i = 0; i < 9; ++i) a.data()[i] = entry(random) * std::pow(10.0, decade(random));
    for (int i = 0; i < 9; ++i) rhs.data()[i] = entry(random) * std::pow(10.0, decade(random));
    for (int i = 0; i < 3; ++i) v[i] = entry(random) * std::pow(10.0, decade(random));
    switch (k % 5) {
      case 1: a.row(k % 3) = Eigen::Vector3d::Unit((k / 5) % 3).transpose(); break;  // a known-force row
      case 2: a(1, 0) = -a(0, 0); a(2, 0) = a(0, 0); break;                          // pivot ties in column 0
      case 3: a(0, 0) = 0.0; a(2, 1) = 0.0; break;                                   // zeros on the way
      case 4: a = a * a.transpose() + Eigen::Matrix3d::Identity(); break;            // symmetric positive
      default: break;
    }
    EXPECT_EQ(differingEntries(a, rhs, v), 0) << "case " << k << "\n" << a;
    ++cases;
  }
  EXPECT_EQ(cases, 20000);
}

}  // namespace
}  // namespace maris::riser
