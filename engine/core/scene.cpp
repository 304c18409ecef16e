#include "core/scene.hpp"

#include <algorithm>
#include <string_view>

#include "core/input_limits.hpp"


namespace maris {

bool plotGroupHolds(const PlotGroupSpec& group, const std::string& plot_name) {
  return std::any_of(group.plots.begin(), group.plots.end(), [&](const std::string& pattern) {
    const std::size_t star = pattern.find('*');
    if (star == std::string::npos) return pattern == plot_name;
    const std::string_view head(pattern.data(), star), tail(pattern.data() + star + 1, pattern.size() - star - 1);
    const std::string_view name(plot_name);
    return name.size() >= head.size() + tail.size() && name.substr(0, head.size()) == head &&
           name.substr(name.size() - tail.size()) == tail;
  });
}

std::vector<std::string> upgradeParameters(const SceneDefinition& scene, Json& parameters) {
  if (!scene.upgrade || !parameters.is_object()) return {};
  return scene.upgrade(parameters);
}

std::vector<FieldError> validateParameters(const SceneDefinition& scene, const Json& parameters) {
  Json upgraded = parameters;
  upgradeParameters(scene, upgraded);
  auto errors = validateAgainstSchema(scene.schema, upgraded, "parameters");
  if (!errors.empty() || !scene.check) return errors;
  for (auto e : scene.check(upgraded)) {
    e.path = "parameters." + e.path;
    errors.push_back(std::move(e));
  }
  return errors;
}

WorkEstimate estimateWork(const SceneDefinition& scene, const Json& parameters) {
  if (!scene.estimate || !validateParameters(scene, parameters).empty()) return {};
  Json upgraded = parameters;
  upgradeParameters(scene, upgraded);
  return scene.estimate(upgraded);
}

std::vector<FieldError> plausibilityWarnings(const SceneDefinition& scene, const Json& parameters) {
  if (!scene.plausibility || !validateParameters(scene, parameters).empty()) return {};
  Json upgraded = parameters;
  upgradeParameters(scene, upgraded);
  std::vector<FieldError> warnings = scene.plausibility(upgraded);
  for (auto& w : warnings) w.path = "parameters." + w.path;
  return warnings;
}

Results runScenario(const SceneDefinition& scene, const Scenario& scenario, RunContext& context) {
  if (scenario.scene != scene.name)
    throw InputError("scene", "\"" + scenario.scene + "\"", "does not match the solver's scene \"" + scene.name + "\"");
  Json parameters = scenario.parameters;
  for (auto& note : upgradeParameters(scene, parameters)) context.warn(std::move(note));
  auto errors = validateParameters(scene, parameters);
  if (!errors.empty()) throw InputError(std::move(errors));
  if (scene.plausibility)
    for (auto& w : scene.plausibility(parameters)) {
      w.path = "parameters." + w.path;
      context.warn(w.str());
    }
  const double t0 = context.elapsedSeconds();
  Results r = scene.run(parameters, context);
  r.stats.wall_time_s = context.elapsedSeconds() - t0;
  requireFiniteResults(r);
  for (auto& w : context.warnings()) r.warnings.push_back(std::move(w));
  return r;
}

Scenario defaultScenario(const SceneDefinition& scene) {
  Scenario s;
  s.scene = scene.name;
  s.name = "New " + scene.title;
  s.parameters = scene.schema.defaults();
  return s;
}

}  // namespace maris
