// Exact properties of the uncorrected Michell integral and the transom end terms.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "ship/hull_form.hpp"
#include "ship/michell_quadrature.hpp"
#include "ship/michell_resistance.hpp"
#include "michell_test_water.hpp"

using namespace maris::ship;

namespace {

using maris::ship::test_data::kG, maris::ship::test_data::kRho;

WaveResistance onGrid(const HullGrid& grid, double speed, double rtol = 1e-6) {
  GridKochin k(grid, false);
  MichellSettings s;
  s.relative_tolerance = rtol;
  return michellWaveResistance(k, speed, kG, kRho, s);
}

// A hull that is not symmetric fore and aft, so the reversal test can fail: parametric p = 3, cut by a
// linear factor (fuller aft).
HullGrid asymmetricGrid(double scale) {
  HullGrid g = sampleHull(makeParametricHull(2.0 * scale, 0.25 * scale, 0.12 * scale, 3.0, 2.5), 129, 25);
  for (int i = 0; i < g.nx(); ++i) g.half_breadth.row(i) *= 1.3 - 0.6 * i / (g.nx() - 1.0);
  return g;
}

}  // namespace

TEST(MichellProperties, WaveCoefficientIsInvariantUnderFroudeScaling) {
  // Scaling every length by s at fixed Fn: R_W ∝ s³ (C_W unchanged). The λ quadrature is the same in
  // scaled variables up to its tolerance (1e-8 requested), so compare at 1e-7.
  const double fn = 0.3;
  const double r1 = onGrid(asymmetricGrid(1.0), fn * std::sqrt(kG * 2.0), 1e-9).resistance;
  const double r3 = onGrid(asymmetricGrid(3.0), fn * std::sqrt(kG * 6.0), 1e-9).resistance;
  EXPECT_NEAR(r3 / r1, 27.0, 27.0 * 1e-7);
}

TEST(MichellProperties, ResistanceIsQuadraticInBeam) {
  // Michell's integral is quadratic in Y: B → 1.7 B multiplies R_W by 1.7² (round-off only, 1e-12).
  HullGrid g = asymmetricGrid(1.0);
  const double U = 0.4 * std::sqrt(kG * 2.0);
  // The λ panels depend only on L, T and U, so both runs use identical nodes: the ratio is exact.
  const double r1 = onGrid(g, U).resistance;
  g.half_breadth *= 1.7;
  const double r2 = onGrid(g, U).resistance;
  EXPECT_NEAR(r2 / r1, 1.7 * 1.7, 1e-9);
}

TEST(MichellProperties, DoublingTheHullQuadruplesResistance) {
  // A coincident duplicate hull (twice the source strength) gives 4 R_W.
  HullGrid g = asymmetricGrid(1.0);
  const double U = 0.25 * std::sqrt(kG * 2.0);
  const double r1 = onGrid(g, U).resistance;
  g.half_breadth *= 2.0;
  EXPECT_NEAR(onGrid(g, U).resistance / r1, 4.0, 4e-9);
}

TEST(MichellProperties, ReversingBowAndSternLeavesResistanceUnchanged) {
  // Y(x, z) → Y(L − x, z) conjugates P + iQ (up to a phase), so |P + iQ|² and R_W are unchanged.
  const HullGrid g = asymmetricGrid(1.0);
  for (double fn : {0.18, 0.3, 0.5}) {
    const double U = fn * std::sqrt(kG * 2.0);
    const double forward = onGrid(g, U).resistance;
    const double reversed = onGrid(g.reversed(), U).resistance;
    EXPECT_NEAR(reversed / forward, 1.0, 1e-10) << "Fn " << fn;
  }
  // And the hull really is asymmetric: a different hull (mirrored section only) changes R_W.
  HullGrid other = g;
  other.half_breadth.row(g.nx() / 2) *= 1.05;
  EXPECT_GT(std::abs(onGrid(other, 0.3 * std::sqrt(kG * 2.0)).resistance / onGrid(g, 0.3 * std::sqrt(kG * 2.0)).resistance - 1.0), 1e-6);
}

TEST(MichellProperties, TransomEndTermMatchesTruncatedWigleyClosedForm) {
  // Hard case: a Wigley hull cut square at x_t = −0.3 L/2 (a transom: Y ≠ 0 at the aft end). The Kochin
  // function over the remaining hull is ∫_{x_t}^{L/2} Y_x e^{iκξ} dξ · Z(b) with Y_x = −(4B ξ/L²), ξ from
  // mid-length, i.e. X = −(4B/L²) [e^{iκξ}(ξ/(iκ) + 1/κ²)]_{x_t}^{L/2} in closed form. The grid path carries
  // the transom through the end term of its integration by parts; 257×51 grid: 0.1 % (as for the Wigley).
  const double L = 1.0, B = 0.1, T = 0.0625, xt = -0.3 * L / 2.0;
  HullGrid g;
  const int nx = 257, nz = 51;
  g.x_aft = xt;
  g.dx = (L / 2.0 - xt) / (nx - 1);
  g.dz = T / (nz - 1);
  g.half_breadth.resize(nx, nz);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nz; ++j) {
      const double xi = g.x(i), z = g.z(j);
      g.half_breadth(i, j) = 0.5 * B * (1 - 4 * xi * xi / (L * L)) * (1 - z * z / (T * T));
    }
  GridKochin kochin(g, false);
  const double fn = 0.3, k0 = 1.0 / (fn * fn * L);
  const std::complex<double> I(0, 1);
  for (double lambda : {1.0, 1.4, 3.0, 8.0}) {
    const double kappa = k0 * lambda;
    auto antiderivative = [&](double x) { return std::exp(I * kappa * x) * (x / (I * kappa) + 1.0 / (kappa * kappa)); };
    const std::complex<double> X = -(4.0 * B / (L * L)) * (antiderivative(L / 2.0) - antiderivative(xt));
    const double Z = std::abs(wigleyDepthFactor(T, k0 * lambda * lambda));
    const double exact = std::norm(X) * Z * Z;
    double fine = 0, coarse = 0;
    kochin.evaluate(k0, lambda, fine, coarse);
    EXPECT_NEAR(fine, exact, 1e-3 * exact) << "lambda " << lambda;
  }
}
