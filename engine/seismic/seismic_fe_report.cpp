// Post-processing of the FE runs (paper eqs 29–31): peak ratios R along the reef flat, Fourier
// spectral ratios H_a, the seawater deviation δ, histories, the angle sweep and wave-field frames.
// The reference motion is the surface of a homogeneous half-space under the same wave at vertical
// incidence: twice the incident displacement, velocity or acceleration (paper §4.1).
#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <numeric>

#include "core/errors.hpp"
#include "core/spectrum.hpp"
#include "core/text_format.hpp"
#include "seismic/seismic_outline.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

namespace {

double peak(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

double mean(const std::vector<double>& v) { return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

// The time column of c's records: one sample per step, t_k = k Δt.
std::vector<double> sampleTimes(const FeCase& c) {
  std::vector<double> t(c.incident.size());
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = k * c.time_step;
  return t;
}

}  // namespace

PeakRatios amplificationRatios(const FeCase& c) {
  const double dt = c.time_step;
  const auto v0 = timeRate(c.incident, dt), a0 = timeRate(v0, dt);
  const double ru = 2.0 * peak(c.incident), rv = 2.0 * peak(v0), ra = 2.0 * peak(a0);
  // A run that ends before the incident wave reaches the seabed origin has no reference motion: every ratio
  // would be 0/0. That is a duration too short for the model, not a solver failure.
  if (!(ru > 0.0 && rv > 0.0 && ra > 0.0))
    throw InputError("solver.duration", formatText("%.4g", static_cast<double>(c.steps) * dt) + " s",
                     "ends before the incident wave reaches the seabed origin at incidence " +
                         formatText("%.4g", c.angle_deg) +
                         " deg, so there is no reference motion for the peak ratios: simulate longer");
  PeakRatios r;
  for (std::size_t s = 0; s < c.ux.size(); ++s) {
    const auto vx = timeRate(c.ux[s], dt), vy = timeRate(c.uy[s], dt);
    r.ux.push_back(peak(c.ux[s]) / ru);
    r.uy.push_back(peak(c.uy[s]) / ru);
    r.vx.push_back(peak(vx) / rv);
    r.vy.push_back(peak(vy) / rv);
    r.ax.push_back(peak(timeRate(vx, dt)) / ra);
    r.ay.push_back(peak(timeRate(vy, dt)) / ra);
    // The water's effect δ divides by these ratios: a station the wave has not reached is the same short
    // duration, not a result.
    if (!(r.ax.back() > 0.0))
      throw InputError("solver.duration", formatText("%.4g", static_cast<double>(c.steps) * dt) + " s",
                       "ends before the wave reaches the station at x = " + formatText("%.4g", c.station_x[s]) +
                           " m (incidence " + formatText("%.4g", c.angle_deg) + " deg): simulate longer");
  }
  return r;
}

void addFeResults(const SeismicParameters& p, const FeCase& c, const FeCase* dry, const std::vector<FeCase>& sweep,
                  Results& results) {
  const bool reef = p.model == "reef";
  const double dt = c.time_step;
  results.addScalar("element_size", c.element_size, "m", "Cell side Δ from Δ ≤ v_min/(10 f_cut)", "Cell side Δ");
  results.addScalar("cell_count", c.cell_count, "-", "Solid and water cells of the main model", "Cells");
  results.addScalar("time_step", dt, "s", "Central-difference step", "Time step Δt");
  results.addScalar("stable_step", c.stable_step, "s", "Element (Irons) bound on the stable step", "Stable step bound");
  results.stats.steps = c.steps;
  results.stats.method = "explicit central difference, lumped mass, dt = " + numberText(dt) + " s";

  // Amplification along the reef flat (paper eq 29).
  const PeakRatios r = amplificationRatios(c);
  Table amp{"amplification", reef ? "Peak ratios along the reef flat" : "Peak ratios along the seabed", {}};
  amp.add("x", "m", c.station_x, "x");
  std::vector<double> x_over_l;
  for (double x : c.station_x) x_over_l.push_back(x / (reef ? p.flat_width : 1.0));
  amp.add("x_over_L", "-", x_over_l, "x/L");
  amp.add("R_ux", "-", r.ux, "R_ux");
  amp.add("R_uy", "-", r.uy, "R_uy");
  amp.add("R_vx", "-", r.vx, "R_vx");
  amp.add("R_vy", "-", r.vy, "R_vy");
  amp.add("R_ax", "-", r.ax, "R_ax");
  amp.add("R_ay", "-", r.ay, "R_ay");
  results.addScalar("max_R_ax", peak(r.ax), "-", "Largest horizontal peak-acceleration ratio along the flat", "max R_ax");
  results.addScalar("max_R_ay", peak(r.ay), "-", "Largest vertical peak-acceleration ratio along the flat", "max R_ay");
  results.addScalar("mean_R_ax", mean(r.ax), "-", "Mean horizontal peak-acceleration ratio along the flat", "mean R_ax");
  results.addScalar("mean_R_ay", mean(r.ay), "-", "Mean vertical peak-acceleration ratio along the flat", "mean R_ay");
  std::vector<std::string> amp_y{"R_ax", "R_ay", "R_vx", "R_vy"};
  if (dry) {
    // Seawater deviation δ = (R_sloping platform − R_reef–seawater)/R_reef–seawater (paper eq 31).
    const PeakRatios d = amplificationRatios(*dry);
    std::vector<double> dx, dy;
    for (std::size_t s = 0; s < r.ax.size(); ++s) {
      dx.push_back((d.ax[s] - r.ax[s]) / r.ax[s]);
      dy.push_back((d.ay[s] - r.ay[s]) / r.ay[s]);
    }
    amp.add("R_ax_dry", "-", d.ax, "R_ax without water");
    amp.add("R_ay_dry", "-", d.ay, "R_ay without water");
    amp.add("delta_ax", "-", dx, "δ of R_ax");
    amp.add("delta_ay", "-", dy, "δ of R_ay");
    amp_y.insert(amp_y.end(), {"R_ax_dry", "R_ay_dry"});
    results.addScalar("water_deviation_mean_ax", (mean(d.ax) - mean(r.ax)) / mean(r.ax), "-",
                      "δ of the mean horizontal R_a: (dry − wet)/wet (paper eq 31)", "Water effect on mean R_ax");
    results.addScalar("water_deviation_mean_ay", (mean(d.ay) - mean(r.ay)) / mean(r.ay), "-",
                      "δ of the mean vertical R_a: (dry − wet)/wet (paper eq 31)", "Water effect on mean R_ay");
    double worst = 0.0;
    for (std::size_t s = 0; s < dx.size(); ++s) worst = std::max({worst, std::abs(dx[s]), std::abs(dy[s])});
    results.addScalar("water_deviation_max", worst, "-", "Largest pointwise |δ| of R_a along the flat", "max |δ| water effect");
  }
  results.tables.push_back(std::move(amp));
  results.plots.push_back({"amplification", "Peak ratios R along the flat", "amplification", "x_over_L", amp_y, false,
                           false, "", {}});

  addStationHistories(c, results);
  const std::size_t last = c.ux.size() - 1, mid = last / 2;

  // Fourier spectral ratios H_a = |A(f)| / (2|A_0(f)|) (paper eq 30), up to f_cut where the input has energy.
  const std::size_t n_fft = std::bit_ceil(c.incident.size());
  const auto a0 = fourierAmplitude(timeRate(timeRate(c.incident, dt), dt), dt, n_fft);
  const double a0_max = *std::max_element(a0.begin(), a0.end());
  Table spec{"spectral_ratio", "Acceleration Fourier spectral ratios H_a", {}};
  auto& f_col = spec.add("frequency", "Hz", {}, "Frequency f").values;
  std::vector<std::vector<double>> h(6);
  std::vector<std::vector<double>> s_ax(3), s_ay(3);
  const std::size_t which[3] = {0, mid, last};
  for (int w = 0; w < 3; ++w) {
    s_ax[w] = fourierAmplitude(timeRate(timeRate(c.ux[which[w]], dt), dt), dt, n_fft);
    s_ay[w] = fourierAmplitude(timeRate(timeRate(c.uy[which[w]], dt), dt), dt, n_fft);
  }
  for (std::size_t k = 1; k < a0.size(); ++k) {
    const double f = k / (n_fft * dt);
    if (f > p.cutoff_frequency) break;
    if (a0[k] < 1e-3 * a0_max) continue;
    f_col.push_back(f);
    for (int w = 0; w < 3; ++w) {
      h[w].push_back(s_ax[w][k] / (2.0 * a0[k]));
      h[3 + w].push_back(s_ay[w][k] / (2.0 * a0[k]));
    }
  }
  const char* names[6] = {"Hax_left", "Hax_centre", "Hax_right", "Hay_left", "Hay_centre", "Hay_right"};
  const char* labels[6] = {"H_ax, left edge", "H_ax, centre", "H_ax, right edge", "H_ay, left edge", "H_ay, centre",
                           "H_ay, right edge"};
  for (int w = 0; w < 6; ++w) spec.add(names[w], "-", h[w], labels[w]);
  results.tables.push_back(std::move(spec));
  results.plots.push_back({"spectral_ratio", "Acceleration spectral ratios", "spectral_ratio", "frequency",
                           {"Hax_left", "Hax_centre", "Hax_right", "Hay_centre"}, false, false, "", {}});

  // H_a along the flat: per station the largest ratio and its frequency, from the map (input band
  // above 5 % of its peak), and the map itself.
  {
    const SpectralRatioMap map = spectralRatioMap(c, p.cutoff_frequency, 0.05);
    std::vector<double> xl, hx_max, hx_f, hy_max, hy_f;
    for (std::size_t st = 0; st < c.ux.size(); ++st) {
      double bx = 0.0, fx = 0.0, by = 0.0, fy = 0.0;
      for (std::size_t k = 0; k < map.frequency.size(); ++k) {
        if (map.hx[st][k] > bx) bx = map.hx[st][k], fx = map.frequency[k];
        if (map.hy[st][k] > by) by = map.hy[st][k], fy = map.frequency[k];
      }
      xl.push_back(c.station_x[st] / (reef ? p.flat_width : 1.0));
      hx_max.push_back(bx);
      hx_f.push_back(fx);
      hy_max.push_back(by);
      hy_f.push_back(fy);
    }
    Table along{"spectral_ratio_along_flat", "Largest H_a per station and its frequency", {}};
    along.add("x_over_L", "-", xl, "x/L");
    along.add("Hax_max", "-", hx_max, "max H_ax");
    along.add("Hax_peak_frequency", "Hz", hx_f, "f at max H_ax");
    along.add("Hay_max", "-", hy_max, "max H_ay");
    along.add("Hay_peak_frequency", "Hz", hy_f, "f at max H_ay");
    results.addScalar("max_H_ax", peak(hx_max), "-", "Largest horizontal spectral ratio H_a,x along the flat", "max H_ax");
    results.addScalar("max_H_ay", peak(hy_max), "-", "Largest vertical spectral ratio H_a,y along the flat", "max H_ay");
    results.tables.push_back(std::move(along));
    results.plots.push_back({"spectral_ratio_along_flat", "Largest spectral ratio along the flat",
                             "spectral_ratio_along_flat", "x_over_L", {"Hax_max", "Hay_max"}, false, false, "", {}});
    addSpectralMap(p, c, results);
  }

  // Box: FE against the analytic free field at B (seabed) and A (water surface).
  if (!c.probe_fe_uy.empty()) {
    double worst = 0.0;
    auto compare = [&](const std::vector<double>& fe, const std::vector<double>& ff, const char* name, const char* what,
                       const char* label) {
      const double e = std::abs(peak(fe) - peak(ff)) / peak(ff);
      worst = std::max(worst, e);
      results.addScalar(name, e, "-", what, label);
    };
    compare(c.seabed_fe_ux, c.seabed_ff_ux, "peak_error_B_ux", "|peak FE − peak free field|/peak free field, B u_x",
            "Peak error of u_x at B");
    compare(c.seabed_fe_uy, c.seabed_ff_uy, "peak_error_B_uy", "|peak FE − peak free field|/peak free field, B u_y",
            "Peak error of u_y at B");
    compare(c.probe_fe_uy, c.probe_ff_uy, "peak_error_A_uy", "|peak FE − peak free field|/peak free field, A u_y",
            "Peak error of u_y at A");
    results.stats.error_estimate = worst;
    results.stats.error_unit = "relative peak error vs analytic free field";
    addVerificationHistories(c, results);
  }

  // Angle sweep (main angle included).
  if (!sweep.empty()) {
    Table s{"angle_sweep", "Reef-flat amplification against incidence angle", {}};
    // Columns are filled first and added last: Table::add may reallocate, so no references are kept.
    std::vector<double> ang, mx, my, ax, ay, ux, uy;
    std::vector<const FeCase*> all{&c};
    for (const auto& k : sweep) all.push_back(&k);
    std::sort(all.begin(), all.end(), [](auto* a, auto* b) { return a->angle_deg < b->angle_deg; });
    for (const FeCase* k : all) {
      const PeakRatios q = amplificationRatios(*k);
      ang.push_back(k->angle_deg);
      mx.push_back(peak(q.ax));
      my.push_back(peak(q.ay));
      ax.push_back(mean(q.ax));
      ay.push_back(mean(q.ay));
      ux.push_back(peak(q.ux));
      uy.push_back(peak(q.uy));
    }
    s.add("angle", "deg", ang, "Incidence angle");
    s.add("max_R_ax", "-", mx, "max R_ax");
    s.add("max_R_ay", "-", my, "max R_ay");
    s.add("mean_R_ax", "-", ax, "mean R_ax");
    s.add("mean_R_ay", "-", ay, "mean R_ay");
    s.add("max_R_ux", "-", ux, "max R_ux");
    s.add("max_R_uy", "-", uy, "max R_uy");
    results.tables.push_back(std::move(s));
    results.plots.push_back({"angle_sweep", "Amplification vs incidence angle", "angle_sweep", "angle",
                             {"max_R_ax", "max_R_ay", "mean_R_ax", "mean_R_ay"}, false, false, "", {}});
  }

  addWaveFieldFrames(p, c, results);
}

void addStationHistories(const FeCase& c, Results& results) {
  const std::size_t last = c.ux.size() - 1, mid = last / 2;
  Table hist{"station_histories", "Displacement at the flat's edges and centre", {}};
  hist.add("time", "s", sampleTimes(c), "Time");
  hist.add("incident", "m", c.incident, "Incident u₀");
  for (auto [name, s] : {std::pair{"left", std::size_t{0}}, std::pair{"centre", mid}, std::pair{"right", last}}) {
    hist.add(std::string("ux_") + name, "m", c.ux[s], std::string("u_x, ") + name);
    hist.add(std::string("uy_") + name, "m", c.uy[s], std::string("u_y, ") + name);
  }
  results.tables.push_back(std::move(hist));
  results.plots.push_back({"station_histories", "Displacement histories on the flat", "station_histories", "time",
                           {"incident", "ux_centre", "uy_centre", "ux_right", "uy_right"}, false, false, "", {}});
}

void addVerificationHistories(const FeCase& c, Results& results) {
  if (c.probe_fe_uy.empty()) return;
  Table v{"verification", "FE vs analytic free field at B (seabed) and A (water surface)", {}};
  v.add("time", "s", sampleTimes(c), "Time");
  v.add("fe_B_ux", "m", c.seabed_fe_ux, "FE u_x at B");
  v.add("free_B_ux", "m", c.seabed_ff_ux, "Free field u_x at B");
  v.add("fe_B_uy", "m", c.seabed_fe_uy, "FE u_y at B");
  v.add("free_B_uy", "m", c.seabed_ff_uy, "Free field u_y at B");
  v.add("fe_A_uy", "m", c.probe_fe_uy, "FE u_y at A");
  v.add("free_A_uy", "m", c.probe_ff_uy, "Free field u_y at A");
  results.tables.push_back(std::move(v));
  results.plots.push_back({"verification", "FE vs free field", "verification", "time",
                           {"fe_B_uy", "free_B_uy", "fe_A_uy", "free_A_uy"}, false, false, "", {}});
}

FrameStride frameStride(int nx, int ny) { return {std::max(1, (nx + 159) / 160), std::max(1, (ny + 79) / 80)}; }

// Wave-field frames: the x–y section drawn in the x–z plane, coloured by |u|, decimated to ≤ 160 × 80, with the
// reef's outline and layer interfaces over it.
void addWaveFieldFrames(const SeismicParameters& p, const FeCase& c, Results& results) {
  if (c.snapshot_magnitude.empty()) return;
  const auto [step_i, step_j] = frameStride(c.nx, c.ny);
  const int gu = c.nx / step_i + 1, gv = c.ny / step_j + 1;
  const double delta = c.element_size;
  for (std::size_t f = 0; f < c.snapshot_magnitude.size(); ++f) {
    Shape3D surf;
    surf.kind = Shape3D::Kind::Surface;
    surf.name = "displacement magnitude";
    surf.grid_u = gu;
    surf.grid_v = gv;
    for (int jj = 0; jj < gv; ++jj)
      for (int ii = 0; ii < gu; ++ii) {
        const int i = ii * step_i, j = jj * step_j;
        surf.points.emplace_back(c.x0 + i * delta, 0.0, c.y0 + j * delta);
        surf.scalars.push_back(c.snapshot_magnitude[f][j * (c.nx + 1) + i]);
      }
    std::vector<Shape3D> shapes{std::move(surf)};
    for (Shape3D& line : reefLayerOutlines(p)) shapes.push_back(std::move(line));
    results.view.frames.push_back({c.snapshot_time[f], std::move(shapes), {}});
  }
  results.view.scalar_name = "displacement magnitude";
  results.view.scalar_unit = "m";
  if (c.water) results.view.water_level_z = p.water_depth;
  results.view.seabed_z = 0.0;
}

void addDiscretisationEstimate(const FeCase& main, const FeCase& coarse, Results& results) {
  const PeakRatios fine = amplificationRatios(main), rough = amplificationRatios(coarse);
  const double change_x = std::abs(peak(rough.ax) / peak(fine.ax) - 1.0);
  const double change_y = std::abs(peak(rough.ay) / peak(fine.ay) - 1.0);
  results.addScalar("coarse_element_size", coarse.element_size, "m", "Cell side of the error-estimate companion mesh", "Coarse cell side");
  results.addScalar("mesh_change_max_R_ax", change_x, "-",
                    "Relative change of the largest R_a,x on the flat, main vs companion mesh", "Mesh change of max R_ax");
  results.addScalar("mesh_change_max_R_ay", change_y, "-",
                    "Relative change of the largest R_a,y on the flat, main vs companion mesh", "Mesh change of max R_ay");
  results.stats.error_estimate = std::max(change_x, change_y);
  results.stats.error_unit = "relative change of the largest R_a on the flat between Δ = " +
                             numberText(main.element_size) + " m and " + numberText(coarse.element_size) + " m";
}

}  // namespace maris::seismic
