#include "wec/wec_results.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/text_format.hpp"

namespace maris::wec {

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
std::string col(const std::string& name, std::size_t i) { return name + "_" + std::to_string(i + 1); }
// The label of float i's column: "|θ|/A, float 1".
std::string lab(const std::string& what, std::size_t i) { return what + ", float " + std::to_string(i + 1); }
}  // namespace

Table frequencyTable(const std::vector<double>& omega, const std::vector<std::vector<FrequencyResponse>>& response) {
  Table t;
  t.name = "frequency_response";
  t.title = "Frequency-domain response per unit wave amplitude";
  t.add("omega", "rad/s", omega, "ω");
  for (std::size_t i = 0; i < response.size(); ++i) {
    std::vector<double> rao, phase, fx, fz, my, power, cw, bound, opt;
    for (const auto& r : response[i]) {
      rao.push_back(std::abs(r.pitch));
      phase.push_back(std::arg(r.pitch) * kDeg);
      fx.push_back(std::abs(r.hinge_fx));
      fz.push_back(std::abs(r.hinge_fz));
      my.push_back(std::abs(r.moment_y));
      power.push_back(r.power);
      cw.push_back(r.capture_width);
      bound.push_back(r.capture_width_bound);
      opt.push_back(r.optimal_damping);
    }
    t.add(col("rao", i), "rad/m", rao, lab("|θ|/A", i));
    t.add(col("rao_phase", i), "deg", phase, lab("Phase of θ", i));
    t.add(col("hinge_fx", i), "N/m", fx, lab("|F_x|/A", i));
    t.add(col("hinge_fz", i), "N/m", fz, lab("|F_z|/A", i));
    t.add(col("moment_y", i), "N*m/m", my, lab("|M_y|/A", i));
    t.add(col("power", i), "W/m^2", power, lab("P/A²", i));
    t.add(col("capture_width", i), "m", cw, lab("Capture width", i));
    if (i == 0) t.add("capture_width_bound", "m", bound, "Bound 3λ/2π");
    t.add(col("optimal_pto_damping", i), "N*m*s/rad", opt, lab("Optimal PTO damping", i));
  }
  return t;
}

Table timeDomainRaoTable(const std::vector<SteadyResponse>& points, std::size_t float_count) {
  Table t;
  t.name = "rao_time_domain";
  t.title = "Time-domain steady-state response (DFT over the last whole periods)";
  std::vector<double> omega;
  for (const auto& p : points) omega.push_back(p.omega);
  t.add("omega", "rad/s", omega, "ω");
  for (std::size_t i = 0; i < float_count; ++i) {
    std::vector<double> rao, phase, fx, fz, power;
    for (const auto& p : points) {
      rao.push_back(std::abs(p.pitch[i]));
      phase.push_back(std::arg(p.pitch[i]) * kDeg);
      fx.push_back(std::abs(p.hinge_fx[i]));
      fz.push_back(std::abs(p.hinge_fz[i]));
    }
    t.add(col("rao", i), "rad/m", rao, lab("|θ|/A", i));
    t.add(col("rao_phase", i), "deg", phase, lab("Phase of θ", i));
    t.add(col("hinge_fx", i), "N/m", fx, lab("|F_x|/A", i));
    t.add(col("hinge_fz", i), "N/m", fz, lab("|F_z|/A", i));
  }
  return t;
}

