#include "riser/riser_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/scene.hpp"
#include "core/text_format.hpp"
#include "riser/riser_envelope.hpp"
#include "riser/riser_frequency_sweep.hpp"
#include "riser/riser_integration.hpp"
#include "riser/riser_modes_krylov.hpp"
#include "riser/riser_plausibility.hpp"
#include "riser/riser_plot_groups.hpp"
#include "riser/riser_results.hpp"
#include "riser/riser_statics.hpp"
#include "riser/riser_stress_convergence.hpp"
#include "riser/riser_vessel.hpp"
#include "core/text_format.hpp"

namespace maris::riser {

namespace {

// A riser that floats in statics (FloatingRiserError) is an input the model cannot take: the error is put on the
// fields that make the floating stretch buoyant, the module rows over it, else the section rows, else the uniform
// section.
std::vector<FieldError> floatingRiserFields(const RiserParameters& p, const FloatingRiserError& e) {
  const std::string remedy =
      ". Keep the buoyant part below the surface: modules farther along the riser, or fewer, heavier or smaller ones; "
      "or a deeper top (top.z)";
  const auto over = [&](double start, double end) { return start <= e.last() && end >= e.first(); };
  std::vector<FieldError> errors;
  for (std::size_t k = 0; k < p.buoyancy_modules.size(); ++k)
    if (const auto& row = p.buoyancy_modules[k]; over(row.start, row.end))
      errors.push_back(
          {"buoyancy_modules[" + std::to_string(k) + "].start", numberText(row.start), e.detail() + remedy});
  if (errors.empty())
    for (std::size_t k = 0; k < p.sections.size(); ++k)
      if (const auto& row = p.sections[k]; over(row.start, row.end))
        errors.push_back({"sections[" + std::to_string(k) + "].outer_diameter", numberText(row.outer_diameter),
                          e.detail() + remedy});
  if (errors.empty()) errors.push_back({"section.outer_diameter", numberText(p.outer_diameter), e.detail() + remedy});
  return errors;
}

}  // namespace

StaticSolution initialShape(const RiserModel& m, const RiserParameters& p, RunContext& context) {
  if (p.solve_statics) {
    try {
      return solveStatics(m, context);
    } catch (const FloatingRiserError& e) {
      throw InputError(floatingRiserFields(p, e));
    }
  }
  return StaticSolution{m.initial_orientation, m.initial_top, Vec3::Zero(), 0, 0, 0.0};
}

Results simulateRiser(const RiserModel& m, const RiserParameters& p, const StaticSolution& initial,
                      const RiserModes& modes, RunContext& context) {
  Eigen::VectorXd y = restState(m, initial.orientation, initial.top);
  const IntegrationPlan plan = planIntegration(m, p);
  RiserRecorder recorder(m, p);
  recorder.publishPartialsTo(&context);  // live plots in the GUI (no-op without a partial sink)
  recorder.sample(0.0, y, true, std::string("profile_static"));
  if (!modes.frequencies.empty()) recorder.addModes(modes);
  const SolverStats stats = integrateRiser(m, p, plan, y, recorder, context);
  return recorder.finish(stats, initial);
}

Results solveRiser(const RiserParameters& p, RunContext& context) {
  const RiserModel model = buildRiserModel(p);
  if (model.vessel)
    for (const std::string& w : model.vessel->warnings) context.warn(w);
  const StaticSolution statics = initialShape(model, p, context);
  // Natural frequencies about the static state: dense up to n = 199, shift-invert Krylov above (riser_modes_krylov).
  RiserModes modes;
  std::string modes_method;
  if (p.modes && p.solve_statics) {
    context.progress(0.0, "natural frequencies");
    modes = naturalModes(model, statics, 6, context, &modes_method);
    if (modesMethod(model) == ModesMethod::None) context.warn("natural frequencies " + modes_method);
    if (modes.slowly_growing_count > 0)
      context.warn(slowGrowthNote(modes.slowly_growing_count, modes.largest_growth_rate, modes.largest_growth_per_radian));
    if (modes.unstable_count > 0)
      context.warn(std::to_string(modes.unstable_count) + " linearised modes are unstable: internal flow speed " +
                   numberText(std::abs(model.flow_speed)) + " m/s is beyond the divergence speed " +
                   numberText(modes.divergence_flow_speed) + " m/s (or in flutter)");
  }
  Results results = simulateRiser(model, p, statics, modes, context);
  if (!p.modes) results.stats.method += "; natural frequencies and modes not computed (output.modes = false)";
  if (!modes_method.empty()) results.stats.method += "; natural frequencies: " + modes_method;
  for (std::string& w : accuracyWarnings(results)) context.warn(std::move(w));
  addEnvelope(model, results);
  addFrequencySweeps(p, results, context);  // paper Sect. 8.2 tables (no-op without sweep lists)
  addStressConvergence(p, results, context);  // paper Sect. 9, σ_b(L/2) against n (no-op without its list)
  // Without a time history the 3D view animates the mode shapes instead (one period per mode).
  if (p.end_time <= 0 && !modes.frequencies.empty()) {
    results.view.frames.clear();
    appendModeFrames(model, statics, modes, 24, results.view);
  }
  return results;
}

}  // namespace maris::riser

namespace maris {

SceneDefinition makeRiserScene() {
  SceneDefinition scene = makeScene<riser::RiserParameters>(
      "riser", "Riser / cable dynamics",
      "Risers, cables and mooring lines by the segment method (Adamiec-Wójcik, Brzozowska & Wojciech, "
      "Acta Mechanica 231, 2020): n+1 rigid segments joined by rotary spring-damping elements for bending "
      "and torsion, in joint or absolute coordinates; gravity, buoyancy, Morison drag against a depth-varying "
      "current, prescribed top motion or a tensioner, pinned/clamped/free/spring bottom, point loads; static "
      "equilibrium by Newton's method, dynamics by RK4, DOPRI5 or implicit generalized-α with an O(n) "
      "block-tridiagonal reaction solve.",
      riser::riserBinder(), riser::checkRiserParameters, riser::solveRiser);
  scene.upgrade = riser::upgradeRiserParameters;
  setWorkEstimate<riser::RiserParameters>(scene, riser::riserBinder(), riser::estimateRiserWork);
  setPlausibility<riser::RiserParameters>(scene, riser::riserBinder(), riser::riserPlausibility);
  scene.plot_groups = riser::riserPlotGroups();
  return scene;
}

}  // namespace maris
