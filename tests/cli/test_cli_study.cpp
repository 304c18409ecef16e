// `maris-cli study` and `validate` end to end, on the riser and ship scenes (skipped if not compiled in):
// the same study run with --jobs 1 and --jobs 2 writes the same study.csv byte for byte, and its values
// are those of single runs; a study killed midway and resumed runs no case twice; a bad study names
// every bad case and runs nothing; failed and timed-out cases are recorded and the study goes on;
// relative data paths resolve against the file that names them.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "catalog.hpp"
#include "cli_runner.hpp"
#include "study_cli_helpers.hpp"
#include "source_tree.hpp"
#include "scratch_folder.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;
using test::completeCases;
using test::contains;
using test::runCli;
using test::slurp;
using test::startCli;
using test::writeText;

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

std::string cell(const std::vector<std::vector<std::string>>& rows, std::size_t row, const std::string& column) {
  for (std::size_t c = 0; c < rows[0].size(); ++c)
    if (rows[0][c] == column) return c < rows[row].size() ? rows[row][c] : "";
  return "(no column " + column + ")";
}

std::string seventeenDigits(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

class CliStudy : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findBuiltin("riser_cantilever_tip_load") || !findBuiltin("ship_default"))
      GTEST_SKIP() << "needs the riser and ship scenes";
    dir_ = test::freshTestFolder("maris_cli_study_");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// A riser cantilever (statics only, a few ms per case) over a 4 x 3 grid, and a ship load-case table of 12
// hulls (20 speeds each; 5 under the sanitizers, where the speeds are most of the test's time and add no path):
// two scenes, two designs.
const char* kRiserStudy = R"({"format": "maris-study/1", "name": "cantilever", "base": "riser_cantilever_tip_load",
  "grid": {"geometry.length": {"from": 10, "to": 30, "count": 4},
           "section.youngs_modulus": [1.5e11, 2.07e11, 2.5e11]}})";
#if defined(__SANITIZE_ADDRESS__)
#define MARIS_TEST_SHIP_SPEEDS "5"
#else
#define MARIS_TEST_SHIP_SPEEDS "20"
#endif
const char* kShipStudy = R"({"format": "maris-study/1", "name": "hulls", "base": "ship_default",
  "set": {"speed.count": )" MARIS_TEST_SHIP_SPEEDS R"(, "numerics.threads": 1}, "table": "hulls.csv",
  "results": ["c_total", "r_total", "wetted_surface"]})";
const char* kShipTable =
    "hull.length,hull.beam,water.kind\nm,m,-\n"
    "2,0.2,fresh\n2.5,0.25,sea\n3,0.3,fresh\n3.5,0.35,sea\n4,0.4,fresh\n4.5,0.45,sea\n"
    "5,0.5,fresh\n5.5,0.55,sea\n6,0.6,fresh\n6.5,0.65,sea\n7,0.7,fresh\n7.5,0.75,sea\n";

