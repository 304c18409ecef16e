// Fatigue at the riser's joints: the 8-point hot-spot stress, rainflow and Miner damage of a synthetic joint
// history against the S–N formula, and a short run in an Airy wave (fatigue table, wave elevation history
// against the ramped closed form, energy balance with the wave loads' work).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/fatigue.hpp"
#include "riser/riser_fatigue.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;
constexpr double kYear = 365.25 * 24 * 3600;

// One joint: tension T0, bending σ_xy = S cos(2π t/T) and σ_xz = S_z sin(2π t/T), 20 samples a period, K periods.
struct SyntheticJoint {
  std::vector<double> time;
  JointStressSeries series;
};
SyntheticJoint syntheticJoint(double s, double s_z, int periods, double thickness) {
  SyntheticJoint j;
  j.series.arc_length = 7.5;
  j.series.wall_area = 0.0373;
  j.series.wall_thickness = thickness;
  const double period = 10.0;
  for (int i = 0; i <= 20 * periods; ++i) {
    const double t = i * period / 20;
    j.time.push_back(t);
    j.series.tension.push_back(1e6);
    j.series.stress_xy.push_back(s * std::cos(2 * pi * t / period));
    j.series.stress_xz.push_back(s_z * std::sin(2 * pi * t / period));
  }
  return j;
}

TEST(RiserFatigue, UniaxialBendingDamagesTheFibresInItsPlaneAsTheSnFormulaSays) {
  // σ(θ) = T/A − S cos ωt cos θ: the range 2S·SCF at θ = 0° and 180°, zero at 90°. K = 50 periods of
  // 2·40 MPa·1.5 = 120 MPa on F1 in seawater with CP (log a = 11.299, m = 3; N = 1.2e5 < 1e6, first slope);
  // wall 40 mm > t_ref = 25 mm: Δσ × (40/25)^0.25.
  const SyntheticJoint j = syntheticJoint(40e6, 0.0, 50, 0.040);
  const fatigue::SnCurve f1 = fatigue::dnvCurve("F1", fatigue::SnEnvironment::SeawaterCathodicProtection);
  const auto result = jointFatigue(j.time, {j.series}, f1, 1.5, 0.0);
  ASSERT_EQ(result.size(), 1u);
  const double range = 120.0 * std::pow(40.0 / 25.0, 0.25);
  const double expected = 50.0 * std::pow(range, 3) / std::pow(10.0, 11.299);
  EXPECT_NEAR(result[0].damage, expected, 1e-12 * expected);
  EXPECT_TRUE(result[0].worst_point == 0 || result[0].worst_point == 4) << result[0].worst_point;
  EXPECT_NEAR(result[0].damage_per_year, expected * kYear / 500.0, 1e-12 * expected * kYear / 500.0);
  EXPECT_NEAR(result[0].life, 500.0 / (expected * kYear), 1e-12 * 500.0 / (expected * kYear));
  // θ = 90°: only the constant tension: no range.
  for (std::size_t k = 0; k < j.time.size(); ++k)  // cos 90° = 6e-17 in floating point: 4e-9 Pa of bending left
    EXPECT_NEAR(hotSpotStress(j.series, k, 2, 1.5), 1.5 * 1e6 / 0.0373, 1e-6);
  // Counting from t = 250 s on: half the periods, half the damage, the same damage per year.
  const auto later = jointFatigue(j.time, {j.series}, f1, 1.5, 250.0);
  EXPECT_NEAR(later[0].damage, 0.5 * expected, 1e-12 * expected);
  EXPECT_NEAR(later[0].damage_per_year, result[0].damage_per_year, 1e-12 * result[0].damage_per_year);
}

