#include "core/work_estimate.hpp"

#include <algorithm>

#include <unistd.h>

#include "core/text_format.hpp"

namespace maris {

WorkLimits defaultWorkLimits() {
  WorkLimits limits;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0)
    limits.memory_bytes = std::min(limits.memory_bytes, 0.5 * static_cast<double>(pages) * static_cast<double>(page_size));
  return limits;
}

namespace {

void check(std::vector<FieldError>& errors, const WorkQuantity& q, double limit, const char* what) {
  if (q.value <= limit) return;
  std::string names;
  for (const auto& p : q.parameters) names += (names.empty() ? "" : ", ") + p;
  const std::string path = q.parameters.empty() ? std::string("parameters") : "parameters." + q.parameters.front();
  errors.push_back(FieldError{
      path, "",
      formatText("estimated %.3g %s exceed the limit %.3g", q.value, what, limit) +
          (names.empty() ? std::string() : " (set by " + names + ")") +
          "; change these parameters, or allow a large run (maris-cli run --allow-large; the GUI asks)"});
}

}  // namespace

std::vector<FieldError> workLimitErrors(const WorkEstimate& estimate, const WorkLimits& limits) {
  std::vector<FieldError> errors;
  check(errors, estimate.steps, limits.steps, "time steps or solver iterations");
  check(errors, estimate.cells, limits.cells, "unknowns");
  check(errors, estimate.samples, limits.samples, "stored result values");
  if (estimate.memory_bytes.value > limits.memory_bytes) {
    WorkQuantity gigabytes{estimate.memory_bytes.value / 1e9, estimate.memory_bytes.parameters};
    check(errors, gigabytes, limits.memory_bytes / 1e9, "GB of memory");
  }
  check(errors, estimate.seconds, limits.seconds, "s of solver work that cannot be stopped once started (a dense eigen solve or FFT)");
  return errors;
}

double csvOutputBytes(double values, int plots) {
  constexpr double kBytesPerValue = 24.0;  // "%.17g" is up to 24 characters, plus the comma
  constexpr double kBytesPerPlot = 150e3;  // a 1200 × 800 PNG of line plots
  return kBytesPerValue * values + kBytesPerPlot * plots + 64e3;  // + scenario.json, summary.json
}

}  // namespace maris
