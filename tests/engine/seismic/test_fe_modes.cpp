// Modal analysis of the solid FE model (fe_modes): closed-form column frequencies, and identities.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "fe_test_support.hpp"
#include "seismic/fe_modes.hpp"

namespace maris::seismic {
namespace {

// Periodic soil column of height H on a clamped base: 1D shear modes f_n = (2n−1)v_s/(4H) and
// compression modes f_n = (2n−1)v_p/(4H) (Kramer, Geotechnical Earthquake Engineering, §7.2).
FeModel clampedColumn(double height, double delta) {
  auto p = testing::boxParameters(false, 1800.0 / (10.0 * delta), 10.0, height);
  FeMesh mesh = buildMesh(p, false);
  mesh.periodic_x = true;
  return buildFeModel(mesh);
}

TEST(FeModes, ClampedColumnMatchesQuarterWaveFrequencies) {
  // H = 600 m, Δ = 15 m (40 cells). A laterally uniform mode of bilinear squares with lumped mass is
  // the 1D lumped chain, whose frequencies are exactly (2c/Δ)·sin(kΔ/2)/(2π) with k = (2n−1)π/(2H):
  // checked to 1e-9 (round-off of the Lanczos solve, converged to 1e-10). Against the continuum the
  // difference is the dispersion ≈ (kΔ)²/24 (≤ 0.32 % here).
  const double h = 600.0, vs = 1800.0, vp = 4500.0, delta = 15.0;
  const FeModel model = clampedColumn(h, delta);
  ASSERT_NEAR(model.mesh.delta, delta, 1e-9);
  RunContext ctx;
  const ModalResult r = computeSolidModes(model, 6, true, ctx);
  ASSERT_EQ(r.modes.size(), 6u);
  struct Expected {
    double speed;
    int n;
  };
  // Ascending: shear 0.75, P 1.875, shear 2.25, 3.75, 5.25, P 5.625 Hz.
  const Expected expected[6] = {{vs, 1}, {vp, 1}, {vs, 2}, {vs, 3}, {vs, 4}, {vp, 2}};
  for (std::size_t m = 0; m < 6; ++m) {
    const double k = (2 * expected[m].n - 1) * std::numbers::pi / (2 * h);
    const double continuum = expected[m].speed * k / (2 * std::numbers::pi);
    const double discrete = 2 * expected[m].speed / delta * std::sin(k * delta / 2) / (2 * std::numbers::pi);
    EXPECT_NEAR(r.modes[m].frequency / discrete, 1.0, 1e-9) << "mode " << m + 1;
    EXPECT_NEAR(r.modes[m].frequency / continuum, 1.0, std::pow(k * delta, 2) / 24 * 1.05) << "mode " << m + 1;
    EXPECT_LT(r.modes[m].residual, 1e-8) << "mode " << m + 1;
    // Shear modes move horizontally only, compression modes vertically only (decoupled in 1D).
    EXPECT_NEAR(r.modes[m].horizontal_share, expected[m].speed == vs ? 1.0 : 0.0, 1e-9) << "mode " << m + 1;
  }
  // Effective mass of the first shear mode of a uniform clamped column: 8/π² of the total (closed
  // form, continuum); the lumped chain differs by O(1/N²) = 1e-3 for 40 cells.
  EXPECT_NEAR(r.modes[0].mass_ratio_x, 8.0 / (std::numbers::pi * std::numbers::pi), 2e-3);
}

TEST(FeModes, UnsupportedSolidIsASolverError) {
  // A periodic column without base and without springs has rigid-body motion: K is singular.
  FeModel model = clampedColumn(300.0, 15.0);
  std::fill(model.spring_x.begin(), model.spring_x.end(), 0.0);
  std::fill(model.spring_y.begin(), model.spring_y.end(), 0.0);
  RunContext ctx;
  EXPECT_THROW(computeSolidModes(model, 3, false, ctx), SolverError);
}

}  // namespace
}  // namespace maris::seismic
