// Waves on the riser: the Morison drag and inertia on a fixed vertical segment against the force integrated by
// hand over the segment (closed forms of the Wheeler-stretched Airy kinematics) at 16 times over a period; calm
// water reduces the wave loads bit for bit to the current-only drag; waves = none builds no sea.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "catalog.hpp"
#include "core/ocean_waves.hpp"
#include "riser/riser_loads.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_waves.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

// Default riser (100 m, n = 20: interior segments 5 m) in 100 m of water with a 4 m, 8 s Airy wave along +x and a
// uniform current U along +x.
RiserParameters riserInAiryWave(double current) {
  RiserParameters p;
  p.wave_type = "airy";
  p.wave_height = 4.0;
  p.wave_period = 8.0;
  p.wave_ramp_time = 10.0;
  p.water_level = 0.0;
  p.seabed_level = -100.0;
  p.current_speed_surface = p.current_speed_seabed = current;
  p.current_direction_deg = 0.0;
  return p;
}

// Segment i of the model held still and vertical (tangent −z) with its origin at depth `top_z`; the other
// segments elsewhere do not matter (each segment's load is its own).
RiserPose fixedVerticalSegment(const RiserModel& m, int i, double top_z, double t) {
  RiserPose pose;
  pose.resize(m.segmentCount());
  pose.time = t;
  Mat3 r;
  r << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // columns: x' = −z (down the riser), y' = y, z' = x
  pose.rotation[i] = r;
  pose.position[i] = Vec3(0, 0, top_z);
  return pose;
}

// Hand-integrated Morison force along x on the vertical stretch z ∈ [z_bottom, z_top] at x = 0, for
// u = V(t) cosh k(z'+h), V = a ω cos ωt / sinh kh (ψ = −ωt), u̇ = −a ω² sin ωt cosh k(z'+h)/sinh kh, with Wheeler's
// z' = h (z − η)/(h + η), η = a cos ωt:
//   F = ½ ρ D C_d ∫ |U + u|(U + u) dz + ρ A (1 + C_a) ∫ u̇ dz,
// where |U+u|(U+u) = |V|V cosh² for U = 0, and (U+u)² for U = 1 m/s (U + u > 0 below 20 m: |u| ≤ 0.44 m/s there),
// dz = (h + η)/h dz', ∫ cosh k(z'+h) dz' = sinh k(z'+h)/k, ∫ cosh² k(z'+h) dz' = (z'+h)/2 + sinh 2k(z'+h)/(4k).
double handMorisonForce(const RiserParameters& p, double z_bottom, double z_top, double t, double current) {
  const double h = p.water_level - p.seabed_level, a = 0.5 * p.wave_height, omega = 2 * pi / p.wave_period;
  const double k = ocean::waveNumber(omega, h, p.gravity);
  const double eta = a * std::cos(omega * t);
  const double jacobian = (h + eta) / h;
  auto stretched = [&](double z) { return h * (z - eta) / (h + eta) + h; };  // z' + h
  const double s1 = stretched(z_bottom), s2 = stretched(z_top);
  const double i1 = jacobian * (std::sinh(k * s2) - std::sinh(k * s1)) / k;
  const double i2 = jacobian * ((s2 - s1) / 2 + (std::sinh(2 * k * s2) - std::sinh(2 * k * s1)) / (4 * k));
  const double velocity = a * omega / std::sinh(k * h) * std::cos(omega * t);
  const double acceleration = -a * omega * omega / std::sinh(k * h) * std::sin(omega * t);
  const double area = pi / 4 * p.outer_diameter * p.outer_diameter;
  const double drag = 0.5 * p.water_density * p.outer_diameter * p.normal_drag_coefficient *
                      (current * current * (z_top - z_bottom) + 2 * current * velocity * i1 +
                       (current == 0.0 ? std::abs(velocity) : velocity) * velocity * i2);
  const double inertia = p.water_density * area * (1 + p.added_mass_coefficient) * acceleration * i1;
  return drag + inertia;
}

TEST(RiserWaves, MorisonLoadOnAFixedSegmentMatchesTheHandIntegratedForceOverAPeriod) {
  for (double current : {0.0, 1.0}) {
    const RiserParameters p = riserInAiryWave(current);
    const RiserModel m = buildRiserModel(p);
    ASSERT_TRUE(m.sea);
    const int i = 5;  // interior segment, 5 m long, placed from z = −20 m to −25 m
    const double top_z = -20.0, length = m.segments[i].length;
    ASSERT_EQ(length, 5.0);
    double peak = 0.0, worst = 0.0;
    for (int step = 0; step < 16; ++step) {
      const double t = p.wave_ramp_time + step * p.wave_period / 16;  // after the ramp: full waves
      const RiserPose pose = fixedVerticalSegment(m, i, top_z, t);
      SegmentLoads loads;
      loads.resize(m.segmentCount());
      addMorisonInWaves(m, pose, 1.0, loads);
      const double expected = handMorisonForce(p, top_z - length, top_z, t, current);
      peak = std::max(peak, std::abs(expected));
      worst = std::max(worst, std::abs(loads.force[i].x() - expected));
      // No force along y, none along the segment (drag D_x = 0; inertia on the normal acceleration only).
      EXPECT_NEAR(loads.force[i].y(), 0.0, 1e-12 * std::abs(expected) + 1e-9);
      EXPECT_NEAR(loads.force[i].z(), 0.0, 1e-12 * std::abs(expected) + 1e-9);
    }
    // The loads use 3 Gauss points a segment: error ~ 5e-7 (2kl)^6 relative, 2kl = 0.63 here → ~3e-8.
    EXPECT_LT(worst, 1e-6 * peak) << "current " << current;
    EXPECT_GT(peak, 100.0);  // a load worth testing: hundreds of newtons on 5 m
  }
}

