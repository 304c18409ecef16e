#include "core/run_output.hpp"

#include <ctime>
#include <thread>

#include "core/version.hpp"

namespace maris {

std::string isoUtc(std::chrono::system_clock::time_point t) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  char text[32];
  return std::string(text, std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc));
}

std::vector<std::filesystem::path> writeRunFolder(const std::filesystem::path& dir, const Scenario& scenario,
                                                  const Results& results,
                                                  std::chrono::system_clock::time_point started_at) {
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> written;
  auto put = [&](const std::string& name, const std::string& content) {
    const auto file = dir / name;
    writeStagedFile(file, content);
    written.push_back(file);
  };
  put("scenario.json", scenarioToText(scenario));
  for (const auto& t : results.tables) put(t.name + ".csv", t.toCsv());
  Json summary = summaryJson(results);
  summary["scene"] = scenario.scene;
  summary["scenario"] = scenario.name;
  summary["tables"] = Json::array();
  for (const auto& t : results.tables) summary["tables"].push_back(t.name + ".csv");
  // Which Maris ran it, when, and on how many hardware threads (for comparing wall times).
  summary["maris_version"] = projectVersion();
  summary["commit"] = commitId();
  summary["started_at"] = isoUtc(started_at);
  summary["host_threads"] = std::thread::hardware_concurrency();
  // summary.json last: its presence marks a complete folder.
  put("summary.json", summary.dump(2) + "\n");
  return written;
}

}  // namespace maris