void appendHistory(Table& table, const TimeDomainResult& td, const std::vector<double>& theta0,
                   const std::string& suffix, bool with_time) {
  if (with_time) {
    table.add("time", "s", td.time, "Time");
    table.add("wave_elevation", "m", td.wave_at_origin, "Wave elevation η");
  }
  for (std::size_t i = 0; i < td.floats.size(); ++i) {
    const auto& h = td.floats[i];
    std::vector<double> dtheta(h.theta.size());
    for (std::size_t k = 0; k < dtheta.size(); ++k) dtheta[k] = (h.theta[k] - theta0[i]) * kDeg;
    table.add(col("pitch_deg", i) + suffix, "deg", dtheta, lab("Pitch θ − θ₀", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("theta_dt", i) + suffix, "rad/s", h.theta_dt, lab("dθ/dt", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("theta_dtdt", i) + suffix, "rad/s^2", h.theta_dtdt, lab("d²θ/dt²", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("hinge_fx", i) + suffix, "N", h.hinge_fx, lab("Hinge F_x", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("hinge_fz", i) + suffix, "N", h.hinge_fz, lab("Hinge F_z", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("moment_y", i) + suffix, "N*m", h.moment_y, lab("Moment M_y", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("pto_power", i) + suffix, "W", h.pto_power, lab("PTO power", i) + (suffix.empty() ? "" : " (augmented)"));
    table.add(col("pto_energy", i) + suffix, "J", h.pto_energy, lab("PTO energy", i) + (suffix.empty() ? "" : " (augmented)"));
  }
}

Table historyTable(const TimeDomainResult& main, const TimeDomainResult* augmented, const std::vector<double>& theta0,
                   std::size_t rows) {
  Table t;
  t.name = "time_history";
  t.title = "Time histories (" + main.method + ")";
  appendHistory(t, main, theta0, "", true);
  if (augmented) appendHistory(t, *augmented, theta0, "_aug", false);
  // The first `rows` instants of every column (the partial and the final table hold the same numbers).
  for (Column& c : t.columns) c.values.resize(rows);
  return t;
}

Table kernelTable(const FloatModel& f) {
  Table t;
  t.name = "radiation_kernel";
  t.title = "Radiation impulse response K(t) and its state-space fit (float 1)";
  std::vector<double> time, ks, ksf, kh, khf;
  const auto& k = f.heave.kernel;
  const std::size_t stride = std::max<std::size_t>(1, k.values.size() / 400);
  for (std::size_t j = 0; j < k.values.size(); j += stride) {
    const double tj = k.dt * static_cast<double>(j);
    time.push_back(tj);
    ks.push_back(f.surge.kernel.at(tj));
    ksf.push_back(f.surge.fit.at(tj));
    kh.push_back(k.values[j]);
    khf.push_back(f.heave.fit.at(tj));
  }
  t.add("time", "s", time, "Time");
  t.add("kernel_surge", "N/m", ks, "K₁₁(t) surge");
  t.add("kernel_surge_fit", "N/m", ksf, "K₁₁ fit");
  t.add("kernel_heave", "N/m", kh, "K₃₃(t) heave");
  t.add("kernel_heave_fit", "N/m", khf, "K₃₃ fit");
  return t;
}

Table hydroTable(const WecModel& model, const std::vector<double>& omega) {
  Table t;
  t.name = "hydrodynamics";
  t.title = "Float 1 coefficients: " + model.floats.front().hydro->describe();
  std::vector<double> a11, b11, a33, b33, x1, x3, p1, p3;
  for (double w : omega) {
    const FloatHydro h = model.floats.front().hydro->at(w);
    a11.push_back(h.surge.added_mass);
    b11.push_back(h.surge.damping);
    a33.push_back(h.heave.added_mass);
    b33.push_back(h.heave.damping);
    x1.push_back(std::abs(h.surge.excitation));
    x3.push_back(std::abs(h.heave.excitation));
    p1.push_back(std::arg(h.surge.excitation) * kDeg);
    p3.push_back(std::arg(h.heave.excitation) * kDeg);
  }
  t.add("omega", "rad/s", omega, "ω");
  t.add("added_mass_surge", "kg", a11, "A₁₁ surge");
  t.add("damping_surge", "N*s/m", b11, "B₁₁ surge");
  t.add("added_mass_heave", "kg", a33, "A₃₃ heave");
  t.add("damping_heave", "N*s/m", b33, "B₃₃ heave");
  t.add("excitation_surge", "N/m", x1, "|X₁| surge");
  t.add("excitation_heave", "N/m", x3, "|X₃| heave");
  t.add("excitation_phase_surge", "deg", p1, "Phase of X₁");
  t.add("excitation_phase_heave", "deg", p3, "Phase of X₃");
  return t;
}

std::vector<PlotSpec> wecPlots(std::size_t n, bool have_td_points, bool have_augmented) {
  std::vector<PlotSpec> p;
  auto cols = [&](const std::string& name) {
    std::vector<std::string> c;
    for (std::size_t i = 0; i < n; ++i) c.push_back(col(name, i));
    return c;
  };
  auto fd = [&](std::string name, std::string title, std::string what) {
    PlotSpec s = makePlot(std::move(name), std::move(title), "frequency_response", "omega", cols(what));
    if (have_td_points) {
      s.reference_table = "rao_time_domain";
      s.reference_y = cols(what);
    }
    p.push_back(std::move(s));
  };
  fd("pitch_rao", "Pitch RAO (curve: frequency domain, markers: time domain)", "rao");
  fd("pitch_rao_phase", "Pitch RAO phase relative to the wave at x = 0", "rao_phase");
  fd("hinge_fx", "Horizontal hinge reaction per unit wave amplitude", "hinge_fx");
  fd("hinge_fz", "Vertical hinge reaction per unit wave amplitude", "hinge_fz");
  auto cw = cols("capture_width");
  cw.push_back("capture_width_bound");
  p.push_back(makePlot("capture_width", "Capture width and the point-absorber bound 3λ/2π", "frequency_response", "omega", cw));
  p.push_back(makePlot("optimal_pto_damping", "Optimal passive PTO damping", "frequency_response", "omega",
               cols("optimal_pto_damping")));
  auto hist = [&](std::string name, std::string title, std::string what) {
    auto c = cols(what);
    if (have_augmented)
      for (std::size_t i = 0; i < n; ++i) c.push_back(col(what, i) + "_aug");
    p.push_back(makePlot(std::move(name), std::move(title), "time_history", "time", c));
  };
  p.push_back(makePlot("wave_elevation", "Wave elevation at x = 0", "time_history", "time", {"wave_elevation"}));
  hist("pitch_history", "Pitch angle from equilibrium", "pitch_deg");
  hist("hinge_fx_history", "Horizontal hinge reaction", "hinge_fx");
  hist("hinge_fz_history", "Vertical hinge reaction", "hinge_fz");
  hist("moment_history", "Moment about the hinge (paper eq 8)", "moment_y");
  hist("pto_power_history", "PTO power", "pto_power");
  p.push_back(makePlot("radiation_kernel", "Radiation kernel K(t) and state-space fit", "radiation_kernel", "time",
               {"kernel_heave", "kernel_heave_fit", "kernel_surge", "kernel_surge_fit"}));
  p.push_back(makePlot("hydro_damping", "Radiation damping", "hydrodynamics", "omega", {"damping_surge", "damping_heave"}));
  p.push_back(makePlot("hydro_added_mass", "Added mass", "hydrodynamics", "omega", {"added_mass_surge", "added_mass_heave"}));
  return p;
}

std::string powerMatrixColumn(double hs) {
  std::string name = formatText("power_hs_%gm", hs);
  std::replace(name.begin(), name.end(), '.', 'p');
  return name;
}

PlotSpec powerMatrixPlot(const std::vector<double>& hs, const std::string& spectrum) {
  PlotSpec plot;
  plot.name = "power_matrix";
  plot.title = "Mean PTO power of all floats in irregular seas (" + spectrum + ")";
  plot.table = "power_matrix";
  plot.x = "peak_period";
  for (double h : hs) plot.y.push_back(powerMatrixColumn(h));
  return plot;
}

PlotSpec responseSpectraPlot(std::size_t float_count) {
  PlotSpec plot;
  plot.name = "hinge_reaction_spectra";
  plot.title = "Hinge reaction spectra S_F = |F_h/a|² S_η";
  plot.table = "response_spectra";
  plot.x = "omega";
  for (std::size_t i = 0; i < float_count; ++i) {
    plot.y.push_back(col("hinge_fx_spectrum", i));
    plot.y.push_back(col("hinge_fz_spectrum", i));
  }
  return plot;
}

View3D wecView(const WecModel& model, const IncidentWaves& waves, const TimeDomainResult& td, int frames) {
  View3D v;
  v.scalar_name = "wave elevation";
  v.scalar_unit = "m";
  v.water_level_z = 0.0;
  v.seabed_z = -model.depth;
  double x_lo = 1e300, x_hi = -1e300, r_max = 0.0;
  for (const auto& f : model.floats) {
    x_lo = std::min({x_lo, f.x_f0, f.hinge_x});
    x_hi = std::max({x_hi, f.x_f0, f.hinge_x});
    r_max = std::max(r_max, f.radius);
  }
  x_lo -= 4.0 * r_max + 10.0;
  x_hi += 4.0 * r_max + 10.0;
  const int nu = 48, nv = 10;
  const double y_half = 4.0 * r_max;
  const std::size_t samples = td.time.size();
  const int count = std::max(1, std::min<int>(frames, static_cast<int>(samples)));
  for (int fr = 0; fr < count; ++fr) {
    const std::size_t k = count == 1 ? samples - 1 : (samples - 1) * static_cast<std::size_t>(fr) / static_cast<std::size_t>(count - 1);
    Frame3D frame;
    frame.time = td.time[k];
    for (std::size_t i = 0; i < model.floats.size(); ++i) {
      const auto& f = model.floats[i];
      const double th = td.floats[i].theta[k], phi = th - f.theta0;
      const Eigen::Vector3d hinge(f.hinge_x, 0.0, f.hinge_z);
      const Eigen::Vector3d centre = hinge + f.arm_length * Eigen::Vector3d(std::cos(th), 0.0, std::sin(th));
      // Jacket leg from the sea bed to just above the hinge.
      Shape3D leg;
      leg.kind = Shape3D::Kind::Box;
      leg.name = "jacket leg " + std::to_string(i + 1);
      const double top = f.hinge_z + 1.0, bottom = -model.depth;
      leg.points = {Eigen::Vector3d(f.hinge_x, 0.0, 0.5 * (top + bottom))};
      leg.size = Eigen::Vector3d(1.0, 1.0, top - bottom);
      leg.color = {0.55, 0.55, 0.6};
      Shape3D pin;
      pin.kind = Shape3D::Kind::Sphere;
      pin.name = "hinge " + std::to_string(i + 1);
      pin.points = {hinge};
      pin.radius = 0.6;
      pin.color = {0.9, 0.3, 0.2};
      Shape3D arm;
      arm.kind = Shape3D::Kind::Tube;
      arm.name = "arm " + std::to_string(i + 1);
      arm.points = {hinge, centre};
      arm.radius = 0.3;
      arm.color = {0.3, 0.3, 0.35};
      Shape3D hull;
      hull.kind = Shape3D::Kind::Hemisphere;
      hull.name = "float " + std::to_string(i + 1);
      hull.points = {centre};
      hull.radius = f.radius;
      hull.direction = Eigen::Vector3d(std::sin(phi), 0.0, -std::cos(phi));
      hull.color = {0.95, 0.75, 0.2};
      for (auto* s : {&leg, &pin, &arm, &hull}) frame.shapes.push_back(std::move(*s));
    }
    Shape3D sea;
    sea.kind = Shape3D::Kind::Surface;
    sea.name = "free surface";
    sea.grid_u = nu;
    sea.grid_v = nv;
    sea.opacity = 0.5;
    // Long-crested waves along x: η depends on x only, so each column of the grid is evaluated once.
    std::vector<double> x(nu), eta(nu);
    for (int i = 0; i < nu; ++i) {
      x[i] = x_lo + (x_hi - x_lo) * i / (nu - 1);
      eta[i] = waves.elevation(x[i], frame.time);
    }
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const double y = -y_half + 2.0 * y_half * j / (nv - 1);
        sea.points.emplace_back(x[i], y, eta[i]);
        sea.scalars.push_back(eta[i]);
      }
    frame.shapes.push_back(std::move(sea));
    v.frames.push_back(std::move(frame));
  }
  return v;
}

}  // namespace maris::wec
