// What a solver sees of the outside world while it runs: progress reporting, cooperative
// cancellation, warnings, and (optionally) a sink for partial results so a GUI can plot live.
// The engine never knows whether it runs under the CLI, the GUI or a test.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace maris {

struct Results;

class RunContext {
 public:
  // fraction in [0, 1]; stage names what is running ("statics", "time integration").
  using ProgressFn = std::function<void(double fraction, const std::string& stage)>;
  using PartialFn = std::function<void(std::shared_ptr<const Results>)>;

  RunContext() = default;
  RunContext(ProgressFn progress, const std::atomic<bool>* cancel_flag)
      : progress_(std::move(progress)), cancel_(cancel_flag) {}

  // Reports progress; calls the callback at most every `min_interval` of wall time (and always for 0 and 1),
  // so solvers may call it every step.
  void progress(double fraction, std::string_view stage = {});

  // True once cancellation was requested. A relaxed atomic load: cheap enough for every step.
  bool cancelRequested() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
  // Throws RunCancelled if cancellation was requested. Solvers call this at least every ~10 ms of work.
  void throwIfCancelled() const;

  // Non-fatal notes for the user (e.g. "drag coefficients are zero: no damping"). Thread-safe.
  void warn(std::string message);
  std::vector<std::string> warnings() const;

  // Partial results for live plots. Solvers check wantsPartialResults() before building one.
  void setPartialSink(PartialFn sink, double min_interval_s = 0.25);
  bool wantsPartialResults();
  void publishPartial(std::shared_ptr<const Results> partial);

  // A context for one part of a longer run (a sweep row): its progress f shows as from + f (to − from) here, with
  // `stage_prefix` before its stage; it sees this context's cancellation. Its warnings and partial results stay
  // with it (the caller passes on what it wants); it reports as often as this one. Must not outlive this context.
  RunContext part(double from, double to, std::string stage_prefix);

  // Whether anyone will look at the 3D view (Results::view). The GUI does; maris-cli, which writes no 3D view,
  // says no, and a scene may then leave out frames that are costly to make (the ship's free surface takes most of
  // a short ship run). Parts of this context inherit it.
  void setViewWanted(bool wanted) { view_wanted_ = wanted; }
  bool wantsView() const { return view_wanted_; }

  // Seconds of wall time since the context was created.
  double elapsedSeconds() const;

  void setProgressInterval(double seconds) { min_progress_interval_s_ = seconds; }

 private:
  RunContext(ProgressFn progress, const std::atomic<bool>* cancel_flag, double min_progress_interval_s, bool view_wanted)
      : progress_(std::move(progress)), cancel_(cancel_flag), min_progress_interval_s_(min_progress_interval_s),
        view_wanted_(view_wanted) {}

  using Clock = std::chrono::steady_clock;
  ProgressFn progress_;
  const std::atomic<bool>* cancel_ = nullptr;
  PartialFn partial_;
  double min_progress_interval_s_ = 0.05;
  double min_partial_interval_s_ = 0.25;
  bool view_wanted_ = true;
  Clock::time_point start_ = Clock::now();
  // Empty until the first call: a default time_point is the clock's epoch (boot time for steady_clock), so
  // "interval since last" would stay false for the first hour after boot with a 3600 s interval.
  std::optional<Clock::time_point> last_progress_, last_partial_;
  mutable std::mutex warnings_mutex_;
  std::vector<std::string> warnings_;
};

// Throws SolverError naming the first non-finite entry of `state` if there is one.
// `name_of(i)` turns an index into the quantity's name ("segment 3 angle phi").
void throwIfNotFinite(const Eigen::Ref<const Eigen::VectorXd>& state, double time_s, long step,
                      const std::function<std::string(Eigen::Index)>& name_of);

}  // namespace maris