TEST(RiserFatigue, ARotatingBendingMomentLoadsEveryPointAlike) {
  // σ_xy = S cos ωt, σ_xz = S sin ωt: σ(θ) = T/A − S cos(ωt + θ), range 2S at all 8 points; wall 20 mm ≤ t_ref.
  const SyntheticJoint j = syntheticJoint(30e6, 30e6, 40, 0.020);
  const fatigue::SnCurve d = fatigue::dnvCurve("D", fatigue::SnEnvironment::Air);
  const auto result = jointFatigue(j.time, {j.series}, d, 1.0, 0.0);
  // 60 MPa on D in air: N = 10^12.164/60³ = 6.7e6 < 1e7 (first slope). The points off the sampled peaks see
  // slightly smaller ranges (cos(ωt + 45°) peaks between samples): the worst is a sampled-peak point.
  EXPECT_NEAR(result[0].damage, 40.0 * std::pow(60.0, 3) / std::pow(10.0, 12.164), 1e-12);
}

TEST(RiserFatigue, RunInAnAiryWaveRecordsElevationFatigueAndClosesItsEnergyBalance) {
  RiserParameters p;
  p.segment_count = 10;
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.motion_amplitude_x = p.motion_amplitude_y = 0.0;
  p.wave_type = "airy";
  p.wave_height = 4.0;
  p.wave_period = 8.0;
  p.wave_phase_deg = 30.0;
  p.wave_ramp_time = 4.0;
  p.seabed_level = -100.0;
  p.end_time = 16.0;
  p.integrator = "implicit";
  p.tolerance = 1e-5;
  p.frame_count = 4;
  p.stress_times.clear();
  p.fatigue_enabled = true;
  p.fatigue_start_time = 8.0;
  ASSERT_TRUE(checkRiserParameters(p).empty());
  RunContext context;
  const Results r = solveRiser(p, context);
  // η at x = y = 0: r(t)·(H/2) cos(−ωt + φ), r = τ³(10 − 15τ + 6τ²) with τ = t/T_r before T_r.
  const Table* history = r.findTable("history");
  ASSERT_NE(history, nullptr);
  const Column* eta = history->find("wave_elevation");
  ASSERT_NE(eta, nullptr);
  const Column* time = history->find("time");
  for (std::size_t k = 0; k < time->values.size(); ++k) {
    const double t = time->values[k];
    const double tau = std::min(t / 4.0, 1.0), ramp = tau * tau * tau * (10 - 15 * tau + 6 * tau * tau);
    EXPECT_NEAR(eta->values[k], ramp * 2.0 * std::cos(-2 * pi / 8.0 * t + pi / 6), 1e-12) << t;
  }
  // Fatigue: one row per joint, the scalar is the table's shortest life.
  const Table* fatigue = r.findTable("fatigue");
  ASSERT_NE(fatigue, nullptr);
  ASSERT_EQ(fatigue->rows(), 10u);
  const auto& life = fatigue->find("life")->values;
  ASSERT_NE(r.findScalar("min_fatigue_life"), nullptr);
  EXPECT_EQ(r.findScalar("min_fatigue_life")->value, *std::min_element(life.begin(), life.end()));
  for (double l : life) EXPECT_GT(l, 0.0);
  // ... and the annual damage there is the table's largest (what a scatter-diagram study adds up).
  const auto& per_year = fatigue->find("damage_per_year")->values;
  ASSERT_NE(r.findScalar("max_fatigue_damage_per_year"), nullptr);
  EXPECT_EQ(r.findScalar("max_fatigue_damage_per_year")->value, *std::max_element(per_year.begin(), per_year.end()));
  EXPECT_GT(r.findScalar("max_fatigue_damage_per_year")->value, 0.0);
  // The wave loads do work on the riser (their power is in work_drag): the balance must still close.
  const Scalar* balance = r.findScalar("energy_balance_error");
  ASSERT_NE(balance, nullptr);
  EXPECT_LT(balance->value, 1e-2);
  // The sea surface moves in the 3D view.
  ASSERT_GE(r.view.frames.size(), 2u);
  const auto& shapes = r.view.frames.back().shapes;
  EXPECT_TRUE(std::any_of(shapes.begin(), shapes.end(), [](const Shape3D& s) { return s.name == "sea surface"; }));
}

}  // namespace
}  // namespace maris::riser