TEST_F(CliStudy, OneAndTwoJobsWriteTheSameStudyCsvWithTheValuesOfSingleRuns) {
  writeText(dir_ / "riser.json", kRiserStudy);
  writeText(dir_ / "ship.json", kShipStudy);
  writeText(dir_ / "hulls.csv", kShipTable);
  for (const char* study : {"riser", "ship"}) {
    const std::string file = std::string(study) + ".json";
    const auto one = runCli({"study", "run", file, "--out", std::string(study) + "1", "--jobs", "1", "--no-plots"}, dir_.string());
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const auto two = runCli({"study", "run", file, "--out", std::string(study) + "2", "--jobs", "2"}, dir_.string());
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const std::string csv = slurp(dir_ / (std::string(study) + "1") / "study.csv");
    EXPECT_EQ(csv, slurp(dir_ / (std::string(study) + "2") / "study.csv")) << study;
    const auto rows = csvRows(csv);
    ASSERT_EQ(rows.size(), 14u) << csv;  // names, units, 12 cases
    for (std::size_t r = 2; r < rows.size(); ++r) EXPECT_EQ(cell(rows, r, "status"), "ok") << csv;
    EXPECT_TRUE(fs::exists(dir_ / (std::string(study) + "2") / "study.json"));
    EXPECT_FALSE(fs::exists(dir_ / (std::string(study) + "1") / "plots"));
  }
  // The riser grid: the last parameter varies fastest; units from the scene's schema.
  const auto riser = csvRows(slurp(dir_ / "riser1" / "study.csv"));
  EXPECT_EQ(riser[0][2], "geometry.length");
  EXPECT_EQ(riser[1][2], "m");
  EXPECT_EQ(riser[1][3], "Pa");
  EXPECT_EQ(cell(riser, 3, "section.youngs_modulus"), "207000000000");
  EXPECT_EQ(cell(riser, 5, "geometry.length"), seventeenDigits(10.0 + 20.0 / 3.0));
  // Case 0005 equals a single run with the same two values, to the last bit.
  const auto single = runCli({"run", "riser_cantilever_tip_load", "--set", "geometry.length=" + seventeenDigits(10.0 + 20.0 / 3.0),
                              "--set", "section.youngs_modulus=2.07e11", "--out", "single", "--no-plots"},
                             dir_.string());
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const Json summary = Json::parse(slurp(dir_ / "single" / "summary.json"));
  // end_z is the static tip's height (tip_deflection counts from the static shape: 0 in a statics-only run).
  EXPECT_EQ(cell(riser, 6, "end_z"), seventeenDigits(summary["results"]["end_z"]["value"].get<double>()));
  EXPECT_LT(summary["results"]["end_z"]["value"].get<double>(), -1e-3);
  // The ship table: only the requested results, in the order asked; the table's values in its columns.
  const auto ship = csvRows(slurp(dir_ / "ship1" / "study.csv"));
  EXPECT_EQ(ship[0], (std::vector<std::string>{"case", "status", "hull.length", "hull.beam", "water.kind", "c_total",
                                               "r_total", "wetted_surface"}));
  EXPECT_EQ(cell(ship, 3, "water.kind"), "sea");
  EXPECT_EQ(cell(ship, 13, "hull.length"), "7.5");
  // Plots: each result against each varied number parameter (a 2-D grid: a heat map per result).
  EXPECT_TRUE(fs::exists(dir_ / "ship2" / "plots" / "c_total_vs_hull.length.png"));
  EXPECT_TRUE(fs::exists(dir_ / "riser2" / "plots" / "end_z_map.png"));
}

