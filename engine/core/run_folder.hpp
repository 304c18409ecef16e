// A run folder written as a transaction: the folder is either one complete run or untouched.
//
//   RunFolder folder(out, {.replace = force, .expected_bytes = estimate.output_bytes});  // before the solve
//   ... solve ...
//   writeRunFolder(folder.staging(), scenario, results);  // plus plots
//   folder.commit();                                       // renames the staged folder into place
//
// The constructor checks everything that can be checked before a long solve: the name, that the parent
// can be created and written, that the target is not a file, not a foreign folder and not another run's
// folder (unless `replace`), that no other run is writing it (an exclusive flock on the sibling lock
// file `.NAME.lock`, kept for the object's life) and that the file system has room for the expected
// output. Files go into the hidden sibling `.NAME.partial`; commit() renames it onto NAME (an
// existing run is swapped out atomically and then removed). An uncommitted folder (error, cancellation)
// is removed by the destructor, and stale staging folders of killed runs are removed by the next run.
// Maris 0.5 and earlier named them with the process id (`.NAME.partial-PID`, `.NAME.old-PID`); a run
// removes those of its NAME too, and a study those of all its cases at once (removeOldVersionLeftovers).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace maris {

// Why a run folder cannot be written (bad --out, another run's results, locked, no room, I/O error).
class RunFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunFolderOptions {
  bool replace = false;             // replace a folder that holds another run's results (maris-cli --force)
  std::uintmax_t expected_bytes = 0;  // free space the run's files need [bytes]
  // commit() waits until the files are on the device. Off (maris-cli run --no-sync) for a caller that makes
  // many folders durable at once (a study: one syncfs per batch of cases); until then a power loss can leave
  // the committed folder absent or with empty files (see docs/studies.md, "Crash safety").
  bool sync = true;
  // Also remove the staging and set-aside folders that a killed run of Maris 0.5 or earlier left beside the
  // target under names with its process id (`.NAME.partial-PID`, `.NAME.old-PID`): one listing of the parent.
  // Off for a study's cases (`maris-cli run --study-case`): the study removes its cases' leftovers with one
  // listing for all of them (removeOldVersionLeftovers), not one per case of a folder of 40 000 entries.
  bool remove_old_version_leftovers = true;
};

class RunFolder {
 public:
  // Throws RunFolderError naming the folder and what to change.
  explicit RunFolder(std::filesystem::path target, RunFolderOptions options = {});
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  const std::filesystem::path& target() const { return target_; }    // absolute, normalised
  const std::filesystem::path& staging() const { return staging_; }  // write the run's files here

  // Makes the staged files durable (unless options.sync is off) and moves the folder into place as a whole.
  // Throws RunFolderError (the target is then untouched).
  void commit();

 private:
  void release();  // removes an uncommitted staging folder, drops the lock

  std::filesystem::path target_, staging_;
  RunFolderOptions options_;
  int lock_fd_ = -1;
  bool committed_ = false;
};

// True when `dir` holds the files of a run (scenario.json or summary.json).
bool isRunFolder(const std::filesystem::path& dir);

// Removes every staging or set-aside folder that a killed run of Maris 0.5 or earlier left in `parent`
// (`.NAME.partial-PID`, `.NAME.old-PID`, for any NAME), each while holding NAME's run-folder lock; one
// whose lock another process holds (a run still writing it) is kept. One listing of `parent`; returns how
// many folders were removed.
std::size_t removeOldVersionLeftovers(const std::filesystem::path& parent);

// True when another process holds the run-folder lock of `target`: a run is writing it (a study's case
// process left running by a killed study, say). Takes the lock for an instant when it is free, so it is for
// the owner of `target` (the study of a case), not for a bystander. Never creates the lock file.
bool runFolderBusy(const std::filesystem::path& target);

}  // namespace maris
