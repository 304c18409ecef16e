// Scenario files written for earlier riser schemas load into the same model: the angles that were radians
// (current.direction, top.motion_phase_x/y/z, initial.inclination, initial.azimuth) are read as their *_deg
// fields, a file without a tangential added-mass coefficient keeps its isotropic added mass, one without
// output.modes computes the modes as before, and one without the fatigue sampling interval and user S-N curve
// fields gets their defaults (automatic sampling; the table curve it names).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/angles.hpp"
#include "core/scene.hpp"
#include "riser/riser_fatigue.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_parameters.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

// A new file with every renamed angle away from zero; pinned top and free bottom, so the initial shape follows
// initial.inclination/azimuth.
Json newFile() {
  RiserParameters p;
  p.top_condition = "pinned";
  p.bottom_condition = "free";
  p.current_direction_deg = 30.0;
  p.motion_phase_x_deg = 10.0;
  p.motion_phase_y_deg = 100.0;
  p.motion_phase_z_deg = -45.0;
  p.motion_amplitude_z = 0.5;
  p.initial_inclination_deg = 60.0;
  p.initial_azimuth_deg = -120.0;
  return riserBinder().write(p);
}

struct Renamed {
  const char* section;
  const char* old_name;
  const char* new_name;
};
constexpr Renamed kRenamed[] = {{"current", "direction", "direction_deg"},
                                {"top", "motion_phase_x", "motion_phase_x_deg"},
                                {"top", "motion_phase_y", "motion_phase_y_deg"},
                                {"top", "motion_phase_z", "motion_phase_z_deg"},
                                {"initial", "inclination", "inclination_deg"},
                                {"initial", "azimuth", "azimuth_deg"}};

// The same file as an older schema wrote it: angles in radians under their former names.
Json oldFile(const Json& current) {
  Json old = current;
  for (const Renamed& r : kRenamed) {
    old[r.section][r.old_name] = radiansFromDegrees(old[r.section][r.new_name].get<double>());
    old[r.section].erase(r.new_name);
  }
  return old;
}

RiserModel modelOf(Json parameters) {
  upgradeParameters(makeRiserScene(), parameters);
  return buildRiserModel(riserBinder().read(parameters));
}

// Each renamed field: the old file (rad) gives the model of the new file (deg) to round-off (1e-14 rad on the
// angles; 1e-14 on the unit quaternions of the initial shape), with one note per field naming both spellings.
TEST(RiserUpgrade, AnglesInRadiansUnderTheirFormerNamesGiveTheSameModel) {
  const SceneDefinition scene = makeRiserScene();
  const Json current = newFile();
  Json upgraded = oldFile(current);
  EXPECT_TRUE(validateParameters(scene, upgraded).empty()) << describeErrors(validateParameters(scene, upgraded));
  const std::vector<std::string> notes = upgradeParameters(scene, upgraded);
  ASSERT_EQ(notes.size(), std::size(kRenamed));
  for (std::size_t k = 0; k < notes.size(); ++k) {
    const Renamed& r = kRenamed[k];
    EXPECT_NE(notes[k].find(std::string(r.section) + "." + r.old_name), std::string::npos) << notes[k];
    EXPECT_NE(notes[k].find(std::string(r.section) + "." + r.new_name), std::string::npos) << notes[k];
    EXPECT_FALSE(upgraded[r.section].contains(r.old_name));
    EXPECT_NEAR(upgraded[r.section][r.new_name].get<double>(), current[r.section][r.new_name].get<double>(), 1e-12)
        << r.new_name;
  }
  EXPECT_TRUE(upgradeParameters(scene, upgraded).empty()) << "a second upgrade has nothing to do";

  const RiserModel a = modelOf(current), b = modelOf(oldFile(current));
  EXPECT_NEAR(a.current_direction, radiansFromDegrees(30.0), 1e-15);
  EXPECT_NEAR(a.current_direction, b.current_direction, 1e-14);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.motion_phase[k], b.motion_phase[k], 1e-14) << "axis " << k;
  EXPECT_NEAR(a.motion_phase.y(), radiansFromDegrees(100.0), 1e-15);
  ASSERT_EQ(a.initial_orientation.size(), b.initial_orientation.size());
  for (std::size_t i = 0; i < a.initial_orientation.size(); ++i)
    EXPECT_LT((a.initial_orientation[i].coeffs() - b.initial_orientation[i].coeffs()).norm(), 1e-14) << "segment " << i;
  // The initial direction is what the angles say: 60° from straight down, heading −120° from +x.
  const Vec3 t = a.initial_orientation.front() * Vec3::UnitX();
  const double inclination = radiansFromDegrees(60.0), azimuth = radiansFromDegrees(-120.0);
  EXPECT_LT((t - Vec3(std::sin(inclination) * std::cos(azimuth), std::sin(inclination) * std::sin(azimuth),
                      -std::cos(inclination))).norm(), 1e-14);
}

