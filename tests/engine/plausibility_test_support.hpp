// Plausibility warnings of a built-in scenario after overrides, and the one at a parameter path.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "catalog.hpp"
#include "core/scene.hpp"

namespace maris::testing {

// The scenario must stay valid: plausibility warnings are for valid parameters only.
inline std::vector<FieldError> plausibilityOf(const std::string& builtin, const std::vector<std::string>& overrides) {
  Scenario s = findBuiltin(builtin)->scenario;
  for (const auto& o : overrides) applyOverride(s, o);
  EXPECT_TRUE(validateParameters(requireScene(s.scene), s.parameters).empty())
      << builtin << ":\n" << describeErrors(validateParameters(requireScene(s.scene), s.parameters));
  return plausibilityWarnings(requireScene(s.scene), s.parameters);
}

inline const FieldError* warningAt(const std::vector<FieldError>& warnings, const std::string& path) {
  for (const auto& w : warnings)
    if (w.path == path) return &w;
  return nullptr;
}

// Every built-in scenario of `scene` raises none, except those listed (which warn on purpose).
inline void expectBuiltinsRaiseNone(const std::string& scene, const std::vector<std::string>& except = {}) {
  int checked = 0;
  for (const auto& b : builtinScenarios()) {
    if (b.scenario.scene != scene || std::find(except.begin(), except.end(), b.id) != except.end()) continue;
    const auto w = plausibilityOf(b.id, {});
    EXPECT_TRUE(w.empty()) << b.id << ":\n" << describeErrors(w);
    ++checked;
  }
  EXPECT_GT(checked, 0) << scene;
}

// Exactly one warning, at `path` (relative to "parameters."), whose message contains `words`.
inline void expectOnlyWarning(const std::vector<FieldError>& warnings, const std::string& path, const std::string& words) {
  ASSERT_EQ(warnings.size(), 1u) << describeErrors(warnings);
  EXPECT_EQ(warnings[0].path, "parameters." + path) << describeErrors(warnings);
  EXPECT_NE(warnings[0].message.find(words), std::string::npos) << warnings[0].message;
}

}  // namespace maris::testing
