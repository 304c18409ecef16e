// Plausibility warnings of the riser: valid settings the model doubts are named with their field and the
// number that makes them doubtful (closed forms: the top of a straight vertical riser is at z_anchor + L; the
// deep-water wave length is g T²/2π), and never refuse the run.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "catalog.hpp"
#include "core/scene.hpp"

namespace maris {
namespace {

std::vector<FieldError> warningsOf(const std::string& builtin, const std::vector<std::string>& overrides) {
  Scenario s = findBuiltin(builtin)->scenario;
  for (const auto& o : overrides) applyOverride(s, o);
  EXPECT_TRUE(validateParameters(requireScene(s.scene), s.parameters).empty()) << builtin;
  return plausibilityWarnings(requireScene(s.scene), s.parameters);
}

const FieldError* at(const std::vector<FieldError>& warnings, const std::string& path) {
  for (const auto& w : warnings)
    if (w.path == path) return &w;
  return nullptr;
}

TEST(RiserPlausibility, TheDefaultRiserRaisesNone) {
  const auto w = warningsOf("riser_default", {});
  EXPECT_TRUE(w.empty()) << describeErrors(w);
}

TEST(RiserPlausibility, ARiserLongerThanTheDepthHasItsTopInTheAir) {
  // 120 m on a tensioner from the sea bed at -100 m: the top stands at -100 + 120 = +20 m.
  const auto w = warningsOf("riser_default", {"geometry.length=120"});
  const FieldError* top = at(w, "parameters.geometry.length");
  ASSERT_NE(top, nullptr) << describeErrors(w);
  EXPECT_NE(top->message.find("20 m above the still-water level"), std::string::npos) << top->message;
}

TEST(RiserPlausibility, AnchorsUnderOrFarAboveTheSeaBed) {
  const auto under = warningsOf("riser_default", {"bottom.z=-105", "geometry.length=104"});
  ASSERT_NE(at(under, "parameters.bottom.z"), nullptr) << describeErrors(under);
  EXPECT_NE(at(under, "parameters.bottom.z")->message.find("5 m below the sea bed"), std::string::npos);
  const auto mid = warningsOf("riser_default", {"bottom.z=-50", "geometry.length=100"});
  ASSERT_NE(at(mid, "parameters.bottom.z"), nullptr) << describeErrors(mid);
  EXPECT_NE(at(mid, "parameters.bottom.z")->message.find("50 m above the sea bed"), std::string::npos);
}

TEST(RiserPlausibility, ACurrentFasterThanTheOceansIsNamed) {
  EXPECT_TRUE(warningsOf("riser_default", {"current.speed_surface=2.9"}).empty());
  const auto w = warningsOf("riser_default", {"current.speed_surface=4"});
  EXPECT_NE(at(w, "parameters.current.speed_surface"), nullptr) << describeErrors(w);
}

TEST(RiserPlausibility, AWaveSteeperThanTheBreakingLimit) {
  // T = 5 s in 100 m of water is deep water: λ = g T²/2π = 39.0 m (tanh(kd) = 1 to 1e-13), so H = 10 m is
  // H/λ = 0.256 > 1/7, and H = 5 m is 0.128 < 1/7.
  const double lambda = 9.81 * 25 / (2 * std::numbers::pi);
  const auto steep = warningsOf("riser_default", {"waves.type=\"airy\"", "waves.period=5", "waves.height=10"});
  const FieldError* w = at(steep, "parameters.waves.height");
  ASSERT_NE(w, nullptr) << describeErrors(steep);
  char expected[64];
  std::snprintf(expected, sizeof expected, "H/λ = %.4g", 10 / lambda);
  EXPECT_NE(w->message.find(expected), std::string::npos) << w->message << " (expected " << expected << ")";
  EXPECT_TRUE(warningsOf("riser_default", {"waves.type=\"airy\"", "waves.period=5", "waves.height=5"}).empty());
}

TEST(RiserPlausibility, AModelInAirRaisesNone) {
  // The cantilever benchmark is a beam in air, with no water near it.
  const auto w = warningsOf("riser_cantilever_tip_load", {});
  EXPECT_TRUE(w.empty()) << describeErrors(w);
}

TEST(RiserPlausibility, WarningsReachTheRunButDoNotStopIt) {
  Scenario s = findBuiltin("riser_default")->scenario;
  applyOverride(s, "current.speed_surface=4");
  applyOverride(s, "solver.end_time=0.5");
  RunContext context({}, nullptr);
  const Results r = runScenario(requireScene(s.scene), s, context);
  bool found = false;
  for (const auto& w : r.warnings) found = found || w.find("parameters.current.speed_surface") != std::string::npos;
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace maris
