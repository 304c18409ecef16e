// RunFolder: a run folder is either the complete new run or untouched; checks before the solve; the lock.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "core/run_folder.hpp"
#include "core/scenario.hpp"
#include "scratch_folder.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;

class RunFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test::freshTestFolder("maris_run_folder_");
  }
  void TearDown() override { fs::remove_all(root_); }

  // A finished run's files in `dir` (what writeRunFolder leaves), marked with `tag`.
  static void fakeRun(const fs::path& dir, const std::string& tag) {
    fs::create_directories(dir);
    writeFileAtomic(dir / "scenario.json", "{}\n");
    writeFileAtomic(dir / (tag + ".csv"), tag + "\n");
    writeFileAtomic(dir / "summary.json", "{\"tag\": \"" + tag + "\"}\n");
  }
  // Everything in root_ except the lock files.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(root_))
      if (e.path().extension() != ".lock") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path root_;
};

TEST_F(RunFolderTest, CommitMovesTheStagedRunIntoPlaceAndLeavesNothingBeside) {
  const fs::path out = root_ / "out";
  {
    RunFolder folder(out);
    EXPECT_EQ(folder.target(), out);
    EXPECT_FALSE(fs::exists(out));  // nothing visible until commit
    fakeRun(folder.staging(), "new");
    folder.commit();
  }
  EXPECT_EQ(readTextFile(out / "new.csv"), "new\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

TEST_F(RunFolderTest, AnUncommittedRunLeavesTheTargetAsItWas) {
  const fs::path out = root_ / "out";
  fakeRun(out, "old");
  {
    RunFolder folder(out, {.replace = true});
    fakeRun(folder.staging(), "new");
  }  // error or cancellation: no commit
  EXPECT_EQ(readTextFile(out / "summary.json"), "{\"tag\": \"old\"}\n");
  EXPECT_TRUE(fs::exists(out / "old.csv"));
  EXPECT_FALSE(fs::exists(out / "new.csv"));
  EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

TEST_F(RunFolderTest, AnotherRunIsReplacedOnlyWhenAskedAndThenAsAWhole) {
  const fs::path out = root_ / "out";
  fakeRun(out, "old");
  try {
    RunFolder refused(out);
    FAIL() << "an earlier run was accepted without replace";
  } catch (const RunFolderError& e) {
    EXPECT_NE(std::string(e.what()).find("results of another run"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  RunFolder folder(out, {.replace = true});
  fakeRun(folder.staging(), "new");
  folder.commit();
  EXPECT_FALSE(fs::exists(out / "old.csv"));  // no mix of two runs
  EXPECT_EQ(readTextFile(out / "summary.json"), "{\"tag\": \"new\"}\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

TEST_F(RunFolderTest, AnEmptyFolderIsUsedAndAForeignFolderOrAFileIsNeverReplaced) {
  fs::create_directories(root_ / "empty");
  RunFolder empty(root_ / "empty/");
  fakeRun(empty.staging(), "new");
  empty.commit();
  EXPECT_TRUE(fs::exists(root_ / "empty" / "new.csv"));

  fs::create_directories(root_ / "home");
  writeFileAtomic(root_ / "home" / "notes.txt", "mine\n");
  EXPECT_THROW(RunFolder(root_ / "home", {.replace = true}), RunFolderError);
  EXPECT_EQ(readTextFile(root_ / "home" / "notes.txt"), "mine\n");

  writeFileAtomic(root_ / "file", "x");
  try {
    RunFolder f(root_ / "file", {.replace = true});
    FAIL();
  } catch (const RunFolderError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a folder"), std::string::npos) << e.what();
  }
  EXPECT_THROW(RunFolder(root_ / "file" / "below"), RunFolderError);  // parent is a file
  EXPECT_THROW(RunFolder(""), RunFolderError);
}

TEST_F(RunFolderTest, ASecondWriterOfTheSameFolderIsRefusedWhileTheFirstHoldsIt) {
  const fs::path out = root_ / "out";
  RunFolder first(out);
  try {
    RunFolder second(out);
    FAIL() << "two writers of one folder";
  } catch (const RunFolderError& e) {
    EXPECT_NE(std::string(e.what()).find("another maris run is writing"), std::string::npos) << e.what();
  }
  RunFolder other(root_ / "other");  // a sibling folder is independent
  fakeRun(first.staging(), "first");
  first.commit();
  EXPECT_TRUE(fs::exists(out / "first.csv"));
}

TEST_F(RunFolderTest, TheLockIsAnFlockOnTheSiblingLockFile) {
  const fs::path out = root_ / "out";
  fs::create_directories(root_);
  const int fd = ::open((root_ / ".out.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  EXPECT_THROW(RunFolder f(out), RunFolderError);
  ::close(fd);
  EXPECT_NO_THROW(RunFolder f(out));
}

TEST_F(RunFolderTest, StagingFoldersOfAKilledRunAreRemovedByTheNext) {
  // What a run killed while writing (.out.partial) or while swapping an earlier run aside (.out.old) leaves.
  fakeRun(root_ / ".out.partial", "killed");
  fakeRun(root_ / ".out.old", "earlier");
  fs::create_directories(root_ / ".other.partial");
  RunFolder folder(root_ / "out");
  EXPECT_EQ(folder.staging(), root_ / ".out.partial");
  EXPECT_FALSE(fs::exists(folder.staging() / "killed.csv")) << "a killed run's files mixed into the new run";
  EXPECT_FALSE(fs::exists(root_ / ".out.old"));
  fakeRun(folder.staging(), "new");
  folder.commit();
  EXPECT_EQ(entries(), (std::vector<std::string>{".other.partial", "out"}));
  EXPECT_FALSE(fs::exists(root_ / "out" / "killed.csv"));
}

// Maris 0.5 and earlier staged into `.NAME.partial-PID` and set aside into `.NAME.old-PID`; a killed run of
// such a version left them. Names that only look alike belong to someone else and stay.
const std::vector<std::string> kNotOldVersionLeftovers = {
    ".out.partial-", ".out.partial-12a", ".out.partial-12345678901", ".out.partial-x1", "out.partial-12",
    ".out.old-1-2", ".out.partialx-12", "..partial-12", ".out.lock-12"};

TEST_F(RunFolderTest, OldVersionStagingFoldersOfTheSameNameAreRemovedByTheNextRunAndNothingElse) {
  fakeRun(root_ / ".out.partial-4242", "killed");
  fakeRun(root_ / ".out.old-17", "earlier");
  // Other folders' (their own next runs remove them).
  const std::vector<std::string> others = {".other.partial-99", ".outer.partial-12", ".ou.old-3"};
  for (const auto& name : others) fs::create_directories(root_ / name);
  for (const auto& name : kNotOldVersionLeftovers) fs::create_directories(root_ / name);
  std::vector<std::string> kept = kNotOldVersionLeftovers;
  kept.insert(kept.end(), others.begin(), others.end());
  kept.push_back("out");
  std::sort(kept.begin(), kept.end());
  RunFolder folder(root_ / "out");
  fakeRun(folder.staging(), "new");
  folder.commit();
  EXPECT_EQ(entries(), kept);
  EXPECT_EQ(readTextFile(root_ / "out" / "summary.json"), "{\"tag\": \"new\"}\n");
}

TEST_F(RunFolderTest, AStudyCaseLeavesOldVersionLeftoversToItsStudy) {
  fakeRun(root_ / ".out.partial-4242", "killed");
  RunFolder folder(root_ / "out", {.remove_old_version_leftovers = false});
  fakeRun(folder.staging(), "new");
  folder.commit();
  EXPECT_EQ(entries(), (std::vector<std::string>{".out.partial-4242", "out"}));
}

TEST_F(RunFolderTest, AllOldVersionLeftoversOfAFolderAreRemovedUnderTheirRunsLocksAndALockedOneIsKept) {
  for (const std::string name : {".0001.partial-11", ".0001.old-12", ".0002.partial-13", ".0003.old-14"})
    fakeRun(root_ / name, name);
  for (const auto& name : kNotOldVersionLeftovers) fs::create_directories(root_ / name);
  fs::create_directories(root_ / ".0004.partial");  // this version's: removed by case 0004's next run
  // Case 0003 is being written: an old version's run holds its lock (and owns its staging folder).
  const int fd = ::open((root_ / ".0003.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  EXPECT_EQ(removeOldVersionLeftovers(root_), 3u);
  std::vector<std::string> kept = kNotOldVersionLeftovers;
  kept.push_back(".0003.old-14");
  kept.push_back(".0004.partial");
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(entries(), kept);
  ::close(fd);
  EXPECT_EQ(removeOldVersionLeftovers(root_), 1u);
  EXPECT_FALSE(fs::exists(root_ / ".0003.old-14"));
  EXPECT_EQ(removeOldVersionLeftovers(root_ / "absent"), 0u);
}

TEST_F(RunFolderTest, AFolderIsBusyExactlyWhileAnotherHolderHasItsLock) {
  const fs::path out = root_ / "out";
  EXPECT_FALSE(runFolderBusy(out));
  EXPECT_FALSE(fs::exists(root_ / ".out.lock")) << "probing created the lock file";
  {
    RunFolder folder(out);
    EXPECT_TRUE(runFolderBusy(out));
    EXPECT_TRUE(runFolderBusy(root_ / "out/"));
    EXPECT_FALSE(runFolderBusy(root_ / "other"));
  }
  EXPECT_FALSE(runFolderBusy(out));  // the lock file stays, unlocked
  RunFolder again(out);               // and probing left it free
  EXPECT_TRUE(runFolderBusy(out));
}

TEST_F(RunFolderTest, TooLittleFreeSpaceIsRefusedBeforeTheRun) {
  try {
    RunFolder f(root_ / "out", {.expected_bytes = std::uintmax_t(1) << 62});  // 4.6 EB
    FAIL();
  } catch (const RunFolderError& e) {
    EXPECT_NE(std::string(e.what()).find("not enough free space"), std::string::npos) << e.what();
  }
  EXPECT_EQ(entries(), std::vector<std::string>{});
}

}  // namespace
}  // namespace maris
