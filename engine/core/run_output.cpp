#include "core/run_output.hpp"

namespace maris {

std::vector<std::filesystem::path> writeRunFolder(const std::filesystem::path& dir, const Scenario& scenario,
                                                  const Results& results) {
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> written;
  auto put = [&](const std::string& name, const std::string& content) {
    const auto file = dir / name;
    writeFileAtomic(file, content);
    written.push_back(file);
  };
  put("scenario.json", scenarioToText(scenario));
  for (const auto& t : results.tables) put(t.name + ".csv", t.toCsv());
  Json summary = summaryJson(results);
  summary["scene"] = scenario.scene;
  summary["scenario"] = scenario.name;
  summary["tables"] = Json::array();
  for (const auto& t : results.tables) summary["tables"].push_back(t.name + ".csv");
  // summary.json last: its presence marks a complete folder.
  put("summary.json", summary.dump(2) + "\n");
  return written;
}

}  // namespace maris
