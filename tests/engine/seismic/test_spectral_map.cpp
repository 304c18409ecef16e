// The spectral-ratio map H_a(x, f) (seismic_spectral_map.cpp) on a model with a closed-form answer:
// the box without water is a homogeneous half-space, whose surface moves with frequency-independent
// amplitudes (Aki & Richards free surface, checked against an independent reference computation). With the reference
// motion twice the incident one, H_a,x = |u_x|/2 and H_a,y = |u_y|/2 at every station and frequency.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "catalog.hpp"
#include "core/results.hpp"
#include "core/run_context.hpp"

namespace maris {
namespace {

TEST(SpectralMap, HalfSpaceMapEqualsTheFreeSurfaceAmplitudes) {
  // P at 45° on the verification seabed (vp 4500, vs 1800): |u_x| = 0.968349, |u_y| = 1.499140 (§5.3).
  // Ricker 1.5 Hz on a 6 Hz mesh (Δ = 30 m, ≥ 10 cells per S wavelength in the input band, which the
  // map keeps to where the input spectrum exceeds 5 % of its peak). Tolerance 3 %: the dispersion of
  // the discrete waves and the local absorbing boundaries' residual reflections (FE box tests B4).
  auto prm = findBuiltin("seismic_verification_box")->scenario.parameters;
  prm["model"]["include_water"] = false;
  prm["incidence"]["angle_deg"] = 45.0;
  prm["input"]["kind"] = "ricker";
  prm["input"]["ricker_peak_frequency"] = 1.5;
  prm["solver"]["cutoff_frequency"] = 6.0;
  prm["solver"]["duration"] = 4.0;
  prm["output"]["snapshot_count"] = 0;
  prm["output"]["station_count"] = 9;
  const auto& scene = requireScene("seismic");
  ASSERT_TRUE(validateParameters(scene, prm).empty());
  RunContext ctx;
  const Results r = scene.run(prm, ctx);
  const Table* map = r.findTable("spectral_ratio_map");
  ASSERT_NE(map, nullptr);
  const auto& f = map->find("frequency")->values;
  const auto& hx = map->find("H_ax")->values;
  const auto& hy = map->find("H_ay")->values;
  ASSERT_GE(map->rows(), 9u * 10u);  // 9 stations × at least 10 frequencies of the input band
  double worst_x = 0.0, worst_y = 0.0, f_lo = 1e9, f_hi = 0.0;
  for (std::size_t k = 0; k < map->rows(); ++k) {
    worst_x = std::max(worst_x, std::abs(hx[k] / (0.968349 / 2.0) - 1.0));
    worst_y = std::max(worst_y, std::abs(hy[k] / (1.499140 / 2.0) - 1.0));
    f_lo = std::min(f_lo, f[k]);
    f_hi = std::max(f_hi, f[k]);
  }
  std::printf("[ measured ] band %.2f-%.2f Hz: largest relative error H_ax %.4f, H_ay %.4f\n", f_lo, f_hi, worst_x,
              worst_y);
  EXPECT_LT(worst_x, 0.03);
  EXPECT_LT(worst_y, 0.03);
  // The line table holds the five chosen points over the same frequencies.
  const Table* lines = r.findTable("spectral_ratio_lines");
  ASSERT_NE(lines, nullptr);
  EXPECT_EQ(lines->columns.size(), 11u);
  EXPECT_EQ(lines->rows() * 9, map->rows());
}

}  // namespace
}  // namespace maris
