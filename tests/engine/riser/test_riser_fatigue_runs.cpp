// Fatigue over whole runs: in a stationary (regular) sea the damage grows in proportion to the counted duration,
// it scales as Δσ^m with the stress, the default sampling resolves the stress cycles where the history's rows are
// too far apart, and the S–N curve choices (a user curve, a slope check) give what their formulas give.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/fatigue.hpp"
#include "riser/riser_fatigue.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

constexpr double kWavePeriod = 8.0;  // [s]

// A 100 m riser, n = 10, in 1 m/s current and an Airy wave (H 4 m, T 8 s, 4 s ramp); the automatic implicit step
// (T/50); fatigue counted from 64 s on, when the start-up transient has died away in the current's drag.
RiserParameters regularSea(double end_time) {
  RiserParameters p;
  p.segment_count = 10;
  p.current_speed_surface = p.current_speed_seabed = 1.0;
  p.motion_amplitude_x = p.motion_amplitude_y = 0.0;
  p.wave_type = "airy";
  p.wave_height = 4.0;
  p.wave_period = kWavePeriod;
  p.wave_ramp_time = 4.0;
  p.seabed_level = -100.0;
  p.end_time = end_time;
  p.integrator = "implicit";
  p.tolerance = 1e-5;
  p.frame_count = 4;
  p.stress_times.clear();
  p.modes = false;
  p.fatigue_enabled = true;
  p.fatigue_start_time = 64.0;
  return p;
}

double worstDamage(const Results& r) {
  const auto& damage = test::column(r, "fatigue", "damage");
  return damage.empty() ? 0.0 : *std::max_element(damage.begin(), damage.end());
}

// Rainflow over N periods of a periodic stress counts N − 1 closed cycles of one period's damage d plus the half
// cycles at the ends, which add r ≤ d: D(N) = (N − 1) d + r. So D(2N)/D(N) = 2 + (d − r)/D(N) lies within 1/(N − 1)
// of 2. Windows of 10, 20 and 40 wave periods: the ratios within 1/9. (Measured: 2.002 and 1.995, and the annual
// damages of the three windows within 0.1 % of each other. Before the automatic step followed the waves, the
// 40-period run stepped at 1.9 s and its annual damage was 22 % above the 10-period run's.)
TEST(RiserFatigueRuns, DamageGrowsInProportionToTheCountedDurationInARegularSea) {
  double previous = 0.0, first_per_year = 0.0;
  for (int periods : {10, 20, 40}) {
    RiserParameters p = regularSea(64.0 + periods * kWavePeriod);
    p.fatigue_sample_interval = kWavePeriod / 40;
    const Results r = test::run(p);
    const double damage = worstDamage(r);
    ASSERT_GT(damage, 0.0);
    const double per_year = r.findScalar("max_fatigue_damage_per_year")->value;
    if (previous > 0) {
      EXPECT_NEAR(damage / previous, 2.0, 1.0 / (periods / 2 - 1)) << periods << " periods";
      EXPECT_NEAR(per_year / first_per_year, 1.0, 1.0 / 9) << periods << " periods";
    } else {
      first_per_year = per_year;
    }
    previous = damage;
  }
}

// SCF × 2 multiplies every stress, so every range, by 2: on a one-slope curve the damage by 2^m exactly.
TEST(RiserFatigueRuns, DamageScalesAsTheStressRangeToTheSlope) {
  for (double m : {3.0, 4.0}) {
    double damage[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
      RiserParameters p = regularSea(96.0);  // four periods counted: the scaling is exact whatever the count
      p.fatigue_sn_curve = "user";
      p.fatigue_user_log_a1 = 12.0;
      p.fatigue_user_m1 = m;
      p.fatigue_user_m2 = 0.0;  // one slope
      p.fatigue_stress_concentration_factor = 1.0 + k;
      ASSERT_TRUE(checkRiserParameters(p).empty());
      damage[k] = worstDamage(test::run(p));
    }
    ASSERT_GT(damage[0], 0.0);
    EXPECT_NEAR(damage[1] / damage[0], std::pow(2.0, m), 1e-12 * std::pow(2.0, m)) << "m = " << m;
  }
}

// 800 s: the history's 2000 rows are 0.4 s apart, T/20. The default samples the joint stresses at T/40 or finer
// (a sine's range then low by at most 1 − cos(π/40) = 0.31 %, its damage by 1.5 % on the m = 5 slope these small
// ranges fall on) and is compared with sampling at T/200 (its own range error ≤ 1.2e-4).
TEST(RiserFatigueRuns, DefaultSamplingResolvesTheCyclesWhereTheHistoryIsTooCoarse) {
  RiserParameters p = regularSea(800.0);
  EXPECT_DOUBLE_EQ(fatigueSampleInterval(p), kWavePeriod / 40);
  const Results automatic = test::run(p);
  EXPECT_LE(automatic.findScalar("fatigue_sample_interval")->value, kWavePeriod / 40 * (1 + 1e-12));
  p.fatigue_sample_interval = kWavePeriod / 200;
  const Results fine = test::run(p);
  EXPECT_NEAR(worstDamage(automatic) / worstDamage(fine), 1.0, 0.015);
  // Without fatigue (or without a forcing period) nothing is sampled beyond the history.
  p.fatigue_enabled = false;
  EXPECT_EQ(fatigueSampleInterval(p), 0.0);
}

