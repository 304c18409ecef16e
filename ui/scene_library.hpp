// The scenes and example scenarios the GUI offers. The main window takes a library instead of
// reading the engine's global catalog, so tests can hand it a small scene of their own.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "catalog.hpp"

namespace maris::ui {

struct SceneLibrary {
  std::vector<SceneDefinition> scenes;    // in catalog order
  std::vector<BuiltinScenario> examples;  // grouped by scene, in catalog order

  // The engine's compiled-in catalog and built-in scenarios.
  static std::shared_ptr<const SceneLibrary> fromEngine();

  const SceneDefinition* findScene(const std::string& name) const;
  const BuiltinScenario* findExample(const std::string& id) const;
  // "<first scene>_default" if present, else the first example, else nullptr.
  const BuiltinScenario* defaultExample() const;
};

}  // namespace maris::ui
