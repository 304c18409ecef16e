// The WEC scene's work estimate: kernel samples, time steps of the main run(s) and of the time-domain RAO
// checks (each a ramp and ten wave periods, as in addTimeDomainChecks), and what the results keep.
#include <cmath>
#include <numbers>

#include "wec/wec_parameters.hpp"
#include "wec/wec_work.hpp"

namespace maris::wec {

WorkEstimate estimateWecWork(const WecParameters& p) {
  constexpr double kCheckPeriods = 10;     // steadyResponse's periods after the ramp
  constexpr double kHistoryRows = 4000;    // the main run's stored rows (output stride)
  constexpr double kColumnsPerFloat = 12;  // history and sweep columns per float
  const double floats = static_cast<double>(p.floats.size());
  const double kernel_samples = 2.0 * floats * std::ceil(p.kernel_duration / p.time_step);
  double steps = (p.formulation == "both" ? 2.0 : 1.0) * std::ceil(p.duration / p.time_step) + kernel_samples;
  for (double w : p.check_frequencies)
    steps += std::ceil((p.ramp_duration + kCheckPeriods * 2.0 * std::numbers::pi / w) / p.time_step);
  WorkEstimate e;
  e.steps = {steps, {"time.time_step", "time.duration", "time.kernel_duration", "frequency.check_frequencies"}};
  e.cells = {floats, {"floats"}};
  const double kept = kernel_samples + kColumnsPerFloat * floats * (kHistoryRows + p.frequency_count);
  e.samples = {kept, {"time.time_step", "time.kernel_duration", "frequency.count"}};
  e.memory_bytes = {8.0 * kept, {"time.time_step", "time.kernel_duration"}};
  e.output_bytes = csvOutputBytes(kColumnsPerFloat * floats * (kHistoryRows + p.frequency_count), 8);
  return e;
}

}  // namespace maris::wec
