// maris-cli run folders as transactions and runs as bounded and cancellable: SIGINT/SIGTERM during a run
// (exit 130/143, no folder), --out checked before the solve (file, read-only, no room, empty name, locked),
// an earlier run refused without --force and replaced whole with it, a write failure (file-size limit) leaving
// the earlier run untouched, and a run beyond the work limits refused unless --allow-large.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "catalog.hpp"
#include "cli_runner.hpp"
#include "scratch_folder.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;
using test::runCli;
using test::kQuickBuiltin;

// A run long enough to be interrupted (about 2e7 RK4 steps; within the work limits).
const std::vector<std::string> kLongRun = {"run", "riser_default", "--set", "solver.integrator=\"rk4\"",
                                           "--set", "solver.time_step=1e-6", "--no-plots"};

class CliRunFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findBuiltin("riser_default")) GTEST_SKIP() << "needs the riser scene";
    root_ = test::freshTestFolder("maris_cli_folder_");
  }
  void TearDown() override {
    if (!mounted_.empty()) std::system(("umount '" + mounted_.string() + "' 2>/dev/null").c_str());
    fs::remove_all(root_);
  }
  // Every name in root_ apart from lock files: what a run left visible or half-written.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(root_))
      if (e.path().extension() != ".lock") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  test::CliResult quickRun(const fs::path& out, std::vector<std::string> extra = {}, const std::string& prefix = "") {
    std::vector<std::string> args = {"run", kQuickBuiltin, "--no-plots", "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runCli(args, ".", 0.0, SIGINT, prefix);
  }
  // Mounts a tmpfs at `dir` (root only; CI runs as root). False when that is impossible here.
  bool mountTmpfs(const fs::path& dir, const std::string& options) {
    fs::create_directories(dir);
    if (::geteuid() != 0) return false;
    if (std::system(("mount -t tmpfs -o " + options + " tmpfs '" + dir.string() + "' 2>/dev/null").c_str()) != 0)
      return false;
    mounted_ = dir;
    return true;
  }

  fs::path root_, mounted_;
};

TEST_F(CliRunFolder, SigintAndSigtermCancelTheRunAndWriteNothing) {
  for (const auto& [sig, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    auto args = kLongRun;
    args.insert(args.end(), {"--out", (root_ / "out").string()});
    const auto r = runCli(args, ".", 1.5, sig);
    EXPECT_EQ(r.exit_code, code) << r.err;
    EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
    EXPECT_EQ(entries(), std::vector<std::string>{}) << "signal " << sig;
    std::printf("[ latency  ] signal %d: maris-cli ended %.3f s after it\n", sig, r.exit_after_signal_s);
  }
}

TEST_F(CliRunFolder, AnUnusableOutputFolderIsRefusedBeforeTheSolve) {
  const auto empty = quickRun("");
  EXPECT_EQ(empty.exit_code, 1) << empty.err;
  EXPECT_NE(empty.err.find("--out needs a folder name"), std::string::npos) << empty.err;

  writeFileAtomic(root_ / "file", "x");
  for (const fs::path& out : {root_ / "file", root_ / "file" / "below"}) {
    const auto r = quickRun(out);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("file"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("running"), std::string::npos) << "solved before refusing: " << r.err;
  }
  EXPECT_EQ(readTextFile(root_ / "file"), "x");

  // Read-only: a read-only tmpfs as root (root ignores permission bits), else a folder without write permission.
  const fs::path locked = root_ / "readonly";
  if (!mountTmpfs(locked, "ro,size=1m")) fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  if (::geteuid() == 0 && mounted_.empty()) {
    std::printf("skipped the read-only case: cannot mount a tmpfs here\n");
  } else {
    const auto r = quickRun(locked / "out");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("cannot write in"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("running"), std::string::npos) << r.err;
  }
  if (mounted_.empty()) fs::permissions(locked, fs::perms::owner_all);  // a read-only mount is undone in TearDown
}

TEST_F(CliRunFolder, AFullDiskIsRefusedBeforeTheSolveOrLeavesNothing) {
  if (!mountTmpfs(root_ / "small", "size=16k")) GTEST_SKIP() << "cannot mount a small tmpfs here (needs root)";
  const auto r = quickRun(root_ / "small" / "out");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("not enough free space"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(root_ / "small") || !fs::exists(root_ / "small" / "out"));
}

TEST_F(CliRunFolder, AnEarlierRunIsRefusedWithoutForceAndReplacedWholeWithIt) {
  const fs::path out = root_ / "out";
  ASSERT_EQ(quickRun(out).exit_code, 0);
  writeFileAtomic(out / "stale_table.csv", "from the earlier run\n");
  const auto again = quickRun(out);
  EXPECT_EQ(again.exit_code, 1) << again.err;
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  EXPECT_TRUE(fs::exists(out / "stale_table.csv"));

  const auto forced = quickRun(out, {"--force"});
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_FALSE(fs::exists(out / "stale_table.csv")) << "old and new files mixed";
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

TEST_F(CliRunFolder, AWriteFailureLeavesTheEarlierRunUntouched) {
  const fs::path out = root_ / "out";
  ASSERT_EQ(quickRun(out).exit_code, 0);
  const std::string summary = readTextFile(out / "summary.json");
  // Files above 4 blocks fail with EFBIG (maris-cli ignores SIGXFSZ): a disk that fills during the writing.
  const auto r = quickRun(out, {"--force"}, "ulimit -f 4;");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_EQ(readTextFile(out / "summary.json"), summary);
  EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

TEST_F(CliRunFolder, ASecondRunIntoTheSameFolderIsRefusedWhileTheFirstWrites) {
  const int fd = ::open((root_ / ".out.lock").c_str(), O_RDWR | O_CREAT, 0644);  // what a running maris-cli holds
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const auto r = quickRun(root_ / "out");
  ::close(fd);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("another maris run is writing"), std::string::npos) << r.err;
  EXPECT_EQ(entries(), std::vector<std::string>{});
}

TEST_F(CliRunFolder, ARunBeyondTheWorkLimitsIsRefusedUnlessAllowed) {
  std::vector<std::string> args = {"run", "riser_default", "--set", "solver.integrator=\"rk4\"", "--set",
                                   "solver.time_step=1e-8", "--out", (root_ / "out").string()};
  const auto refused = runCli(args);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("parameters.solver.time_step"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--allow-large"), std::string::npos) << refused.err;
  args.push_back("--allow-large");
  const auto allowed = runCli(args, ".", 1.5);  // it starts (and is cancelled)
  EXPECT_EQ(allowed.exit_code, 130) << allowed.err;
  EXPECT_NE(allowed.err.find("running"), std::string::npos) << allowed.err;
  EXPECT_EQ(entries(), std::vector<std::string>{});
}

}  // namespace
}  // namespace maris
