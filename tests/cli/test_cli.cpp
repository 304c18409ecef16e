// maris-cli end to end, for whatever scenes are compiled in (no scene is named here):
// listing, schema, running the default scenario (summary.json says which Maris ran it and when),
// and every kind of bad input giving exit code 2 with a message that names the field. The command
// line itself: test_cli_usage.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <unistd.h>

#include "catalog.hpp"
#include "cli_runner.hpp"
#include "study_cli_helpers.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;
using test::runCli;
using test::kQuickBuiltin;
using test::writeText;

fs::path freshDir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("maris_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The default scenario with one edit, written to a file.
fs::path editedDefault(const fs::path& dir, const std::function<void(Json&)>& edit) {
  Json doc = scenarioToJson(defaultBuiltin().scenario);
  edit(doc);
  const auto file = dir / "edited.json";
  writeText(file, doc.dump(2));
  return file;
}

// The first real-valued parameter of the default scene whose range excludes -1.
const ParamSpec* boundedRealField() {
  for (const auto& f : requireScene(defaultBuiltin().scenario.scene).schema.fields)
    if (f.kind == ParamKind::Real && !f.range.contains(-1.0)) return &f;
  return nullptr;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (builtinScenarios().empty()) GTEST_SKIP() << "no scene is compiled in yet";
  }
};

