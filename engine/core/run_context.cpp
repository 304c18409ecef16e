#include "core/run_context.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace maris {

void RunContext::progress(double fraction, std::string_view stage) {
  if (!progress_) return;
  const auto now = Clock::now();
  const bool edge = fraction <= 0.0 || fraction >= 1.0;
  if (!edge && last_progress_ &&
      std::chrono::duration<double>(now - *last_progress_).count() < min_progress_interval_s_)
    return;
  last_progress_ = now;
  progress_(std::clamp(fraction, 0.0, 1.0), std::string(stage));
}

RunContext RunContext::part(double from, double to, std::string stage_prefix) {
  return RunContext(
      [this, from, to, prefix = std::move(stage_prefix)](double f, const std::string& stage) {
        progress(from + f * (to - from), prefix + stage);
      },
      cancel_, min_progress_interval_s_, view_wanted_);
}

void RunContext::throwIfCancelled() const {
  if (cancelRequested()) throw RunCancelled();
}

void RunContext::warn(std::string message) {
  std::lock_guard lock(warnings_mutex_);
  warnings_.push_back(std::move(message));
}

std::vector<std::string> RunContext::warnings() const {
  std::lock_guard lock(warnings_mutex_);
  return warnings_;
}

void RunContext::setPartialSink(PartialFn sink, double min_interval_s) {
  partial_ = std::move(sink);
  min_partial_interval_s_ = min_interval_s;
}

bool RunContext::wantsPartialResults() {
  if (!partial_) return false;
  return !last_partial_ || std::chrono::duration<double>(Clock::now() - *last_partial_).count() >= min_partial_interval_s_;
}

void RunContext::publishPartial(std::shared_ptr<const Results> partial) {
  if (!partial_) return;
  last_partial_ = Clock::now();
  partial_(std::move(partial));
}

double RunContext::elapsedSeconds() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void throwIfNotFinite(const Eigen::Ref<const Eigen::VectorXd>& state, double time_s, long step,
                      const std::function<std::string(Eigen::Index)>& name_of) {
  for (Eigen::Index i = 0; i < state.size(); ++i) {
    if (!std::isfinite(state[i])) {
      const std::string name = name_of ? name_of(i) : "state component " + std::to_string(i);
      throw SolverError(name, time_s, step, "became non-finite (" + std::to_string(state[i]) + ")");
    }
  }
}

}  // namespace maris