// π/2 written as 1.5707963267948966 reads as exactly 90 (the upgrade rounds to 12 significant digits, a change
// below 5e-13 relative), so a saved upgraded file shows the round number.
TEST(RiserUpgrade, RightAngleInRadiansReadsAsNinetyDegrees) {
  Json old = newFile();
  old["top"].erase("motion_phase_y_deg");
  old["top"]["motion_phase_y"] = 1.5707963267948966;
  upgradeParameters(makeRiserScene(), old);
  EXPECT_EQ(old["top"]["motion_phase_y_deg"].get<double>(), 90.0);
}

// A file written before the tangential added mass had one isotropic C_a (the paper's eq 11): the section and every
// sections row get C_at = C_a, with a note, and the segments' axial mass equals their normal mass as before.
TEST(RiserUpgrade, FileWithoutTangentialAddedMassKeepsItsIsotropicAddedMass) {
  RiserParameters p;
  p.added_mass_coefficient = 0.8;
  SectionRow row;
  row.start = 40.0;
  row.end = 60.0;
  row.added_mass_coefficient = 1.5;
  p.sections = {row};
  Json old = riserBinder().write(p);
  old["section"].erase("tangential_added_mass_coefficient");
  old["sections"][0].erase("tangential_added_mass_coefficient");
  const std::vector<std::string> notes = upgradeParameters(makeRiserScene(), old);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("section.tangential_added_mass_coefficient = 0.8"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("sections rows"), std::string::npos) << notes[1];
  const RiserParameters q = riserBinder().read(old);
  EXPECT_EQ(q.tangential_added_mass_coefficient, 0.8);
  EXPECT_EQ(q.sections[0].tangential_added_mass_coefficient, 1.5);
  const RiserModel m = buildRiserModel(q);
  for (const Segment& s : m.segments) EXPECT_EQ(s.axial_mass, s.mass);
  // A new file (default C_at = 0) has less mass along the axis: ρ_w C_a A_out per metre.
  const RiserModel fresh = buildRiserModel(RiserParameters{});
  const Segment& s = fresh.segments[5];
  const double a_out = std::numbers::pi / 4 * 0.5 * 0.5;
  EXPECT_NEAR((s.mass - s.axial_mass) / s.length, 1025.0 * 1.0 * a_out, 1e-9);
}

// A file from before output.modes computed the modes: it gets output.modes = true with a note.
TEST(RiserUpgrade, FileWithoutModesSwitchComputesTheModes) {
  Json old = riserBinder().write(RiserParameters{});
  old["output"].erase("modes");
  const std::vector<std::string> notes = upgradeParameters(makeRiserScene(), old);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("output.modes"), std::string::npos) << notes[0];
  EXPECT_TRUE(old["output"]["modes"].get<bool>());
}

// A file from before fatigue.sample_interval and the user S-N curve: the fields are added with their defaults
// and one note; its curve stays the table curve it names.
TEST(RiserUpgrade, FileWithoutFatigueSamplingOrUserCurveGetsTheDefaults) {
  RiserParameters p;
  p.fatigue_enabled = true;
  p.fatigue_sn_curve = "D";
  Json old = riserBinder().write(p);
  for (const char* field : {"sample_interval", "user_log_a1", "user_m1", "user_log_a2", "user_m2",
                            "user_transition_cycles", "user_thickness_exponent", "user_reference_thickness"})
    old["fatigue"].erase(field);
  const std::vector<std::string> notes = upgradeParameters(makeRiserScene(), old);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("fatigue.sample_interval"), std::string::npos) << notes[0];
  const RiserParameters q = riserBinder().read(old);
  EXPECT_EQ(q.fatigue_sample_interval, 0.0);
  EXPECT_EQ(q.fatigue_user_m1, RiserParameters{}.fatigue_user_m1);
  EXPECT_EQ(fatigueCurve(q).name, "DNVGL-RP-C203 D in seawater with cathodic protection");
}

}  // namespace
}  // namespace maris::riser
