// The calibrated model (built-in scenario fiv_calibrated) against the numbers printed in the paper's
// text, with tolerances for a reduced-order model against 2D CFD (15–20 % on amplitude and power, 10 % on
// frequency). Only the
// features the model reproduces are asserted here; the ones it misses are listed with their
// residuals in docs/fiv.md (the low-speed VIV point C4, the lift alternations, the η peak location).
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
    applyOverride(s, "sweep.speed_min=1.0");  // 1.0, 1.1, …, 2.5 m/s; each up-sweep point from rest
    applyOverride(s, "sweep.speed_count=16");
    applyOverride(s, "sweep.sweep_down=false");
    RunContext ctx;
    return runScenario(requireScene("fiv"), s, ctx);
  }();
  return results;
}

double lastRow(const std::string& column) {
  return calibratedSweep().findTable("sweep")->find(column)->values.back();
}

TEST(FivPaper, AmplitudeAtTopSpeedMatchesThePaperWithinFifteenPercentForFiniteSubmergence) {
  // Paper §5.3.1: at 2.5 m/s A* = 3.03 (h* = 1.11), 3.12 (2.22), ≈ 3.45 (3.33, 5.56); ± 15 %.
  // (h* = ∞, +11 % with the current fit, is not asserted; see docs/fiv.md.)
  const std::pair<double, double> cases[] = {{1.11, 3.03}, {2.22, 3.12}, {3.33, 3.45}, {5.56, 3.45}};
  for (const auto& [h_star, a_star] : cases)
    EXPECT_NEAR(lastRow("A_star_up_" + submergenceLabel(h_star)) / a_star, 1.0, 0.15) << "h* = " << h_star;
}

TEST(FivPaper, PowerAtTopSpeedMatchesThePaperWithinTwentyPercent) {
  // Paper §5.4: P_max(2.5 m/s) = 15.4, 16.8, 17.7, 18.3, 17.9 W for h* = 1.11 … ∞; ± 20 %.
  const std::pair<double, double> cases[] = {{1.11, 15.4}, {2.22, 16.8}, {3.33, 17.7}, {5.56, 18.3}, {kDeep, 17.9}};
  for (const auto& [h_star, power] : cases)
    EXPECT_NEAR(lastRow("P_up_" + submergenceLabel(h_star)) / power, 1.0, 0.20) << "h* = " << h_star;
}

TEST(FivPaper, PowerAtTopSpeedRisesWithSubmergenceAndSaturatesFromHStar5_56) {
  // Paper §5.4 ordering 15.4 < 16.8 < 17.7 ≤ 18.3 ≈ 17.9 W (the ordering,
  // |P(5.56)/P(∞) − 1| < 5 % and P(1.11)/P(∞) = 0.86 ± 0.05).
  const double p111 = lastRow("P_up_h1.11"), p222 = lastRow("P_up_h2.22"), p333 = lastRow("P_up_h3.33");
  const double p556 = lastRow("P_up_h5.56"), pinf = lastRow("P_up_hinf");
  EXPECT_LT(p111, p222);
  EXPECT_LT(p222, p333);
  EXPECT_LE(p333, p556 * 1.01);  // "≤" up to the 1e-3 convergence noise of both cycles
  EXPECT_NEAR(p556 / pinf, 1.0, 0.05);
  EXPECT_NEAR(p111 / pinf, 0.86, 0.05);
}

TEST(FivPaper, GallopingFrequenciesOfCasesC3AndC5WithinTenPercent) {
  // Paper §5.1: f1 = 0.53711 Hz (C3, h* = 1.11) and 0.48828 Hz (C5, h* = 5.56) at 2.2 m/s; ± 10 %.
  const Table* t = calibratedSweep().findTable("sweep");
  const double f_n = calibratedSweep().findScalar("natural_frequency_water")->value;
  const auto& u = t->find("U")->values;
  std::size_t i = 0;
  while (std::abs(u[i] - 2.2) > 1e-9) ++i;
  EXPECT_NEAR(t->find("f_star_up_h1.11")->values[i] * f_n / 0.53711, 1.0, 0.10);
  EXPECT_NEAR(t->find("f_star_up_h5.56")->values[i] * f_n / 0.48828, 1.0, 0.10);
}

TEST(FivPaper, GallopingOnsetDoesNotComeEarlierCloserToTheSurface) {
  // Paper conclusion 3: decreasing h* delays galloping (onset(1.11) ≥ … ≥ onset(∞)).
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
