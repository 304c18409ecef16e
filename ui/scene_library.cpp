#include "scene_library.hpp"

namespace maris::ui {

std::shared_ptr<const SceneLibrary> SceneLibrary::fromEngine() {
  auto library = std::make_shared<SceneLibrary>();
  library->scenes = sceneCatalog();
  library->examples = builtinScenarios();
  return library;
}

const SceneDefinition* SceneLibrary::findScene(const std::string& name) const {
  for (const auto& scene : scenes)
    if (scene.name == name) return &scene;
  return nullptr;
}

const BuiltinScenario* SceneLibrary::findExample(const std::string& id) const {
  for (const auto& example : examples)
    if (example.id == id) return &example;
  return nullptr;
}

const BuiltinScenario* SceneLibrary::defaultExample() const {
  if (!scenes.empty())
    if (const auto* preferred = findExample(scenes.front().name + "_default")) return preferred;
  return examples.empty() ? nullptr : &examples.front();
}

}  // namespace maris::ui
