// Michell wave resistance of the Wigley hull: closed-form Kochin path vs the published anchor, the offsets
// (grid) path vs the closed form, grid convergence order, and the hard cases Fn = 0.05 and Fn = 2.
#include <gtest/gtest.h>

#include <cmath>

#include "ship/hull_form.hpp"
#include "ship/michell_resistance.hpp"
#include "michell_test_water.hpp"

using namespace maris::ship;

namespace {

constexpr double kL = 1.0, kB = 0.1, kT = 0.0625;  // [m] B/L = 0.1, T/L = 0.0625
using maris::ship::test_data::kG, maris::ship::test_data::kRho;
constexpr double kWettedSurface = 0.1487906;       // [m²] S/L² of the Wigley hull (exact surface integral)

double speedAt(double fn) { return fn * std::sqrt(kG * kL); }
double waveCoefficient(const WaveResistance& r, double fn) {
  const double U = speedAt(fn);
  return r.resistance / (0.5 * kRho * U * U * kWettedSurface);
}

WaveResistance exactWigley(double fn, double rtol) {
  WigleyKochin k(kL, kB, kT);
  MichellSettings s;
  s.relative_tolerance = rtol;
  return michellWaveResistance(k, speedAt(fn), kG, kRho, s);
}

WaveResistance gridWigley(double fn, int nx, int nz, double rtol = 1e-5) {
  GridKochin k(sampleHull(makeParametricHull(kL, kB, kT), nx, nz));
  MichellSettings s;
  s.relative_tolerance = rtol;
  return michellWaveResistance(k, speedAt(fn), kG, kRho, s);
}

}  // namespace

TEST(MichellWigley, ClosedFormMatchesDoctorsAndBeckAnchor) {
  // Doctors & Beck (1987), J. Ship Res. 31(1), Table 1 (quoted by risingtideresearch/michell): 10³C_W = 1.2486
  // at Fn = 0.35, tolerance 0.5 %. The high-precision value 1.247922 (6 digits) of an independent long-double
  // implementation of the theory (outside this repository) is
  // checked at 1e-6 relative: our quadrature at rtol 1e-9 must reproduce the theory, not just the anchor.
  const WaveResistance r = exactWigley(0.35, 1e-9);
  const double cw = 1e3 * waveCoefficient(r, 0.35);
  EXPECT_NEAR(cw, 1.2486, 0.005 * 1.2486);
  EXPECT_NEAR(cw, 1.247922, 1e-6 * 1.247922 + 5e-7);
}

TEST(MichellWigley, OffsetsPathMatchesClosedFormWithinTenthOfPercent) {
  // Target: 0.1 % for 0.15 <= Fn <= 1 on a 251×51-class grid (257×51 here).
  for (double fn : {0.15, 0.2, 0.25, 0.3, 0.35, 0.42, 0.5, 0.7, 1.0}) {
    const double exact = exactWigley(fn, 1e-8).resistance;
    const WaveResistance grid = gridWigley(fn, 257, 51);
    EXPECT_NEAR(grid.resistance, exact, 1e-3 * exact) << "Fn " << fn;
    // The reported error estimate bounds the true error (it includes the Richardson grid estimate).
    EXPECT_LE(std::abs(grid.resistance - exact), grid.error_estimate) << "Fn " << fn;
  }
}

TEST(MichellWigley, GridErrorConvergesAtSecondOrder) {
  // Second order: the error ratio between successive halvings of (dx, dz) lies in [3, 5].
  const double fn = 0.35, exact = exactWigley(fn, 1e-10).resistance;
  const double e1 = std::abs(gridWigley(fn, 65, 13, 1e-9).resistance - exact);
  const double e2 = std::abs(gridWigley(fn, 129, 25, 1e-9).resistance - exact);
  const double e3 = std::abs(gridWigley(fn, 257, 49, 1e-9).resistance - exact);
  EXPECT_GE(e1 / e2, 3.0);
  EXPECT_LE(e1 / e2, 5.0);
  EXPECT_GE(e2 / e3, 3.0);
  EXPECT_LE(e2 / e3, 5.0);
}

TEST(MichellWigley, ErrorEstimateBoundsTheErrorAtFroudeZeroPointZeroFive) {
  // Hard case: at Fn = 0.05 bow and stern waves nearly cancel (C_W is 200× smaller than at Fn 0.35) and
  // the integrand oscillates with period 2π Fn² = 0.016 in λ. Requested 1e-4: the closed-form result at
  // 1e-4 must lie within its own estimate of the 1e-10 result, and so must the grid path.
  const double fn = 0.05;
  const WaveResistance reference = exactWigley(fn, 1e-10);
  const WaveResistance loose = exactWigley(fn, 1e-4);
  EXPECT_LE(std::abs(loose.resistance - reference.resistance), loose.error_estimate);
  EXPECT_LE(loose.error_estimate, 1e-4 * loose.resistance);
  const WaveResistance grid = gridWigley(fn, 257, 51, 1e-4);
  EXPECT_LE(std::abs(grid.resistance - reference.resistance), grid.error_estimate);
  EXPECT_LE(std::abs(grid.resistance - reference.resistance), 1e-3 * reference.resistance);
}

TEST(MichellWigley, TailEstimateHoldsAtFroudeTwo) {
  // Hard case: at Fn = 2 the depth decay e^{k0 λ² z} sets in only beyond λ ≈ 20, the integrand decays as
  // λ^-5 afterwards and the tail beyond λ_max carries a visible share. The estimate (tail included) must
  // bound the error against the rtol 1e-10 result.
  const double fn = 2.0;
  const WaveResistance reference = exactWigley(fn, 1e-10);
  const WaveResistance loose = exactWigley(fn, 1e-3);
  EXPECT_GT(loose.tail_exponent, 4.0);  // algebraic decay, near the asymptotic λ^-5 of a finite entrance angle
  EXPECT_GT(loose.tail, 0.0);
  EXPECT_LE(std::abs(loose.resistance - reference.resistance), loose.error_estimate);
  const WaveResistance grid = gridWigley(fn, 257, 51, 1e-4);
  EXPECT_LE(std::abs(grid.resistance - reference.resistance), grid.error_estimate);
}

TEST(MichellWigley, ShortWaveCutoffReproducesIndependentTable) {
  // Independent implementation's table (Wigley 101×21, λ ∈ [1, 2] kept): 10³C_W at Fn 0.35 is 1.2466 without the
  // cut and 1.1587 / 1.2265 / 1.2432 with r = 0.10 / 0.05 / 0.02. Four printed digits: 1e-3 relative.
  const double fn = 0.35, U = speedAt(fn);
  const std::pair<double, double> rows[] = {{0.0, 1.2466}, {0.10, 1.1587}, {0.05, 1.2265}, {0.02, 1.2432}};
  for (const auto& [r_cut, expected] : rows) {
    GridKochin k(sampleHull(makeParametricHull(kL, kB, kT), 101, 21), false);
    MichellSettings s;
    s.relative_tolerance = 1e-7;
    s.short_wave_cutoff = r_cut;
    s.cutoff_length = kL;
    const double cw = 1e3 * michellWaveResistance(k, U, kG, kRho, s).resistance / (0.5 * kRho * U * U * kWettedSurface);
    EXPECT_NEAR(cw, expected, 1e-3 * expected) << "r_cut " << r_cut;
  }
}
