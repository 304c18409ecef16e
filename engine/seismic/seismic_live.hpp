// Partial results of a seismic run, so plots grow while the time stepping runs. The FE cases run on
// worker threads but a RunContext is not thread-safe: the solve thread decides when a partial is due
// (RunContext::wantsPartialResults), asks the main case's worker for a copy of its records so far
// (FeCaseHandOver), and builds and publishes the partial Results itself.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

// A one-slot hand-over of a running FE case's records from its worker to the solve thread.
class FeCaseHandOver {
 public:
  // Solve thread: asks for a copy at the worker's next step; no-op while one is asked for or not yet taken.
  void request();
  // Worker: whether a copy is asked for (a relaxed load, cheap enough for every step).
  bool requested() const { return requested_.load(std::memory_order_relaxed); }
  // Worker: hands the copy over.
  void deliver(FeCase so_far);
  // Solve thread: the delivered copy, if any (the slot is then empty).
  std::optional<FeCase> take();

 private:
  std::atomic<bool> requested_{false};
  std::mutex mutex_;
  std::optional<FeCase> delivered_;
};

// The partial Results: `free_field` (the free-field part, complete before the FE runs start) and the
// main case's records so far, built by the same functions as the final results, so every row equals
// the finished run's row: "station_histories", for the box "verification", and the wave field at the
// latest step as the one 3D frame. Post-processing that needs the whole record (peak ratios R,
// spectral ratios H_a, the water's effect, the angle sweep, the modes, error estimates) is left out.
std::shared_ptr<const Results> partialSeismicResults(const SeismicParameters& p, const Results& free_field,
                                                     const FeCase& so_far);

}  // namespace maris::seismic
