// Rainflow counting against ASTM E1049-85's worked example, constant-amplitude histories, the DNVGL-RP-C203
// (2016) tables' own fatigue-limit column, the thickness correction and Miner damage against the S–N formula.
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include <gtest/gtest.h>

#include "core/fatigue.hpp"

namespace maris::fatigue {
namespace {

std::map<double, double> countsByRange(const std::vector<Cycle>& cycles) {
  std::map<double, double> counts;
  for (const auto& c : cycles) counts[c.range] += c.count;
  return counts;
}

TEST(Fatigue, RainflowGivesTheAstmE1049ExampleCounts) {
  // ASTM E1049-85 (2017), Fig. 6 and §5.4.4.3: the history −2, 1, −3, 5, −1, 3, −4, 4, −2 gives
  // range 3: ½, 4: 1½, 6: ½, 8: 1, 9: ½ cycles.
  const std::vector<Cycle> cycles = rainflow({-2, 1, -3, 5, -1, 3, -4, 4, -2});
  const std::map<double, double> expected{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(countsByRange(cycles), expected);
  // The one closed cycle is E–F (−1 → 3): mean 1.
  int closed = 0;
  for (const auto& c : cycles)
    if (c.count == 1.0) {
      ++closed;
      EXPECT_EQ(c.range, 4.0);
      EXPECT_EQ(c.mean, 1.0);
    }
  EXPECT_EQ(closed, 1);
  // Intermediate samples on the way between turning points and repeated samples change nothing.
  const std::vector<Cycle> dense = rainflow({-2, -1, 0, 1, 1, -3, 0, 5, 5, 2, -1, 3, 0, -4, 4, 1, -2});
  EXPECT_EQ(countsByRange(dense), expected);
}

TEST(Fatigue, TurningPointsKeepEndsPeaksAndValleys) {
  EXPECT_EQ(turningPoints({0, 1, 2, 2, 3, 1, 1, 0, 4}), (std::vector<double>{0, 3, 0, 4}));
  EXPECT_EQ(turningPoints({5, 5, 5}), (std::vector<double>{5}));
  EXPECT_THROW(turningPoints({0, NAN}), std::invalid_argument);
}

TEST(Fatigue, ConstantAmplitudeCosineGivesOneCyclePerPeriod) {
  // A cos(2π t/T) sampled 40 times a period, starting and ending at a crest: K periods = K cycles of range 2A
  // (the peaks fall on samples, so the ranges are exact to round-off).
  const double amplitude = 30e6, mean = 5e6;
  for (int periods : {1, 7, 100}) {
    std::vector<double> s;
    for (int i = 0; i <= 40 * periods; ++i) s.push_back(mean + amplitude * std::cos(2.0 * std::numbers::pi * i / 40.0));
    double total = 0.0;
    for (const auto& c : rainflow(s)) {
      EXPECT_NEAR(c.range, 2.0 * amplitude, 1e-9 * amplitude);
      EXPECT_NEAR(c.mean, mean, 1e-9 * amplitude);
      total += c.count;
    }
    EXPECT_EQ(total, periods);
  }
}

TEST(Fatigue, DnvCurvesReproduceTheTablesFatigueLimitsAndAreContinuous) {
  // DNVGL-RP-C203 (2016) Tables 2-1/2-2 list the fatigue limit at 10^7 cycles (rounded to 0.01 MPa): the
  // log a columns must give it, in air and in seawater with cathodic protection, and the two slopes must meet.
  // Tolerance: the limit's rounding (0.005 MPa) plus that of log a_2 to 3 decimals (relative ln 10·0.0005/5).
  for (const auto& name : dnvCurveNames()) {
    for (auto environment : {SnEnvironment::Air, SnEnvironment::SeawaterCathodicProtection}) {
      const SnCurve curve = dnvCurve(name, environment);
      const double limit = dnvFatigueLimit(name);
      EXPECT_NEAR(std::pow(10.0, (curve.log_a2 - 7.0) / curve.m2), limit, 0.005 + limit * std::log(10.0) * 1e-4)
          << curve.name;
      // log N at the listed limit is 7 within the rounding: ±0.005 MPa (m = 5) and ±0.0005 in log a.
      EXPECT_NEAR(std::log10(cyclesToFailure(curve, limit, 0.0)), 7.0, 5.0 * std::log10(1.0 + 0.005 / limit) + 6e-4)
          << curve.name;
      // Continuity at the transition: both branches give the same N there within the 3-decimal rounding of
      // log a_1 and log a_2 (0.0005·(1 + m_2/m_1) ≤ 0.0014).
      const double s_t = curve.transitionRange();
      const double n_second = std::pow(10.0, curve.log_a2 - curve.m2 * std::log10(s_t));
      EXPECT_NEAR(std::log10(n_second), std::log10(curve.transition_cycles), 0.0014) << curve.name;
    }
  }
  EXPECT_THROW(dnvCurve("X9", SnEnvironment::Air), std::invalid_argument);
}

TEST(Fatigue, FreeCorrosionCurvesHaveOneSlopeAndAThirdOfTheLifeInAir) {
  // DNVGL-RP-C203 (2016), S-N curves in seawater for free corrosion: log N = log a − 3 log Δσ at every N. For the
  // curves with m = 3 in air the RP's free-corrosion life is a third of the life in air on the first slope:
  // log a = log a_1(air) − log10 3, within the 3-decimal rounding of both columns (0.001).
  for (const auto& name : dnvCurveNames()) {
    const SnCurve free = dnvCurve(name, SnEnvironment::SeawaterFreeCorrosion);
    EXPECT_EQ(free.m1, 3.0) << free.name;
    EXPECT_EQ(free.m2, 0.0) << free.name;
    const SnCurve air = dnvCurve(name, SnEnvironment::Air);
    if (air.m1 == 3.0) {
      EXPECT_NEAR(free.log_a1, air.log_a1 - std::log10(3.0), 0.001) << free.name;
    }
    // One slope: 10 MPa gives the first slope's N, 10^(log a − 3), far beyond any transition.
    EXPECT_NEAR(std::log10(cyclesToFailure(free, 10.0, 0.0)), free.log_a1 - 3.0, 1e-12) << free.name;
  }
  // Values of the table: D 11.687 (k 0.20), B1 12.436 (m = 3 although 4 in air; k 0), W3 10.493.
  EXPECT_EQ(dnvCurve("D", SnEnvironment::SeawaterFreeCorrosion).log_a1, 11.687);
  EXPECT_EQ(dnvCurve("D", SnEnvironment::SeawaterFreeCorrosion).thickness_exponent, 0.20);
  EXPECT_EQ(dnvCurve("B1", SnEnvironment::SeawaterFreeCorrosion).log_a1, 12.436);
  EXPECT_EQ(dnvCurve("W3", SnEnvironment::SeawaterFreeCorrosion).log_a1, 10.493);
  // 1000 cycles of 100 MPa on D, 50 mm thick: D = 1000 · (100 · 2^0.2)³ / 10^11.687.
  const std::vector<Cycle> cycles{{100e6, 0.0, 1000.0}};
  EXPECT_NEAR(minerDamage(cycles, dnvCurve("D", SnEnvironment::SeawaterFreeCorrosion), 50.0),
              1000.0 * std::pow(100.0 * std::pow(2.0, 0.2), 3) / std::pow(10.0, 11.687), 1e-12);
}

TEST(Fatigue, MinerDamageOfConstantAmplitudeEqualsTheSnFormula) {
  const SnCurve d_air = dnvCurve("D", SnEnvironment::Air);
  const SnCurve d_cp = dnvCurve("D", SnEnvironment::SeawaterCathodicProtection);
  // 1000 cycles of 100 MPa (first slope): D = 1000 · 100³ / 10^12.164 in air, / 10^11.764 in seawater with CP.
  const std::vector<Cycle> cycles{{100e6, 0.0, 1000.0}};
  EXPECT_NEAR(minerDamage(cycles, d_air, 0.0), 1000.0 * 1e6 / std::pow(10.0, 12.164), 1e-12);
  EXPECT_NEAR(minerDamage(cycles, d_cp, 0.0), 1000.0 * 1e6 / std::pow(10.0, 11.764), 1e-12);
  // 30 MPa in air lies beyond 10^7 cycles: the m = 5 branch, N = 10^15.606 / 30^5.
  EXPECT_NEAR(cyclesToFailure(d_air, 30.0, 0.0), std::pow(10.0, 15.606) / std::pow(30.0, 5), 1e-6 * 1e9);
  // Thickness 50 mm with k = 0.20 (D): N divided by (50/25)^{0.2·3} on the first slope; 20 mm ≤ t_ref: none.
  EXPECT_NEAR(cyclesToFailure(d_air, 100.0, 50.0) * std::pow(2.0, 0.6), cyclesToFailure(d_air, 100.0, 0.0), 1e-3);
  EXPECT_EQ(cyclesToFailure(d_air, 100.0, 20.0), cyclesToFailure(d_air, 100.0, 0.0));
  // A rainflow-counted constant-amplitude history gives the same damage as the formula.
  std::vector<double> s;
  for (int i = 0; i <= 20 * 500; ++i) s.push_back(60e6 * std::cos(2.0 * std::numbers::pi * i / 20.0));
  EXPECT_NEAR(minerDamage(rainflow(s), d_cp, 0.0), 500.0 * std::pow(120.0, 3) / std::pow(10.0, 11.764), 1e-12);
  EXPECT_EQ(cyclesToFailure(d_air, 0.0, 0.0), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace maris::fatigue