// The automatic interval: 1/40 of the shortest forcing period (harmonic top, Airy period, half a spectrum's peak
// period); an explicit interval wins.
TEST(RiserFatigueRuns, AutomaticIntervalFollowsTheShortestForcingPeriod) {
  RiserParameters p = regularSea(100.0);
  p.motion_amplitude_x = 1.0;
  p.motion_period = 12.0;
  EXPECT_DOUBLE_EQ(fatigueSampleInterval(p), kWavePeriod / 40);
  p.motion_period = 6.0;
  EXPECT_DOUBLE_EQ(fatigueSampleInterval(p), 6.0 / 40);
  p.wave_type = "jonswap";
  p.wave_peak_period = 10.0;
  EXPECT_DOUBLE_EQ(fatigueSampleInterval(p), 5.0 / 40);
  p.fatigue_sample_interval = 0.3;
  EXPECT_DOUBLE_EQ(fatigueSampleInterval(p), 0.3);
}

// A user curve given the DNVGL-RP-C203 F1-in-air numbers (the defaults) is that curve.
TEST(RiserFatigueRuns, UserCurveWithTheTableNumbersIsTheTableCurve) {
  RiserParameters p;
  p.fatigue_sn_curve = "user";
  const fatigue::SnCurve user = fatigueCurve(p);
  const fatigue::SnCurve table = fatigue::dnvCurve("F1", fatigue::SnEnvironment::Air);
  for (double range : {5.0, 20.0, 36.0, 37.0, 100.0, 400.0})
    for (double thickness : {10.0, 25.0, 60.0})
      EXPECT_DOUBLE_EQ(fatigue::cyclesToFailure(user, range, thickness), fatigue::cyclesToFailure(table, range, thickness))
          << range << " MPa, " << thickness << " mm";
  p.fatigue_sn_curve = "F1";
  p.fatigue_environment = "seawater_free_corrosion";
  EXPECT_EQ(fatigueCurve(p).name, "DNVGL-RP-C203 F1 in seawater for free corrosion");
}

// Slopes that do not meet at the transition would make N jump: refused, naming log a2 and the value that fits.
TEST(RiserFatigueRuns, UserCurveWhoseSlopesDoNotMeetIsRefused) {
  RiserParameters p;
  p.fatigue_sn_curve = "user";
  p.fatigue_user_log_a2 = 15.0;  // F1 in air meets at 14.8317
  const auto errors = test::errorsOf(p);
  ASSERT_TRUE(test::hasErrorAt(errors, "parameters.fatigue.user_log_a2")) << describeErrors(errors);
  for (const auto& e : errors) {
    if (e.path == "parameters.fatigue.user_log_a2") {
      EXPECT_NE(e.message.find("14.8317"), std::string::npos) << e.message;
    }
  }
  p.fatigue_user_m2 = 0.0;  // one slope: log a2 unused
  EXPECT_TRUE(test::errorsOf(p).empty());
  p.fatigue_sn_curve = "D";  // a table curve: the user fields are not checked
  p.fatigue_user_m2 = 5.0;
  EXPECT_TRUE(test::errorsOf(p).empty());
}

// The stress series are kept for rainflow: more than 5e7 joint samples (1.2 GB) is an input error naming the
// interval, whether given or automatic; a 3-hour sea at n = 100 (8.6e6) is accepted.
TEST(RiserFatigueRuns, TooManyStressSamplesAreRefusedNamingTheInterval) {
  RiserParameters p = regularSea(10800.0);
  p.segment_count = 100;
  EXPECT_TRUE(test::errorsOf(p).empty()) << describeErrors(test::errorsOf(p));
  p.fatigue_sample_interval = 1e-3;  // 1.08e7 samples × 100 joints
  auto errors = test::errorsOf(p);
  ASSERT_TRUE(test::hasErrorAt(errors, "parameters.fatigue.sample_interval")) << describeErrors(errors);
  p.fatigue_sample_interval = 0.0;
  p.segment_count = 1000;  // automatic T/40 = 0.2 s: 54 000 samples × 1000 joints
  errors = test::errorsOf(p);
  ASSERT_TRUE(test::hasErrorAt(errors, "parameters.fatigue.sample_interval")) << describeErrors(errors);
  EXPECT_NE(errors[0].message.find("automatic"), std::string::npos) << errors[0].message;
}

}  // namespace
}  // namespace maris::riser
