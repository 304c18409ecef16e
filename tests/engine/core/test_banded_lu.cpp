// Banded LU with partial pivoting against Eigen's dense PartialPivLU on the same matrices.
#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "core/banded_lu.hpp"

namespace maris {
namespace {

// Fills a random n × n band (kl, ku) into both a BandedLu and a dense matrix; `diagonal` scales the
// main diagonal (small values force row interchanges).
void randomBand(Eigen::Index n, Eigen::Index kl, Eigen::Index ku, double diagonal, BandedLu& banded,
                Eigen::MatrixXd& dense) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  banded.resize(n, kl, ku);
  dense.setZero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = std::max<Eigen::Index>(0, i - kl); j <= std::min(n - 1, i + ku); ++j) {
      const double value = (i == j ? diagonal : 1.0) * uniform(rng);
      banded.at(i, j) = value;
      dense(i, j) = value;
    }
}

TEST(BandedLu, SolvesLikeDenseLuWithAndWithoutPivoting) {
  // Reference: Eigen's dense LU on the same matrix. Tolerance 1e-10 relative: both are backward stable,
  // the difference is round-off times the condition number of a random band (≈ 1e3 here). A small
  // diagonal forces interchanges; it is only used with both bandwidths ≥ 1 (a triangular band with a
  // small diagonal is nearly singular by construction).
  for (double diagonal : {10.0, 1e-3}) {
    for (auto [kl, ku] : {std::pair<Eigen::Index, Eigen::Index>{1, 1}, {2, 3}, {0, 2}, {4, 0}, {14, 14}}) {
      if (diagonal < 1.0 && (kl == 0 || ku == 0)) continue;
      BandedLu banded;
      Eigen::MatrixXd dense;
      randomBand(60, kl, ku, diagonal, banded, dense);
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(60, -1.0, 2.0);
      ASSERT_TRUE(banded.factorize()) << "kl " << kl << " ku " << ku << " diag " << diagonal;
      Eigen::VectorXd x = b;
      banded.solve(x);
      const Eigen::VectorXd reference = dense.partialPivLu().solve(b);
      EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << "kl " << kl << " ku " << ku << " diag " << diagonal;
      EXPECT_LT((dense * x - b).norm(), 1e-12 * b.norm() * dense.norm()) << "kl " << kl << " ku " << ku;
    }
  }
}

TEST(BandedLu, ZeroDiagonalNeedsAndGetsPivoting) {
  // [[0, 1], [1, 0]]: without a row interchange the first pivot is zero.
  BandedLu banded;
  banded.resize(2, 1, 1);
  banded.at(0, 1) = 1.0;
  banded.at(1, 0) = 1.0;
  ASSERT_TRUE(banded.factorize());
  Eigen::VectorXd x(2);
  x << 3.0, 5.0;
  banded.solve(x);
  EXPECT_DOUBLE_EQ(x[0], 5.0);
  EXPECT_DOUBLE_EQ(x[1], 3.0);
}

TEST(BandedLu, ReportsASingularMatrix) {
  // Two equal rows in a tridiagonal matrix.
  BandedLu banded;
  banded.resize(3, 1, 1);
  banded.at(0, 0) = 1.0;
  banded.at(0, 1) = 2.0;
  banded.at(1, 0) = 1.0;
  banded.at(1, 1) = 2.0;
  banded.at(2, 2) = 1.0;
  EXPECT_FALSE(banded.factorize());
}

}  // namespace
}  // namespace maris
