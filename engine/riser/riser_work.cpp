#include <algorithm>
#include <cmath>

#include "riser/riser_integration.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_modes_krylov.hpp"
#include "riser/riser_scene.hpp"

namespace maris::riser {

namespace {

constexpr double kHistoryRows = 2000;        // history table rows (riser_integration's sample grid)
constexpr double kHistoryColumns = 40;       // probes, end reactions, energies
constexpr double kValuesPerFramePoint = 8;   // node position (3) and colour scalar in View3D and the node table
constexpr double kDopri5StabilityLimit = 3.3;  // |hλ| on the negative real axis

// Steps of one run of `p` at its own segment count: the plan's step, or (DOPRI5 without a largest step) its
// stability bound, which an adaptive step cannot exceed on long.
double runSteps(const RiserParameters& p) {
  if (p.end_time <= 0) return 0;
  const RiserModel m = buildRiserModel(p);
  const IntegrationPlan plan = planIntegration(m, p);
  const double h = plan.step > 0 ? plan.step : kDopri5StabilityLimit / plan.highest_frequency;
  return std::ceil(p.end_time / h);
}

RiserParameters withSegments(RiserParameters p, double n) {
  p.segment_count = static_cast<int>(std::lround(n));
  p.sweep_pretension_ratios.clear();
  p.sweep_segment_counts.clear();
  p.convergence_segment_counts.clear();
  return p;
}

}  // namespace

WorkEstimate estimateRiserWork(const RiserParameters& p) {
  WorkEstimate w;
  const RiserModel model = buildRiserModel(p);
  const double segments = p.segment_count + 1.0;

  w.steps.value = runSteps(p);
  w.steps.parameters = {"solver.time_step", "solver.end_time", "solver.integrator", "geometry.segment_count"};
  for (double n : p.convergence_segment_counts) w.steps.value += runSteps(withSegments(p, n));
  if (!p.convergence_segment_counts.empty()) w.steps.parameters.push_back("stress_convergence.segment_counts");

  // The largest uninterruptible stretch: one dense eigen solve (natural frequencies, frequency sweep rows).
  double seconds = 0;
  const bool dense_modes = p.solve_statics && p.modes && modesMethod(model) == ModesMethod::Dense;
  if (dense_modes) seconds = modesSolveSeconds(model);  // the Krylov solver above n = 199 stops between iterations
  if (!p.sweep_pretension_ratios.empty()) seconds = std::max(seconds, modesSolveSeconds(model));
  for (double n : p.sweep_segment_counts)
    seconds = std::max(seconds, modesSolveSeconds(buildRiserModel(withSegments(p, n))));
  w.seconds = {seconds, {"geometry.segment_count", "frequency_sweep.segment_counts"}};
  w.cells = {segments, {"geometry.segment_count"}};

  const double frame_values = (p.frame_count + p.stress_times.size()) * segments * kValuesPerFramePoint;
  w.samples = {frame_values + kHistoryRows * kHistoryColumns * std::max<std::size_t>(1, p.probes.size()),
               {"output.frame_count", "geometry.segment_count"}};
  const double order = dense_modes || !p.sweep_pretension_ratios.empty() ? modesEigenOrder(model) : 0.0;
  w.memory_bytes = {8.0 * w.samples.value + 48.0 * order * order, {"output.frame_count", "geometry.segment_count"}};
  w.output_bytes = csvOutputBytes(w.samples.value, 8);
  return w;
}

}  // namespace maris::riser