TEST(RiserWaves, CalmWaterGivesTheCurrentOnlyDragBitForBit) {
  // Before the ramp (t = 0) the sea is calm: the wave path must reduce exactly to addDrag (v − U − 0 = v − U and
  // a zero inertia term add nothing in floating point), so a run's statics and start are those without waves.
  const RiserParameters p = riserInAiryWave(0.8);
  const RiserModel m = buildRiserModel(p);
  RiserPose pose = fixedVerticalSegment(m, 5, -20.0, 0.0);
  pose.velocity[5] = Vec3(0.3, -0.2, 0.1);
  pose.omega[5] = Vec3(0.01, 0.02, -0.03);
  SegmentLoads with_sea, without;
  with_sea.resize(m.segmentCount());
  without.resize(m.segmentCount());
  addMorisonInWaves(m, pose, 1.0, with_sea);
  addDrag(m, pose, 1.0, without);
  for (int i = 0; i < m.segmentCount(); ++i) {
    EXPECT_EQ(with_sea.force[i], without.force[i]) << i;
    EXPECT_EQ(with_sea.moment[i], without.moment[i]) << i;
  }
  EXPECT_EQ(with_sea.power_drag, without.power_drag);
}

TEST(RiserWaves, NoneBuildsNoSeaAndEveryBuiltinScenarioHasAWavesSection) {
  const RiserParameters p = test::paperCaseFive();
  EXPECT_EQ(p.wave_type, "none");
  EXPECT_FALSE(buildRiserModel(p).sea);
  // A scenario without a waves section reads as waves none, with a note saying so.
  Json parameters = riserBinder().write(p);
  parameters.erase("waves");
  const auto notes = upgradeRiserParameters(parameters);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(riserBinder().read(parameters).wave_type, "none");
  // Built-in scenarios carry the section (no upgrade note when they run).
  int riser_scenarios = 0;
  for (const auto& b : builtinScenarios()) {
    if (b.scenario.scene != "riser") continue;
    ++riser_scenarios;
    EXPECT_TRUE(b.scenario.parameters.contains("waves")) << b.id;
  }
  EXPECT_GT(riser_scenarios, 20);
}

TEST(RiserWaves, RampRateAndAccelerationAreTheRampsDerivatives) {
  // r = τ³(10 − 15τ + 6τ²), τ = t/T_r: ṙ and r̈ against central differences of r and ṙ at step δ = 1e-6 T_r
  // (truncation δ²/6 times the next derivative: ≤ 1e-11/T_r and 6e-11/T_r²; rounding ≈ 1e-16/δ times r or ṙ),
  // zero outside (0, T_r), r̈ tending to 0 at both ends (continuous), and one hand value.
  RiserSea sea;
  sea.ramp_time = 10.0;
  const double tr = sea.ramp_time, delta = 1e-6 * tr;
  for (int j = 1; j < 20; ++j) {
    const double t = j * tr / 20;
    const double rate = (sea.ramp(t + delta) - sea.ramp(t - delta)) / (2 * delta);
    const double acceleration = (sea.rampRate(t + delta) - sea.rampRate(t - delta)) / (2 * delta);
    EXPECT_NEAR(sea.rampRate(t), rate, 1e-8 / tr) << t;
    EXPECT_NEAR(sea.rampAcceleration(t), acceleration, 1e-8 / (tr * tr)) << t;
  }
  for (const double t : {-1.0, 0.0, tr, tr + 1.0}) EXPECT_EQ(sea.rampAcceleration(t), 0.0) << t;
  EXPECT_NEAR(sea.rampAcceleration(1e-9 * tr), 0.0, 1e-7 / (tr * tr));
  EXPECT_NEAR(sea.rampAcceleration((1 - 1e-9) * tr), 0.0, 1e-7 / (tr * tr));
  EXPECT_NEAR(sea.rampAcceleration(0.25 * tr), 5.625 / (tr * tr), 1e-15);  // 60 · ¼ · ¾ · ½ / T_r²
}

TEST(RiserWaves, BadWaveInputNamesTheField) {
  RiserParameters p = riserInAiryWave(0.0);
  p.seabed_level = 5.0;  // above the water
  auto errors = checkRiserParameters(p);
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors.front().path, "environment.seabed_level");
  p = riserInAiryWave(0.0);
  p.wave_type = "spectrum_table";
  p.wave_spectrum_table = {{0.5, 1.0}, {0.4, 2.0}};
  errors = checkRiserParameters(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors.front().path, "waves.spectrum_table[1].omega");
}

}  // namespace
}  // namespace maris::riser
