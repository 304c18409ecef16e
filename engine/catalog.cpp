#include "catalog.hpp"

#include <algorithm>

#include "core/resources.hpp"

namespace maris {

const SceneDefinition* findScene(const std::string& name) {
  for (const auto& s : sceneCatalog())
    if (s.name == name) return &s;
  return nullptr;
}

const SceneDefinition& requireScene(const std::string& name) {
  if (const auto* s = findScene(name)) return *s;
  std::vector<std::string> names;
  std::string list;
  for (const auto& s : sceneCatalog()) {
    names.push_back(s.name);
    list += (list.empty() ? "" : ", ") + s.name;
  }
  const auto guess = didYouMean(name, names);
  throw InputError("scene", "\"" + name + "\"",
                   "is not a known scene (known: " + list + ")" +
                       (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
}

const std::vector<BuiltinScenario>& builtinScenarios() {
  static const std::vector<BuiltinScenario> all = [] {
    std::vector<BuiltinScenario> list;
    for (const auto& path : builtinResourcePaths()) {
      if (path.rfind("scenarios/", 0) != 0 || path.size() < 5 || path.substr(path.size() - 5) != ".json") continue;
      const auto slash = path.rfind('/');
      BuiltinScenario b;
      b.id = path.substr(slash + 1, path.size() - slash - 1 - 5);
      b.scenario = scenarioFromText(std::string(*builtinResource(path)), path);
      const SceneDefinition* scene = findScene(b.scenario.scene);
      if (!scene) continue;  // a scene not built into this binary
      upgradeParameters(*scene, b.scenario.parameters);
      list.push_back(std::move(b));
    }
    // Order by the catalog's scene order, then by id.
    auto rank = [](const std::string& scene) {
      const auto& cat = sceneCatalog();
      for (std::size_t i = 0; i < cat.size(); ++i)
        if (cat[i].name == scene) return i;
      return cat.size();
    };
    std::stable_sort(list.begin(), list.end(), [&](const auto& a, const auto& b) {
      const auto ra = rank(a.scenario.scene), rb = rank(b.scenario.scene);
      return ra != rb ? ra < rb : a.id < b.id;
    });
    return list;
  }();
  return all;
}

const BuiltinScenario* findBuiltin(const std::string& id) {
  for (const auto& b : builtinScenarios())
    if (b.id == id) return &b;
  return nullptr;
}

const BuiltinScenario& defaultBuiltin() {
  const auto& all = builtinScenarios();
  // A scenario named "<first scene>_default" wins; otherwise the first one.
  if (!sceneCatalog().empty())
    if (const auto* b = findBuiltin(sceneCatalog().front().name + "_default")) return *b;
  if (all.empty()) throw std::logic_error("no built-in scenarios are compiled in");
  return all.front();
}

}  // namespace maris
