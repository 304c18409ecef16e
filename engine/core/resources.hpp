// Files from resources/ embedded into the engine at build time (scenarios, hull tables), so the
// executables run from any folder without an install step.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace maris {

// Content of resources/<path> (e.g. "scenarios/riser/cantilever.json"), or nullopt.
std::optional<std::string_view> builtinResource(std::string_view path);
// All embedded paths, sorted.
std::vector<std::string> builtinResourcePaths();

}  // namespace maris
