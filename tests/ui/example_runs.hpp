// Every scene's example scenario as ui.framing and ui.labels run it. In Release, each built-in scenario, the riser's
// dynamic runs over their first 2 s of simulated time (their full runs, 3 to 36 s, took most of the test's time):
// the model, the plots, the tables and the scalars are the same, with the profile times scaled into the shorter
// run (so there are as many profiles) and fatigue counted from the same fraction of it, which is what the two tests
// read. Under AddressSanitizer and UndefinedBehaviorSanitizer (10 to 20 times slower) only each scene's main
// example, and those whose full run costs tens of seconds there with a shorter simulated time, a coarser sweep
// or a coarser mesh: `maris-cli run` writes the same tables (the riser's profiles at other times) and the same
// scalars for these as for the full examples.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "catalog.hpp"
#include "sanitized_build.hpp"

namespace maris::test {

// A riser run over its first `end` seconds: profile times and the start of fatigue counting scaled with it.
inline Json shortRiserRun(const Json& parameters, double end) {
  const double full = parameters.at("solver").at("end_time").get<double>();
  Json times = Json::array();
  for (const Json& t : parameters.at("output").at("stress_times")) times.push_back(t.get<double>() * end / full);
  return {{"solver", {{"end_time", end}}},
          {"output", {{"stress_times", times}}},
          {"fatigue", {{"start_time", parameters.at("fatigue").at("start_time").get<double>() * end / full}}}};
}

// The examples to run: all in Release (the riser's shortened); under the sanitizers each scene's
// "<scene>_default", made cheaper.
inline std::vector<BuiltinScenario> uiTestExamples() {
  if (!kSanitizedBuild) {
    constexpr double kRiserEnd = 2.0;  // [s] of simulated time
    std::vector<BuiltinScenario> out = builtinScenarios();
    for (BuiltinScenario& b : out)
      if (b.scenario.scene == "riser" && b.scenario.parameters.at("solver").at("end_time").get<double>() > kRiserEnd)
        b.scenario.parameters.merge_patch(shortRiserRun(b.scenario.parameters, kRiserEnd));
    return out;
  }
  // Their full runs under the sanitizers: riser 28 s, seismic over 40 s, ship 13 s (ui.framing took 112 s and
  // ui.labels 102 s with them, 19 s and 15 s with these).
  const std::vector<std::pair<std::string, Json>> reductions = {
      {"riser_default", {{"solver", {{"end_time", 2.0}}}, {"output", {{"stress_times", Json::array({1.0, 2.0})}}}}},
      {"seismic_default", {{"solver", {{"duration", 1.5}, {"cutoff_frequency", 2.5}}}}},
      {"ship_default", {{"speed", {{"count", 26}}}}},
  };
  std::vector<BuiltinScenario> out;
  for (const BuiltinScenario& b : builtinScenarios()) {
    if (b.id != b.scenario.scene + "_default") continue;
    BuiltinScenario reduced = b;
    for (const auto& [id, patch] : reductions)
      if (id == b.id) reduced.scenario.parameters.merge_patch(patch);
    out.push_back(std::move(reduced));
  }
  return out;
}

}  // namespace maris::test
