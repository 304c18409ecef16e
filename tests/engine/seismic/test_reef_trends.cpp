// Paper-trend checks on the PLACEHOLDER reef (assumed layers, see docs/seismic.md), Ricker 1 Hz input,
// Δ = 25 m. The paper's reef (Table 1) is unknown, so these are smoke checks of the qualitative
// findings that the placeholder does reproduce; the ones it does not reproduce are listed in
// docs/seismic.md ("Paper trends"), not asserted here.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "fe_test_support.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {
namespace {

using testing::maxOf, testing::meanOf;

PeakRatios reefRatios(const std::string& wave, double angle_deg) {
  SeismicParameters p;  // placeholder reef with water
  p.wave_type = wave;
  p.ricker_peak_frequency = 1.0;
  p.cutoff_frequency = 3.2;  // Δ = 25 m, every layer interface on a grid line
  p.duration = 5.0;
  p.station_count = 21;
  RunContext ctx;
  return amplificationRatios(runFeCase(p, angle_deg, true, false, ctx));
}

TEST(ReefTrends, ObliquePAmplifiesHorizontalMostAtModerateAnglesAndVerticalLessWithAngle) {
  // Paper §4.2: the largest horizontal R_a along the flat peaks at an intermediate angle
  // (paper: 30°) and the vertical response decreases with θ (vertical incidence is the worst case).
  // Measured (placeholder): max R_a,x 1.65, 1.76, 1.71, 1.23 at 0, 30, 60, 75°; mean R_a,y 1.77, 1.63,
  // 1.18, 0.76. The 30°-vs-60° margin is 3 %, larger than the 0.4 % mesh change measured in B10.
  const double angles[4] = {0.0, 30.0, 60.0, 75.0};
  std::vector<PeakRatios> r;
  for (double a : angles) r.push_back(reefRatios("P", a));
  EXPECT_GT(maxOf(r[1].ax), maxOf(r[0].ax));
  EXPECT_GT(maxOf(r[1].ax), maxOf(r[2].ax));
  EXPECT_GT(maxOf(r[1].ax), maxOf(r[3].ax));
  for (int k = 0; k + 1 < 4; ++k) EXPECT_GT(meanOf(r[k].ay), meanOf(r[k + 1].ay)) << angles[k] << "° vs " << angles[k + 1] << "°";
}

TEST(ReefTrends, VerticalSvAmplifiesTheWholeFlatHorizontally) {
  // Paper §5.2: under SV the horizontal response exceeds the reference (R_x > 1) on almost
  // all of the flat (asserted: ≥ 90 % of the stations), the mean horizontal R_a decreases from 0° to
  // 25°, and the vertical R_a stays about 0.5–1 (asserted: mean in [0.5, 1]).
  const PeakRatios vertical = reefRatios("SV", 0.0), oblique = reefRatios("SV", 25.0);
  const auto above_one = std::count_if(vertical.ax.begin(), vertical.ax.end(), [](double x) { return x > 1.0; });
  EXPECT_GE(above_one, static_cast<long>(0.9 * vertical.ax.size()));
  EXPECT_GT(meanOf(vertical.ax), meanOf(oblique.ax));
  EXPECT_GE(meanOf(vertical.ay), 0.5);
  EXPECT_LE(meanOf(vertical.ay), 1.0);
}

}  // namespace
}  // namespace maris::seismic
