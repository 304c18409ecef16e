#include "study_runner.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <system_error>

#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "case_durability.hpp"
#include "core/input_limits.hpp"
#include "core/run_folder.hpp"
#include "core/run_output.hpp"

extern char** environ;

namespace maris::cli {

namespace {

using Clock = std::chrono::steady_clock;
using study::CaseOutcome;
using study::CaseStatus;

constexpr double kKillGraceSeconds = 5.0;       // from SIGTERM (timeout) to SIGKILL
constexpr double kElsewherePollSeconds = 0.25;  // how often a case run by another process is looked at

// A case whose run folder another process is writing: a case process that a killed study left running.
struct ElsewhereCase {
  std::string id;
  Clock::time_point since;
};

struct RunningCase {
  std::string id;
  Clock::time_point started;
  std::chrono::system_clock::time_point started_at;
  bool timed_out = false;
  Clock::time_point kill_at;
};

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string durationText(double seconds) {
  char text[32];
  if (seconds < 90) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 5400) std::snprintf(text, sizeof text, "%.0f min", seconds / 60);
  else std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  return text;
}

// Starts `maris-cli run CASE.json --out CASE/ --no-sync --study-case` with its messages going to CASE.log; 0
// when it cannot start. The case does not wait for the disk: CaseDurability syncs the ended cases in batches;
// nor does it list the cases folder for an old version's leftovers: the study did that once for all.
pid_t spawnCase(const study::StudyFolder& folder, const std::string& id, const CaseRunOptions& options) {
  const std::string scenario = folder.caseScenario(id).string(), out = folder.caseRun(id).string();
  const std::string log = folder.caseLog(id).string();
  std::vector<std::string> args = {"maris-cli", "run", scenario, "--out", out, "--no-sync", "--study-case"};
  // A folder of a case that is not complete was torn by a crash (a power loss before its batch was synced):
  // the run replaces it.
  std::error_code exists_error;
  if (std::filesystem::exists(folder.caseRun(id), exists_error)) args.push_back("--force");
  if (!options.case_plots) args.push_back("--no-plots");
  if (options.allow_large) args.push_back("--allow-large");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : {SIGINT, SIGTERM, SIGCHLD, SIGPIPE}) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attributes, &none);  // the study blocks these; the case must receive them
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  // The running executable itself, also if its file was replaced since it started.
  const int error = ::posix_spawn(&pid, "/proc/self/exe", &files, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attributes);
  return error == 0 ? pid : 0;
}

std::string readLog(const study::StudyFolder& folder, const std::string& id) {
  try {
    return readInputFile(folder.caseLog(id), "log", InputLimits::kScenarioFileBytes);
  } catch (const std::exception&) {
    return "";
  }
}

class Progress {
 public:
  Progress(std::size_t total, bool enabled) : total_(total), enabled_(enabled), tty_(::isatty(STDERR_FILENO)) {}
  void show(const CaseRunTally& tally, std::size_t running, std::size_t elsewhere, bool force) {
    if (!enabled_ || (!force && secondsSince(last_) < (tty_ ? 0.5 : 5.0))) return;
    last_ = Clock::now();
    const std::size_t finished = tally.ok + tally.failed + tally.timeout;
    const std::size_t done = finished + tally.skipped;
    std::string left;
    if (finished > 0 && done < total_)
      left = ", about " + durationText(secondsSince(start_) / static_cast<double>(finished) *
                                       static_cast<double>(total_ - done)) + " left";
    const std::string others = elsewhere ? ", " + std::to_string(elsewhere) + " running elsewhere" : "";
    std::fprintf(stderr, "%scases: %zu/%zu done, %zu failed, %zu running%s%s%s", tty_ ? "\r" : "", done, total_,
                 tally.failed + tally.timeout, running, others.c_str(), left.c_str(), tty_ ? "\033[K" : "\n");
    std::fflush(stderr);
  }
  // A line of its own (over the redrawn progress line on a terminal).
  void note(const std::string& text) {
    if (!enabled_) return;
    std::fprintf(stderr, "%s%s\n", tty_ ? "\r\033[K" : "", text.c_str());
    last_ = Clock::now() - std::chrono::hours(1);  // redraw the progress line at once
  }
  void finish() {
    if (enabled_ && tty_) std::fputc('\n', stderr);
  }

 private:
  std::size_t total_;
  bool enabled_, tty_;
  Clock::time_point start_ = Clock::now(), last_ = Clock::now() - std::chrono::hours(1);
};

}  // namespace