TEST_F(CliStudy, AStudyKilledMidwayIsFinishedByResumeWithNoCaseRunTwice) {
  writeText(dir_ / "slow.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"solver.end_time": {"from": 0.5, "to": 1.6, "count": 12}}})");
  const pid_t pid = startCli({"study", "run", (dir_ / "slow.json").string(), "--out", (dir_ / "out").string(),
                              "--jobs", "2", "--no-plots"}, dir_);
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (completeCases(dir_ / "out" / "cases").size() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143) << slurp(dir_ / "err.txt");
  const auto before = completeCases(dir_ / "out" / "cases");
  ASSERT_GE(before.size(), 2u);
  ASSERT_LT(before.size(), 12u) << "every case ended before the signal: nothing left to resume";
  for (const auto& e : fs::directory_iterator(dir_ / "out" / "cases"))  // no half-written case folder
    EXPECT_TRUE(e.is_regular_file() || fs::exists(e.path() / "summary.json")) << e.path();
  EXPECT_TRUE(contains(slurp(dir_ / "err.txt"), "--resume")) << slurp(dir_ / "err.txt");

  const auto refused = runCli({"study", "run", "slow.json", "--out", "out", "--no-plots"}, dir_.string());
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  EXPECT_TRUE(contains(refused.err, "--resume")) << refused.err;
  const auto resumed = runCli({"study", "run", "slow.json", "--out", "out", "--resume", "--jobs", "2", "--no-plots"},
                              dir_.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto after = completeCases(dir_ / "out" / "cases");
  EXPECT_EQ(after.size(), 12u);
  for (const auto& [id, identity] : before) EXPECT_EQ(after.at(id), identity) << "case " << id << " ran again";
  const Json manifest = Json::parse(slurp(dir_ / "out" / "study.json"));
  ASSERT_EQ(manifest["runs"].size(), 2u);
  EXPECT_EQ(manifest["runs"][1]["skipped_complete"], before.size());
  EXPECT_EQ(manifest["runs"][1]["cases_run"], 12 - before.size());
  EXPECT_EQ(manifest["collected"]["ok"], 12);
}

TEST_F(CliStudy, ABadStudyNamesEveryBadCaseAndRunsNothing) {
  // geometry.length must be at least the probe's arc length (10 m) and positive: cases 0002 and 0004 are bad.
  writeText(dir_ / "bad.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"geometry.length": [20, -1, 30, 5]}})");
  const auto run = runCli({"study", "run", "bad.json", "--out", "out"}, dir_.string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "2 of 4 cases are invalid: 0002, 0004; nothing was run")) << run.err;
  EXPECT_TRUE(contains(run.err, "case 0002: parameters.geometry.length = -1")) << run.err;
  EXPECT_TRUE(contains(run.err, "case 0004: parameters.output.probes[0].arc_length")) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const auto validate = runCli({"validate", "bad.json"}, dir_.string());
  EXPECT_EQ(validate.exit_code, 2);
  EXPECT_EQ(validate.err, "bad.json: invalid:\n  " + run.err.substr(run.err.find("cases: ")));
}

TEST_F(CliStudy, ValidateChecksScenariosAndStudiesAndResolvesDataPathsAgainstTheirFolder) {
  fs::create_directories(dir_ / "project" / "data");
  writeText(dir_ / "project" / "data" / "points.csv", "froude,c_total\n0.2,0.004\n0.3,0.005\n");
  Scenario ship = findBuiltin("ship_default")->scenario;
  ship.parameters["measured"]["file"] = "data/points.csv";
  ship.parameters["speed"]["count"] = 20;
  saveScenarioFile(ship, dir_ / "project" / "ship.json");
  writeText(dir_ / "project" / "study.json", R"({"format": "maris-study/1", "base": "ship.json",
    "set": {"speed.count": 20}, "grid": {"hull.length": [3, 4]}})");
  writeText(dir_ / "project" / "other.json", R"({"format": "maris-study/1", "base": "ship_default",
    "set": {"measured.file": "data/nowhere.csv"}, "grid": {"hull.length": [3]}})");
  writeText(dir_ / "project" / "broken.json", R"({"format": "maris-scenario/1", "scene": "ship", "parameters": {"hull": 1}})");
  const auto r = runCli({"validate", "project/ship.json", "project/study.json", "project/other.json", "project/broken.json"},
                        dir_.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.out, "project/ship.json: valid scenario of scene ship")) << r.out;
  EXPECT_TRUE(contains(r.out, "project/study.json: valid study, 2 cases of scene ship (grid)")) << r.out;
  EXPECT_TRUE(contains(r.err, "project/other.json: invalid:")) << r.err;
  EXPECT_TRUE(contains(r.err, "case 0001: parameters.measured.file = \"/")) << r.err;  // made absolute
  EXPECT_TRUE(contains(r.err, "is not a readable file")) << r.err;
  EXPECT_TRUE(contains(r.err, "project/broken.json: invalid:")) << r.err;
  // A run from another folder finds the data beside the scenario; its scenario.json names it absolutely.
  const auto run = runCli({"run", (dir_ / "project" / "ship.json").string(), "--out", (dir_ / "run").string(), "--no-plots"}, "/");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json ran = Json::parse(slurp(dir_ / "run" / "scenario.json"));
  EXPECT_EQ(ran["parameters"]["measured"]["file"], (dir_ / "project" / "data" / "points.csv").string());
}

