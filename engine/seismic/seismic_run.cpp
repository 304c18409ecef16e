// The scene's solve: free field, then the FE runs (main model, dry comparison, sweep angles), which are
// independent and run on std::threads, at most one per hardware thread. While they run, this thread
// reports progress and, when the context wants them, publishes partial results of the main case.
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <thread>

#include "seismic/seismic_live.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

namespace {

struct Job {
  double angle_deg;
  bool water;
  bool snapshots;
  bool coarse_companion;  // on the mesh about twice as coarse (discretisation-error estimate)
  FeCase result;
  std::atomic<double> progress{0.0};
  std::atomic<bool> done{false};
  std::atomic<bool> failed{false};
};

}  // namespace

Results solveSeismic(const SeismicParameters& p, RunContext& ctx) {
  Results results;
  const FreeField field(seabedMaterial(p), waterLayer(p), waveType(p), p.angle_deg * std::numbers::pi / 180.0);
  addFreeFieldResults(p, field, results, ctx);

  // Independent FE runs.
  std::vector<std::unique_ptr<Job>> jobs;
  auto add = [&](double angle, bool water, bool snapshots, bool coarse) {
    auto j = std::make_unique<Job>();
    j->angle_deg = angle;
    j->water = water;
    j->snapshots = snapshots;
    j->coarse_companion = coarse;
    jobs.push_back(std::move(j));
  };
  add(p.angle_deg, p.include_water, true, false);
  // Discretisation-error companion: the main case on a mesh about twice as coarse (1/8 of the work).
  const bool reef = p.model == "reef";
  if (reef) add(p.angle_deg, p.include_water, false, true);
  const bool compare = reef && p.include_water && p.compare_without_water;
  if (compare) add(p.angle_deg, false, false, false);
  for (double a : p.sweep_angles_deg) add(a, p.include_water, false, false);

  // Partial results come from the main case only (jobs[0]): its worker hands over copies on request.
  FeCaseHandOver live;
  bool final_partial_sent = false;  // the main case's complete records, once, while the others still run
  auto publishPartial = [&]() {
    if (!jobs[0]->done) {
      if (std::optional<FeCase> so_far = live.take()) ctx.publishPartial(partialSeismicResults(p, results, *so_far));
      if (ctx.wantsPartialResults()) live.request();  // delivered at the worker's next step
    } else if (!jobs[0]->failed && !final_partial_sent && ctx.wantsPartialResults()) {
      ctx.publishPartial(partialSeismicResults(p, results, jobs[0]->result));
      final_partial_sent = true;
    }
  };

  // Each worker has its own RunContext whose cancel flag the calling thread raises on request.
  std::atomic<bool> cancel{false};
  std::mutex error_mutex;
  std::exception_ptr first_error;  // the failure that ended the batch (others then see RunCancelled)
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
    for (std::size_t k = next++; k < jobs.size(); k = next++) {
      Job& job = *jobs[k];
      RunContext local([&job](double f, const std::string&) { job.progress = f; }, &cancel);
      try {
        job.result = runFeCase(p, job.angle_deg, job.water, job.snapshots, local, job.coarse_companion,
                               k == 0 ? &live : nullptr);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        cancel = true;  // one failure ends the batch
        job.failed = true;
      }
      job.done = true;
    }
  };
  const std::size_t threads =
      std::min<std::size_t>(jobs.size(), std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (;;) {
    bool all_done = true;
    double total = 0.0;
    for (const auto& j : jobs) {
      all_done = all_done && j->done;
      total += j->done ? 1.0 : j->progress.load();
    }
    if (all_done) break;
    if (ctx.cancelRequested()) cancel = true;
    if (!cancel) publishPartial();
    ctx.progress(0.05 + 0.9 * total / jobs.size(), "finite-element runs");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
  ctx.throwIfCancelled();

  const std::size_t dry_job = reef ? 2 : 1, first_sweep = dry_job + (compare ? 1 : 0);
  std::vector<FeCase> sweep;
  for (std::size_t k = first_sweep; k < jobs.size(); ++k) sweep.push_back(std::move(jobs[k]->result));
  addFeResults(p, jobs[0]->result, compare ? &jobs[dry_job]->result : nullptr, sweep, results);
  if (reef) addDiscretisationEstimate(jobs[0]->result, jobs[1]->result, results);
  if (reef && p.mode_count > 0) addModalResults(p, results, ctx);
  ctx.progress(1.0, "done");
  return results;
}

}  // namespace maris::seismic
