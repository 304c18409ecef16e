// The scene catalog and the built-in example scenarios of this build. Generated in part by
// engine/CMakeLists.txt (one entry per scene registered with maris_add_scene()).
#pragma once

#include <string>
#include <vector>

#include "core/scene.hpp"

namespace maris {

// The catalog, in a fixed order (the first scene's first example is the default scenario).
const std::vector<SceneDefinition>& sceneCatalog();
const SceneDefinition* findScene(const std::string& name);
// Throws InputError naming the unknown scene and the known ones.
const SceneDefinition& requireScene(const std::string& name);

// Built-in example scenarios (resources/scenarios/<scene>/<id>.json, embedded at build time).
struct BuiltinScenario {
  std::string id;  // file stem, unique: "riser_cantilever_tip_load"
  Scenario scenario;
};
const std::vector<BuiltinScenario>& builtinScenarios();
const BuiltinScenario* findBuiltin(const std::string& id);
const BuiltinScenario& defaultBuiltin();

}  // namespace maris
