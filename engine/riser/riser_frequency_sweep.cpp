#include "riser/riser_labels.hpp"
#include "riser/riser_frequency_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/abandonable.hpp"
#include "core/errors.hpp"
#include "riser/riser_modes.hpp"
#include "riser/riser_statics.hpp"
#include "core/text_format.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;
constexpr int kGalerkinModes = 24;  // 16 and 24 sine modes agree to < 3e-7 (test_riser_modes.cpp)

// One sweep row: the riser of `p` with tension and segment count replaced, solved and compared.
struct SweepRow {
  BendingPair sm;                      // segment method
  std::optional<ConveyingPipe> pipe;   // continuous model, when the riser is one
  BendingPair reference, eq66;         // Galerkin and eq (66) of that pipe
};

SweepRow solveRow(RiserParameters p, double top_tension, int segment_count, RunContext& context,
                  const std::string& label) {
  p.top_tension = top_tension;
  p.segment_count = segment_count;
  SweepRow row;
  const RiserModel m = buildRiserModel(p);
  try {
    row.sm = firstTwoBendingFrequencies(m, context);
  } catch (const SolverError& e) {
    throw SolverError("frequency sweep, " + label + ": " + e.quantity(), e.time(), e.step(), e.detail());
  }
  row.pipe = conveyingPipeOf(p, m);
  if (row.pipe) {
    const std::vector<double> w = conveyingPipeFrequencies(*row.pipe, kGalerkinModes, 2);
    if (w.size() > 0) row.reference.first = w[0];
    if (w.size() > 1) row.reference.second = w[1];
    const ConveyingPipe& c = *row.pipe;
    const double mean_tension = c.top_tension - c.weight_per_length * c.length / 2;
    row.eq66.first = tensionedBeamFrequency(1, c.length, std::max(mean_tension, 0.0), c.mass_per_length, c.ei);
    row.eq66.second = tensionedBeamFrequency(2, c.length, std::max(mean_tension, 0.0), c.mass_per_length, c.ei);
  }
  return row;
}

// A row whose linearisation has unstable modes has no trustworthy ω₁, ω₂: warn and leave it out. Slowly
// growing modes keep their frequencies; the warning gives their growth.
bool unstable(const BendingPair& sm, const std::string& label, RunContext& context) {
  if (sm.slowly_growing_count > 0)
    context.warn("frequency sweep, " + label + ": " +
                 slowGrowthNote(sm.slowly_growing_count, sm.growth_rate, sm.growth_per_radian));
  if (sm.unstable_count == 0 && sm.second > 0) return false;
  context.warn("frequency sweep, " + label + ": " + std::to_string(sm.unstable_count) +
               " linearised modes are unstable (flow past divergence, or flutter): row left out");
  return true;
}

double relative(double value, double reference) { return reference > 0 ? value / reference - 1 : 0.0; }

}  // namespace

double submergedWeight(const RiserModel& m) {
  double w = 0;
  for (const Segment& s : m.segments) w += (s.weight_per_length - s.buoyancy_per_length) * s.length;
  return w;
}

std::optional<ConveyingPipe> conveyingPipeOf(const RiserParameters& p, const RiserModel& m) {
  const bool straight = std::hypot(p.bottom_x - m.top_mean.x(), p.bottom_y - m.top_mean.y()) == 0.0;
  const bool calm = m.current_profile.max_speed == 0.0;
  if (m.top != TopCondition::Tensioner || m.bottom != BottomCondition::Pinned || !p.sections.empty() || !calm ||
      !p.point_loads.empty() || !straight)
    return std::nullopt;
  const Segment& mid = m.segments[m.n / 2];
  const double net = mid.weight_per_length - mid.buoyancy_per_length;
  for (const Segment& s : m.segments)
    if (std::abs(s.weight_per_length - s.buoyancy_per_length - net) > 1e-9 * std::max(std::abs(net), 1.0))
      return std::nullopt;  // partly submerged: tension is not linear in depth
  ConveyingPipe c;
  c.length = m.length;
  c.mass_per_length = mid.mass / mid.length;
  c.fluid_mass_per_length = mid.fluid_mass_per_length;
  c.ei = p.youngs_modulus * pi / 64 * (std::pow(p.outer_diameter, 4) - std::pow(p.inner_diameter, 4));
  c.top_tension = p.top_tension;
  c.weight_per_length = net;
  c.flow_speed = m.flow_speed;
  return c;
}

BendingPair firstTwoBendingFrequencies(const RiserModel& m, RunContext& context) {
  const StaticSolution statics = solveStatics(m, context);
  const RiserModes modes = runAbandonable(context, [m, statics] { return computeModes(m, statics, 12); });
  std::vector<double> distinct;
  for (std::size_t k = 0; k < modes.frequencies.size(); ++k) {
    if (modes.torsion_share[k] > 0.5) continue;
    const double w = modes.frequencies[k];
    if (distinct.empty() || w > distinct.back() * (1 + 1e-3)) distinct.push_back(w);
  }
  BendingPair out;
  out.unstable_count = modes.unstable_count;
  out.slowly_growing_count = modes.slowly_growing_count;
  out.growth_rate = modes.largest_growth_rate;
  out.growth_per_radian = modes.largest_growth_per_radian;
  if (distinct.size() > 0) out.first = distinct[0];
  if (distinct.size() > 1) out.second = distinct[1];
  return out;
}