unsigned availableProcessors() {
  cpu_set_t set;
  if (::sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  const long online = ::sysconf(_SC_NPROCESSORS_ONLN);
  return online > 0 ? static_cast<unsigned>(online) : 1u;
}

CaseRunTally runCases(const study::StudyFolder& folder, const std::vector<std::string>& ids,
                      const CaseRunOptions& options) {
  CaseRunTally tally;
  const auto start = Clock::now();
  std::vector<std::string> queue;
  for (const auto& id : ids) {
    if (folder.caseComplete(id)) ++tally.skipped;
    else queue.push_back(id);
  }
  sigset_t waited, previous;
  sigemptyset(&waited);
  for (int s : {SIGINT, SIGTERM, SIGCHLD}) sigaddset(&waited, s);
  ::sigprocmask(SIG_BLOCK, &waited, &previous);

  Progress progress(ids.size(), options.progress);
  std::map<pid_t, RunningCase> running;
  // Cases whose run folder is locked by a process that is not ours: left running by a killed study (`--resume`
  // right after the kill). Their folders are theirs to commit; waited for, never run a second time beside them.
  std::vector<ElsewhereCase> elsewhere;
  std::size_t next = 0;
  const unsigned jobs = std::max(1u, options.jobs);
  // Ended cases are counted once their folders are durable and their outcomes recorded (CaseDurability).
  CaseDurability durability(folder);
  auto count = [&](const std::vector<CaseOutcome>& recorded) {
    for (const auto& outcome : recorded) {
      if (outcome.status == CaseStatus::Ok) ++tally.ok;
      if (outcome.status == CaseStatus::Failed) ++tally.failed;
      if (outcome.status == CaseStatus::Timeout) ++tally.timeout;
      if (outcome.status != CaseStatus::Ok) tally.failed_ids.push_back(outcome.id);
    }
  };
  auto finish = [&](pid_t pid, int status) {
    const auto it = running.find(pid);
    if (it == running.end()) return;
    RunningCase c = it->second;
    running.erase(it);
    CaseOutcome outcome;
    outcome.id = c.id;
    outcome.wall_s = secondsSince(c.started);
    outcome.started_at = isoUtc(c.started_at);
    outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const bool complete = folder.caseComplete(c.id);
    if (outcome.exit_code == 0 && complete) {
      outcome.status = CaseStatus::Ok;
    } else if (complete) {
      outcome.status = CaseStatus::Ok;  // its results were committed before the end (a late signal)
    } else if (c.timed_out) {
      outcome.status = CaseStatus::Timeout;
      outcome.message = "no result within the timeout of " + durationText(options.timeout_s) + "; stopped";
    } else if (tally.cancel_signal != 0 && (outcome.exit_code == 130 || outcome.exit_code == 143 ||
                                            outcome.exit_code == 128 + SIGKILL)) {
      return;  // cancelled with the study: not run, so --resume runs it
    } else {
      outcome.status = CaseStatus::Failed;
      outcome.message = study::failureMessage(readLog(folder, c.id));
      if (outcome.message.empty())
        outcome.message = WIFSIGNALED(status) ? "ended by signal " + std::to_string(WTERMSIG(status))
                                              : "exit code " + std::to_string(outcome.exit_code) + " without results";
    }
    durability.add(std::move(outcome));
  };

  // A case that a process of an earlier study run completed: recorded (after the next batch's sync) as ok.
  auto finishedElsewhere = [&](const std::string& id, Clock::time_point since) {
    durability.add({id, CaseStatus::Ok, 0, "completed by a case process of an earlier, stopped study run",
                    secondsSince(since), isoUtc(std::chrono::system_clock::now())});
  };
  // Looks again at the cases run elsewhere: one that ended is recorded when complete, else run here.
  auto recheckElsewhere = [&] {
    for (auto it = elsewhere.begin(); it != elsewhere.end();) {
      if (runFolderBusy(folder.caseRun(it->id))) {
        if (options.timeout_s > 0 && secondsSince(it->since) >= options.timeout_s) {
          durability.add({it->id, CaseStatus::Timeout, 0,
                          "another process kept the case's run folder locked for longer than the timeout of " +
                              durationText(options.timeout_s) + "; it was not stopped (not this study's process)",
                          secondsSince(it->since), isoUtc(std::chrono::system_clock::now())});
          it = elsewhere.erase(it);
        } else {
          ++it;
        }
        continue;
      }
      if (folder.caseComplete(it->id)) finishedElsewhere(it->id, it->since);
      else queue.push_back(it->id);  // it ended without results: run it here
      it = elsewhere.erase(it);
    }
  };

  for (;;) {
    while (tally.cancel_signal == 0 && running.size() < jobs && next < queue.size()) {
      const std::string id = queue[next++];
      if (runFolderBusy(folder.caseRun(id))) {
        elsewhere.push_back({id, Clock::now()});
        progress.note("case " + id + " is being run by another process (a case process of a stopped study run?); "
                      "waiting for it to end");
        continue;
      }
      if (folder.caseComplete(id)) {  // completed by such a process since this run started
        finishedElsewhere(id, Clock::now());
        continue;
      }
      const pid_t pid = spawnCase(folder, id, options);
      if (pid == 0) {
        durability.add({id, CaseStatus::Failed, 127, "could not start maris-cli for the case", 0.0,
                        isoUtc(std::chrono::system_clock::now())});
        continue;
      }
      running[pid] = {id, Clock::now(), std::chrono::system_clock::now(), false, {}};
    }
    count(durability.poll());  // after the next cases have started (the sync itself runs in its own thread)
    progress.show(tally, running.size(), elsewhere.size(), false);
    // Cancelled: the cases run elsewhere are left to their processes (not recorded; --resume looks again).
    if (running.empty() && (tally.cancel_signal != 0 || (elsewhere.empty() && next >= queue.size()))) break;

    // Sleep until a case ends, a signal arrives, a timeout falls due, a batch of cases is to be synced or
    // the progress line is due.
    double wait_s = std::min(elsewhere.empty() ? 1.0 : kElsewherePollSeconds, durability.secondsToNextPoll());
    for (const auto& [pid, c] : running) {
      if (options.timeout_s > 0 && !c.timed_out) wait_s = std::min(wait_s, options.timeout_s - secondsSince(c.started));
      if (c.timed_out) wait_s = std::min(wait_s, -std::chrono::duration<double>(Clock::now() - c.kill_at).count());
    }
    wait_s = std::max(wait_s, 0.001);
    timespec timeout{static_cast<time_t>(wait_s), static_cast<long>((wait_s - static_cast<double>(static_cast<time_t>(wait_s))) * 1e9)};
    siginfo_t info{};
    const int signal = ::sigtimedwait(&waited, &info, &timeout);
    if ((signal == SIGINT || signal == SIGTERM) && tally.cancel_signal == 0) {
      tally.cancel_signal = signal;
      for (const auto& [pid, c] : running) ::kill(pid, signal);
      if (options.progress) std::fprintf(stderr, "\nstopping: %zu running cases are cancelled\n", running.size());
    } else if (signal == SIGINT || signal == SIGTERM) {
      for (const auto& [pid, c] : running) ::kill(pid, SIGKILL);  // asked twice: stop now
    }
    int status = 0;
    for (pid_t pid; (pid = ::waitpid(-1, &status, WNOHANG)) > 0;) finish(pid, status);
    recheckElsewhere();
    for (auto& [pid, c] : running) {
      if (options.timeout_s > 0 && !c.timed_out && secondsSince(c.started) >= options.timeout_s) {
        c.timed_out = true;
        c.kill_at = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kKillGraceSeconds));
        ::kill(pid, SIGTERM);
      } else if (c.timed_out && Clock::now() >= c.kill_at) {
        ::kill(pid, SIGKILL);
        c.kill_at = Clock::now() + std::chrono::hours(1);
      }
    }
  }
  count(durability.finish());
  progress.show(tally, 0, elsewhere.size(), true);
  progress.finish();
  // A signal that arrived after the last case ended still cancels the study (it is pending, not lost).
  sigset_t pending;
  if (tally.cancel_signal == 0 && ::sigpending(&pending) == 0) {
    if (sigismember(&pending, SIGINT)) tally.cancel_signal = SIGINT;
    if (sigismember(&pending, SIGTERM)) tally.cancel_signal = SIGTERM;
  }
  if (tally.cancel_signal != 0) {
    // Consume the pending signal so restoring the mask does not kill the study before it reports.
    timespec zero{0, 0};
    while (::sigtimedwait(&waited, nullptr, &zero) > 0) {
    }
  }
  ::sigprocmask(SIG_SETMASK, &previous, nullptr);
  std::sort(tally.failed_ids.begin(), tally.failed_ids.end());
  tally.wall_s = secondsSince(start);
  return tally;
}

}  // namespace maris::cli
