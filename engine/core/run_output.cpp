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
  // What the CSV files do not say, so that a front end can show the run again from its folder (readRunFolder):
  // each table's title and its columns' labels for people, and the plots' layouts.
  summary["table_labels"] = Json::object();
  for (const auto& t : results.tables) {
    Json columns = Json::object();
    for (const auto& c : t.columns)
      if (!c.label.empty()) columns[c.name] = c.label;
    summary["table_labels"][t.name] = {{"title", t.title}, {"columns", columns}};
  }
  summary["plots"] = Json::array();
  for (const auto& p : results.plots) {
    Json plot = {{"name", p.name}, {"title", p.title}, {"table", p.table}, {"x", p.x}, {"y", p.y}};
    if (p.log_x) plot["log_x"] = true;
    if (p.log_y) plot["log_y"] = true;
    if (!p.reference_table.empty()) {
      plot["reference_table"] = p.reference_table;
      plot["reference_y"] = p.reference_y;
    }
    summary["plots"].push_back(std::move(plot));
  }
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
