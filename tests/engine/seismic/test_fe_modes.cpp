// Modal analysis of the solid FE model (fe_modes): closed-form column frequencies, and identities.
#include <cmath>
#include <cstdio>
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

namespace maris::seismic {
namespace {

// g(f) = Z_s cos(ωH/c_p) cos(ωh/c_f) − Z_f sin(ωH/c_p) sin(ωh/c_f): zero at the vertical modes of a
// clamped solid layer (H, c_p, Z_s = ρ_s c_p) under a water layer (h, c_f, Z_f = ρ_f c_f) with a
// pressure-release surface, from u and σ_yy = −p continuous at the seabed: Z_s cot(ωH/c_p) = Z_f tan(ωh/c_f).
double waterColumnCharacteristic(double f, double h_solid, double h_water) {
  const double w = 2.0 * std::numbers::pi * f;
  const double zs = 2700.0 * 4500.0, zf = 1025.0 * 1450.0;
  return zs * std::cos(w * h_solid / 4500.0) * std::cos(w * h_water / 1450.0) -
         zf * std::sin(w * h_solid / 4500.0) * std::sin(w * h_water / 1450.0);
}

TEST(FeModes, CoupledWaterColumnMatchesTheImpedanceFrequencyEquation) {
  // Periodic column: 600 m of seabed (vp 4500, vs 1800, 2700 kg/m³) clamped at the base, under 600 m of
  // water, Δ = 15 m. Expected: shear modes (2n−1)v_s/(4H) (the water is not driven: water share 0)
  // and the roots of the coupled frequency equation, found here by bisection (0.579, 1.617, 2.063,
  // 3.051, 4.21 Hz). Tolerance 0.5 %: the lumped chains' dispersion ≈ (kΔ)²/24 ≤ 0.2 % below 4.3 Hz.
  auto p = testing::boxParameters(true, 1450.0 / (10.0 * 15.0), 10.0, 600.0);
  FeMesh mesh = buildMesh(p, true);
  mesh.periodic_x = true;
  const FeModel model = buildFeModel(mesh);
  ASSERT_NEAR(model.mesh.delta, 15.0, 1e-9);
  std::vector<double> coupled;
  for (double f = 0.01; f < 4.5; f += 0.01) {
    double a = f, b = f + 0.01;
    if (waterColumnCharacteristic(a, 600.0, 600.0) * waterColumnCharacteristic(b, 600.0, 600.0) > 0.0) continue;
    for (int it = 0; it < 60; ++it) {
      const double c = 0.5 * (a + b);
      (waterColumnCharacteristic(a, 600.0, 600.0) * waterColumnCharacteristic(c, 600.0, 600.0) <= 0.0 ? b : a) = c;
    }
    coupled.push_back(0.5 * (a + b));
  }
  ASSERT_EQ(coupled.size(), 5u);
  const std::vector<double> shear{0.75, 2.25, 3.75};
  RunContext ctx;
  const ModalResult r = computeCoupledModes(model, 8, true, ctx);
  ASSERT_EQ(r.modes.size(), 8u);
  std::size_t next_shear = 0, next_coupled = 0;
  for (const SolidMode& m : r.modes) {
    EXPECT_LT(m.residual, 1e-8) << m.frequency;
    const bool is_shear = m.horizontal_share > 0.5;
    const double expected = is_shear ? shear.at(next_shear++) : coupled.at(next_coupled++);
    EXPECT_NEAR(m.frequency / expected, 1.0, 5e-3) << (is_shear ? "shear " : "coupled ") << expected;
    if (is_shear) EXPECT_LT(m.water_share, 1e-9);
    else EXPECT_GT(m.water_share, 1e-3);
    std::printf("[ measured ] %s mode %.4f Hz (expected %.4f), water share %.3f, residual %.1e\n",
                is_shear ? "shear  " : "coupled", m.frequency, expected, m.water_share, m.residual);
  }
  EXPECT_EQ(next_shear, 3u);
  EXPECT_EQ(next_coupled, 5u);
}

}  // namespace
}  // namespace maris::seismic