TEST_F(Cli, ListShowsEveryBuiltInScenario) {
  const auto r = runCli({"list"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& b : builtinScenarios()) EXPECT_NE(r.out.find(b.id), std::string::npos) << b.id;
}

TEST_F(Cli, ShowPrintsAScenarioThatLoadsAndValidates) {
  for (const auto& b : builtinScenarios()) {
    const auto r = runCli({"show", b.id});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Scenario s = scenarioFromText(r.out, b.id);
    EXPECT_EQ(scenarioToJson(s), scenarioToJson(b.scenario));
    EXPECT_TRUE(validateParameters(requireScene(s.scene), s.parameters).empty()) << b.id;
  }
}

TEST_F(Cli, SchemaListsEveryFieldWithUnitInTextAndJson) {
  for (const auto& scene : sceneCatalog()) {
    const auto text = runCli({"schema", scene.name});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    const auto json = runCli({"schema", scene.name, "--json"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const Json j = Json::parse(json.out);
    ASSERT_EQ(j["fields"].size(), scene.schema.fields.size());
    for (const auto& f : scene.schema.fields) EXPECT_NE(text.out.find(f.path), std::string::npos) << f.path;
    // Every field and table column carries its unit in the JSON; angles (names ending in _deg) read deg or deg/s.
    std::size_t k = 0;
    for (const auto& f : scene.schema.fields) {
      const Json& jf = j["fields"][k++];
      EXPECT_EQ(jf["unit"], f.unit) << scene.name << ": " << f.path;
      std::vector<std::pair<std::string, Json>> named = {{f.key(), jf["unit"]}};
      if (jf.contains("columns"))
        for (const Json& c : jf["columns"]) named.emplace_back(c["path"].get<std::string>(), c["unit"]);
      for (const auto& [name, unit] : named) {
        if (name.size() > 4 && name.compare(name.size() - 4, 4, "_deg") == 0) {
          EXPECT_TRUE(unit == "deg" || unit == "deg/s") << scene.name << ": " << name << " has unit " << unit;
        }
      }
    }
  }
}

// "2026-11-28T11:12:08Z" as a UTC time; nullopt unless it is exactly that form (ISO 8601, UTC, seconds).
std::optional<std::chrono::system_clock::time_point> parseIsoUtc(const std::string& text) {
  if (!std::regex_match(text, std::regex("\\d{4}-\\d{2}-\\d{2}T\\d{2}:\\d{2}:\\d{2}Z"))) return std::nullopt;
  std::tm utc{};
  std::istringstream in(text);
  in >> std::get_time(&utc, "%Y-%m-%dT%H:%M:%SZ");
  if (in.fail()) return std::nullopt;
  return std::chrono::system_clock::from_time_t(::timegm(&utc));
}

TEST_F(Cli, RunWritesScenarioSummaryAndCsvTables) {
  const auto dir = freshDir("run");
  const auto before = std::chrono::system_clock::now();
  const auto* quick = findBuiltin(kQuickBuiltin);
  ASSERT_NE(quick, nullptr);
  const auto r = runCli({"run", quick->id, "--out", (dir / "out").string()});
  const auto after = std::chrono::system_clock::now();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("results written to"), std::string::npos);
  const Scenario ran = loadScenarioFile(dir / "out" / "scenario.json");
  EXPECT_EQ(scenarioToJson(ran), scenarioToJson(quick->scenario));
  const Json summary = Json::parse(readTextFile(dir / "out" / "summary.json"));
  ASSERT_TRUE(summary.contains("results"));
  ASSERT_TRUE(summary["solver"].contains("wall_time"));
  for (const auto& [name, entry] : summary["results"].items()) EXPECT_TRUE(entry.contains("unit")) << name;
  // Which Maris ran it, when (UTC, whole seconds, between the CLI's start and end), on how many threads.
  EXPECT_EQ(summary["maris_version"], MARIS_TEST_PROJECT_VERSION);
  if (MARIS_TEST_GIT_CHECKOUT) {
    EXPECT_FALSE(summary["commit"].get<std::string>().empty());
  }
  const auto started = parseIsoUtc(summary["started_at"].get<std::string>());
  ASSERT_TRUE(started) << summary["started_at"];
  EXPECT_LE(std::chrono::abs(*started - std::chrono::system_clock::now()), std::chrono::minutes(1));
  EXPECT_GE(*started, std::chrono::floor<std::chrono::seconds>(before));
  EXPECT_LE(*started, after);
  EXPECT_EQ(summary["host_threads"].get<unsigned>(), std::thread::hardware_concurrency());
  ASSERT_FALSE(summary["tables"].empty());
  for (const auto& t : summary["tables"]) {
    std::ifstream in(dir / "out" / t.get<std::string>());
    std::string names, units, first;
    ASSERT_TRUE(std::getline(in, names) && std::getline(in, units) && std::getline(in, first)) << t;
    EXPECT_EQ(std::count(names.begin(), names.end(), ','), std::count(units.begin(), units.end(), ',')) << t;
  }
  fs::remove_all(dir);
}

TEST_F(Cli, OverrideIsAppliedAndRecordedInTheScenarioThatRan) {
  const ParamSpec* f = boundedRealField();
  ASSERT_NE(f, nullptr);
  const auto dir = freshDir("override");
  const double value = f->default_value.get<double>();
  const auto r = runCli({"run", kQuickBuiltin, "--no-plots", "--out", (dir / "o").string(), "--set",
                         f->path + "=" + Json(value).dump()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Scenario ran = loadScenarioFile(dir / "o" / "scenario.json");
  EXPECT_EQ(findAtPath(ran.parameters, f->path)->get<double>(), value);
  fs::remove_all(dir);
}

struct BadInput {
  const char* label;
  std::function<fs::path(const fs::path& dir)> make;
  const char* expected_fragment;  // must appear in stderr; "<field>" stands for the bounded field's path
};

TEST_F(Cli, EveryKindOfBadInputExitsTwoAndNamesTheProblem) {
  const ParamSpec* f = boundedRealField();
  ASSERT_NE(f, nullptr);
  const std::string field = f->path;
  const std::vector<BadInput> cases = {
      {"negative value", [&](const fs::path& d) { return editedDefault(d, [&](Json& j) { setAtPath(j["parameters"], field, -1.0); }); },
       "<field> = -1"},
      {"NaN literal", [&](const fs::path& d) {
         auto file = editedDefault(d, [&](Json& j) { setAtPath(j["parameters"], field, 12345.678); });
         std::string text = readTextFile(file);
         text.replace(text.find("12345.678"), 9, "NaN");
         writeText(file, text);
         return file; }, "not valid JSON"},
      {"wrong type", [&](const fs::path& d) { return editedDefault(d, [&](Json& j) { setAtPath(j["parameters"], field, "ten"); }); },
       "<field> = \"ten\": must be a number"},
      {"unknown field", [&](const fs::path& d) { return editedDefault(d, [&](Json& j) { j["parameters"]["bogus_field"] = 1; }); },
       "parameters.bogus_field = 1: unknown field"},
      {"missing field", [&](const fs::path& d) {
         return editedDefault(d, [&](Json& j) {
           // "a.b.c" -> erase key "c" from the object at JSON pointer "/parameters/a/b"
           std::string pointer = "/parameters/" + field;
           std::replace(pointer.begin(), pointer.end(), '.', '/');
           const auto slash = pointer.rfind('/');
           const std::string key(pointer.begin() + static_cast<std::ptrdiff_t>(slash) + 1, pointer.end());
           pointer.resize(slash);
           j.at(Json::json_pointer(pointer)).erase(key); }); },
       "<field>: is missing"},
      {"empty file", [&](const fs::path& d) { writeText(d / "empty.json", ""); return d / "empty.json"; }, "is empty"},
      {"not JSON", [&](const fs::path& d) { writeText(d / "text.json", "hello, world\n"); return d / "text.json"; },
       "not valid JSON"},
      {"unknown scene", [&](const fs::path& d) { return editedDefault(d, [&](Json& j) { j["scene"] = "spaceship"; }); },
       "not a known scene"},
  };
  for (const auto& c : cases) {
    const auto dir = freshDir("bad");
    const auto file = c.make(dir);
    const auto r = runCli({"run", file.string(), "--out", (dir / "out").string()});
    std::string expected = c.expected_fragment;
    if (auto at = expected.find("<field>"); at != std::string::npos) expected.replace(at, 7, "parameters." + field);
    EXPECT_EQ(r.exit_code, 2) << c.label << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << c.label << ": expected '" << expected << "' in\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "summary.json")) << c.label;
    fs::remove_all(dir);
  }
}

TEST_F(Cli, UnknownScenarioNameAndBadOverrideExitTwo) {
  EXPECT_EQ(runCli({"run", "no_such_scenario_anywhere"}).exit_code, 2);
  const auto r = runCli({"run", defaultBuiltin().id, "--set", "novalue"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("path=value"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace maris
