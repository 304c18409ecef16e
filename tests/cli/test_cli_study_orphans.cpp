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

// A study of two slow cases killed alone while its case processes live on, held stopped: the orphans of a study
// that the out-of-memory killer ended. When it goes out of scope, the orphans are continued, however the test ended.
struct StoppedOrphans {
  pid_t group = 0;                   // the killed study's process group, which holds its case processes
  std::vector<std::string> orphans;  // the cases whose run-folder lock an orphaned case process holds
  StoppedOrphans() = default;
  StoppedOrphans(const StoppedOrphans&) = delete;
  StoppedOrphans& operator=(const StoppedOrphans&) = delete;
  ~StoppedOrphans() {
    if (group > 0) ::kill(-group, SIGCONT);
  }
};

// Runs the study `dir`/slow.json (written here: two cases of 4 and 5 s of dynamics, about a second of work each)
// into `dir`/out with two jobs, stops the study and its cases once both cases hold their run-folder locks, and kills
// the study alone.
void stopStudyLeavingOrphans(const fs::path& dir, StoppedOrphans& stopped) {
  writeText(dir / "slow.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"solver.end_time": [4, 5]}})");
  const fs::path study_file = dir / "slow.json", out = dir / "out", cases = out / "cases";
  // The orphans are held stopped. Were they re-parented to init, their process group would be orphaned with
  // stopped members, and the kernel would send it SIGHUP and SIGCONT (POSIX), killing them. This test process
  // adopts them instead (a subreaper in another process group of the same session), so the group stays
  // unorphaned, as it does for case processes that are running, not stopped, when their study is killed.
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  const pid_t study =
      startCli({"study", "run", study_file.string(), "--out", out.string(), "--jobs", "2", "--no-plots"}, dir, true);
  ASSERT_GT(study, 0);
  stopped.group = study;
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
  for (const std::string id : {"0001", "0002"})
    if (runFolderBusy(cases / id)) stopped.orphans.push_back(id);
  ASSERT_FALSE(stopped.orphans.empty()) << "both cases ended before the study was stopped";
  ASSERT_TRUE(completeCases(cases).empty());
}

// True when the resumed study's messages (err.txt in `dir`) say it found every orphaned case locked.
bool notedEveryOrphan(const fs::path& dir, const std::vector<std::string>& orphans) {
  const std::string err = slurp(dir / "err.txt");
  for (const auto& id : orphans)
    if (!contains(err, "case " + id + " is being run by another process")) return false;
  return true;
}

// The exit code of `pid` (a process group's leader, started by startCli), or -1 when it has not ended within
// `limit_s`; then its group is killed, so a test that fails does not hang.
int exitCodeWithin(pid_t pid, double limit_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() >= deadline) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Reaps the adopted orphans that have ended.
void reapAdoptedOrphans() {
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {
  }
}

TEST_F(CliStudyOrphans, ResumeWaitsForACaseProcessThatOutlivedItsStudyAndDoesNotRunItAgain) {
  StoppedOrphans stopped;
  ASSERT_NO_FATAL_FAILURE(stopStudyLeavingOrphans(dir_, stopped));
  const fs::path out = dir_ / "out", cases = out / "cases";
  const auto& orphans = stopped.orphans;
  const pid_t study = stopped.group;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;

  // --resume while the orphans are stopped: it must wait for them, not fail them nor run them beside them.
  fs::create_directories(dir_ / "resume");
  const pid_t resume = startCli({"study", "run", (dir_ / "slow.json").string(), "--out", out.string(), "--resume",
                                 "--jobs", "2", "--no-plots"}, dir_ / "resume", true);
  ASSERT_GT(resume, 0);
  const auto all_noted = [&] { return notedEveryOrphan(dir_ / "resume", orphans); };
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
  reapAdoptedOrphans();  // ended by now
}

// --resume --timeout S: a case that an orphaned case process still holds after S seconds is recorded as timed out,
// and that process is left alone (it is not the resumed study's); when it later completes the case, the next
// --resume keeps its results instead of running the case again.
TEST_F(CliStudyOrphans, ResumeWithATimeoutRecordsACaseLockedElsewhereTooLongAndLeavesItsProcessAlone) {
  StoppedOrphans stopped;
  ASSERT_NO_FATAL_FAILURE(stopStudyLeavingOrphans(dir_, stopped));
  const fs::path out = dir_ / "out", cases = out / "cases";
  // Both cases took their locks before the study was stopped, and a second of work is left in each.
  ASSERT_EQ(stopped.orphans.size(), 2u);

  // Without the timeout it would wait for the stopped orphans for ever; with it, it ends after about 1 s.
  fs::create_directories(dir_ / "resume");
  const pid_t resume = startCli({"study", "run", (dir_ / "slow.json").string(), "--out", out.string(), "--resume",
                                 "--jobs", "2", "--timeout", "1", "--no-plots"}, dir_ / "resume", true);
  ASSERT_GT(resume, 0);
  const int exit_code = exitCodeWithin(resume, 60.0);
  const std::string err = slurp(dir_ / "resume" / "err.txt");
  ASSERT_NE(exit_code, -1) << "--resume --timeout 1 still waited after 60 s: " << err;
  EXPECT_EQ(exit_code, 3) << err;  // the study's code for cases that did not succeed
  EXPECT_TRUE(notedEveryOrphan(dir_ / "resume", stopped.orphans)) << err;
  for (const std::string id : {"0001", "0002"}) {
    const std::string outcome = slurp(cases / (id + ".outcome.json"));
    EXPECT_TRUE(contains(outcome, "\"timeout\"")) << id << ": " << outcome;
    EXPECT_TRUE(contains(outcome, "kept the case's run folder locked for longer than the timeout of 1 s"))
        << id << ": " << outcome;
    // The orphan was neither stopped nor run beside: it still holds the lock, and nothing was written.
    EXPECT_TRUE(runFolderBusy(cases / id)) << id;
  }
  EXPECT_TRUE(completeCases(cases).empty());
  const Json manifest = Json::parse(slurp(out / "study.json"));
  EXPECT_EQ(manifest["collected"]["timeout"], 2);
  EXPECT_EQ(manifest["collected"]["ok"], 0);
  EXPECT_TRUE(contains(slurp(out / "study.csv"), "\n0001,timeout,")) << slurp(out / "study.csv");

  // The orphans go on, complete their cases and end.
  ::kill(-stopped.group, SIGCONT);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while ((runFolderBusy(cases / "0001") || runFolderBusy(cases / "0002")) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  reapAdoptedOrphans();
  const auto completed = completeCases(cases);
  ASSERT_EQ(completed.size(), 2u);

  // The next --resume keeps both (no case runs again) and the study succeeds.
  const auto again = runCli({"study", "run", (dir_ / "slow.json").string(), "--out", out.string(), "--resume",
                             "--timeout", "1", "--no-plots"}, (dir_ / "resume").string());
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(completeCases(cases), completed);
  EXPECT_EQ(Json::parse(slurp(out / "study.json"))["collected"]["ok"], 2);
}

}  // namespace
}  // namespace maris
