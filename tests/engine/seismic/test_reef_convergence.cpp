// Mesh convergence of the reef-flat amplification: halving Δ changes the
// peak ratios along the flat by < 2 %.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "fe_test_support.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {
namespace {

using testing::maxOf, testing::meanOf;

TEST(ReefConvergence, HalvingTheElementSizeChangesTheFlatAmplificationByLessThanTwoPercent) {
  // Placeholder reef with water, Ricker 0.5 Hz P at 30° (content up to ≈ 1.3 Hz: ≥ 12 cells per
  // S wavelength in the 800 m/s top layer on the coarse mesh). Meshes Δ = 50 m and 25 m, both with
  // every layer interface on a grid line (the flanks stay staircases, an O(Δ) geometry error).
  // Target: the largest and the mean R_u, R_a (x and y) along the flat change by < 2 %.
  SeismicParameters p;
  p.wave_type = "P";
  p.angle_deg = 30.0;
  p.ricker_peak_frequency = 0.5;
  p.duration = 5.0;
  p.station_count = 21;
  RunContext ctx;
  std::vector<PeakRatios> r;
  for (double f_cut : {1.6, 3.2}) {
    p.cutoff_frequency = f_cut;
    const FeCase c = runFeCase(p, p.angle_deg, true, false, ctx);
    ASSERT_NEAR(c.element_size, 80.0 / f_cut, 1e-9);
    r.push_back(amplificationRatios(c));
  }
  const char* names[4] = {"R_ux", "R_uy", "R_ax", "R_ay"};
  for (int q = 0; q < 4; ++q) {
    const auto& coarse = q == 0 ? r[0].ux : q == 1 ? r[0].uy : q == 2 ? r[0].ax : r[0].ay;
    const auto& fine = q == 0 ? r[1].ux : q == 1 ? r[1].uy : q == 2 ? r[1].ax : r[1].ay;
    const double change_max = maxOf(coarse) / maxOf(fine) - 1.0, change_mean = meanOf(coarse) / meanOf(fine) - 1.0;
    RecordProperty(std::string("change_max_") + names[q], std::to_string(change_max));
    EXPECT_LT(std::abs(change_max), 0.02) << "largest " << names[q];
    EXPECT_LT(std::abs(change_mean), 0.02) << "mean " << names[q];
  }
}

}  // namespace
}  // namespace maris::seismic
