#include <filesystem>
#include <system_error>

#include "core/errors.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"

namespace maris {

namespace {

constexpr std::string_view kPrefix = "builtin:";

std::string sceneFolder(std::string_view scene) { return "data/" + std::string(scene) + "/"; }

// The embedded data names of a scene (without README and generator scripts), for error messages.
std::string availableNames(std::string_view scene) {
  const std::string folder = sceneFolder(scene);
  std::string list;
  for (const auto& p : builtinResourcePaths()) {
    if (p.rfind(folder, 0) != 0 || p.find("README") != std::string::npos) continue;
    if (p.size() < 4 || p.compare(p.size() - 4, 4, ".csv") != 0) continue;
    list += (list.empty() ? "" : ", ") + std::string(kPrefix) + p.substr(folder.size());
  }
  return list.empty() ? "none" : list;
}

}  // namespace

bool isBuiltinDataPath(std::string_view path) { return path.substr(0, kPrefix.size()) == kPrefix; }

std::optional<std::string> dataPathProblem(std::string_view path, std::string_view scene) {
  if (isBuiltinDataPath(path)) {
    if (builtinResource(sceneFolder(scene) + std::string(path.substr(kPrefix.size())))) return std::nullopt;
    return "is not a built-in data set (available: " + availableNames(scene) + ")";
  }
  std::error_code error;  // a loop of symbolic links is "not a readable file", not an exception
  if (!std::filesystem::is_regular_file(std::filesystem::path(std::string(path)), error)) return "is not a readable file";
  return std::nullopt;
}

std::string readDataText(std::string_view path, std::string_view scene, const std::string& field) {
  const std::string quoted = "\"" + echoText(std::string(path)) + "\"";
  if (isBuiltinDataPath(path)) {
    const auto text = builtinResource(sceneFolder(scene) + std::string(path.substr(kPrefix.size())));
    if (!text) throw InputError(field, quoted, "is not a built-in data set (available: " + availableNames(scene) + ")");
    return std::string(*text);
  }
  std::string text = readInputFile(std::filesystem::path(std::string(path)), field, InputLimits::kDataFileBytes);
  checkDataShape(text, field, std::string(path));
  return text;
}

void resolveDataPaths(const Schema& schema, Json& parameters, const std::filesystem::path& folder) {
  for (const auto& field : schema.fields) {
    if (!field.data_path) continue;
    Json* value = const_cast<Json*>(findAtPath(parameters, field.path));
    if (!value || !value->is_string()) continue;  // validation reports a wrong type
    const std::string path = value->get<std::string>();
    if (path.empty() || isBuiltinDataPath(path) || std::filesystem::path(path).is_absolute()) continue;
    *value = (std::filesystem::absolute(folder) / path).lexically_normal().string();
  }
}

}  // namespace maris
