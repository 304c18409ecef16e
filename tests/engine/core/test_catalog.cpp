// Properties every registered scene and built-in scenario must have, whatever the scene:
// a complete schema (unit, description, default inside its range, a short label where one is declared) and valid
// examples.
#include <gtest/gtest.h>

#include <set>

#include "catalog.hpp"

namespace maris {
namespace {

void expectSpecComplete(const ParamSpec& f, const std::string& scene) {
  SCOPED_TRACE(scene + ": " + f.path);
  EXPECT_FALSE(f.description.empty()) << "every field needs a one-line description";
  if (f.kind == ParamKind::Real || f.kind == ParamKind::Integer || f.kind == ParamKind::RealList) {
    EXPECT_FALSE(f.unit.empty()) << "numbers need a unit (\"-\" when dimensionless)";
  }
  if (f.kind == ParamKind::Real || f.kind == ParamKind::Integer) {
    EXPECT_TRUE(f.range.contains(f.default_value.get<double>())) << "default outside " << f.range.str();
  }
  if (f.kind == ParamKind::Choice) {
    EXPECT_NE(std::find(f.choices.begin(), f.choices.end(), f.default_value.get<std::string>()), f.choices.end());
  }
  // A declared label names the field in plots and legends: short, and no path or unit of its own (the unit is
  // added beside it).
  if (!f.label.empty()) {
    EXPECT_LE(f.label.size(), 40u) << f.label;
    EXPECT_EQ(f.label.find('.'), std::string::npos) << f.label;
    EXPECT_EQ(f.label.find('['), std::string::npos) << f.label;
  }
  EXPECT_FALSE(parameterLabel(f).empty());
  for (const auto& c : f.columns) expectSpecComplete(c, scene);
}

TEST(Catalog, SceneNamesAreUniqueAndEverySchemaIsComplete) {
  std::set<std::string> names;
  for (const auto& s : sceneCatalog()) {
    EXPECT_TRUE(names.insert(s.name).second) << "duplicate scene " << s.name;
    EXPECT_FALSE(s.title.empty());
    EXPECT_TRUE(static_cast<bool>(s.run)) << s.name;
    std::set<std::string> paths;
    for (const auto& f : s.schema.fields) {
      EXPECT_TRUE(paths.insert(f.path).second) << "duplicate path " << f.path;
      expectSpecComplete(f, s.name);
    }
  }
}

// One angle convention for every scene (README): user-facing angles are degrees, in fields whose name ends in _deg
// (rates too: "yaw_rate_deg" [deg/s]); no field is in radians. Angular frequencies (rad/s) and per-radian
// stiffnesses are SI rates and coefficients, not angles, and keep their units.
void expectAngleConvention(const ParamSpec& f, const std::string& scene) {
  SCOPED_TRACE(scene + ": " + f.path);
  EXPECT_NE(f.unit, "rad") << "angles are degrees (field " << f.key() << "_deg, unit deg)";
  if (f.unit == "deg" || f.unit == "deg/s") {
    const std::string key = f.key();
    EXPECT_TRUE(key.size() > 4 && key.compare(key.size() - 4, 4, "_deg") == 0)
        << "a field in " << f.unit << " must say so in its name (ends in _deg)";
  }
  for (const auto& c : f.columns) expectAngleConvention(c, scene);
}

TEST(Catalog, EveryAngleIsInDegreesAndSaysSoInItsName) {
  int angles = 0;
  for (const auto& s : sceneCatalog())
    for (const auto& f : s.schema.fields) {
      expectAngleConvention(f, s.name);
      angles += f.unit == "deg" || f.unit == "deg/s";
      for (const auto& c : f.columns) angles += c.unit == "deg" || c.unit == "deg/s";
    }
  EXPECT_GE(angles, 6) << "the riser alone has six angles";
}

TEST(Catalog, EverySceneDefaultScenarioValidates) {
  for (const auto& s : sceneCatalog()) {
    const auto errors = validateParameters(s, defaultScenario(s).parameters);
    EXPECT_TRUE(errors.empty()) << s.name << ":\n" << describeErrors(errors);
  }
}

TEST(Catalog, EveryBuiltInScenarioValidatesAndRoundTrips) {
  std::set<std::string> ids;
  for (const auto& b : builtinScenarios()) {
    EXPECT_TRUE(ids.insert(b.id).second) << "duplicate id " << b.id;
    EXPECT_FALSE(b.scenario.name.empty()) << b.id;
    EXPECT_FALSE(b.scenario.description.empty()) << b.id << ": say what the case is and what was assumed";
    const auto errors = validateParameters(requireScene(b.scenario.scene), b.scenario.parameters);
    EXPECT_TRUE(errors.empty()) << b.id << ":\n" << describeErrors(errors);
    EXPECT_EQ(scenarioToJson(scenarioFromText(scenarioToText(b.scenario))), scenarioToJson(b.scenario)) << b.id;
  }
}

TEST(Catalog, BuiltInScenariosRaiseNoPlausibilityWarningUnlessTheyExplainIt) {
  // A shipped example runs clean; one whose point is a doubtful setting says so in its description.
  for (const auto& b : builtinScenarios()) {
    const auto warnings = plausibilityWarnings(requireScene(b.scenario.scene), b.scenario.parameters);
    if (warnings.empty()) continue;
    EXPECT_NE(b.scenario.description.find("warn"), std::string::npos)
        << b.id << " warns without saying why:\n" << describeErrors(warnings);
  }
}

TEST(Catalog, EverySceneDeclaresPlausibilityChecks) {
  // Each scene names the valid settings its model doubts (its own <scene>_plausibility.cpp); a scene without
  // them would let every built-in pass the test above without being looked at.
  for (const auto& s : sceneCatalog()) EXPECT_TRUE(static_cast<bool>(s.plausibility)) << s.name;
}

TEST(Catalog, EverySceneHasAnExampleAndTheDefaultExists) {
  for (const auto& s : sceneCatalog()) {
    bool found = false;
    for (const auto& b : builtinScenarios()) found = found || b.scenario.scene == s.name;
    EXPECT_TRUE(found) << s.name << " has no built-in scenario";
  }
  if (!sceneCatalog().empty()) {
    EXPECT_NO_THROW(defaultBuiltin());
  }
}

TEST(Catalog, UnknownSceneErrorListsKnownScenes) {
  try {
    requireScene("spaceship");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a known scene"), std::string::npos);
  }
}

}  // namespace
}  // namespace maris
