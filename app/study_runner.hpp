// Runs a study's cases, each as its own `maris-cli run` process (the same executable), so a case that
// crashes, runs out of memory or hangs ends alone and the study goes on. Up to `jobs` at once; a case
// past its timeout is stopped (SIGTERM, then SIGKILL); SIGINT/SIGTERM to the study are forwarded to the
// running cases, which then write nothing (their run folder transaction is not committed), so every case
// folder is complete or absent and `--resume` finishes the study. The cases do not wait for the disk
// themselves (`run --no-sync`); the study makes them durable in batches before recording them
// (case_durability.hpp).
#pragma once

#include <string>
#include <vector>

#include "study/study_folder.hpp"

namespace maris::cli {

struct CaseRunOptions {
  unsigned jobs = 1;
  double timeout_s = 0.0;    // [s] per case; 0: none
  bool case_plots = false;   // the cases write their PNG plots (off: --no-plots, much faster)
  bool allow_large = false;  // the cases may run beyond the work limits
  bool progress = true;      // progress lines on stderr
};

struct CaseRunTally {
  std::size_t ok = 0, failed = 0, timeout = 0, skipped = 0;  // skipped: complete before this run
  int cancel_signal = 0;                                      // SIGINT or SIGTERM when cancelled, else 0
  double wall_s = 0.0;
  std::vector<std::string> failed_ids;  // failed or timed out, in case order
};

// Runs the cases `ids` of `folder` that are not complete. Blocks SIGINT, SIGTERM and SIGCHLD while it runs
// (they are waited for, not handled), and restores the signal mask when it returns. A case whose run folder
// another process is writing (its lock is held: a case process that a killed study left running) is not
// started beside it but waited for, and then counted ok if that process completed it, else run; with a
// timeout, a wait longer than the timeout is recorded as `timeout` (the other process is not stopped).
CaseRunTally runCases(const study::StudyFolder& folder, const std::vector<std::string>& ids,
                      const CaseRunOptions& options);

// Processors this process may run on (its CPU affinity: a Slurm task's allocation, a taskset), at least 1.
unsigned availableProcessors();

}  // namespace maris::cli