TEST_F(CliStudy, FailedAndTimedOutCasesAreRecordedAndTheStudyGoesOn) {
  // Case 0002 simulates 60 s with explicit RK4 (about 20 s of work; `auto` picks the implicit integrator there,
  // under a second): the 5 s timeout stops it; the others (well under a second, with room for a loaded machine) finish.
  writeText(dir_ / "timeout.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "set": {"solver.integrator": "rk4"}, "grid": {"solver.end_time": [0.1, 60, 0.2]}})");
  const auto r = runCli({"study", "run", "timeout.json", "--out", "t", "--jobs", "2", "--timeout", "5", "--no-plots"},
                        dir_.string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(contains(r.err, "case 0002 timeout")) << r.err;
  const auto rows = csvRows(slurp(dir_ / "t" / "study.csv"));
  EXPECT_EQ(cell(rows, 2, "status"), "ok");
  EXPECT_EQ(cell(rows, 3, "status"), "timeout");
  EXPECT_EQ(cell(rows, 3, "tip_deflection"), "");
  EXPECT_EQ(cell(rows, 4, "status"), "ok");
  EXPECT_FALSE(fs::exists(dir_ / "t" / "cases" / "0002"));

  // A prepared study (submit --dry-run) whose case 0002 was damaged after the check: the array task records
  // the failure with the case's own message, collect lists it, and --resume refuses the changed study.
  writeText(dir_ / "grid.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"geometry.length": [20, 25, 30]}})");
  const auto prepared = runCli({"study", "submit", "grid.json", "--out", "g", "--engine", "slurm", "--dry-run",
                                "--cases-per-task", "2", "--max-parallel", "4", "--partition", "short"},
                               dir_.string());
  ASSERT_EQ(prepared.exit_code, 0) << prepared.err;
  const std::string script = slurp(dir_ / "g" / "slurm" / "cases.sbatch");
  EXPECT_TRUE(contains(script, "#SBATCH --array=0-1%4")) << script;
  EXPECT_TRUE(contains(script, "#SBATCH --partition=short")) << script;
  EXPECT_TRUE(contains(script, "study run-cases '" + (dir_ / "g").string() + "' --first \"$first\" --count 2")) << script;
  EXPECT_TRUE(contains(slurp(dir_ / "g" / "slurm" / "collect.sbatch"), "study collect '" + (dir_ / "g").string() + "'"));
  writeText(dir_ / "g" / "cases" / "0002.json", "{}");
  const auto task = runCli({"study", "run-cases", "g", "--first", "1", "--count", "2", "--jobs", "1"}, dir_.string());
  EXPECT_EQ(task.exit_code, 3) << task.err;
  const Json outcome = Json::parse(slurp(dir_ / "g" / "cases" / "0002.outcome.json"));
  EXPECT_EQ(outcome["status"], "failed");
  EXPECT_EQ(outcome["exit_code"], 2);
  EXPECT_TRUE(contains(outcome["message"].get<std::string>(), "invalid input")) << outcome;
  const auto collected = runCli({"study", "collect", "g", "--no-plots"}, dir_.string());
  EXPECT_EQ(collected.exit_code, 3);
  EXPECT_TRUE(contains(collected.err, "case 0002 failed (exit code 2): invalid input")) << collected.err;
  EXPECT_TRUE(contains(collected.err, "not run yet: 0003")) << collected.err;
  EXPECT_TRUE(contains(collected.out, "3 cases: 1 ok, 1 failed, 0 timed out, 1 not run")) << collected.out;
  const auto rows2 = csvRows(slurp(dir_ / "g" / "study.csv"));
  EXPECT_EQ(cell(rows2, 3, "status"), "failed");
  EXPECT_EQ(cell(rows2, 4, "status"), "missing");
  const auto resume = runCli({"study", "run", "grid.json", "--out", "g", "--resume"}, dir_.string());
  EXPECT_EQ(resume.exit_code, 1) << resume.err;
  EXPECT_TRUE(contains(resume.err, "case 0002 differs")) << resume.err;
}

// A fatigue scatter diagram is a table study over sea states: study.csv holds each case's annual damage at its
// critical hot spot, and the table's probability column weights them into the year's damage, which `study
// collect` writes into study.json (docs/studies.md).
TEST_F(CliStudy, AFatigueScatterStudyCollectsEachSeaStatesAnnualDamage) {
  if (!findBuiltin("riser_jonswap_sea")) GTEST_SKIP() << "needs the riser sea scenario";
  writeText(dir_ / "seas.csv", "waves.significant_height,probability,waves.peak_period\nm,-,s\n2.0,0.75,8.0\n6.0,0.25,11.0\n");
  // 20 s of sea counted after the 20 s ramp: enough cycles for the comparison below, short under the sanitizers.
  writeText(dir_ / "scatter.json", R"({"format": "maris-study/1", "base": "riser_jonswap_sea",
    "set": {"solver.end_time": 40}, "table": "seas.csv", "results": ["max_fatigue_damage_per_year", "min_fatigue_life"],
    "weighted_sum": {"weight": "probability", "results": ["max_fatigue_damage_per_year"]}})");
  const auto run = runCli({"study", "run", "scatter.json", "--out", "scatter", "--jobs", "2", "--no-plots"}, dir_.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = csvRows(slurp(dir_ / "scatter" / "study.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(cell(rows, 1, "max_fatigue_damage_per_year"), "1/yr");
  double damage[2] = {0, 0};
  for (std::size_t r = 2; r < 4; ++r) {
    damage[r - 2] = std::stod(cell(rows, r, "max_fatigue_damage_per_year"));
    const double life = std::stod(cell(rows, r, "min_fatigue_life"));
    EXPECT_GT(damage[r - 2], 0.0);
    EXPECT_NEAR(damage[r - 2] * life, 1.0, 1e-12) << r;  // the same hot spot: life = 1 / damage per year (uncapped)
  }
  // Miner damage grows as a power (3 to 5, the S-N slopes) of the stress range, which grows with Hs: three times
  // the wave height gives far more than ten times the damage.
  EXPECT_GT(damage[1], 10.0 * damage[0]);
  EXPECT_EQ(rows[0].size(), 6u);  // case, status, the two parameters, the two results: the weight is no parameter

  // The year's damage: 0.75 d_1 + 0.25 d_2 by hand from study.csv (17 digits: each d_i read back exactly; the
  // weights are exact in binary, so the sums agree to the last bit but for the order of rounding, 1e-15).
  const Json manifest = Json::parse(slurp(dir_ / "scatter" / "study.json"));
  const Json& sums = manifest.at("collected").at("weighted_sums");
  ASSERT_EQ(sums.size(), 1u);
  EXPECT_EQ(sums[0].at("result"), "max_fatigue_damage_per_year");
  EXPECT_EQ(sums[0].at("weight"), "probability");
  EXPECT_EQ(sums[0].at("unit"), "1/yr");
  EXPECT_EQ(sums[0].at("weight_total").get<double>(), 1.0);
  const double year = 0.75 * damage[0] + 0.25 * damage[1];
  EXPECT_NEAR(sums[0].at("value").get<double>(), year, 1e-15 * year);
  EXPECT_TRUE(contains(run.out, "weighted sum of max_fatigue_damage_per_year over probability: ")) << run.out;

  // A case gone (a node lost its folder): collect says the sum waits for it, by name, and records no value.
  fs::remove_all(dir_ / "scatter" / "cases" / "0002");
  const auto partial = runCli({"study", "collect", "scatter", "--no-plots"}, dir_.string());
  EXPECT_EQ(partial.exit_code, 3) << partial.err;
  EXPECT_TRUE(contains(partial.out, "over probability: not yet; case 0002 has weight but no value")) << partial.out;
  const Json waiting = Json::parse(slurp(dir_ / "scatter" / "study.json")).at("collected").at("weighted_sums").at(0);
  EXPECT_TRUE(waiting.at("value").is_null());
  EXPECT_EQ(waiting.at("missing"), Json::array({"0002"}));
}

// A study over a table cell writes its plot under a portable file name (the cell's "[0]" as "_0"), and no file
// name in plots/ holds a character outside [A-Za-z0-9._-].
TEST_F(CliStudy, APlotAgainstATableCellHasAPortableFileName) {
  writeText(dir_ / "cell.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"output.probes[0].arc_length": [2, 8]}, "results": ["tip_deflection"]})");
  const auto run = runCli({"study", "run", "cell.json", "--out", "cell", "--jobs", "2"}, dir_.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "cell" / "plots" / "tip_deflection_vs_output.probes_0.arc_length.png")) << run.out;
  std::size_t pngs = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "cell" / "plots")) {
    ++pngs;
    for (const char c : e.path().filename().string())
      EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-') << e.path();
  }
  EXPECT_EQ(pngs, 1u);
}

