// Scenario files: versioned JSON documents
//   {"format": "maris-scenario/1", "scene": "riser", "name": "...", "description": "...",
//    "parameters": { ... SI units ... }}
// Loading reports every problem at once; saving is atomic (temp file + rename) so a crash or a
// full disk never leaves a half-written scenario behind.
#pragma once

#include <filesystem>
#include <string>

#include "core/schema.hpp"

namespace maris {

inline constexpr const char* kScenarioFormat = "maris-scenario/1";

struct Scenario {
  std::string scene;        // registry name of the scene, e.g. "riser"
  std::string name;         // short title
  std::string description;  // what the case is, where its numbers come from, what was assumed
  Json parameters = Json::object();
};

Json scenarioToJson(const Scenario& scenario);
std::string scenarioToText(const Scenario& scenario);  // pretty JSON, 2-space indent, trailing newline

// Parses the envelope (format, scene, name, description, parameters). Does not validate the
// parameters against a schema: validateScenario() in scene.hpp does that. Throws InputError.
Scenario scenarioFromJson(const Json& document);
Scenario scenarioFromText(const std::string& text, const std::string& origin = "scenario");
Scenario loadScenarioFile(const std::filesystem::path& file);
void saveScenarioFile(const Scenario& scenario, const std::filesystem::path& file);

// When a file written by writeFileAtomic is durable: at once (fsync before the rename), or later, by one
// syncFileSystem after many files (each fsync costs a journal commit and a device flush).
enum class FileSync { Now, Later };
// Writes `content` to `file` atomically: a temp file in the same folder, flushed, then renamed.
// Throws std::runtime_error naming the file and the OS error.
void writeFileAtomic(const std::filesystem::path& file, const std::string& content, FileSync sync = FileSync::Now);
// syncfs(2) of the file system that holds `dir`: every file written there is durable after one flush.
// Throws std::runtime_error naming `dir` and the OS error.
void syncFileSystem(const std::filesystem::path& dir);
// Writes `content` to `file` in place, without syncing it: for a file in a private staging folder that
// is synced and moved into place as a whole (RunFolder::commit). Throws std::runtime_error.
void writeStagedFile(const std::filesystem::path& file, const std::string& content);
std::string readTextFile(const std::filesystem::path& file);

// Applies "geometry.length=120" to scenario.parameters. The value is parsed as JSON when it
// parses ("120", "true", "[1,2]", "\"text\""), else taken as a string. Throws InputError.
void applyOverride(Scenario& scenario, const std::string& assignment);

}  // namespace maris
