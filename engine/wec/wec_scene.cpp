// Registry entry of the hinged-float WEC scene: parameters → model → frequency domain, radiation memory,
// time-domain check points, main time-domain run(s) → Results.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/checked_count.hpp"
#include "core/scene.hpp"
#include "core/text_format.hpp"
#include "wec/wec_frequency.hpp"
#include "wec/wec_parameters.hpp"
#include "wec/wec_plausibility.hpp"
#include "wec/wec_response.hpp"
#include "wec/wec_results.hpp"
#include "wec/wec_time.hpp"
#include "wec/wec_work.hpp"

namespace maris {

namespace {

using namespace maris::wec;

// Partial results for live plots: the finished part of the results, the tables being filled and the radiation
// kernel table, with the final plot list, so a GUI draws them as it will draw the finished run (only fewer rows).
struct LivePublisher {
  RunContext& ctx;
  const Results& finished;
  std::vector<PlotSpec> plots;
  Table kernel;
  bool wanted() const { return ctx.wantsPartialResults(); }
  void publish(std::vector<Table> growing) const {
    auto partial = std::make_shared<Results>();
    partial->scalars = finished.scalars;
    partial->tables = finished.tables;
    for (auto& t : growing) partial->tables.push_back(std::move(t));
    partial->tables.push_back(kernel);
    partial->plots = plots;
    ctx.publishPartial(std::move(partial));
  }
};

// The frequency-response table of the frequencies done so far, with the deep-water flag.
Table sweepTable(const std::vector<double>& omega, const std::vector<std::vector<FrequencyResponse>>& resp,
                 double omega_deep) {
  Table t = frequencyTable(omega, resp);
  std::vector<double> flag;
  for (double w : omega) flag.push_back(w >= omega_deep ? 1.0 : 0.0);
  t.add("deep_water", "-", flag, "Deep water (1 = yes)");
  return t;
}

// Frequency sweep, flags where the deep-water coefficients are approximate.
void addFrequencyDomain(const WecParameters& p, const WecModel& model, Results& res, RunContext& ctx,
                        const LivePublisher& live) {
  std::vector<double> omega;
  for (int i = 0; i < p.frequency_count; ++i)
    omega.push_back(p.omega_min + (p.omega_max - p.omega_min) * i / (p.frequency_count - 1));
  const double omega_deep = std::sqrt(std::numbers::pi * p.gravity / p.depth);  // kh = π
  std::vector<std::vector<FrequencyResponse>> resp(model.floats.size());
  for (std::size_t k = 0; k < omega.size(); ++k) {
    for (std::size_t f = 0; f < model.floats.size(); ++f) resp[f].push_back(solveFrequency(model, model.floats[f], omega[k]));
    ctx.throwIfCancelled();
    if (k + 1 < omega.size() && live.wanted()) {
      const std::vector<double> done(omega.begin(), omega.begin() + static_cast<std::ptrdiff_t>(k + 1));
      live.publish({sweepTable(done, resp, omega_deep), hydroTable(model, done)});
    }
  }
  res.tables.push_back(sweepTable(omega, resp, omega_deep));
  res.tables.push_back(hydroTable(model, omega));
  if (p.omega_min < omega_deep && p.hydro_source == "hemisphere_hulme")
    ctx.warn(formatText("below %.3g rad/s kh < pi at %.3g m depth: the deep-water Hulme coefficients are approximate there "
                        "(finite depth lowers heave damping by several %%); see the column \"Deep water (1 = yes)\" of "
                        "the frequency sweep",
                        omega_deep, p.depth));
  for (std::size_t f = 0; f < model.floats.size(); ++f) {
    const std::string n = std::to_string(f + 1);
    const double wn = naturalFrequency(model, model.floats[f]);
    res.addScalar("natural_frequency_" + n, wn, "rad/s", "Undamped pitch natural frequency, root of K = ω² J(ω)", "ω_n, float " + n);
    double cw_ratio = 0.0;
    for (const auto& r : resp[f]) cw_ratio = std::max(cw_ratio, r.capture_width / r.capture_width_bound);
    res.addScalar("max_capture_width_ratio_" + n, cw_ratio, "-", "max over the sweep of capture width / (3 lambda / 2 pi)", "max capture width / (3λ/2π), float " + n);
  }
  // Power matrix (total over floats) for irregular seas from the frequency domain.
  if (!p.power_hs.empty()) {
    Table pm;
    pm.name = "power_matrix";
    pm.title = "Mean PTO power of all floats in irregular seas (" + p.spectrum + ")";
    pm.add("peak_period", "s", p.power_tp, "T_p");
    for (double hs : p.power_hs) {
      std::vector<double> row;
      for (double tp : p.power_tp) {
        ctx.throwIfCancelled();
        double total = 0.0;
        for (const auto& f : model.floats) total += irregularMeanPower(model, f, p.spectrum, hs, tp, p.peak_enhancement);
        row.push_back(total);
      }
      pm.add(powerMatrixColumn(hs), "W", row, formatText("P at H_s = %g m", hs));
    }
    res.tables.push_back(std::move(pm));
  }
}

// Radiation kernel fit quality and the Ogilvie check of A∞ for float 1.
void addRadiationScalars(const WecModel& model, Results& res, RunContext& ctx) {
  const auto& f = model.floats.front();
  if (model.coupled) {
    double worst_r2 = 1.0, worst_b = 0.0;
    for (const auto& c : model.cross) {
      worst_r2 = std::min(worst_r2, c.mode.fit.r_squared);
      worst_b = std::max(worst_b, c.mode.quality.damping_error);
      if (!c.mode.fit.stable()) ctx.warn("cross radiation kernel fit has an unstable pole");
    }
    res.addScalar("cross_radiation_channels", static_cast<double>(model.cross.size()), "-",
                  "Off-diagonal (float-float and surge-heave) radiation entries with their own kernels", "Cross-radiation channels");
    res.addScalar("cross_kernel_fit_r2_min", worst_r2, "-", "Lowest R² of the cross-kernel modal fits", "min R² of the cross-kernel fits");
    res.addScalar("cross_kernel_fit_damping_error_max", worst_b, "-",
                  "Largest max|B_fit - B| / max|B| of the cross-kernel fits on 0.3-3 rad/s", "max damping error of the cross-kernel fits");
  }
  for (auto [name, mode] : {std::pair{"surge", &f.surge}, std::pair{"heave", &f.heave}}) {
    const std::string s = name;
    res.addScalar("kernel_fit_order_" + s, mode->fit.order, "-", "States of the modal (Prony) fit of K(t)", "K(t) fit order, " + s);
    res.addScalar("kernel_fit_r2_" + s, mode->fit.r_squared, "-", "Coefficient of determination of the K(t) fit", "K(t) fit R², " + s);
    res.addScalar("kernel_fit_damping_error_" + s, mode->quality.damping_error, "-",
                  "max |B_fit - B| / max B on 0.3-3 rad/s", "K(t) fit damping error, " + s);
    res.addScalar("kernel_fit_added_mass_error_" + s, mode->quality.added_mass_error, "-",
                  "max |w (A_fit - A)| / max B on 0.3-3 rad/s", "K(t) fit added-mass error, " + s);
    res.addScalar("kernel_fit_min_real_part_" + s, mode->quality.min_real_part, "-",
                  "min Re K_fit(iw) / max B on 0.3-3 rad/s (passivity: >= 0)", "K(t) fit min Re pole, " + s);
    if (!mode->fit.stable()) ctx.warn(s + " kernel fit has an unstable pole");
    if (mode->quality.min_real_part < -0.01) ctx.warn(s + " kernel fit is not passive on 0.3-3 rad/s");
    const double w = 1.0;
    const FloatHydro h = f.hydro->at(w);
    const double a = ogilvieAddedMassInfinity(mode->kernel, w, s == "heave" ? h.heave.added_mass : h.surge.added_mass);
    res.addScalar("added_mass_inf_ogilvie_ratio_" + s, a / mode->a_inf, "-",
                  "A_inf recovered by Ogilvie at 1 rad/s over the database A_inf", "A∞ Ogilvie ratio, " + s);
    const double a_err = s == "heave" ? model.a_inf_error_heave : model.a_inf_error_surge;
    if (a_err > 0.0)
      res.addScalar("added_mass_inf_error_" + s, a_err, "kg",
                    "Error bar of the imported A_inf recovered by Ogilvie (spread over the band + half the tail term)", "A∞ error, " + s);
  }
}

void addTimeDomainChecks(const WecParameters& p, const WecModel& model, const TimeDomainOptions& base, Results& res,
                         RunContext& ctx, const LivePublisher& live) {
  if (p.check_frequencies.empty()) return;
  std::vector<SteadyResponse> points;
  double err_amp = 0.0, err_phase = 0.0;
  for (std::size_t k = 0; k < p.check_frequencies.size(); ++k) {
    ctx.progress(0.3 + 0.3 * k / p.check_frequencies.size(), "time-domain RAO points");
    const double w = p.check_frequencies[k];
    points.push_back(steadyResponse(model, w, p.check_wave_height, p.ramp_duration, base, 10, &ctx));
    for (std::size_t f = 0; f < model.floats.size(); ++f) {
      const Complex fd = solveFrequency(model, model.floats[f], w).pitch, td = points.back().pitch[f];
      err_amp = std::max(err_amp, std::abs(std::abs(td) / std::abs(fd) - 1.0));
      err_phase = std::max(err_phase, std::abs(std::arg(td / fd)) * 180.0 / std::numbers::pi);
    }
    if (k + 1 < p.check_frequencies.size() && live.wanted()) live.publish({timeDomainRaoTable(points, model.floats.size())});
  }
  res.tables.push_back(timeDomainRaoTable(points, model.floats.size()));
  res.addScalar("td_fd_rao_amplitude_error", err_amp, "-", "max relative |RAO| difference, time vs frequency domain", "|RAO| time vs frequency domain");
  res.addScalar("td_fd_rao_phase_error", err_phase, "deg", "max RAO phase difference, time vs frequency domain", "RAO phase time vs frequency domain");
}

// Irregular sea: frequency-domain response spectra of pitch, hinge reactions and moment (S_q = |H_q|² S_η), their
// standard deviations, and the same deviations measured in the time-domain run after ramp and settling.
void addIrregularStatistics(const WecParameters& p, const WecModel& model, const TimeDomainResult& td, Results& res) {
  const double wp = 2.0 * std::numbers::pi / p.peak_period;
  std::vector<double> omega;
  for (int i = 0; i <= 600; ++i) omega.push_back(wp * (0.2 + 3.8 * i / 600.0));
  Table t;
  t.name = "response_spectra";
  t.title = "Response spectra in the irregular sea (" + p.spectrum + ", frequency domain)";
  t.add("omega", "rad/s", omega, "ω");
  const double settle = p.ramp_duration + settlingTime(model);
  std::size_t k0 = 0;
  while (k0 + 1 < td.time.size() && td.time[k0] < settle) ++k0;
  auto deviation = [&](const std::vector<double>& s) {
    const double n = static_cast<double>(s.size() - k0);
    double mean = 0.0, sq = 0.0;
    for (std::size_t k = k0; k < s.size(); ++k) mean += s[k] / n;
    for (std::size_t k = k0; k < s.size(); ++k) sq += (s[k] - mean) * (s[k] - mean) / n;
    return std::sqrt(sq);
  };
  for (std::size_t i = 0; i < model.floats.size(); ++i) {
    const std::string n = std::to_string(i + 1);
    const ResponseSpectra s = responseSpectra(model, model.floats[i], p.spectrum, p.significant_height,
                                              p.peak_period, p.peak_enhancement, omega);
    if (i == 0) t.add("wave_spectrum", "m^2*s/rad", s.wave, "S_η");
    t.add("pitch_spectrum_" + n, "rad^2*s/rad", s.pitch, "S_θ, float " + n);
    t.add("hinge_fx_spectrum_" + n, "N^2*s/rad", s.hinge_fx, "S_Fx, float " + n);
    t.add("hinge_fz_spectrum_" + n, "N^2*s/rad", s.hinge_fz, "S_Fz, float " + n);
    t.add("moment_spectrum_" + n, "N^2*m^2*s/rad", s.moment_y, "S_My, float " + n);
    res.addScalar("sd_pitch_fd_" + n, s.sd_pitch * 180.0 / std::numbers::pi, "deg", "Std of pitch, frequency domain", "σ pitch (frequency domain), float " + n);
    res.addScalar("sd_hinge_fx_fd_" + n, s.sd_fx, "N", "Std of the horizontal hinge reaction, frequency domain", "σ F_x (frequency domain), float " + n);
    res.addScalar("sd_hinge_fz_fd_" + n, s.sd_fz, "N", "Std of the vertical hinge reaction, frequency domain", "σ F_z (frequency domain), float " + n);
    if (td.time.size() - k0 < 100) continue;  // run too short after settling for statistics
    const auto& h = td.floats[i];
    const double record = td.time.back() - td.time[k0];
    res.addScalar("sd_pitch_td_" + n, deviation(h.theta) * 180.0 / std::numbers::pi, "deg",
                  "Std of pitch in the time-domain run after ramp and settling (see sd_pitch_sampling_error)", "σ pitch (time domain), float " + n);
    res.addScalar("sd_hinge_fx_td_" + n, deviation(h.hinge_fx), "N", "Std of the horizontal hinge reaction, time domain", "σ F_x (time domain), float " + n);
    res.addScalar("sd_hinge_fz_td_" + n, deviation(h.hinge_fz), "N", "Std of the vertical hinge reaction, time domain", "σ F_z (time domain), float " + n);
    struct Quantity {
      const char* name;
      const char* symbol;  // the label people read
      const std::vector<double>* spectrum;
    };
    for (const Quantity& q : {Quantity{"pitch", "pitch", &s.pitch}, Quantity{"hinge_fx", "F_x", &s.hinge_fx},
                              Quantity{"hinge_fz", "F_z", &s.hinge_fz}})
      res.addScalar(std::string("sd_") + q.name + "_sampling_error_" + n, deviationSamplingError(omega, *q.spectrum, record), "-",
                    "Relative standard error of the time-domain std from the record length, for a Gaussian sea of this spectrum "
                    "(the scene's fixed-amplitude sea scatters less)",
                    std::string("σ ") + q.symbol + " sampling error, float " + n);
  }
  res.tables.push_back(std::move(t));
}

// Every plot of the finished run, in order (partial results carry the same list).
std::vector<PlotSpec> allPlots(const WecParameters& p, std::size_t float_count) {
  std::vector<PlotSpec> plots = wecPlots(float_count, !p.check_frequencies.empty(), p.formulation == "both");
  if (!p.power_hs.empty()) plots.push_back(powerMatrixPlot(p.power_hs, p.spectrum));
  if (p.wave_type == "irregular") plots.push_back(responseSpectraPlot(float_count));
  return plots;
}

Results solveWec(const WecParameters& p, RunContext& ctx) {
  Results res;
  ctx.throwIfCancelled();
  ctx.progress(0.0, "radiation kernels");
  WecModel model = buildWecModel(p);
  buildRadiation(model, p.kernel_duration, p.time_step, &ctx);
  addRadiationScalars(model, res, ctx);
  const std::size_t nf = model.floats.size();
  const bool both = p.formulation == "both";
  const LivePublisher live{ctx, res, allPlots(p, nf), kernelTable(model.floats.front())};
  if (live.wanted()) live.publish({});
  ctx.throwIfCancelled();
  ctx.progress(0.1, "frequency domain");
  addFrequencyDomain(p, model, res, ctx, live);

  TimeDomainOptions base;
  base.state_space = p.radiation == "state_space";
  base.projection = p.constraint_control == "projection";
  base.newmark = p.augmented_integrator == "newmark_two_loop";
  base.baumgarte_rate = p.baumgarte_rate;
  base.time_step = p.time_step;
  base.duration = p.duration;
  base.initial_offset = p.initial_offset_deg * std::numbers::pi / 180.0;
  base.augmented = p.formulation == "augmented";
  const double h_lim = rk4StabilityStep(model, base);
  res.addScalar("rk4_stability_step", h_lim, "s", "Estimated RK4 stability limit of the fastest mode", "RK4 stability step");
  if (p.time_step > 0.8 * h_lim)
    ctx.warn(formatText("time step %.3g s is close to or above the RK4 stability limit %.3g s", p.time_step, h_lim));
  addTimeDomainChecks(p, model, base, res, ctx, live);

  // Main run(s).
  IncidentWaves waves;
  if (p.wave_type == "regular")
    waves = makeRegularWave(p.wave_height, p.wave_frequency, p.ramp_duration, model.direction, p.gravity);
  else if (p.wave_type == "irregular")
    waves = makeIrregularWave(p, model.direction);
  else
    waves.ramp_duration = p.ramp_duration;
  const long steps = checkedCount(p.duration / p.time_step, kMaxTimeSteps, "parameters.time.time_step",
                                  "time steps over time.duration");
  base.output_stride = static_cast<int>(std::max(1L, steps / 4000));
  std::vector<double> theta0;
  for (const auto& f : model.floats) theta0.push_back(f.theta0);
  ctx.progress(0.6, "time integration");
  // Live time histories: of the main run alone, or, comparing formulations, rows the second run has reached
  // (the table needs both runs' columns to the same length).
  TimeDomainObserver observe_main;
  if (!both)
    observe_main = [&](const TimeDomainResult& so_far) {
      live.publish({historyTable(so_far, nullptr, theta0, so_far.time.size())});
    };
  const TimeDomainResult main = simulateTimeDomain(model, waves, base, &ctx, observe_main);
  res.stats.method = main.method;
  res.stats.steps = main.steps;
  res.stats.rhs_evaluations = main.rhs_evaluations;
  res.stats.error_estimate = main.error_estimate;
  res.stats.error_unit = "rad (theta, sum of embedded RK4 local-error estimates)";
  if (!(base.augmented && base.newmark))
    res.addScalar("error_estimate_relative", main.relative_error_estimate, "-",
                  "Shared RK4's own estimate (core/ode.hpp): sum of embedded local errors over all states / max |state|", "Relative error estimate");
  if (both) {
    TimeDomainOptions aug = base;
    aug.augmented = true;
    const TimeDomainResult second = simulateTimeDomain(model, waves, aug, &ctx, [&](const TimeDomainResult& so_far) {
      live.publish({historyTable(main, &so_far, theta0, so_far.time.size())});
    });
    res.tables.push_back(historyTable(main, &second, theta0, main.time.size()));
    double d_theta = 0.0, amp = 0.0, d_f = 0.0, amp_f = 0.0;
    for (std::size_t i = 0; i < model.floats.size(); ++i)
      for (std::size_t k = 0; k < main.time.size(); ++k) {
        d_theta = std::max(d_theta, std::abs(main.floats[i].theta[k] - second.floats[i].theta[k]));
        amp = std::max(amp, std::abs(main.floats[i].theta[k] - theta0[i]));
        d_f = std::max({d_f, std::abs(main.floats[i].hinge_fx[k] - second.floats[i].hinge_fx[k]),
                        std::abs(main.floats[i].hinge_fz[k] - second.floats[i].hinge_fz[k])});
        amp_f = std::max({amp_f, std::abs(main.floats[i].hinge_fz[k]), std::abs(main.floats[i].hinge_fx[k])});
      }
    res.addScalar("classical_augmented_pitch_difference", amp > 0 ? d_theta / amp : d_theta, "-",
                  "max |theta_classical - theta_augmented| / max |theta - theta0|", "Pitch: classical vs augmented");
    res.addScalar("classical_augmented_force_difference", amp_f > 0 ? d_f / amp_f : d_f, "-",
                  "max hinge-force difference / max hinge force", "Force: classical vs augmented");
    res.addScalar("constraint_drift_max", second.max_position_drift, "m",
                  "max |C| of the augmented run (RK4: before projection; Newmark: after the Newton-Raphson loop)", "max constraint drift");
    res.addScalar("constraint_velocity_drift_max", second.max_velocity_drift, "m/s", "max |C_q dq/dt| of the augmented run", "max constraint velocity drift");
    if (base.newmark) {
      res.addScalar("newmark_stability_step", second.stability_step, "s", "Stability limit 2/omega_max of explicit Newmark", "Newmark stability step");
      res.addScalar("newmark_max_velocity_iterations", second.max_velocity_iterations, "-",
                    "Most velocity fixed-point iterations in one Newmark step", "Newmark max velocity iterations");
    }
    res.stats.method += "; " + second.method;
    res.stats.steps += second.steps;
    res.stats.rhs_evaluations += second.rhs_evaluations;
    res.addScalar("error_estimate_augmented", second.error_estimate, "rad",
                  "Sum of local-error estimates of theta, augmented run (RK4 embedded pair or Newmark h²/6 |d²θ/dt²|)", "Error estimate, augmented");
  } else {
    res.tables.push_back(historyTable(main, nullptr, theta0, main.time.size()));
  }
  for (std::size_t i = 0; i < nf; ++i) {
    const auto& h = main.floats[i];
    const std::string n = std::to_string(i + 1);
    double amp = 0.0, fx = 0.0, fz = 0.0;
    for (std::size_t k = 0; k < h.theta.size(); ++k) {
      amp = std::max(amp, std::abs(h.theta[k] - theta0[i]));
      fx = std::max(fx, std::abs(h.hinge_fx[k]));
      fz = std::max(fz, std::abs(h.hinge_fz[k]));
    }
    res.addScalar("max_pitch_" + n, amp * 180.0 / std::numbers::pi, "deg", "max |theta - theta0|", "max pitch, float " + n);
    res.addScalar("max_hinge_fx_" + n, fx, "N", "max |horizontal hinge reaction|", "max |F_x|, float " + n);
    res.addScalar("max_hinge_fz_" + n, fz, "N", "max |vertical hinge reaction|", "max |F_z|, float " + n);
    res.addScalar("pto_energy_" + n, h.pto_energy.back(), "J", "PTO energy absorbed over the run", "PTO energy, float " + n);
    const double t_mean = std::max(0.0, main.time.back() - p.ramp_duration);
    if (t_mean > 0.0) {
      std::size_t k0 = 0;
      while (main.time[k0] < p.ramp_duration) ++k0;
      res.addScalar("mean_pto_power_" + n, (h.pto_energy.back() - h.pto_energy[k0]) / (main.time.back() - main.time[k0]),
                    "W", "Mean PTO power after the ramp", "mean PTO power, float " + n);
    }
  }
  if (p.wave_type == "irregular") addIrregularStatistics(p, model, main, res);
  res.tables.push_back(live.kernel);
  res.plots = live.plots;
  ctx.progress(0.95, "3D view");
  res.view = wecView(model, waves, main, p.animation_frames);
  ctx.progress(1.0, "done");
  return res;
}

}  // namespace

SceneDefinition makeWecScene() {
  SceneDefinition scene = makeScene<WecParameters>(
      "wec", "Hinged-float wave energy converter",
      "Hemispherical floats on rigid arms hinged to a fixed jacket, pitching about the hinge with a linear "
      "PTO damper (Heo & Koo, Wavestar-type). Hulme hemisphere coefficients (deep water) or WAMIT files, "
      "Haskind excitation, Cummins radiation memory (state-space fit or direct convolution), classical and "
      "augmented (Lagrange-multiplier) time-domain formulations, frequency-domain RAOs, hinge reactions, "
      "PTO power and capture width.",
      wecBinder(), checkWecParameters, solveWec);
  scene.upgrade = upgradeWecParameters;
  setWorkEstimate<WecParameters>(scene, wecBinder(), estimateWecWork);
  setPlausibility<WecParameters>(scene, wecBinder(), wecPlausibility);
  // The plot list's headings (the names are those of wecPlots, powerMatrixPlot and responseSpectraPlot in
  // wec_results.cpp; ui.labels checks that every plot of every built-in scenario is in exactly one group).
  scene.plot_groups = {
      {"Response per unit wave amplitude (frequency domain)",
       {"pitch_rao", "pitch_rao_phase", "hinge_fx", "hinge_fz", "capture_width", "optimal_pto_damping"}},
      {"Over time (time domain)",
       {"wave_elevation", "pitch_history", "hinge_fx_history", "hinge_fz_history", "moment_history", "pto_power_history"}},
      {"Irregular seas: reaction spectra and power", {"hinge_reaction_spectra", "power_matrix"}},
      {"Hydrodynamic coefficients of float 1", {"radiation_kernel", "hydro_damping", "hydro_added_mass"}},
  };
  return scene;
}

}  // namespace maris