void addFrequencySweeps(const RiserParameters& p, Results& results, RunContext& context) {
  const std::size_t total = p.sweep_pretension_ratios.size() + p.sweep_segment_counts.size();
  if (total == 0) return;
  std::size_t done = 0;
  const double weight = submergedWeight(buildRiserModel(p));
  double max_difference = -1;
  if (!p.sweep_pretension_ratios.empty()) {
    Table t;
    t.name = "frequency_vs_pretension";
    t.title = "First two bending frequencies against pretension ratio i_T (n = " + std::to_string(p.segment_count) + ")";
    for (const char* c : {"pretension_ratio"}) t.add(c, "-", {}, riserColumnLabel(c));
    t.add("top_tension", "N", {}, riserColumnLabel("top_tension"));
    for (const char* c : {"omega_1", "omega_2", "omega_1_reference", "omega_2_reference", "omega_1_eq66", "omega_2_eq66"})
      t.add(c, "rad/s", {}, riserColumnLabel(c));
    for (const char* c : {"difference_1", "difference_2"}) t.add(c, "-", {}, riserColumnLabel(c));
    bool referenced = true;
    for (double ratio : p.sweep_pretension_ratios) {
      context.throwIfCancelled();
      context.progress(double(done++) / double(total), "frequency sweep: i_T = " + numberText(ratio));
      const SweepRow r = solveRow(p, ratio * weight, p.segment_count, context, "i_T = " + numberText(ratio));
      if (unstable(r.sm, "i_T = " + numberText(ratio), context)) continue;
      referenced = referenced && r.pipe.has_value();
      const double d1 = relative(r.sm.first, r.reference.first), d2 = relative(r.sm.second, r.reference.second);
      const double row[10] = {ratio, ratio * weight, r.sm.first, r.sm.second, r.reference.first, r.reference.second,
                              r.eq66.first, r.eq66.second, d1, d2};
      for (int c = 0; c < 10; ++c) t.columns[c].values.push_back(row[c]);
      if (r.pipe) max_difference = std::max({max_difference, std::abs(d1), std::abs(d2)});
    }
    std::vector<std::string> y = {"omega_1", "omega_2"};
    if (referenced) y.insert(y.end(), {"omega_1_reference", "omega_2_reference", "omega_1_eq66", "omega_2_eq66"});
    results.plots.push_back(makePlot("frequency_vs_pretension", "Bending frequencies against pretension ratio i_T",
                                     t.name, "pretension_ratio", y));
    results.tables.push_back(std::move(t));
  }
  if (!p.sweep_segment_counts.empty()) {
    Table t;
    t.name = "frequency_vs_segments";
    t.title = "First two bending frequencies against segment count n (T = " + numberText(p.top_tension) + " N)";
    t.add("segment_count", "-", {}, riserColumnLabel("segment_count"));
    for (const char* c : {"omega_1", "omega_2", "omega_1_reference", "omega_2_reference"}) t.add(c, "rad/s", {}, riserColumnLabel(c));
    for (const char* c : {"error_1", "error_2"}) t.add(c, "-", {}, riserColumnLabel(c));
    bool referenced = true;
    for (double count : p.sweep_segment_counts) {
      const int n = static_cast<int>(std::lround(count));
      context.throwIfCancelled();
      context.progress(double(done++) / double(total), "frequency sweep: n = " + std::to_string(n));
      const SweepRow r = solveRow(p, p.top_tension, n, context, "n = " + std::to_string(n));
      if (unstable(r.sm, "n = " + std::to_string(n), context)) continue;
      referenced = referenced && r.pipe.has_value();
      const double row[7] = {double(n), r.sm.first, r.sm.second, r.reference.first, r.reference.second,
                             std::abs(relative(r.sm.first, r.reference.first)),
                             std::abs(relative(r.sm.second, r.reference.second))};
      for (int c = 0; c < 7; ++c) t.columns[c].values.push_back(row[c]);
    }
    results.plots.push_back(makePlot("frequency_vs_segments", "Bending frequencies against segment count n", t.name,
                                     "segment_count", {"omega_1", "omega_2"}));
    if (referenced) {
      PlotSpec errors = makePlot("frequency_error_vs_segments", "Relative frequency error against n (Galerkin reference)",
                                 t.name, "segment_count", {"error_1", "error_2"}, true);
      errors.log_x = true;
      results.plots.push_back(std::move(errors));
    }
    results.tables.push_back(std::move(t));
  }
  if (max_difference >= 0)
    results.addScalar("sweep_max_difference", max_difference, "-",
                      "Largest |ω − ω_ref|/ω_ref of ω₁, ω₂ over the pretension sweep (Galerkin reference with "
                      "depth-varying tension and internal flow)", "max relative difference of ω");
  context.progress(1.0, "frequency sweep");
}

}  // namespace maris::riser
