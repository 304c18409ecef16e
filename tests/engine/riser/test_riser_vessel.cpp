// Vessel motion at the riser top from displacement RAOs (riser_vessel): a unit heave RAO with no phase makes the top
// follow the wave elevation at the RAO origin (1e-12 m); a pitch RAO with the hang-off point away from the RAO origin
// gives the rigid lever-arm motion of the closed form; the lag/lead phase conventions shift the motion by ε/ω
// against the wave at the origin; velocity and acceleration are the time derivatives of the position (central
// differences); a bad RAO file is refused naming the field, the line and the column.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/ocean_waves.hpp"
#include "core/run_context.hpp"
#include "riser/riser_integration.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_vessel.hpp"
#include "riser/riser_scene.hpp"
#include "riser/riser_waves.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;
constexpr const char* kHeader =
    "heading,omega,surge_amplitude,surge_phase,sway_amplitude,sway_phase,heave_amplitude,heave_phase,"
    "roll_amplitude,roll_phase,pitch_amplitude,pitch_phase,yaw_amplitude,yaw_phase\n";

// One RAO row: heading, omega and (amplitude, phase) for the six degrees of freedom.
std::string row(double heading, double omega, const double (&dof)[12]) {
  std::ostringstream s;
  s.precision(17);
  s << heading << "," << omega;
  for (double v : dof) s << "," << v;
  s << "\n";
  return s.str();
}

