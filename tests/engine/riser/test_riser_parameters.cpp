// Bad input gives field errors naming the path and the allowed range; good input passes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/resources.hpp"
#include "core/scene.hpp"
#include "riser/riser_parameters.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

Json defaults() { return riserBinder().write(RiserParameters{}); }

using test::hasErrorAt;

std::string describe(const std::vector<FieldError>& errors) { return describeErrors(errors); }

TEST(RiserParameters, DefaultsAreValid) {
  const auto errors = validateParameters(makeRiserScene(), defaults());
  EXPECT_TRUE(errors.empty()) << describe(errors);
}

TEST(RiserParameters, EveryBuiltInScenarioIsValid) {
  const SceneDefinition scene = makeRiserScene();
  int count = 0;
  for (const auto& path : builtinResourcePaths()) {
    if (path.rfind("scenarios/riser/", 0) != 0) continue;
    const Scenario s = scenarioFromText(std::string(*builtinResource(path)), path);
    const auto errors = validateParameters(scene, s.parameters);
    EXPECT_TRUE(errors.empty()) << path << ":\n" << describe(errors);
    ++count;
  }
  EXPECT_GE(count, 1);
}

TEST(RiserParameters, TooFewSegmentsNamesTheFieldAndRange) {
  Json j = defaults();
  j["geometry"]["segment_count"] = 1;
  const auto errors = validateParameters(makeRiserScene(), j);
  ASSERT_TRUE(hasErrorAt(errors, "parameters.geometry.segment_count")) << describe(errors);
  EXPECT_NE(describe(errors).find("[2, 5000]"), std::string::npos) << describe(errors);
}

TEST(RiserParameters, InnerDiameterMustBeBelowOuter) {
  Json j = defaults();
  j["section"]["inner_diameter"] = 0.6;
  const auto errors = validateParameters(makeRiserScene(), j);
  EXPECT_TRUE(hasErrorAt(errors, "parameters.section.inner_diameter")) << describe(errors);
}

TEST(RiserParameters, NegativeDiameterZeroLengthAndNaNAreRejected) {
  Json j = defaults();
  j["section"]["outer_diameter"] = -0.5;
  j["geometry"]["length"] = 0.0;
  j["top"]["tension"] = std::numeric_limits<double>::quiet_NaN();
  const auto errors = validateParameters(makeRiserScene(), j);
  EXPECT_TRUE(hasErrorAt(errors, "parameters.section.outer_diameter")) << describe(errors);
  EXPECT_TRUE(hasErrorAt(errors, "parameters.geometry.length")) << describe(errors);
  EXPECT_TRUE(hasErrorAt(errors, "parameters.top.tension")) << describe(errors);
}

TEST(RiserParameters, SectionRowsAreChecked) {
  RiserParameters p;
  SectionRow row;
  row.start = 50.0;
  row.end = 40.0;
  row.inner_diameter = 0.7;
  p.sections = {row};
  const auto errors = checkRiserParameters(p);
  EXPECT_TRUE(hasErrorAt(errors, "sections[0].end")) << describe(errors);
  EXPECT_TRUE(hasErrorAt(errors, "sections[0].inner_diameter")) << describe(errors);
}

TEST(RiserParameters, UnreachableAnchorIsRejected) {
  RiserParameters p;
  p.top_condition = "pinned";
  p.bottom_condition = "pinned";
  p.bottom_z = -p.length;  // exactly L away: a taut inextensible chain is singular
  EXPECT_TRUE(hasErrorAt(checkRiserParameters(p), "bottom.z"));
  p.bottom_z = -0.9 * p.length;
  EXPECT_FALSE(hasErrorAt(checkRiserParameters(p), "bottom.z"));
}

TEST(RiserParameters, PointLoadNodeMustExist) {
  RiserParameters p;
  PointLoadRow l;
  l.node = p.segment_count + 2;
  p.point_loads = {l};
  EXPECT_TRUE(hasErrorAt(checkRiserParameters(p), "point_loads[0].node"));
}

}  // namespace
}  // namespace maris::riser
