// maris-cli against hostile input (the fuzz campaign's findings, scene-independent): every case exits 2
// with a message naming the file or field and the limit; none crashes, exhausts memory or exits 1.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

#include "catalog.hpp"
#include "cli_runner.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;
using test::runCli;

class CliLimits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("maris_cli_limits_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  // The default scenario's text with `raw` spliced in as the value of a new top-level parameter group.
  std::string defaultWith(const std::string& key, const std::string& raw) {
    std::string text = scenarioToJson(defaultBuiltin().scenario).dump();
    const auto at = text.find("\"parameters\":{") + 14;
    return text.insert(at, "\"" + key + "\":" + raw + ",");
  }
  // Runs and expects exit 2 with every fragment in stderr.
  void expectRejected(const std::vector<std::string>& args, const std::vector<std::string>& fragments) {
    auto full = args;
    for (const char* a : {"--no-plots", "--out"}) full.push_back(a);
    full.push_back((dir_ / "out").string());
    const auto r = runCli(full);
    EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 2000);
    for (const auto& f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << f << " not in\n" << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), 4000u) << "message not bounded";
  }

  fs::path dir_;
};

TEST_F(CliLimits, DeeplyNestedDocumentsAreRefusedNamingThePath) {
  const std::string deep = std::string(60000, '[') + std::string(60000, ']');
  expectRejected({"run", write("deep.json", defaultWith("deep", deep)).string()},
                 {"parameters.deep[0][0]", "nested deeper than 64 levels", "deep.json"});
  std::string objects;
  for (int i = 0; i < 60000; ++i) objects += "{\"a\":";
  objects += "1" + std::string(60000, '}');
  expectRejected({"run", write("objects.json", objects).string()}, {"a.a.a", "nested deeper than 64"});
}

TEST_F(CliLimits, NumberOverflowIsAnInputErrorInFilesAndSetValues) {
  expectRejected({"run", write("big.json", defaultWith("big", "[1, 1e400]")).string()},
                 {"parameters.big[1] = 1e400", "out of the range of a double"});
  expectRejected({"run", defaultBuiltin().id, "--set", "x.y=1e400"}, {"parameters.x.y = 1e400"});
}

TEST_F(CliLimits, SetPathsWithThousandsOfComponentsAreRefused) {
  std::string path;
  for (int i = 0; i < 60000; ++i) path += "a.";
  expectRejected({"run", defaultBuiltin().id, "--set", path + "b=1"}, {"path components; the limit is 16"});
}

TEST_F(CliLimits, FilesThatAreNotRegularAreNamedNotRead) {
  const auto fifo = dir_ / "fifo.json", loop = dir_ / "loop.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("loop.json", loop);
  expectRejected({"run", fifo.string()}, {fifo.string(), "not a regular file"});
  expectRejected({"run", "/dev/zero"}, {"/dev/zero", "not a regular file"});
  expectRejected({"run", loop.string()}, {loop.string(), "loop of symbolic links"});
  expectRejected({"run", dir_.string()}, {dir_.string(), "is a folder"});
}

TEST_F(CliLimits, DuplicateKeysLongNamesAndManyErrorsGiveShortMessages) {
  std::string text = scenarioToJson(defaultBuiltin().scenario).dump();
  text.insert(text.find("\"parameters\":{") + 14, "\"dup\":1,\"dup\":2,");
  expectRejected({"run", write("dup.json", text).string()}, {"parameters.dup: duplicate key"});
  // A 5 MB scene name: refused by the string limit; the message stays short.
  Json doc = scenarioToJson(defaultBuiltin().scenario);
  doc["name"] = std::string(5'000'000, 'n');
  expectRejected({"run", write("name.json", doc.dump()).string()}, {"name: text of 5000000 characters"});
  // 100 unknown fields: 20 listed, then a count.
  doc = scenarioToJson(defaultBuiltin().scenario);
  for (int i = 0; i < 100; ++i) doc["parameters"]["unknown_" + std::to_string(i)] = i;
  expectRejected({"run", write("many.json", doc.dump()).string()}, {"... and 80 more errors (100 in all)"});
}

// Input the model cannot take that shows only in the solve: the lazy-wave riser with its modules from the top floats
// at the surface, where the riser's all-or-nothing buoyancy has no equilibrium (docs/riser.md, "A riser that
// floats"). Refused with exit 2 on the module row, naming the water level, after half a pendulum period of statics'
// relaxation (n = 20: 0.6 s in Release); it ran for tens of minutes before.
TEST_F(CliLimits, FloatingRiserIsRefusedNamingTheModuleRow) {
  const BuiltinScenario* lazy = findBuiltin("riser_lazy_wave");
  ASSERT_NE(lazy, nullptr);
  Json doc = scenarioToJson(lazy->scenario);
  doc["parameters"]["buoyancy_modules"][0]["start"] = 0.0;
  doc["parameters"]["geometry"]["segment_count"] = 20;
  expectRejected({"run", write("floating.json", doc.dump()).string()},
                 {"buoyancy_modules[0].start = 0", "the riser floats", "still-water level z = 0 m"});
}

}  // namespace
}  // namespace maris
