// Registry entry of the "fiv" scene: flow-induced vibration (VIV + galloping) of a square cylinder
// near a free surface, for hydrokinetic energy conversion.
#include <cmath>
#include <memory>
#include <sstream>

#include "core/scene.hpp"
#include "fiv/fiv_calibration.hpp"
#include "fiv/fiv_parameters.hpp"
#include "fiv/fiv_plausibility.hpp"
#include "fiv/fiv_results.hpp"
#include "fiv/fiv_sweep.hpp"
#include "fiv/fiv_theory.hpp"
#include "fiv/fiv_timeseries.hpp"

namespace maris {

namespace fiv {
namespace {

void addModelScalars(Results& r, const FivModel& m) {
  r.addScalar("natural_frequency_water", m.f_n, "Hz", "f_n = √(k/(m + m_a))/2π", "f_n in water");
  r.addScalar("added_mass", m.added_mass, "kg", "m_a = C_a ρ D² L", "Added mass m_a");
  r.addScalar("damping_coefficient", m.damping, "N*s/m", "c_total (generator + transmission)", "Damping c");
  r.addScalar("damping_ratio", m.damping_ratio, "-", "ξ = c / (2√(k m_t))", "ξ");
  r.addScalar("mass_ratio", m.mass / (m.density * m.side * m.side * m.length), "-", "m* = m / (ρ D² L)", "m*");
}

void warnAboutModel(const FivModel& m, RunContext& ctx) {
  if (m.damping == 0.0)
    ctx.warn("zero structural damping: no power is converted and galloping grows until the force curve saturates");
}

Results postProcess(const FivParameters& p, RunContext& ctx) {
  Results r;
  const FivModel m = buildFivModel(p);
  ctx.progress(0.1, "reading series");
  const ImportedSeries s = readSeriesCsv(p.series_file);
  const SeriesAnalysis a = analyseSeries(s, m.damping, m.density, p.series_flow_speed, m.length, m.side);
  r.addScalar("amplitude", a.amplitude, "m", "Mean half peak-to-peak of y over whole cycles", "Amplitude A");
  r.addScalar("amplitude_ratio", a.amplitude / m.side, "-", "A/D", "A/D");
  r.addScalar("amplitude_spread", a.amplitude_spread, "m", "Standard deviation of the per-cycle amplitudes", "Amplitude spread");
  r.addScalar("cycles", a.cycles, "-", "Whole cycles in the record", "Cycles");
  r.addScalar("frequency", a.frequency, "Hz", "From zero up-crossings", "Frequency f");
  r.addScalar("f1", a.spectra.f1, "Hz", "Main peak of the y spectrum", "f₁");
  if (a.spectra.f2 > 0.0) {
    r.addScalar("f2", a.spectra.f2, "Hz", "Largest lift-spectrum peak above 1.5 f1", "f₂");
    r.addScalar("lift_alternations", a.spectra.alternations, "-", "n = round(f2/f1), paper eq 22", "Lift alternations n");
  }
  r.addScalar("power", a.power_damper, "W", "c⟨ẏ²⟩ (paper eq 13)", "P = c⟨ẏ²⟩");
  if (!s.lift.empty()) r.addScalar("power_fluid", a.power_fluid, "W", "⟨lift·ẏ⟩ (paper eq 8)", "⟨F ẏ⟩");
  r.addScalar("fluid_power", a.fluid_power, "W", "½ρU³L(D + 2A) (paper eq 14)", "P_fluid");
  r.addScalar("efficiency", a.efficiency, "-", "P / (P_fluid·16/27) (paper eq 15)", "η");
  Table spec;
  spec.name = "series_spectrum";
  spec.title = "Amplitude spectra of the imported y and lift";
  spec.add("frequency", "Hz", a.spectra.frequency, "Frequency f");
  spec.add("y_amplitude", "m", a.spectra.displacement_amplitude, "|Y(f)|");
  spec.add("lift_amplitude", "N", a.spectra.lift_amplitude, "|F(f)|");
  r.tables.push_back(std::move(spec));
  r.plots.push_back(makePlot("series_spectrum", "Amplitude spectra of the imported record", "series_spectrum", "frequency",
                     {"y_amplitude", "lift_amplitude"}, true));
  r.stats.method = "post-processing of " + std::to_string(s.time.size()) + " samples";
  ctx.progress(1.0, "done");
  return r;
}

Results solveFiv(const FivParameters& input, RunContext& ctx) {
  if (input.analysis == "post_process") return postProcess(input, ctx);
  Results r;
  FivParameters p = input;
  const std::vector<ReferencePoint> references = loadReferencePoints(p.reference_file);
  std::string calibration_note;
  if (p.calibrate) {
    const CalibrationResult cal = calibrate(p, references, ctx);
    calibration_note = addCalibrationResults(r, cal);
    p = cal.parameters;
  }
  const FivModel model = buildFivModel(p);
  warnAboutModel(model, ctx);
  addModelScalars(r, model);
  // Sweep over U for every h*, up then down.
  const SweepSettings settings = sweepSettingsFrom(p);
  // Partial results: the sweep's curves so far, so a GUI's plots grow during the run.
  const SweepObserver publish = [&](const SweepResult& so_far) {
    auto partial = std::make_shared<Results>();
    addModelScalars(*partial, model);
    addReferenceTables(*partial, model, references);
    addSweepResults(*partial, model, so_far, true);
    ctx.publishPartial(std::move(partial));
  };
  const SweepResult sweep = runSweep(model, settings, ctx, publish);
  addReferenceTables(r, model, references);
  addSweepResults(r, model, sweep, true);
  // Detail point: converge from the seed, then record.
  DetailPoint detail;
  detail.point = makeOperatingPoint(model, p.detail_speed, p.detail_deep ? kDeep : p.detail_submergence);
  detail.clearance = p.detail_deep ? kDeep : (p.detail_submergence - 0.5) * model.side;
  State state = seedState(model, p.initial_amplitude_ratio);  // from near rest, as the CFD runs
  const FivRhs rhs(model, detail.point);
  detail.cycle = runToLimitCycle(rhs, state, settings.cycle, &ctx, &detail.history, p.detail_cycles);
  addDetailResults(r, model, detail, p.animation_frames);
  // Solver statistics: the worst limit-cycle residual is the error estimate of A.
  r.stats.steps = sweep.steps + detail.cycle.steps;
  r.stats.rhs_evaluations = 4 * r.stats.steps;
  r.stats.error_estimate = sweep.worst_residual;
  r.stats.error_unit = "relative amplitude";
  std::ostringstream method;
  method << "RK4, " << p.steps_per_period << " steps per shortest period; limit cycles converged to "
         << p.convergence_tolerance << "; of " << sweep.branches.size() * sweep.speeds.size() * (p.sweep_down ? 2 : 1)
         << " responses " << sweep.stationary << " quasi-periodic (stationary, averaged over their windows) and "
         << sweep.unconverged << " still drifting after " << p.max_cycles << " periods";
  if (!calibration_note.empty()) method << "; " << calibration_note;
  r.stats.method = method.str();
  if (sweep.unconverged > 0)
    ctx.warn(std::to_string(sweep.unconverged) + " responses were still growing or drifting after numerics.max_cycles " +
             "periods (neither a converged cycle nor statistically stationary; response column 3); their residual " +
             "columns give the drift or the cycle-to-cycle spread");
  return r;
}

// RK4 steps of the sweep (every speed of every submergence, up and down, at most max_cycles periods) and of the
// detail point; the 3D frames and tables it keeps.
WorkEstimate estimateFivWork(const FivParameters& p) {
  constexpr double kColumnsPerSpeed = 18;
  const double curves = static_cast<double>(p.submergence_ratios.size()) + (p.include_deep ? 1.0 : 0.0);
  const double speeds = curves * p.speed_count * (p.sweep_down ? 2.0 : 1.0);
  const double detail = static_cast<double>(p.detail_cycles) * p.steps_per_period;
  WorkEstimate w;
  if (p.analysis != "sweep") return w;
  w.steps = {speeds * p.max_cycles * p.steps_per_period + detail,
             {"sweep.speed_count", "numerics.max_cycles", "numerics.steps_per_period", "free_surface.submergence_ratios"}};
  w.cells = {1.0, {}};
  w.samples = {kColumnsPerSpeed * speeds + 4.0 * detail, {"sweep.speed_count", "detail.cycles"}};
  w.memory_bytes = {8.0 * w.samples.value, w.samples.parameters};
  w.output_bytes = csvOutputBytes(w.samples.value, 8);
  return w;
}

}  // namespace
}  // namespace fiv

SceneDefinition makeFivScene() {
  SceneDefinition scene = makeScene<fiv::FivParameters>(
      "fiv", "Flow-induced vibration near a free surface",
      "1-DOF elastically mounted square cylinder in a current under a free surface: quasi-steady galloping "
      "(Parkinson & Smith 1964) plus a Facchinetti (2004) wake oscillator for VIV, with a calibrated free-surface "
      "factor; sweeps of amplitude, frequency, converted power and Betz efficiency over current speed and "
      "submergence (after Zhang, Song, Li, Su & Ding, square cylinder near a free surface), calibration to "
      "reference points and post-processing of imported records.",
      fiv::fivBinder(), fiv::checkFivParameters, fiv::solveFiv);
  setWorkEstimate<fiv::FivParameters>(scene, fiv::fivBinder(), fiv::estimateFivWork);
  setPlausibility<fiv::FivParameters>(scene, fiv::fivBinder(), fiv::fivPlausibility);
  return scene;
}

}  // namespace maris
