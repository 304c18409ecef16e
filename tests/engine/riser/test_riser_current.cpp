// Current profile as a table (riser_current): the linear profile is its two-row case, evaluated bit for bit as the
// linear formula (speed_surface + f (speed_seabed − speed_surface), f = (water_level − z)/depth clamped to [0, 1]);
// a two-row table gives the same bits; between rows speed and heading are linear in depth (heading along the
// shorter arc); the end rows hold beyond the table; nothing above the water; bad tables name their row.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/run_context.hpp"
#include "core/scene.hpp"
#include "riser/riser_current.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_plausibility.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "riser_test_support.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

RiserParameters linearCurrent() {
  RiserParameters p;
  p.water_level = 2.0;
  p.seabed_level = -300.0;
  p.current_speed_surface = 0.5;
  p.current_speed_seabed = 0.1;
  p.current_direction_deg = 30.0;
  return p;
}

// The linear formula the riser used before the table existed (its code, verbatim in arithmetic).
Vec3 linearFormula(const RiserParameters& p, double z) {
  if (z > p.water_level) return Vec3::Zero();
  const double depth = p.water_level - p.seabed_level;
  const double f = depth > 0 ? std::clamp((p.water_level - z) / depth, 0.0, 1.0) : 0.0;
  const double speed = p.current_speed_surface + f * (p.current_speed_seabed - p.current_speed_surface);
  const double direction = p.current_direction_deg * (pi / 180.0);
  return speed * Vec3(std::cos(direction), std::sin(direction), 0.0);
}

TEST(RiserCurrent, LinearTypeAndTwoRowTableAreTheLinearFormulaBitForBit) {
  const RiserParameters linear = linearCurrent();
  RiserParameters table = linear;
  table.current_type = "table";
  table.current_profile = {{0.0, 0.5, 30.0}, {302.0, 0.1, 30.0}};
  EXPECT_TRUE(checkRiserParameters(table).empty());
  const RiserModel a = buildRiserModel(linear), b = buildRiserModel(table);
  for (int j = 0; j <= 4000; ++j) {
    const double z = 10.0 - 0.0813 * j;  // above the water, through the column, below the sea bed
    const Vec3 expected = linearFormula(linear, z);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(a.currentAt(z)[c], expected[c]) << "z = " << z;
      EXPECT_EQ(b.currentAt(z)[c], expected[c]) << "z = " << z;
    }
  }
  // No depth (sea bed at the water level): the surface speed everywhere in the water, as f = 0 gave.
  RiserParameters flat = linear;
  flat.seabed_level = flat.water_level;
  const RiserModel c = buildRiserModel(flat);
  for (double z : {2.0, 0.0, -50.0, -400.0}) EXPECT_EQ(c.currentAt(z), linearFormula(flat, z)) << z;
}

// Rows (0 m, 1 m/s, 350°), (100 m, 0.5 m/s, 10°), (200 m, 0, 10°): at 50 m 0.75 m/s towards 0° (350° → 10° the
// short way), at 150 m 0.25 m/s towards 10°, below 200 m nothing, at and above the first row 1 m/s towards 350°.
TEST(RiserCurrent, TableInterpolatesSpeedAndHeadingBetweenRows) {
  RiserParameters p = linearCurrent();
  p.water_level = 0.0;
  p.current_type = "table";
  p.current_profile = {{0.0, 1.0, 350.0}, {100.0, 0.5, 10.0}, {200.0, 0.0, 10.0}};
  EXPECT_TRUE(checkRiserParameters(p).empty());
  const CurrentProfile c = buildCurrentProfile(p);
  const double d = pi / 180;
  auto towards = [&](double speed, double deg) { return Vec3(speed * std::cos(deg * d), speed * std::sin(deg * d), 0); };
  EXPECT_LT((c.at(-50.0) - towards(0.75, 0.0)).norm(), 1e-15);
  EXPECT_LT((c.at(-25.0) - towards(0.875, 355.0)).norm(), 1e-15);
  EXPECT_LT((c.at(-150.0) - towards(0.25, 10.0)).norm(), 1e-15);
  EXPECT_LT(c.at(-250.0).norm(), 1e-15);
  EXPECT_LT((c.at(0.0) - towards(1.0, 350.0)).norm(), 1e-15);
  EXPECT_EQ(c.at(0.5), Vec3::Zero());
  EXPECT_EQ(c.max_speed, 1.0);
  // A table starting below the surface holds its first row up to the water level; one row is uniform.
  p.current_profile = {{20.0, 0.8, 90.0}};
  const CurrentProfile one = buildCurrentProfile(p);
  EXPECT_LT((one.at(-5.0) - towards(0.8, 90.0)).norm(), 1e-15);
  EXPECT_LT((one.at(-500.0) - towards(0.8, 90.0)).norm(), 1e-15);
}

