// `maris-cli study run --resume` after crashes. The cases run without syncing (`run --no-sync`) and the
// study syncs them in batches, so a power loss can leave the last batch's case folders with empty or torn
// files: such a case is not complete and --resume runs it again, and only it. A study killed at once with
// all its cases (SIGKILL to the process group: a crashed node without the power loss) is finished by
// --resume with no complete case run twice.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "cli_runner.hpp"
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

class CliStudyResume : public test::StudyTestFolder {
 protected:
  CliStudyResume() : StudyTestFolder("maris_cli_study_resume_") {}
};

// Entries of `cases` that are a run's staging or set-aside folder (.NNNN.partial, .NNNN.old).
std::vector<std::string> stagingFolders(const fs::path& cases) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(cases)) {
    const fs::path name = e.path().filename();
    if (name.extension() == ".partial" || name.extension() == ".old") found.push_back(name.string());
  }
  return found;
}

TEST_F(CliStudyResume, ACaseWhoseSummaryIsEmptyTornOrMissingRunsAgainAndNoOther) {
  writeText(dir_ / "grid.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"geometry.length": {"from": 10, "to": 30, "count": 4}, "section.youngs_modulus": [1.5e11, 2.07e11, 2.5e11]}})");
  const auto first = runCli({"study", "run", "grid.json", "--out", "out", "--jobs", "2", "--no-plots"}, dir_.string());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const fs::path cases = dir_ / "out" / "cases";
  const auto before = completeCases(cases);
  ASSERT_EQ(before.size(), 12u);
  // Every ended case is recorded, after its folder was synced.
  for (const auto& [id, identity] : before)
    EXPECT_TRUE(contains(slurp(cases / (id + ".outcome.json")), "\"status\": \"ok\"")) << id;
  const std::string csv = slurp(dir_ / "out" / "study.csv");

  // What a power loss before the last batch's sync can leave: a zero-length summary.json (its rename reached
  // the disk, its data did not), a truncated one, a folder without it; and a lost outcome record.
  const std::string summary = slurp(cases / "0003" / "summary.json");
  ASSERT_GT(summary.size(), 20u);
  writeText(cases / "0003" / "summary.json", "");
  writeText(cases / "0007" / "summary.json", summary.substr(0, summary.size() / 2));
  fs::remove(cases / "0010" / "summary.json");
  fs::remove(cases / "0005.outcome.json");
  const std::vector<std::string> torn = {"0003", "0007", "0010"};

  // Collect counts the torn cases as not run (not as failed), the others as ok (0005 without its record).
  const auto collected = runCli({"study", "collect", "out", "--no-plots"}, dir_.string());
  EXPECT_EQ(collected.exit_code, 3) << collected.err;
  EXPECT_TRUE(contains(collected.out, "12 cases: 9 ok, 0 failed, 0 timed out, 3 not run")) << collected.out;
  EXPECT_TRUE(contains(collected.err, "not run yet: 0003, 0007, 0010")) << collected.err;

  const auto resumed = runCli({"study", "run", "grid.json", "--out", "out", "--resume", "--jobs", "2", "--no-plots"},
                              dir_.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto after = completeCases(cases);
  ASSERT_EQ(after.size(), 12u);
  for (const auto& [id, identity] : before) {
    const bool was_torn = std::find(torn.begin(), torn.end(), id) != torn.end();
    if (was_torn) {
      EXPECT_NE(after.at(id).first, identity.first) << "case " << id << " did not run again";
    } else {
      EXPECT_EQ(after.at(id), identity) << "case " << id << " ran again";
    }
  }
  const Json manifest = Json::parse(slurp(dir_ / "out" / "study.json"));
  ASSERT_EQ(manifest["runs"].size(), 2u);
  EXPECT_EQ(manifest["runs"][1]["skipped_complete"], 9);
  EXPECT_EQ(manifest["runs"][1]["cases_run"], 3);
  // The cases give the same numbers again: study.csv is the first run's, byte for byte.
  EXPECT_EQ(slurp(dir_ / "out" / "study.csv"), csv);
  EXPECT_TRUE(stagingFolders(cases).empty());
}

TEST_F(CliStudyResume, AStudyKilledWithItsCasesIsFinishedByResumeWithNoCompleteCaseRunTwice) {
  // 12 cases of 0.5 to 1.6 s of dynamics (a tenth to half a second of work each).
  writeText(dir_ / "slow.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"solver.end_time": {"from": 0.5, "to": 1.6, "count": 12}}})");
  const pid_t pid = startCli({"study", "run", (dir_ / "slow.json").string(), "--out", (dir_ / "out").string(),
                              "--jobs", "2", "--no-plots"}, dir_, true);
  ASSERT_GT(pid, 0);
  const fs::path cases = dir_ / "out" / "cases";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (completeCases(cases).size() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(-pid, SIGKILL);  // the study and its running cases, at once: nothing is cleaned up
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the killed cases' processes end too
  const auto before = completeCases(cases);
  ASSERT_GE(before.size(), 2u);
  ASSERT_LT(before.size(), 12u) << "every case ended before the kill: nothing left to resume";
  for (const auto& e : fs::directory_iterator(cases)) {  // a case folder is whole or absent
    const std::string name = e.path().filename().string();
    const bool case_folder = e.is_directory() && name.front() != '.';
    EXPECT_TRUE(!case_folder || before.count(name)) << name << " is torn";
  }

  const auto resumed = runCli({"study", "run", "slow.json", "--out", "out", "--resume", "--jobs", "2", "--no-plots"},
                              dir_.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto after = completeCases(cases);
  EXPECT_EQ(after.size(), 12u);
  for (const auto& [id, identity] : before) EXPECT_EQ(after.at(id), identity) << "case " << id << " ran again";
  const Json manifest = Json::parse(slurp(dir_ / "out" / "study.json"));
  // The killed run recorded nothing in study.json; the resumed one ran exactly the cases that were missing.
  ASSERT_EQ(manifest["runs"].size(), 1u);
  EXPECT_EQ(manifest["runs"][0]["skipped_complete"], before.size());
  EXPECT_EQ(manifest["runs"][0]["cases_run"], 12 - before.size());
  EXPECT_EQ(manifest["collected"]["ok"], 12);
  EXPECT_TRUE(stagingFolders(cases).empty()) << "a killed case's staging folder was left behind";
}

}  // namespace
}  // namespace maris
