#include "riser/riser_labels.hpp"
#include "riser/riser_stress_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/text_format.hpp"
#include "riser/riser_integration.hpp"
#include "riser/riser_scene.hpp"

namespace maris::riser {
namespace {

// Linear interpolation of column `y` of table `t` at time `at` (the history holds a sample at every stress time,
// so this is exact there).
double valueAt(const Table& t, const std::string& y, double at) {
  const std::vector<double>& time = t.find("time")->values;
  const std::vector<double>& v = t.find(y)->values;
  const auto upper = std::lower_bound(time.begin(), time.end(), at);
  if (upper == time.begin()) return v.front();
  if (upper == time.end()) return v.back();
  const std::size_t k = static_cast<std::size_t>(upper - time.begin());
  const double w = time[k] > time[k - 1] ? (at - time[k - 1]) / (time[k] - time[k - 1]) : 1.0;
  return (1 - w) * v[k - 1] + w * v[k];
}

struct ConvergenceRow {
  int n = 0;
  double max_stress = 0.0;          // [Pa] first probe, largest over the samples
  std::vector<double> at_times;     // [Pa] first probe, at each stress time
  double expected_error = 0.0;      // [-] plan's expected probe error, relative to the motion
  long steps = 0;
  double wall_time = 0.0;           // [s]
};

// step_from_tolerance: under a harmonic top motion generalized-α's error model gives the step for the tolerance at
// every n; other runs keep the scenario's solver settings.
ConvergenceRow runRow(const RiserParameters& p, int n, bool step_from_tolerance, const std::vector<double>& times,
                      RunContext& context) {
  RiserParameters q = p;
  q.segment_count = n;
  const RiserModel m = buildRiserModel(q);  // the solver and output settings below do not enter the model
  if (step_from_tolerance) {
    q.integrator = "implicit";
    q.time_step = implicitStepForTolerance(m.formulation, p.motion_period, p.convergence_tolerance);
    q.tolerance = p.convergence_tolerance;
  }
  q.frame_count = 1;
  q.probes = {p.probes.front()};
  q.sweep_pretension_ratios.clear();
  q.sweep_segment_counts.clear();
  q.convergence_segment_counts.clear();
  const Results r = simulateRiser(m, q, initialShape(m, q, context), RiserModes{}, context);
  ConvergenceRow row;
  row.n = n;
  row.max_stress = r.findTable("probes")->find("max_bending_stress")->values.front();
  for (double t : times) row.at_times.push_back(valueAt(*r.findTable("history"), "probe_bending_stress", t));
  row.expected_error = r.stats.error_estimate;
  row.steps = r.stats.steps;
  row.wall_time = context.elapsedSeconds();
  for (std::string& w : accuracyWarnings(r)) context.warn(std::move(w));
  return row;
}

}  // namespace

void addStressConvergence(const RiserParameters& p, Results& results, RunContext& context) {
  if (p.convergence_segment_counts.empty() || p.probes.empty()) return;
  std::vector<double> times;
  for (double t : p.stress_times)
    if (t > 0 && t <= p.end_time) times.push_back(t);
  // The top motion does not depend on n: decided once, for every row and the table's title.
  const bool step_from_tolerance = hasHarmonicTopMotion(buildRiserModel(p)) && p.motion_period > 0;
  const std::size_t total = p.convergence_segment_counts.size();
  std::vector<ConvergenceRow> rows;
  for (std::size_t k = 0; k < total; ++k) {
    const int n = static_cast<int>(std::lround(p.convergence_segment_counts[k]));
    const std::string label = "stress convergence, n = " + std::to_string(n);
    context.throwIfCancelled();
    RunContext row_context = context.part(double(k) / double(total), double(k + 1) / double(total), label + ": ");
    row_context.progress(0.0, "statics");
    try {
      rows.push_back(runRow(p, n, step_from_tolerance, times, row_context));
    } catch (const SolverError& e) {
      throw SolverError(label + ": " + e.quantity(), e.time(), e.step(), e.detail());
    }
    for (std::string& w : row_context.warnings()) context.warn(label + ": " + w);
  }
  std::sort(rows.begin(), rows.end(), [](const ConvergenceRow& a, const ConvergenceRow& b) { return a.n < b.n; });

  const double probe = p.probes.front().arc_length;
  Table t;
  t.name = "bending_stress_vs_segments";
  t.title = step_from_tolerance
                ? formatText("Bending stress at probe 1 (s = %g m) against segment count n (generalized-α, expected "
                             "probe error %g of the motion)", probe, p.convergence_tolerance)
                : formatText("Bending stress at probe 1 (s = %g m) against segment count n (the run's solver "
                             "settings)", probe);
  t.add("segment_count", "-", {}, riserColumnLabel("segment_count"));
  t.add("max_bending_stress", "Pa", {}, riserColumnLabel("max_bending_stress"));
  std::vector<std::string> stress_columns = {"max_bending_stress"};
  for (double time : times) {
    stress_columns.push_back("bending_stress_t" + formatTime(time));
    t.add(stress_columns.back(), "Pa", {}, riserColumnLabel(stress_columns.back()));
  }
  t.add("integrator_error_estimate", "-", {}, riserColumnLabel("integrator_error_estimate"));
  t.add("steps", "-", {}, riserColumnLabel("steps"));
  t.add("wall_time", "s", {}, riserColumnLabel("wall_time"));
  for (const ConvergenceRow& r : rows) {
    std::vector<double> values = {double(r.n), r.max_stress};
    values.insert(values.end(), r.at_times.begin(), r.at_times.end());
    values.insert(values.end(), {r.expected_error, double(r.steps), r.wall_time});
    for (std::size_t c = 0; c < values.size(); ++c) t.columns[c].values.push_back(values[c]);
  }
  PlotSpec stresses = makePlot("bending_stress_vs_segments", "Bending stress at probe 1 against n", t.name,
                               "segment_count", stress_columns);
  stresses.log_x = true;
  results.plots.push_back(std::move(stresses));
  results.tables.push_back(std::move(t));

  if (rows.size() >= 2) {
    // Differences from the finest n: each row's own discretisation error while it is well above the finest's.
    const ConvergenceRow& finest = rows.back();
    Table d;
    d.name = "bending_stress_difference_vs_segments";
    d.title = "Relative difference of the bending stress at probe 1 from n = " + std::to_string(finest.n);
    d.add("segment_count", "-", {}, riserColumnLabel("segment_count"));
    d.add("max_bending_stress_difference", "-", {}, riserColumnLabel("max_bending_stress_difference"));
    std::vector<std::string> difference_columns = {"max_bending_stress_difference"};
    for (double time : times) {
      difference_columns.push_back("bending_stress_t" + formatTime(time) + "_difference");
      d.add(difference_columns.back(), "-", {}, riserColumnLabel(difference_columns.back()));
    }
    auto relative = [](double value, double reference) {
      return reference != 0 ? std::abs(value / reference - 1) : std::abs(value);
    };
    for (std::size_t k = 0; k + 1 < rows.size(); ++k) {
      d.columns[0].values.push_back(rows[k].n);
      d.columns[1].values.push_back(relative(rows[k].max_stress, finest.max_stress));
      for (std::size_t c = 0; c < times.size(); ++c)
        d.columns[2 + c].values.push_back(relative(rows[k].at_times[c], finest.at_times[c]));
    }
    PlotSpec differences =
        makePlot("bending_stress_difference_vs_segments", "Bending stress at probe 1: relative difference from n = " +
                                                                std::to_string(finest.n),
                 d.name, "segment_count", difference_columns, true);
    differences.log_x = true;
    results.plots.push_back(std::move(differences));
    results.tables.push_back(std::move(d));
  }
  context.progress(1.0, "stress convergence");
}

}  // namespace maris::riser