// The examples in resources/studies are valid wherever they are checked from (their table and base resolve
// against their folder); the riser grid runs and draws a heat map per result. Its tip deflection, -end_z, is the
// small-load closed form PL^3/(3EI)(1 - 1/(4n^2)) (the base scenario's description; P = 60 N, D 0.1/0.08 m,
// n = 20) within 2e-4 where PL^2/EI <= 0.03 (the 10 m cases; the large-deflection term is about 0.11 (PL^2/EI)^2,
// 1e-4 there), and below it in every other case (a cantilever stiffens as it bends: 5.6 % at 50 m, 70 GPa,
// where PL^2/EI = 0.74).
TEST_F(CliStudy, TheExampleStudiesAreValidAndTheGridRuns) {
  const fs::path examples = fs::path(maris::test::sourceDir()) / "resources" / "studies";
  std::vector<std::string> args = {"validate"};
  for (const auto& e : fs::directory_iterator(examples))
    if (e.path().extension() == ".json") args.push_back(e.path().string());
  ASSERT_GE(args.size(), 4u);
  const auto r = runCli(args, "/");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto run = runCli({"study", "run", (examples / "riser_cantilever_grid.json").string(), "--out", "grid", "--jobs", "2"},
                          dir_.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(contains(run.out, "20 cases: 20 ok")) << run.out;
  for (const char* plot : {"end_z_map.png", "max_bending_stress_map.png", "first_natural_frequency_map.png"})
    EXPECT_TRUE(fs::exists(dir_ / "grid" / "plots" / plot)) << plot;
  const auto rows = csvRows(slurp(dir_ / "grid" / "study.csv"));
  ASSERT_EQ(rows.size(), 22u);
  const double second_moment = 3.14159265358979323846 / 64.0 * (std::pow(0.1, 4) - std::pow(0.08, 4));
  for (std::size_t r = 2; r < rows.size(); ++r) {
    const double length = std::stod(cell(rows, r, "geometry.length"));
    const double modulus = std::stod(cell(rows, r, "section.youngs_modulus"));
    const double closed = 60.0 * std::pow(length, 3) / (3.0 * modulus * second_moment) * (1.0 - 1.0 / 1600.0);
    const double deflection = -std::stod(cell(rows, r, "end_z"));
    if (60.0 * length * length / (modulus * second_moment) <= 0.03)
      EXPECT_NEAR(deflection, closed, 2e-4 * closed) << "case " << cell(rows, r, "case");
    else
      EXPECT_TRUE(deflection > 0.9 * closed && deflection < closed) << "case " << cell(rows, r, "case");
  }
}

}  // namespace
}  // namespace maris
