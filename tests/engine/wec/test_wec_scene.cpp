// The registered scene: built-in scenarios validate and run, results are self-consistent, bad input is reported
// field by field, cancellation is honoured.
#include <gtest/gtest.h>

#include <atomic>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "wec_test_models.hpp"

using namespace maris;

namespace {
using wec_test::scene;
Scenario builtin(const std::string& id) {
  const BuiltinScenario* b = findBuiltin(id);
  EXPECT_NE(b, nullptr) << id;
  return b ? b->scenario : Scenario{};
}
}  // namespace

// Every built-in wec scenario passes validation (all parameters present, in range, cross-checks satisfied).
TEST(WecScene, BuiltinScenariosAreValid) {
  int count = 0;
  for (const auto& b : builtinScenarios()) {
    if (b.scenario.scene != "wec") continue;
    EXPECT_TRUE(validateParameters(scene(), b.scenario.parameters).empty()) << b.id;
    ++count;
  }
  EXPECT_GE(count, 3);
}

// A file from before waves.discretisation loads as random_frequency, with a note; a second upgrade does nothing.
TEST(WecScene, FilesWithoutTheDiscretisationLoadAsRandomFrequency) {
  Json old = builtin("wec_irregular").parameters;
  old["waves"].erase("discretisation");
  Json upgraded = old;
  const std::vector<std::string> notes = upgradeParameters(scene(), upgraded);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("waves.discretisation = random_frequency added"), std::string::npos);
  EXPECT_EQ(upgraded["waves"]["discretisation"], "random_frequency");
  EXPECT_TRUE(validateParameters(scene(), old).empty()) << describeErrors(validateParameters(scene(), old));
  EXPECT_TRUE(upgradeParameters(scene(), upgraded).empty()) << "a second upgrade has nothing to do";
}

// The default scenario runs; every plotted column exists in its table, the time-domain RAO points agree with the
// frequency domain (1.5 %, 2°) and the classical and augmented runs agree (0.5 %).
TEST(WecScene, DefaultScenarioRunsAndIsConsistent) {
  RunContext ctx;
  const Results r = runScenario(scene(), builtin("wec_default"), ctx);
  for (const auto& p : r.plots) {
    const Table* t = r.findTable(p.table);
    ASSERT_NE(t, nullptr) << p.name;
    EXPECT_NE(t->find(p.x), nullptr) << p.name << " x " << p.x;
    for (const auto& y : p.y) EXPECT_NE(t->find(y), nullptr) << p.name << " y " << y;
    if (!p.reference_table.empty()) {
      const Table* ref = r.findTable(p.reference_table);
      ASSERT_NE(ref, nullptr) << p.name;
      for (const auto& y : p.reference_y) EXPECT_NE(ref->find(y), nullptr) << p.name << " ref " << y;
    }
  }
  EXPECT_LT(r.findScalar("td_fd_rao_amplitude_error")->value, 0.015);
  EXPECT_LT(r.findScalar("td_fd_rao_phase_error")->value, 2.0);
  EXPECT_LT(r.findScalar("classical_augmented_pitch_difference")->value, 0.005);
  EXPECT_LT(r.findScalar("max_capture_width_ratio_1")->value, 1.0);
  EXPECT_FALSE(r.view.empty());
  EXPECT_EQ(r.view.frames.front().shapes.size(), 5u);  // leg, hinge, arm, float, sea
}

// The two-float case runs and reports both floats.
TEST(WecScene, TwoFloatScenarioRuns) {
  RunContext ctx;
  const Results r = runScenario(scene(), builtin("wec_two_floats"), ctx);
  EXPECT_NE(r.findScalar("mean_pto_power_2"), nullptr);
  EXPECT_NE(r.findTable("frequency_response")->find("rao_2"), nullptr);
}

// Bad input: every problem is reported with its path (schema range and cross-field checks).
TEST(WecScene, BadInputNamesEveryField) {
  Scenario s = builtin("wec_default");
  s.parameters["floats"][0]["arm_length"] = 2.0;  // shorter than the 3 m radius
  s.parameters["time"]["time_step"] = -1.0;       // out of range
  const auto errors = validateParameters(scene(), s.parameters);
  ASSERT_FALSE(errors.empty());
  bool step = false;
  for (const auto& e : errors) step |= e.path == "parameters.time.time_step";
  EXPECT_TRUE(step);
  s.parameters["time"]["time_step"] = 0.05;
  const auto cross = validateParameters(scene(), s.parameters);
  ASSERT_EQ(cross.size(), 1u);
  EXPECT_EQ(cross[0].path, "parameters.floats[0].arm_length");
  RunContext ctx;
  EXPECT_THROW(runScenario(scene(), s, ctx), InputError);
}

// A cancel request stops the run with RunCancelled.
TEST(WecScene, CancellationIsHonoured) {
  std::atomic<bool> cancel{true};
  RunContext ctx([](double, const std::string&) {}, &cancel);
  EXPECT_THROW(runScenario(scene(), builtin("wec_default"), ctx), RunCancelled);
}
