// maris-cli links no Qt: its PNG plots come from the module maris_plot_renderer.so, loaded only when plots
// are written. Checked here: the executable's own libraries (the dynamic loader's list, as ldd prints it)
// hold no Qt; a run writes its PNGs through the module; a copy of maris-cli without the module refuses a
// run with plots before the solve (exit 1, naming the module and --no-plots, no output folder) and runs
// with --no-plots; `study run` refuses likewise before any case runs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "cli_runner.hpp"
#include "source_tree.hpp"
#include "study_cli_helpers.hpp"

namespace fs = std::filesystem;
using maris::test::runCli;
using maris::test::slurp;

namespace {

struct Shell {
  int exit_code = -1;
  std::string out, err;
};

// Runs `command` with /bin/sh in `dir`, stdout and stderr captured.
Shell shell(const fs::path& dir, const std::string& command) {
  const std::string full = "cd '" + dir.string() + "' && " + command + " >out.txt 2>err.txt </dev/null";
  const int status = std::system(full.c_str());
  Shell r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out.txt");
  r.err = slurp(dir / "err.txt");
  return r;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("maris_cli_plots_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST(CliPlotRenderer, MarisCliLinksNoQt) {
  const fs::path dir = scratch("ldd");
  // LD_TRACE_LOADED_OBJECTS makes the dynamic loader list the libraries it would map instead of running.
  const Shell r = shell(dir, "LD_TRACE_LOADED_OBJECTS=1 '" + maris::test::cliPath() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("libc.so"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("libQt"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("QCustomPlot"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

#if MARIS_TEST_PLOT_RENDERER
TEST(CliPlotRenderer, ARunWritesItsPlotsThroughTheModule) {
  const fs::path dir = scratch("run");
  const auto r = runCli({"run", "riser_cantilever_tip_load", "--set", "solver.end_time=0", "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int pngs = 0;
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    if (entry.path().extension() == ".png" && fs::file_size(entry.path()) > 1000) ++pngs;
  EXPECT_GT(pngs, 0);
  fs::remove_all(dir);
}

// Without a login session (a Slurm job, a container: no XDG_RUNTIME_DIR) Qt warns about its runtime folder, which
// off-screen rendering does not use: the module keeps that line out of the run's stderr.
TEST(CliPlotRenderer, NoRuntimeFolderWarningWithoutALoginSession) {
  const fs::path dir = scratch("session");
  const auto r = runCli({"run", "riser_cantilever_tip_load", "--set", "solver.end_time=0", "--out", (dir / "out").string()},
                        ".", 0.0, 2, "unset XDG_RUNTIME_DIR;");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
  EXPECT_EQ(r.err.find("QStandardPaths"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("XDG_RUNTIME_DIR"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(CliPlotRenderer, WithoutTheModuleARunWithPlotsIsRefusedBeforeTheSolve) {
  const fs::path dir = scratch("missing");
  fs::copy_file(maris::test::cliPath(), dir / "maris-cli");
  const Shell refused = shell(dir, "./maris-cli run riser_cantilever_tip_load --set solver.end_time=0 --out out");
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  EXPECT_NE(refused.err.find("maris_plot_renderer.so"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--no-plots"), std::string::npos) << refused.err;
  EXPECT_EQ(refused.err.find("running "), std::string::npos) << "refused after the solve started: " << refused.err;
  EXPECT_FALSE(fs::exists(dir / "out"));

  const Shell plain = shell(dir, "./maris-cli run riser_cantilever_tip_load --set solver.end_time=0 --out out --no-plots");
  EXPECT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));

  std::ofstream(dir / "study.json") << R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "set": {"solver.end_time": 0}, "grid": {"geometry.length": [10, 20]}})";
  const Shell study = shell(dir, "./maris-cli study run study.json --out study_out --jobs 1");
  EXPECT_EQ(study.exit_code, 1) << study.err;
  EXPECT_NE(study.err.find("maris_plot_renderer.so"), std::string::npos) << study.err;
  EXPECT_FALSE(fs::exists(dir / "study_out" / "cases"));
  fs::remove_all(dir);
}
#endif
