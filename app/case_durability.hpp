// Makes a study's finished cases durable in batches. Each case process runs `maris-cli run --no-sync`: it
// commits its run folder (a rename) without waiting for the device, which on a disk cost one flush of the
// whole file system per case and held the speed-up of small cases well below the number of cores. The study
// runner hands every ended case to a CaseDurability, which syncs the study's file system once for all cases
// ended since the last sync (at most every kBatchSeconds, in a thread of its own so that the next cases start
// meanwhile) and only then writes their outcome records (DIR/cases/NNNN.outcome.json). finish() syncs the
// rest and then the outcomes themselves; a Slurm array task (`study run-cases`) calls it at its end too.
//
// Crash safety (also in docs/studies.md): a case's record never says "ok" before its folder is on the
// disk. A power loss can lose the cases of the last batch: their folders are then absent or hold empty or
// torn files, which StudyFolder::caseComplete does not count (summary.json must parse as a JSON object),
// so `--resume` runs them again (over the torn folder: the runner passes --force for a folder that exists).
#pragma once

#include <chrono>
#include <future>
#include <string>
#include <vector>

#include "study/study_folder.hpp"

namespace maris::cli {

class CaseDurability {
 public:
  static constexpr double kBatchSeconds = 0.5;  // [s] at most two flushes a second, however short the cases

  explicit CaseDurability(const study::StudyFolder& folder) : folder_(folder) {}
  ~CaseDurability();  // waits for a sync in flight (finish() should have been called)
  CaseDurability(const CaseDurability&) = delete;
  CaseDurability& operator=(const CaseDurability&) = delete;

  // A case that ended (any status); its outcome is written once its folder is durable.
  void add(study::CaseOutcome outcome) { waiting_.push_back(std::move(outcome)); }
  // Starts a sync of the waiting cases when one is due and none is in flight; returns the outcomes of a
  // sync that has ended, each written to its record file (unsynced: the next sync makes it durable). A case
  // whose folder could not be synced (an I/O error) comes back Failed, its folder removed.
  std::vector<study::CaseOutcome> poll();
  // Seconds until poll() has something to do (a sync in flight, or one due); a large number when idle.
  double secondsToNextPoll() const;
  // Syncs every case still waiting and records it, then makes the records durable. Blocks.
  std::vector<study::CaseOutcome> finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::vector<study::CaseOutcome> record(std::vector<study::CaseOutcome> batch, const std::string& sync_error);
  std::future<std::string> startSync();  // its result: the error message, or "" when synced

  const study::StudyFolder& folder_;
  std::vector<study::CaseOutcome> waiting_;    // ended, not yet in a sync
  std::vector<study::CaseOutcome> in_flight_;  // in the sync running now
  std::future<std::string> sync_;
  bool records_unsynced_ = false;              // outcome records written after the last sync started
  Clock::time_point last_sync_ = Clock::now() - std::chrono::hours(1);
};

}  // namespace maris::cli
