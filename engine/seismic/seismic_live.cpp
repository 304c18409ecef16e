#include "seismic/seismic_live.hpp"

#include <string>

namespace maris::seismic {

void FeCaseHandOver::request() {
  std::lock_guard lock(mutex_);
  if (!delivered_) requested_.store(true, std::memory_order_relaxed);
}

void FeCaseHandOver::deliver(FeCase so_far) {
  std::lock_guard lock(mutex_);
  delivered_ = std::move(so_far);
  requested_.store(false, std::memory_order_relaxed);
}

std::optional<FeCase> FeCaseHandOver::take() {
  std::lock_guard lock(mutex_);
  std::optional<FeCase> out = std::move(delivered_);
  delivered_.reset();
  return out;
}

std::shared_ptr<const Results> partialSeismicResults(const SeismicParameters& p, const Results& free_field,
                                                     const FeCase& so_far) {
  auto out = std::make_shared<Results>(free_field);
  const double reached = so_far.incident.empty() ? 0.0 : (so_far.incident.size() - 1) * so_far.time_step;
  out->addScalar("time_reached", reached, "s", "Simulated time the main finite-element run has reached so far", "Time reached");
  addStationHistories(so_far, *out);
  addVerificationHistories(so_far, *out);
  addWaveFieldFrames(p, so_far, *out);
  return out;
}

}  // namespace maris::seismic
