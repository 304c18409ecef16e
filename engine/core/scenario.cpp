#include "core/scenario.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

#include "core/input_limits.hpp"

namespace maris {

Json scenarioToJson(const Scenario& s) {
  Json j = Json::object();
  j["format"] = kScenarioFormat;
  j["scene"] = s.scene;
  j["name"] = s.name;
  j["description"] = s.description;
  j["parameters"] = s.parameters;
  return j;
}

std::string scenarioToText(const Scenario& s) { return scenarioToJson(s).dump(2) + "\n"; }

Scenario scenarioFromJson(const Json& doc) {
  std::vector<FieldError> errors;
  if (!doc.is_object()) throw InputError("(document)", jsonSnippet(doc), "a scenario must be a JSON object");
  const auto fmt = doc.find("format");
  if (fmt == doc.end())
    errors.push_back({"format", "", std::string("is missing; expected \"") + kScenarioFormat + "\""});
  else if (!fmt->is_string() || fmt->get<std::string>() != kScenarioFormat)
    errors.push_back({"format", jsonSnippet(*fmt), std::string("must be \"") + kScenarioFormat + "\""});
  Scenario s;
  auto text = [&](const char* key, std::string& out, bool required) {
    auto it = doc.find(key);
    if (it == doc.end()) {
      if (required) errors.push_back({key, "", "is missing (text)"});
      return;
    }
    if (!it->is_string())
      errors.push_back({key, jsonSnippet(*it), "must be a text string"});
    else
      out = it->get<std::string>();
  };
  text("scene", s.scene, true);
  text("name", s.name, false);
  text("description", s.description, false);
  auto p = doc.find("parameters");
  if (p == doc.end())
    errors.push_back({"parameters", "", "is missing (an object of parameters)"});
  else if (!p->is_object())
    errors.push_back({"parameters", jsonSnippet(*p), "must be a JSON object"});
  else
    s.parameters = *p;
  static const std::vector<std::string> known = {"format", "scene", "name", "description", "parameters"};
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    const auto guess = didYouMean(it.key(), known);
    errors.push_back({it.key(), jsonSnippet(it.value()),
                      "unknown field" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
  }
  if (!errors.empty()) throw InputError(std::move(errors));
  return s;
}

Scenario scenarioFromText(const std::string& text, const std::string& origin) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(origin, "", "is empty; expected a JSON scenario document");
  return scenarioFromJson(parseJsonLimited(text, origin));
}

std::string readTextFile(const std::filesystem::path& file) {
  return readInputFile(file, file.string(), InputLimits::kScenarioFileBytes);
}

Scenario loadScenarioFile(const std::filesystem::path& file) {
  return scenarioFromText(readTextFile(file), file.string());
}

namespace {

// Writes all of `content` to `fd`; false (errno set) on an error.
bool writeAll(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void writeFileAtomic(const std::filesystem::path& file, const std::string& content, FileSync sync) {
  const auto dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::string tmpl = (dir / ("." + file.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
  const bool written = writeAll(fd, content) && (sync == FileSync::Later || ::fsync(fd) == 0);
  const int write_error = errno;
  if (::close(fd) != 0 || !written) {
    const int err = written ? errno : write_error;
    ::unlink(tmpl.c_str());
    throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(err));
  }
  ::chmod(tmpl.c_str(), 0644);
  std::error_code ec;
  std::filesystem::rename(tmpl, file, ec);
  if (ec) {
    ::unlink(tmpl.c_str());
    throw std::runtime_error("cannot write " + file.string() + ": " + ec.message());
  }
}

void syncFileSystem(const std::filesystem::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot read back " + dir.string() + ": " + std::strerror(errno));
  const bool synced = ::syncfs(fd) == 0;
  const int err = errno;
  ::close(fd);
  if (!synced) throw std::runtime_error("cannot write the files of " + dir.string() + ": " + std::strerror(err));
}

void writeStagedFile(const std::filesystem::path& file, const std::string& content) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
  const bool written = writeAll(fd, content);
  const int write_error = errno;
  if (::close(fd) != 0 || !written)
    throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(written ? errno : write_error));
}

void saveScenarioFile(const Scenario& scenario, const std::filesystem::path& file) {
  writeFileAtomic(file, scenarioToText(scenario));
}

void applyOverride(Scenario& scenario, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + echoText(assignment), "", "must look like path=value, e.g. geometry.length=120");
  std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  if (path.rfind("parameters.", 0) == 0) path = path.substr(11);
  const std::string origin = "--set " + echoText(path);
  const auto components = static_cast<std::size_t>(std::count(path.begin(), path.end(), '.')) + 1;
  if (components > InputLimits::kSetPathComponents)
    throw InputError(origin, "", "has " + std::to_string(components) + " path components; the limit is " +
                                     std::to_string(InputLimits::kSetPathComponents));
  if (path.size() > InputLimits::kStringLength || text.size() > InputLimits::kStringLength)
    throw InputError(origin, "", "is longer than " + std::to_string(InputLimits::kStringLength) + " characters");
  Json value;
  try {
    value = parseJsonLimited(text, origin, "parameters." + path);
  } catch (const JsonSyntaxError&) {
    value = text;  // not JSON: taken as text, which must then be valid UTF-8 to be saved
    try {
      (void)value.dump();
    } catch (const Json::type_error&) {
      throw InputError(origin, "", "is not valid UTF-8 text");
    }
  }
  setAtPath(scenario.parameters, path, std::move(value));
}

}  // namespace maris