// Writes `text` to a file of this process's temporary folder and returns its path.
std::string writeTemporary(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / ("maris_riser_vessel_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / name;
  std::ofstream(file) << text;
  return file.string();
}

// A 100 m riser pinned at the top in 100 m of water, top.motion = vessel with the RAO text given, JONSWAP sea.
RiserParameters vesselRiser(const std::string& rao_text, const std::string& name) {
  RiserParameters p;
  p.top_condition = "pinned";
  p.top_x = 3.0;
  p.top_y = -2.0;
  p.top_z = 0.0;
  p.bottom_z = -99.0;
  p.seabed_level = -100.0;
  p.wave_type = "jonswap";
  p.wave_significant_height = 4.0;
  p.wave_peak_period = 9.0;
  p.wave_component_count = 60;
  p.wave_direction_deg = 30.0;
  p.wave_ramp_time = 10.0;
  p.top_motion = "vessel";
  p.vessel_rao_file = writeTemporary(name, rao_text);
  return p;
}

// A single-heading table with the same row at ω = 0.05 and 20 rad/s (covers every component of the seas used).
std::string flatTable(double heading, const double (&dof)[12]) {
  return std::string(kHeader) + row(heading, 0.05, dof) + row(heading, 20.0, dof);
}

TEST(RiserVessel, UnitHeaveRaoMakesTheTopFollowTheWaveElevationAtTheRaoOrigin) {
  const double heave[12] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  RiserParameters p = vesselRiser(flatTable(0.0, heave), "unit_heave.csv");
  p.vessel_heading_deg = 30.0;  // waves along the vessel's x axis: relative direction 0, the table's heading
  p.vessel_hang_off_x = 25.0;   // the top away from the RAO origin: the phase is the origin's
  p.vessel_hang_off_y = -8.0;
  p.vessel_hang_off_z = 12.0;
  p.vessel_offset_x = 4.0;
  EXPECT_TRUE(checkRiserParameters(p).empty());
  const RiserModel m = buildRiserModel(p);
  ASSERT_TRUE(m.vessel);
  EXPECT_TRUE(m.vessel->warnings.empty());
  EXPECT_NEAR(m.top_mean.x(), 7.0, 1e-15);  // top.x + the static offset
  const Vec3 origin = m.vessel->reference;
  const Vec3 expected_origin = m.top_mean - Eigen::AngleAxisd(pi / 6, Vec3::UnitZ()) * Vec3(25.0, -8.0, 12.0);
  EXPECT_LT((origin - expected_origin).norm(), 1e-12);
  double largest = 0.0;
  for (int j = 0; j <= 600; ++j) {
    const double t = 0.1 * j;
    const Vec3 d = m.topAt(t).position - m.top_mean;
    const double eta = m.sea->elevation(origin.x(), origin.y(), t);
    largest = std::max(largest, std::abs(eta));
    EXPECT_NEAR(d.z(), eta, 1e-12) << "t = " << t;
    EXPECT_NEAR(d.x(), 0.0, 1e-12);
    EXPECT_NEAR(d.y(), 0.0, 1e-12);
  }
  EXPECT_GT(largest, 1.0);  // the sea is not calm
}

// The same unit heave three hours into the run, where ω t ≈ 1e4 rad: the synthesis (phases reduced to [−π, π],
// polynomial sine and cosine) against the field's own elevation (libm). Each side rounds ω t once (≤ 2e-12 rad at
// 2e4 rad), so they may differ by Σ a (4e-12) ≈ 5e-11 m here (Σ a ≈ 11 m for 60 components of Hs 4 m).
TEST(RiserVessel, UnitHeaveRaoFollowsTheElevationAfterThreeHours) {
  const double heave[12] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  RiserParameters p = vesselRiser(flatTable(0.0, heave), "unit_heave_late.csv");
  p.wave_direction_deg = 0.0;
  const RiserModel m = buildRiserModel(p);
  const Vec3 origin = m.vessel->reference;
  double largest = 0.0;
  for (int j = 0; j <= 200; ++j) {
    const double t = 10800.0 + 0.3 * j;
    const double eta = m.sea->elevation(origin.x(), origin.y(), t);
    largest = std::max(largest, std::abs(eta));
    EXPECT_NEAR((m.topAt(t).position - m.top_mean).z(), eta, 2e-10) << "t = " << t;
  }
  EXPECT_GT(largest, 1.0);
}

// Pitch only: θ(t) = r(t) a P cos(ψ + ε) about the vessel's y axis; the hang-off point r_h = (40, 0, 15) moves by
// R_y(θ) r_h − r_h = (r_x cos θ + r_z sin θ − r_x, 0, −r_x sin θ + r_z cos θ − r_z) (exact rotation).
TEST(RiserVessel, PitchRaoWithAnOffsetHangOffGivesTheLeverArmMotion) {
  const double pitch_deg_per_m = 2.0, lag_deg = 30.0;
  const double pitch[12] = {0, 0, 0, 0, 0, 0, 0, 0, pitch_deg_per_m, lag_deg, 0, 0};
  RiserParameters p = vesselRiser(flatTable(0.0, pitch), "pitch.csv");
  p.wave_type = "airy";
  p.wave_height = 2.0;  // a = 1 m
  p.wave_period = 10.0;
  p.wave_direction_deg = 0.0;
  p.vessel_hang_off_x = 40.0;
  p.vessel_hang_off_z = 15.0;
  const RiserModel m = buildRiserModel(p);
  ASSERT_TRUE(m.vessel);
  const Vec3 origin = m.vessel->reference;
  const double omega = 2 * pi / p.wave_period, k = ocean::waveNumber(omega, 100.0, p.gravity);
  double largest_heave = 0.0;
  for (int j = 0; j <= 400; ++j) {
    const double t = 0.1 * j;
    const double theta = m.sea->ramp(t) * 1.0 * pitch_deg_per_m * pi / 180 *
                         std::cos(k * origin.x() - omega * t + lag_deg * pi / 180);
    const Vec3 closed(40.0 * std::cos(theta) + 15.0 * std::sin(theta) - 40.0, 0.0,
                      -40.0 * std::sin(theta) + 15.0 * std::cos(theta) - 15.0);
    const Vec3 d = m.topAt(t).position - m.top_mean;
    EXPECT_LT((d - closed).norm(), 1e-12) << "t = " << t;
    largest_heave = std::max(largest_heave, std::abs(d.z()));
  }
  // The lever arm matters: 40 m × 2°/m × 1 m ≈ 1.4 m of vertical motion at the top.
  EXPECT_GT(largest_heave, 1.3);
}

// Phase lag ε = 90° delays the motion by a quarter period against the wave crest at the RAO origin; a lead advances it.
TEST(RiserVessel, PhaseLagDelaysAndLeadAdvancesTheMotion) {
  const double heave[12] = {0, 0, 0, 0, 1, 90, 0, 0, 0, 0, 0, 0};
  for (const char* convention : {"lag", "lead"}) {
    RiserParameters p = vesselRiser(flatTable(0.0, heave), std::string("quarter_") + convention + ".csv");
    p.wave_type = "airy";
    p.wave_direction_deg = 0.0;
    p.vessel_rao_phase = convention;
    const RiserModel m = buildRiserModel(p);
    const Vec3 origin = m.vessel->reference;
    const double quarter = p.wave_period / 4 * (std::string(convention) == "lag" ? 1 : -1);
    for (int j = 0; j <= 100; ++j) {
      const double t = 15.0 + 0.2 * j;  // after the 10 s ramp and a quarter period
      EXPECT_NEAR((m.topAt(t).position - m.top_mean).z(), m.sea->field.elevation(origin.x(), origin.y(), t - quarter),
                  1e-12)
          << convention << ", t = " << t;
    }
  }
}

// All six degrees of freedom with phases, a hang-off lever and a vessel heading: velocity and acceleration are the
// derivatives of the position (central differences, step 1e-4 s: error ~ h²/6 |x'''| < 1e-7 m/s).
TEST(RiserVessel, VelocityAndAccelerationAreTheDerivativesOfThePosition) {
  const double all[12] = {0.8, 95, 0.6, 80, 0.9, 10, 1.5, 120, 2.0, 200, 0.7, 300};
  RiserParameters p = vesselRiser(flatTable(0.0, all), "all.csv");
  p.vessel_heading_deg = 30.0;
  p.vessel_hang_off_x = 35.0;
  p.vessel_hang_off_y = 10.0;
  p.vessel_hang_off_z = 20.0;
  const RiserModel m = buildRiserModel(p);
  const double h = 1e-4;
  for (double t : {2.0, 5.0, 9.9, 10.1, 17.3, 33.0}) {
    const TopKinematics k = m.topAt(t), before = m.topAt(t - h), after = m.topAt(t + h);
    EXPECT_LT((k.velocity - (after.position - before.position) / (2 * h)).norm(), 1e-6) << "t = " << t;
    EXPECT_LT((k.acceleration - (after.velocity - before.velocity) / (2 * h)).norm(), 1e-6) << "t = " << t;
  }
}

// The vessel motion looked up per time (RiserModel::topAt with a VesselMotionCache, as evaluateRhs does): the same
// numbers as computed afresh, exactly, for repeated and new times and for a cache passed between two vessels.
TEST(RiserVessel, TopMotionLookedUpPerTimeEqualsTheMotionComputedAfresh) {
  const double all[12] = {0.8, 95, 0.6, 80, 0.9, 10, 1.5, 120, 2.0, 200, 0.7, 300};
  RiserParameters p = vesselRiser(flatTable(0.0, all), "cache_a.csv");
  p.vessel_hang_off_x = 35.0;
  p.vessel_hang_off_z = 20.0;
  const RiserModel a = buildRiserModel(p);
  p.vessel_heading_deg = 60.0;  // another vessel: another motion at the same times
  const RiserModel b = buildRiserModel(p);
  VesselMotionCache cache;
  auto expectSame = [&](const RiserModel& m, double t) {
    const TopKinematics looked_up = m.topAt(t, cache), afresh = m.topAt(t);
    EXPECT_EQ(looked_up.position, afresh.position) << "t = " << t;
    EXPECT_EQ(looked_up.velocity, afresh.velocity) << "t = " << t;
    EXPECT_EQ(looked_up.acceleration, afresh.acceleration) << "t = " << t;
  };
  for (const double t : {3.0, 3.0, 12.5, 12.5, 3.0}) {
    expectSame(a, t);
    expectSame(a, t);
    expectSame(b, t);  // the same time, the other vessel
    expectSame(a, t);
  }
  EXPECT_NE(a.topAt(12.5).position, b.topAt(12.5).position);  // the two vessels do move differently
}

// A tensioner leaves the top's height free: the vessel's heave does not prescribe it.
TEST(RiserVessel, TensionerIgnoresTheVerticalMotion) {
  const double heave_and_surge[12] = {1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  RiserParameters p = vesselRiser(flatTable(30.0, heave_and_surge), "tensioner.csv");
  p.top_condition = "tensioner";
  const RiserModel m = buildRiserModel(p);
  const TopKinematics k = m.topAt(30.0);
  EXPECT_EQ(k.position.z(), m.top_mean.z());
  EXPECT_EQ(k.velocity.z(), 0.0);
  EXPECT_GT(std::abs(k.position.x() - m.top_mean.x()) + std::abs(k.position.y() - m.top_mean.y()), 1e-3);
}

TableSpec spec() { return TableSpec{"vessel.rao_file", "test.csv", "RAO columns"}; }

std::string errorsOf(const std::string& text) {
  std::vector<FieldError> errors;
  raoTableFromText(text, spec(), false, false, errors);
  std::string all;
  for (const FieldError& e : errors) all += e.path + " = " + e.value + ": " + e.message + "\n";
  return all;
}

TEST(RiserVessel, BadRaoTablesAreRefusedNamingLineAndColumn) {
  const double z[12] = {};
  // A column missing.
  std::string header = kHeader;
  header.replace(header.find(",yaw_phase"), 10, "");
  std::string text = header + "0,0.5,0,0,0,0,0,0,0,0,0,0,0\n";
  EXPECT_NE(errorsOf(text).find("missing: yaw_phase"), std::string::npos) << errorsOf(text);
  // Frequencies of one heading not increasing.
  text = std::string(kHeader) + row(0, 0.5, z) + row(0, 0.8, z) + row(0, 0.7, z);
  EXPECT_NE(errorsOf(text).find("line 4, column 2 (omega): must be greater than the previous row's 0.8"),
            std::string::npos)
      << errorsOf(text);
  // A negative amplitude.
  const double negative[12] = {0, 0, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0};
  text = std::string(kHeader) + row(0, 0.5, z) + row(0, 0.8, negative);
  EXPECT_NE(errorsOf(text).find("line 3, column 7 (heave_amplitude): must be ≥ 0 (an amplitude), found -0.5"),
            std::string::npos)
      << errorsOf(text);
  // Headings out of order, and a heading with other frequencies.
  text = std::string(kHeader) + row(90, 0.5, z) + row(0, 0.5, z);
  EXPECT_NE(errorsOf(text).find("in increasing heading"), std::string::npos) << errorsOf(text);
  text = std::string(kHeader) + row(0, 0.5, z) + row(0, 0.8, z) + row(90, 0.5, z) + row(90, 0.9, z);
  EXPECT_NE(errorsOf(text).find("other frequencies"), std::string::npos) << errorsOf(text);
  // Not a number, both omega and period, no rows.
  text = std::string(kHeader) + "0,abc,0,0,0,0,0,0,0,0,0,0,0,0\n";
  EXPECT_NE(errorsOf(text).find("line 2"), std::string::npos) << errorsOf(text);
  EXPECT_NE(errorsOf(std::string(kHeader)).find("no data rows"), std::string::npos);
  for (const std::string& e : {errorsOf(text), errorsOf(std::string(kHeader))})
    EXPECT_EQ(e.rfind("vessel.rao_file = \"test.csv\"", 0), 0u) << e;
}

// The scenario-level checks name their fields: no waves, no file, a file that is not there, a bad file's content.
TEST(RiserVessel, ScenarioChecksNameTheirFields) {
  const double heave[12] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  RiserParameters p = vesselRiser(flatTable(0.0, heave), "checks.csv");
  p.wave_type = "none";
  auto has = [](const std::vector<FieldError>& errors, const std::string& path, const std::string& text) {
    for (const FieldError& e : errors)
      if (e.path == path && e.message.find(text) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(has(checkRiserParameters(p), "top.motion", "needs waves.type"));
  p.vessel_rao_file = "";
  EXPECT_TRUE(has(checkRiserParameters(p), "vessel.rao_file", "must name a CSV"));
  p.vessel_rao_file = "/nonexistent/rao.csv";
  EXPECT_TRUE(has(checkRiserParameters(p), "vessel.rao_file", "is not a readable file"));
  p.vessel_rao_file = writeTemporary("bad.csv", std::string(kHeader) + "0,0.5,0,0,0,0,-1,0,0,0,0,0,0,0\n");
  EXPECT_TRUE(has(checkRiserParameters(p), "vessel.rao_file", "must be ≥ 0"));
}

// A period column (increasing periods) is the same table as the omega column; amplitude and phase are linear in
// frequency and in heading (phases along the shorter arc), headings wrap round 360.
TEST(RiserVessel, InterpolationInFrequencyAndHeading) {
  const double a0[12] = {1, 350, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0};
  const double a1[12] = {3, 10, 0, 0, 4, 40, 0, 0, 0, 0, 0, 0};
  const double b0[12] = {5, 0, 0, 0, 6, 0, 0, 0, 0, 0, 0, 0};
  const double b1[12] = {7, 0, 0, 0, 8, 0, 0, 0, 0, 0, 0, 0};
  std::vector<FieldError> errors;
  const std::string by_omega = std::string(kHeader) + row(0, 0.5, a0) + row(0, 1.0, a1) + row(180, 0.5, b0) + row(180, 1.0, b1);
  const RaoTable t = raoTableFromText(by_omega, spec(), false, false, errors);
  ASSERT_TRUE(errors.empty());
  // Periods must increase down a heading's rows (6.28 after 12.57 is refused); increasing ones are read and reversed.
  std::string decreasing = std::string(kHeader) + row(0, 4 * pi, a0) + row(0, 2 * pi, a1);
  decreasing.replace(decreasing.find("omega"), 5, "period");
  EXPECT_NE(errorsOf(decreasing).find("must be greater than the previous row's"), std::string::npos);
  const std::string increasing_periods = std::string(kHeader) + row(0, 2 * pi, a1) + row(0, 4 * pi, a0) +
                                         row(180, 2 * pi, b1) + row(180, 4 * pi, b0);
  std::string periods = increasing_periods;
  periods.replace(periods.find("omega"), 5, "period");
  const RaoTable tp = raoTableFromText(periods, spec(), false, false, errors);
  ASSERT_TRUE(errors.empty()) << errors.front().message;
  const double degree = pi / 180;
  for (const RaoTable* table : {&t, &tp}) {
    // Halfway in frequency at heading 0: surge 2 m/m, phase 0 (350° and 10° along the shorter arc); heave 3, 20°.
    const RaoValue mid = interpolateRao(*table, 0.0, 0.75);
    EXPECT_NEAR(mid.amplitude[0], 2.0, 1e-12);
    EXPECT_NEAR(std::remainder(mid.phase_lag[0], 2 * pi), 0.0, 1e-12);
    EXPECT_NEAR(mid.amplitude[2], 3.0, 1e-12);
    EXPECT_NEAR(mid.phase_lag[2], 20 * degree, 1e-12);
    // Heading 90 (halfway between 0 and 180) at ω = 1: surge (3 + 7)/2, heave (4 + 8)/2 with phase 20°.
    const RaoValue h90 = interpolateRao(*table, 90.0, 1.0);
    EXPECT_NEAR(h90.amplitude[0], 5.0, 1e-12);
    EXPECT_NEAR(h90.amplitude[2], 6.0, 1e-12);
    EXPECT_NEAR(h90.phase_lag[2], 20 * degree, 1e-12);
    // Heading 270 wraps between 180 and 360 (= 0): the same as 90 here; −90 is 270.
    EXPECT_NEAR(interpolateRao(*table, 270.0, 1.0).amplitude[0], 5.0, 1e-12);
    EXPECT_NEAR(interpolateRao(*table, -90.0, 1.0).amplitude[2], 6.0, 1e-12);
    // Outside the frequencies: the end row, flagged.
    bool outside = false;
    EXPECT_NEAR(interpolateRao(*table, 0.0, 3.0, &outside).amplitude[2], 4.0, 1e-12);
    EXPECT_TRUE(outside);
  }
  // Rotations in deg/m become rad/m; rad/m stay; a lead phase changes sign.
  const double roll[12] = {0, 0, 0, 0, 0, 0, 2, 30, 0, 0, 0, 0};
  const std::string text = flatTable(0.0, roll);
  const RaoTable deg = raoTableFromText(text, spec(), false, false, errors);
  const RaoTable rad = raoTableFromText(text, spec(), true, true, errors);
  EXPECT_NEAR(deg.amplitude[3][0], 2 * degree, 1e-15);
  EXPECT_NEAR(rad.amplitude[3][0], 2.0, 1e-15);
  EXPECT_NEAR(rad.phase_lag[3][0], -30 * degree, 1e-15);
}

// Headings covering only part of the circle: a relative direction beyond them takes the nearer end heading and is
// warned about; so are wave components beyond the frequencies.
TEST(RiserVessel, DirectionsAndFrequenciesOutsideTheTableAreWarned) {
  const double heave[12] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  const std::string text = std::string(kHeader) + row(0, 0.4, heave) + row(0, 1.0, heave) + row(45, 0.4, heave) +
                           row(45, 1.0, heave);
  RiserParameters p = vesselRiser(text, "partial.csv");
  p.wave_direction_deg = 120.0;
  const RiserModel m = buildRiserModel(p);
  ASSERT_EQ(m.vessel->warnings.size(), 2u);
  EXPECT_NE(m.vessel->warnings[0].find("outside the RAO frequencies [0.4, 1]"), std::string::npos) << m.vessel->warnings[0];
  EXPECT_NE(m.vessel->warnings[1].find("relative wave direction 120"), std::string::npos) << m.vessel->warnings[1];
}

// The automatic step under a vessel-driven top: 50 implicit steps per mean wave period T_m01 = 2π m0/m1 of the
// synthesised sea (as under a harmonic top), not end_time/200.
TEST(RiserVessel, AutomaticImplicitStepResolvesTheMeanWavePeriod) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_vessel_rao_sea.json");
  p.time_step = 0.0;
  p.end_time = 600.0;
  p.frame_count = 600;
  const RiserModel m = buildRiserModel(p);
  double m0 = 0.0, m1 = 0.0;
  for (const auto& c : m.sea->field.components()) {
    m0 += 0.5 * c.amplitude * c.amplitude;
    m1 += 0.5 * c.amplitude * c.amplitude * c.omega;
  }
  const double mean_period = 2 * pi * m0 / m1;
  EXPECT_NEAR(m.vessel->mean_period, mean_period, 1e-12 * mean_period);
  EXPECT_GT(mean_period, 7.0);  // JONSWAP Tp = 11 s, γ = 3.3: T_m01 ≈ 0.77 Tp
  EXPECT_LT(mean_period, 10.0);
  const IntegrationPlan plan = planIntegration(m, p);
  EXPECT_LE(plan.step, mean_period / 50 * (1 + 1e-12));
  EXPECT_GT(plan.step, mean_period / 100);  // rounded down to whole steps per 1 s frame only
}

// Waves without a vessel set the automatic step the same way (it used to be end_time/200: 3 s in an 11 s sea
// over 600 s).
TEST(RiserVessel, AutomaticImplicitStepResolvesTheMeanWavePeriodWithoutAVessel) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_jonswap_sea.json");
  p.time_step = 0.0;
  p.end_time = 600.0;
  p.frame_count = 600;
  const RiserModel m = buildRiserModel(p);
  ASSERT_TRUE(m.sea);
  ASSERT_FALSE(m.vessel);
  const double mean_period = m.sea->field.meanPeriod();
  EXPECT_GT(mean_period, 7.0);
  EXPECT_LT(mean_period, 11.0);
  const IntegrationPlan plan = planIntegration(m, p);
  EXPECT_LE(plan.step, mean_period / 50 * (1 + 1e-12));
  EXPECT_GT(plan.step, mean_period / 100);
}

// The built-in floater case, 12 s: the integrated riser's top (a tensioner: horizontal motion prescribed) is where
// the vessel puts it at every history sample, and the run warns of nothing (the RAO table covers the sea's band).
TEST(RiserVessel, BuiltInRunMovesTheTopWithTheVessel) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_vessel_rao_sea.json");
  p.end_time = 12.0;
  p.stress_times = {12.0};
  p.frame_count = 12;
  EXPECT_TRUE(checkRiserParameters(p).empty());
  const RiserModel m = buildRiserModel(p);
  ASSERT_TRUE(m.vessel);
  EXPECT_TRUE(m.vessel->warnings.empty());
  RunContext context;
  const Results r = solveRiser(p, context);
  const Table& history = *r.findTable("history");
  const auto& time = history.find("time")->values;
  const auto& top_x = history.find("top_x")->values;
  const auto& top_y = history.find("top_y")->values;
  double moved = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    const TopKinematics top = m.topAt(time[k]);
    EXPECT_NEAR(top_x[k], top.position.x(), 1e-9) << "t = " << time[k];
    EXPECT_NEAR(top_y[k], top.position.y(), 1e-9) << "t = " << time[k];
    moved = std::max(moved, std::hypot(top_x[k] - m.top_mean.x(), top_y[k] - m.top_mean.y()));
  }
  EXPECT_GT(moved, 0.01);  // the ramp has started the motion by 12 s
  EXPECT_NEAR(m.top_mean.x(), 10.0, 1e-12);  // the static offset
}

}  // namespace
}  // namespace maris::riser
