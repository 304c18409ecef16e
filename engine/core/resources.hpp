// Files from resources/ embedded into the engine at build time (scenarios, hull tables), so the
// executables run from any folder without an install step.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/schema.hpp"

namespace maris {

// Content of resources/<path> (e.g. "scenarios/riser/cantilever.json"), or nullopt.
std::optional<std::string_view> builtinResource(std::string_view path);
// All embedded paths, sorted.
std::vector<std::string> builtinResourcePaths();

}  // namespace maris

namespace maris {

// Data files that scenarios name (offsets, measured points, records): "builtin:NAME" is
// resources/data/<scene>/NAME embedded in the engine, anything else a path on disk. One spelling
// for every scene, so a scenario that ships its data runs from any folder.
bool isBuiltinDataPath(std::string_view path);
// Why `path` cannot be read ("no built-in data set ... (available: ...)", "is not a readable
// file"), or nullopt when it can. For validation, which reports every bad field.
std::optional<std::string> dataPathProblem(std::string_view path, std::string_view scene);
// The text behind `path`; throws InputError(field, path, reason) when it cannot be read.
std::string readDataText(std::string_view path, std::string_view scene, const std::string& field);
// Makes every relative data path in `parameters` (the schema's fields marked data_path; not "builtin:",
// not empty) absolute against `folder`, the folder of the file that holds them: a scenario or study finds
// its data beside it whatever the current folder, and the scenario.json a run writes still finds it.
void resolveDataPaths(const Schema& schema, Json& parameters, const std::filesystem::path& folder);

}  // namespace maris
