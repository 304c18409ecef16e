#include "case_durability.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "core/scenario.hpp"

namespace maris::cli {

namespace {

using study::CaseOutcome;
using study::CaseStatus;

// One syncfs(2) of the file system that holds `dir`; the error message, or "" when it succeeded.
std::string syncError(const std::filesystem::path& dir) {
  try {
    syncFileSystem(dir);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace

CaseDurability::~CaseDurability() {
  if (sync_.valid()) sync_.wait();
}

std::future<std::string> CaseDurability::startSync() {
  records_unsynced_ = false;  // those written so far are in this sync
  return std::async(std::launch::async, [dir = folder_.cases()] { return syncError(dir); });
}

std::vector<CaseOutcome> CaseDurability::record(std::vector<CaseOutcome> batch, const std::string& sync_error) {
  for (auto& outcome : batch) {
    if (!sync_error.empty() && outcome.status == CaseStatus::Ok) {
      // Its files may not be on the disk: not complete, so `--resume` runs it again.
      std::error_code ignored;
      std::filesystem::remove_all(folder_.caseRun(outcome.id), ignored);
      outcome.status = CaseStatus::Failed;
      outcome.message = "its results could not be made durable: " + sync_error;
    }
    study::writeCaseOutcome(folder_, outcome, FileSync::Later);
    records_unsynced_ = true;
  }
  return batch;
}

std::vector<CaseOutcome> CaseDurability::poll() {
  std::vector<CaseOutcome> recorded;
  if (sync_.valid() && sync_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    recorded = record(std::move(in_flight_), sync_.get());
    in_flight_.clear();
  }
  const double since_last = std::chrono::duration<double>(Clock::now() - last_sync_).count();
  if (!sync_.valid() && !waiting_.empty() && since_last >= kBatchSeconds) {
    in_flight_ = std::move(waiting_);
    waiting_.clear();
    last_sync_ = Clock::now();
    sync_ = startSync();
  }
  return recorded;
}

double CaseDurability::secondsToNextPoll() const {
  if (sync_.valid()) return 0.02;  // a sync is in flight: record its cases soon after it ends
  if (waiting_.empty()) return 1e9;
  return std::max(0.0, kBatchSeconds - std::chrono::duration<double>(Clock::now() - last_sync_).count());
}

std::vector<CaseOutcome> CaseDurability::finish() {
  std::vector<CaseOutcome> recorded;
  if (sync_.valid()) {
    recorded = record(std::move(in_flight_), sync_.get());
    in_flight_.clear();
  }
  if (!waiting_.empty()) {
    std::vector<CaseOutcome> batch = std::move(waiting_);
    waiting_.clear();
    records_unsynced_ = false;
    const std::string error = syncError(folder_.cases());
    for (auto& outcome : record(std::move(batch), error)) recorded.push_back(std::move(outcome));
  }
  // The records themselves: without them a complete case is still complete, a failed one would run again.
  if (records_unsynced_) {
    records_unsynced_ = false;
    if (const std::string error = syncError(folder_.cases()); !error.empty())
      std::fprintf(stderr, "warning: the cases' outcome records may not be on the disk: %s\n", error.c_str());
  }
  return recorded;
}

}  // namespace maris::cli
