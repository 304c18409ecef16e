// Scenario files: envelope checks, parse errors with positions, exact round trip, atomic save.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "core/scenario.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("maris_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Scenario sample() {
  Scenario s;
  s.scene = "riser";
  s.name = "Sample";
  s.description = "A sample with \"quotes\" and ünïcode";
  s.parameters = {{"geometry", {{"length", 0.1}, {"segment_count", 20}}}, {"values", {1e-300, 3.141592653589793}}};
  return s;
}

TEST(Scenario, SaveThenLoadGivesTheIdenticalScenario) {
  const auto dir = tempDir("roundtrip");
  const Scenario s = sample();
  saveScenarioFile(s, dir / "a.json");
  const Scenario t = loadScenarioFile(dir / "a.json");
  EXPECT_EQ(scenarioToJson(t), scenarioToJson(s));
  saveScenarioFile(t, dir / "b.json");
  EXPECT_EQ(readTextFile(dir / "a.json"), readTextFile(dir / "b.json"));
  // Doubles survive exactly (shortest round-trip representation).
  EXPECT_EQ(t.parameters["values"][1].get<double>(), 3.141592653589793);
  fs::remove_all(dir);
}

TEST(Scenario, EmptyFileIsAnInputError) {
  try {
    scenarioFromText("  \n", "empty.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("is empty"), std::string::npos);
  }
}

TEST(Scenario, NonJsonNamesLineAndColumn) {
  try {
    scenarioFromText("{\n  \"format\": \"maris-scenario/1\",\n  oops\n}", "bad.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not valid JSON (line 3"), std::string::npos) << e.what();
  }
}

TEST(Scenario, EnvelopeErrorsAreAllReported) {
  const Json doc = {{"format", "maris-scenario/2"}, {"parameters", 3}, {"scene", 7}, {"extra", true}};
  try {
    scenarioFromJson(doc);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.errors().size(), 4u) << e.what();
  }
}

TEST(Scenario, UnknownTopLevelFieldSuggestsTheKnownOne) {
  Json doc = scenarioToJson(sample());
  doc["parameter"] = doc["parameters"];
  try {
    scenarioFromJson(doc);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'parameters'"), std::string::npos) << e.what();
  }
}

TEST(Scenario, AtomicWriteReplacesWholeFileAndLeavesNoTemporaries) {
  const auto dir = tempDir("atomic");
  writeFileAtomic(dir / "f.txt", std::string(100000, 'a'));
  writeFileAtomic(dir / "f.txt", "short");
  EXPECT_EQ(readTextFile(dir / "f.txt"), "short");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
  fs::remove_all(dir);
}

TEST(Scenario, AtomicWriteIntoMissingFolderThrowsAndNamesTheFile) {
  try {
    writeFileAtomic("/nonexistent_maris_dir/x.json", "{}");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("x.json"), std::string::npos);
  }
}

TEST(Scenario, OverridesParseJsonValuesAndFallBackToText) {
  Scenario s = sample();
  applyOverride(s, "geometry.length=120");
  applyOverride(s, "parameters.geometry.segment_count=50");
  applyOverride(s, "model.name=joint");
  applyOverride(s, "output.times=[1,2]");
  EXPECT_EQ(s.parameters["geometry"]["length"], 120);
  EXPECT_EQ(s.parameters["geometry"]["segment_count"], 50);
  EXPECT_EQ(s.parameters["model"]["name"], "joint");
  EXPECT_EQ(s.parameters["output"]["times"].size(), 2u);
  EXPECT_THROW(applyOverride(s, "novalue"), InputError);
}

}  // namespace
}  // namespace maris
