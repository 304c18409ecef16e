// What a killed study leaves beside its cases, and how the next `study run --resume` or `study collect`
// deals with it: staging folders named by an earlier version (`.NNNN.partial-PID`, `.NNNN.old-PID`) are
// removed with one listing of the cases folder, and a case process that outlived its study (the study alone
// was killed) is waited for instead of being run a second time beside it or recorded as failed.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_runner.hpp"
#include "core/run_folder.hpp"
#include "study_cli_helpers.hpp"
#include "study_test_folder.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;
using test::completeCases;
using test::contains;
using test::runCli;
using test::slurp;
using test::startCli;
using test::writeText;

class CliStudyOrphans : public test::StudyTestFolder {
 protected:
  CliStudyOrphans() : StudyTestFolder("maris_cli_study_orphans_") {}
};

// A staging folder as a killed run of an earlier version left it: some of the run's files.
void leftover(const fs::path& dir) {
  fs::create_directories(dir);
  writeText(dir / "scenario.json", "{}\n");
}

TEST_F(CliStudyOrphans, OldVersionStagingFoldersAreRemovedByResumeAndCollectNotByEachCase) {
  writeText(dir_ / "grid.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"geometry.length": [10, 20, 30, 40]}})");
  ASSERT_EQ(runCli({"study", "run", "grid.json", "--out", "out", "--jobs", "2", "--no-plots"}, dir_.string()).exit_code, 0);
  const fs::path cases = dir_ / "out" / "cases";
  leftover(cases / ".0002.partial-4242");
  leftover(cases / ".0003.old-77");
  leftover(cases / ".0002.partial-x");  // not an old version's name: someone else's, kept
  const auto collected = runCli({"study", "collect", "out", "--no-plots"}, dir_.string());
  EXPECT_EQ(collected.exit_code, 0) << collected.err;
  EXPECT_TRUE(contains(collected.err, "note: removed 2 staging folders that killed runs of an earlier maris version"))
      << collected.err;
  EXPECT_FALSE(fs::exists(cases / ".0002.partial-4242"));
  EXPECT_FALSE(fs::exists(cases / ".0003.old-77"));
  EXPECT_TRUE(fs::exists(cases / ".0002.partial-x"));

  // --resume removes them too, before it runs the incomplete cases (0001 here).
  leftover(cases / ".0001.partial-5");
  fs::remove_all(cases / "0001");
  const auto resumed = runCli({"study", "run", "grid.json", "--out", "out", "--resume", "--no-plots"}, dir_.string());
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_TRUE(contains(resumed.err, "note: removed 1 staging folder that")) << resumed.err;
  EXPECT_FALSE(fs::exists(cases / ".0001.partial-5"));
  EXPECT_EQ(completeCases(cases).size(), 4u);

  // A case process (`run --study-case`) does not list the cases folder for them; a single run removes its own.
  leftover(cases / ".0004.partial-6");
  const std::vector<std::string> rerun = {"run", "out/cases/0004.json", "--out", "out/cases/0004", "--force",
                                          "--no-plots", "--no-sync"};
  auto as_case = rerun;
  as_case.push_back("--study-case");
  EXPECT_EQ(runCli(as_case, dir_.string()).exit_code, 0);
  EXPECT_TRUE(fs::exists(cases / ".0004.partial-6"));
  EXPECT_EQ(runCli(rerun, dir_.string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(cases / ".0004.partial-6"));
}

// Resumes the group `group` (stopped) when the test ends, however it ends: its processes are never left stopped.
struct ContinueOnExit {
  pid_t group;
  ~ContinueOnExit() { ::kill(-group, SIGCONT); }
};

TEST_F(CliStudyOrphans, ResumeWaitsForACaseProcessThatOutlivedItsStudyAndDoesNotRunItAgain) {
  // Two cases of 4 and 5 s of dynamics (about a second of work each), both running at once.
  writeText(dir_ / "slow.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"solver.end_time": [4, 5]}})");
  const fs::path out = dir_ / "out", cases = out / "cases";
  // The orphans are held stopped below. Were they re-parented to init, their process group would be orphaned
  // with stopped members, and the kernel would send it SIGHUP and SIGCONT (POSIX), killing them. This test
  // process adopts them instead (a subreaper in another process group of the same session), so the group stays
  // unorphaned, as it does for case processes that are running, not stopped, when their study is killed.
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  const pid_t study = startCli({"study", "run", (dir_ / "slow.json").string(), "--out", out.string(), "--jobs", "2",
                                "--no-plots"}, dir_, true);
  ASSERT_GT(study, 0);
  const ContinueOnExit continue_on_exit{study};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!(runFolderBusy(cases / "0001") && runFolderBusy(cases / "0002")) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  // Stop the study and its cases where they are, then kill the study alone (the out-of-memory killer's way):
  // its case processes live on, each holding its case's run-folder lock.
  ::kill(-study, SIGSTOP);
  ::kill(study, SIGKILL);
  int status = 0;
  ::waitpid(study, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  std::vector<std::string> orphans;
  for (const std::string id : {"0001", "0002"})
    if (runFolderBusy(cases / id)) orphans.push_back(id);
  ASSERT_FALSE(orphans.empty()) << "both cases ended before the study was stopped";
  ASSERT_TRUE(completeCases(cases).empty());

  // --resume while the orphans are stopped: it must wait for them, not fail them nor run them beside them.
  fs::create_directories(dir_ / "resume");
  const pid_t resume = startCli({"study", "run", (dir_ / "slow.json").string(), "--out", out.string(), "--resume",
                                 "--jobs", "2", "--no-plots"}, dir_ / "resume", true);
  ASSERT_GT(resume, 0);
  const auto all_noted = [&] {
    const std::string err = slurp(dir_ / "resume" / "err.txt");
    for (const auto& id : orphans)
      if (!contains(err, "case " + id + " is being run by another process")) return false;
    return true;
  };
  while (!all_noted() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(all_noted()) << slurp(dir_ / "resume" / "err.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(::waitpid(resume, &status, WNOHANG), 0) << "--resume ended while the orphaned cases still ran: "
                                                     << slurp(dir_ / "resume" / "err.txt");
  ::kill(-study, SIGCONT);  // the orphans go on and commit their folders
  ::waitpid(resume, &status, 0);
  const std::string err = slurp(dir_ / "resume" / "err.txt");
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 0) << err;

  EXPECT_EQ(completeCases(cases).size(), 2u);
  for (const auto& id : orphans) {
    EXPECT_TRUE(contains(slurp(cases / (id + ".outcome.json")), "completed by a case process of an earlier"))
        << id << ": " << slurp(cases / (id + ".outcome.json"));
    // The orphan's own messages: the case log was not restarted by a second run of the case.
    EXPECT_TRUE(contains(slurp(cases / (id + ".log")), "running ")) << slurp(cases / (id + ".log"));
    EXPECT_FALSE(contains(slurp(cases / (id + ".log")), "another maris run is writing"));
  }
  const Json manifest = Json::parse(slurp(out / "study.json"));
  EXPECT_EQ(manifest["collected"]["ok"], 2);
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {  // the adopted orphans, ended by now
  }
}

}  // namespace
}  // namespace maris
