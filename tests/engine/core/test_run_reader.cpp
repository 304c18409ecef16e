// readRunFolder: a run folder read back gives the run's scalars, tables (every double exactly: the CSV has 17
// significant digits), plots, statistics and warnings; an older folder without plot layouts gives its tables and
// says so; a folder that is not a complete run, or lists a file outside itself, is refused naming the file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "core/errors.hpp"
#include "core/run_output.hpp"
#include "core/run_reader.hpp"
#include "scratch_folder.hpp"

namespace maris {

namespace fs = std::filesystem;

class RunReaderTest : public ::testing::Test {
 protected:
  void SetUp() override { root_ = test::freshTestFolder("maris_run_reader_"); }
  void TearDown() override { fs::remove_all(root_); }

  // A run with two tables (one with labels and a title), a log plot with reference points, a warning.
  static Results sampleRun() {
    Results r;
    r.addScalar("tip_deflection", -0.123456789012345678, "m", "Static tip deflection", "Tip deflection δ");
    r.addScalar("count", 3.0, "-", "How many");
    Table history;
    history.name = "tip_history";
    history.title = "Tip displacement history";
    history.add("time", "s", {0.0, 0.1, 0.30000000000000004}, "Time");
    history.add("tip_x", "m", {1e-300, -2.5e-17, 1.0 / 3.0}, "Tip x");
    r.tables.push_back(history);
    Table points;
    points.name = "measured";
    points.add("time", "s", {0.05, 0.2});
    points.add("tip_x_measured", "m", {0.01, 0.02});
    r.tables.push_back(points);
    PlotSpec plot = makePlot("tip_x", "Tip x against time", "tip_history", "time", {"tip_x"}, true);
    plot.reference_table = "measured";
    plot.reference_y = {"tip_x_measured"};
    r.plots.push_back(plot);
    r.plots.push_back(makePlot("gone", "A plot of a missing column", "tip_history", "time", {"nothing"}));
    r.stats.method = "RK4 h=0.1 s";
    r.stats.steps = 3;
    r.stats.wall_time_s = 0.25;
    r.stats.error_estimate = 1e-6;
    r.stats.error_unit = "m";
    r.warnings = {"a warning"};
    return r;
  }

  void write(const fs::path& dir, const Results& results) {
    Scenario scenario;
    scenario.scene = "test";
    scenario.name = "run";
    writeRunFolder(dir, scenario, results, std::chrono::system_clock::now());
  }

  fs::path root_;
};

TEST_F(RunReaderTest, AWrittenRunReadsBackWithEveryValueExact) {
  const Results run = sampleRun();
  write(root_ / "run", run);
  const RunFolderContents read = readRunFolder(root_ / "run");
  const Results& r = read.results;
  ASSERT_EQ(r.scalars.size(), 2u);
  const Scalar* tip = r.findScalar("tip_deflection");
  ASSERT_NE(tip, nullptr);
  EXPECT_EQ(tip->value, run.scalars[0].value);  // summary.json keeps a double exactly
  EXPECT_EQ(tip->unit, "m");
  EXPECT_EQ(tip->label, "Tip deflection δ");
  ASSERT_EQ(r.tables.size(), 2u);
  const Table* history = r.findTable("tip_history");
  ASSERT_NE(history, nullptr);
  EXPECT_EQ(history->title, "Tip displacement history");
  ASSERT_EQ(history->columns.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(history->columns[c].name, run.tables[0].columns[c].name);
    EXPECT_EQ(history->columns[c].unit, run.tables[0].columns[c].unit);
    EXPECT_EQ(history->columns[c].label, run.tables[0].columns[c].label);
    EXPECT_EQ(history->columns[c].values, run.tables[0].columns[c].values);  // 17 significant digits: exact
  }
  EXPECT_EQ(r.findTable("measured")->columns[1].label, "");
  // The plot whose column is not in its table is left out; the other comes back as it was.
  ASSERT_EQ(r.plots.size(), 1u);
  EXPECT_EQ(r.plots[0], run.plots[0]);
  EXPECT_EQ(r.stats.method, "RK4 h=0.1 s");
  EXPECT_EQ(r.stats.steps, 3);
  EXPECT_EQ(r.stats.error_estimate, 1e-6);
  EXPECT_EQ(r.warnings, run.warnings);
  EXPECT_TRUE(r.view.empty());
  ASSERT_EQ(read.missing.size(), 1u);  // the 3D view, which no run folder holds
  EXPECT_NE(read.missing[0].find("3D view"), std::string::npos);
}

TEST_F(RunReaderTest, AFolderWithoutPlotLayoutsGivesItsTablesAndSaysSo) {
  write(root_ / "run", sampleRun());
  Json summary = Json::parse(readTextFile(root_ / "run" / "summary.json"));
  summary.erase("plots");
  summary.erase("table_labels");
  writeFileAtomic(root_ / "run" / "summary.json", summary.dump());
  const RunFolderContents read = readRunFolder(root_ / "run");
  EXPECT_EQ(read.results.tables.size(), 2u);
  EXPECT_TRUE(read.results.plots.empty());
  EXPECT_EQ(read.results.findTable("tip_history")->columns[1].label, "");
  ASSERT_EQ(read.missing.size(), 2u);
  EXPECT_NE(read.missing[0].find("plots"), std::string::npos);
}

TEST_F(RunReaderTest, NoRunOrAFileOutsideTheFolderIsRefusedNamingTheFile) {
  fs::create_directories(root_ / "empty");
  try {
    readRunFolder(root_ / "empty");
    FAIL() << "an empty folder was read";
  } catch (const InputError& e) {
    // The input gate names the file it could not read (shortened to 80 characters, as every echoed value).
    ASSERT_FALSE(e.errors().empty());
    EXPECT_EQ(e.errors().front().path.rfind(root_.string().substr(0, 40), 0), 0u) << e.what();
    EXPECT_EQ(e.errors().front().message, "does not exist") << e.what();
  }
  write(root_ / "run", sampleRun());
  Json summary = Json::parse(readTextFile(root_ / "run" / "summary.json"));
  summary["tables"] = {"../elsewhere.csv"};
  writeFileAtomic(root_ / "run" / "summary.json", summary.dump());
  try {
    readRunFolder(root_ / "run");
    FAIL() << "a table outside the folder was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("../elsewhere.csv"), std::string::npos) << e.what();
  }
}

}  // namespace maris