TEST(RiserCurrent, BadTablesNameTheirRow) {
  RiserParameters p = linearCurrent();
  p.current_type = "table";
  auto messages = [](const std::vector<FieldError>& errors) {
    std::string all;
    for (const FieldError& e : errors) all += e.path + " = " + e.value + ": " + e.message + "\n";
    return all;
  };
  EXPECT_NE(messages(checkRiserParameters(p)).find("current.profile = 0 rows: current.type = table needs at least 1 row"),
            std::string::npos);
  p.current_profile = {{0.0, 1.0, 0.0}, {50.0, 1.0, 0.0}, {50.0, 0.5, 0.0}};
  EXPECT_NE(messages(checkRiserParameters(p)).find(
                "current.profile[2].depth = 50: must be greater than the previous row's depth 50"),
            std::string::npos)
      << messages(checkRiserParameters(p));
}

// A row faster than ocean currents (3 m/s) is named by the plausibility warnings; the unused linear fields are not.
TEST(RiserCurrent, ImplausibleRowSpeedIsWarned) {
  RiserParameters p = linearCurrent();
  p.current_type = "table";
  p.current_speed_surface = 5.0;
  p.current_profile = {{0.0, 1.0, 0.0}, {100.0, 3.5, 0.0}};
  int rows = 0, linear = 0;
  for (const FieldError& w : riserPlausibility(p)) {
    rows += w.path == "current.profile[1].speed";
    linear += w.path.rfind("current.speed", 0) == 0;
  }
  EXPECT_EQ(rows, 1);
  EXPECT_EQ(linear, 0);
}

// A file from before the table: type linear added with a note, and the same model.
TEST(RiserCurrent, FilesWithoutTheTableLoadAsLinear) {
  const SceneDefinition scene = makeRiserScene();
  Json old = riserBinder().write(linearCurrent());
  old["current"].erase("type");
  old["current"].erase("profile");
  old.erase("vessel");
  Json upgraded = old;
  const std::vector<std::string> notes = upgradeParameters(scene, upgraded);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("current.type = linear added"), std::string::npos);
  EXPECT_NE(notes[1].find("vessel added"), std::string::npos);
  EXPECT_TRUE(validateParameters(scene, upgraded).empty()) << describeErrors(validateParameters(scene, upgraded));
  EXPECT_EQ(riserBinder().read(upgraded).current_type, "linear");
  EXPECT_TRUE(upgradeParameters(scene, upgraded).empty()) << "a second upgrade has nothing to do";
}

// The default riser with a current falling from 1 m/s to 0.2 m/s, rerun with that linear profile as a two-row
// table: every table of the results (history, frames, stresses) the same bit for bit. Under the sanitizers over
// 2 s instead of 6 s (the same code runs from the first step).
TEST(RiserCurrent, RunWithTheLinearProfileAsATableIsBitIdentical) {
  RiserParameters linear = test::builtinParameters("scenarios/riser/riser_default.json");
  linear.current_speed_seabed = 0.2;
  linear.current_direction_deg = 20.0;
  linear.end_time = ::maris::test::kSanitizedBuild ? 2.0 : 6.0;
  linear.stress_times = {linear.end_time / 2, linear.end_time};
  RiserParameters table = linear;
  table.current_type = "table";
  table.current_profile = {{0.0, linear.current_speed_surface, linear.current_direction_deg},
                           {linear.water_level - linear.seabed_level, linear.current_speed_seabed,
                            linear.current_direction_deg}};
  RunContext ca, cb;
  const Results a = solveRiser(linear, ca), b = solveRiser(table, cb);
  ASSERT_EQ(a.tables.size(), b.tables.size());
  std::size_t compared = 0;
  for (std::size_t k = 0; k < a.tables.size(); ++k) {
    const Table& ta = a.tables[k];
    const Table& tb = b.tables[k];
    ASSERT_EQ(ta.columns.size(), tb.columns.size()) << ta.name;
    for (std::size_t c = 0; c < ta.columns.size(); ++c) {
      ASSERT_EQ(ta.columns[c].values.size(), tb.columns[c].values.size());
      for (std::size_t r = 0; r < ta.columns[c].values.size(); ++r, ++compared)
        ASSERT_EQ(ta.columns[c].values[r], tb.columns[c].values[r]) << ta.name << "." << ta.columns[c].name << " row " << r;
    }
  }
  EXPECT_GT(compared, 1000u);
}

}  // namespace
}  // namespace maris::riser
