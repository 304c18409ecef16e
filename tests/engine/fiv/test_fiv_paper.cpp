// The calibrated model (built-in scenario fiv_calibrated) against the numbers printed in the paper's
// text, with the research brief's tolerances (§6 E: digitising and reduced-order fidelity). Only the
// features the model reproduces are asserted here; the ones it misses are listed with their
// residuals in docs/fiv.md (power level −23…−33 %, A* at h* = 1.11 −22 %, the η peak location).
#include <gtest/gtest.h>

#include <cmath>

#include "catalog.hpp"
#include "fiv/fiv_model.hpp"
#include "fiv/fiv_reference.hpp"

namespace maris::fiv {
namespace {

const Results& calibratedSweep() {
  static const Results results = [] {
    Scenario s = findBuiltin("fiv_calibrated")->scenario;
    applyOverride(s, "sweep.speed_count=24");  // 0.2, 0.3, …, 2.5 m/s; each up-sweep point from rest
    applyOverride(s, "sweep.sweep_down=false");
    RunContext ctx;
    return runScenario(requireScene("fiv"), s, ctx);
  }();
  return results;
}

double lastRow(const std::string& column) {
  return calibratedSweep().findTable("sweep")->find(column)->values.back();
}

TEST(FivPaper, AmplitudeAtTopSpeedMatchesThePaperWithinFifteenPercentForHStarAtLeast2_22) {
  // Paper §5.3.1: at 2.5 m/s A* = 3.12 (h* = 2.22) and ≈ 3.45 for the deep cases; brief T16/T18 ± 15 %.
  const std::pair<double, double> cases[] = {{2.22, 3.12}, {3.33, 3.45}, {5.56, 3.45}, {kDeep, 3.45}};
  for (const auto& [h_star, a_star] : cases)
    EXPECT_NEAR(lastRow("A_star_up_" + submergenceLabel(h_star)) / a_star, 1.0, 0.15) << "h* = " << h_star;
}

TEST(FivPaper, PowerAtTopSpeedRisesWithSubmergenceAndSaturatesFromHStar5_56) {
  // Paper §5.4: P_max(2.5 m/s) = 15.4 < 16.8 < 17.7 ≤ 18.3 ≈ 17.9 W for h* = 1.11 … ∞ (brief T19:
  // the ordering, and |P(5.56)/P(∞) − 1| < 5 %).
  const double p111 = lastRow("P_up_h1.11"), p222 = lastRow("P_up_h2.22"), p333 = lastRow("P_up_h3.33");
  const double p556 = lastRow("P_up_h5.56"), pinf = lastRow("P_up_hinf");
  EXPECT_LT(p111, p222);
  EXPECT_LT(p222, p333);
  EXPECT_LE(p333, p556 * 1.01);  // "≤" up to the 1e-3 convergence noise of both cycles
  EXPECT_NEAR(p556 / pinf, 1.0, 0.05);
}

TEST(FivPaper, GallopingOnsetDoesNotComeEarlierCloserToTheSurface) {
  // Paper conclusion 3: decreasing h* delays galloping (brief T20: onset(1.11) ≥ … ≥ onset(∞)).
  const Results& r = calibratedSweep();
  double previous = 1e9;
  for (double h_star : {1.11, 2.22, 3.33, 5.56, kDeep}) {
    const Scalar* onset = r.findScalar("galloping_onset_speed_" + submergenceLabel(h_star));
    ASSERT_NE(onset, nullptr) << h_star;
    EXPECT_LE(onset->value, previous + 1e-9) << "h* = " << h_star;
    previous = onset->value;
  }
}

}  // namespace
}  // namespace maris::fiv
