#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/text_format.hpp"
#include "ship/ship_wave_field.hpp"
#include "ship/ship_study.hpp"

namespace maris::ship {

namespace {

// Index of the sweep point closest to the design Froude number.
std::size_t designIndex(const ResistanceCurves& c, double design_froude) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < c.froude.size(); ++i)
    if (std::abs(c.froude[i] - design_froude) < std::abs(c.froude[best] - design_froude)) best = i;
  return best;
}

void addParticulars(Results& r, const ShipModel& m) {
  const HullParticulars& q = m.particulars;
  r.addScalar("length_pp", q.length_pp, "m", "Length between perpendiculars Lpp", "L_pp");
  r.addScalar("length_wl", q.length_wl, "m", "Waterline length", "L_WL");
  r.addScalar("beam_wl", q.beam_wl, "m", "Waterline beam", "B_WL");
  r.addScalar("draft", q.draft, "m", "Moulded draft T (deepest keel point in the middle half of Lpp)", "Draft T");
  r.addScalar("max_depth", q.max_depth, "m", "Deepest point of the hull below the waterline (domes, keels)", "Maximum depth");
  r.addScalar("displacement_volume", q.volume, "m^3", "Displacement volume", "Displacement ∇");
  r.addScalar("displacement_mass", q.volume * m.water.density, "kg", "Displacement mass", "Displacement Δ");
  r.addScalar("wetted_surface_geometry", q.wetted_surface, "m^2", "Wetted surface computed from the grid", "Wetted surface S (grid)");
  r.addScalar("wetted_surface", m.wetted_surface, "m^2", "Wetted surface used for the coefficients", "Wetted surface S");
  r.addScalar("waterplane_area", q.waterplane_area, "m^2", "Waterplane area", "Waterplane area A_WP");
  r.addScalar("block_coefficient", q.block_coefficient, "-", "C_B = volume/(Lpp B T)", "C_B");
  r.addScalar("prismatic_coefficient", q.prismatic_coefficient, "-", "C_P = volume/(A_M Lpp)", "C_P");
  r.addScalar("midship_coefficient", q.midship_coefficient, "-", "C_M = A_M/(B T), A_M the largest section", "C_M");
  r.addScalar("waterplane_coefficient", q.waterplane_coefficient, "-", "C_WP = A_WP/(Lpp B)", "C_WP");
  r.addScalar("lcb", q.lcb_percent, "%", "LCB forward of midship, % of Lpp", "LCB");
  r.addScalar("form_factor", m.form_factor, "-", "Form factor 1+k used for C_T", "Form factor 1+k");
  r.addScalar("holtrop_form_factor", holtropFormFactor(m.holtrop_hull, m.holtrop_edition), "-",
              "Holtrop's regression 1+k1", "Holtrop 1+k");
  if (m.prohaska) {
    r.addScalar("prohaska_points", m.prohaska->points, "-", "Measured points in Prohaska's fit", "Prohaska points");
    r.addScalar("prohaska_slope", m.prohaska->slope, "-", "Slope c of C_T/C_F = (1+k) + c Fn^4/C_F", "Prohaska slope c");
    r.addScalar("prohaska_rms_residual", m.prohaska->rms_residual, "-", "RMS residual of C_T/C_F about the fit", "Prohaska RMS residual");
  }
  r.addScalar("water_density", m.water.density, "kg/m^3", "Water density", "ρ");
  r.addScalar("kinematic_viscosity", m.water.kinematic_viscosity, "m^2/s", "Kinematic viscosity", "ν");
  if (m.fore_shoulder.distance > 0) {
    r.addScalar("fore_shoulder_ratio", m.fore_shoulder.arc_length / m.fore_shoulder.distance, "-",
                "s_FS/l_FS: waterline arc over distance from FP to the fore shoulder", "Fore shoulder arc/chord");
    r.addScalar("fore_shoulder_distance", m.fore_shoulder.distance, "m", "l_FS: fore shoulder aft of the FP", "l_FS");
  }
  r.addScalar("wave_number_factor", m.wave_number_factor, "-", "k0_hat/k0 applied by the wave-number correction", "k̂₀/k₀");
}

// The hull as two Surface shapes (port and starboard), sampled coarser than the Michell grid.
Shape3D hullSurface(const HullForm& hull, double side) {
  const HullGrid g = sampleHull(hull, 81, 21);
  Shape3D s;
  s.kind = Shape3D::Kind::Surface;
  s.name = side > 0 ? "hull (starboard)" : "hull (port)";
  s.grid_u = g.nx();
  s.grid_v = g.nz();
  for (int j = 0; j < g.nz(); ++j)
    for (int i = 0; i < g.nx(); ++i) s.points.emplace_back(g.x(i), side * g.half_breadth(i, j), g.z(j));
  s.color = {0.75, 0.3, 0.2};
  return s;
}

// The hull, both sides.
Frame3D hullFrame(const HullForm& hull) {
  Frame3D frame;
  frame.shapes.push_back(hullSurface(hull, 1.0));
  frame.shapes.push_back(hullSurface(hull, -1.0));
  return frame;
}

PlotSpec waveSpectrumPlot(bool corrected) {
  return makePlot("wave_spectrum", "Wave-angle spectrum of R_W", "wave_spectrum", "theta_deg",
                  corrected ? std::vector<std::string>{"dr_dtheta", "dr_dtheta_corrected"}
                            : std::vector<std::string>{"dr_dtheta"});
}

PlotSpec boundaryLayerPlot() {
  return makePlot("boundary_layer", "Boundary layer on the waterline at 0.2 T", "boundary_layer", "x",
                  {"half_breadth", "corrected_half_breadth", "displacement_thickness"});
}

// The resistance-curve table of the rows in `c`, the measured points and the curve plots, followed by the specs of
// the design-speed plots (their tables come with the final results). Row i depends on row i of `c` only, so a
// partial sweep's rows equal the finished sweep's bit for bit.
void addResistanceCurves(Results& r, const ShipParameters& p, const ShipModel& m, const ResistanceCurves& c,
                         const MeasuredPoints* measured) {
  const std::size_t n = c.froude.size();
  const double S = m.wetted_surface, rho = m.water.density;
  auto q = [&](std::size_t i) { return 0.5 * rho * c.speed[i] * c.speed[i] * S; };
  const bool corrected = !c.corrected.empty(), exact = !c.exact.empty();
  // Resistance curve table.
  Table t;
  t.name = "resistance_curve";
  t.title = "Resistance curves: " + m.hull.name;
  std::vector<double> cw, cw_err, cwc, cwe, ct, ctc, cth, cwh, rw, rt, rtc, rth;
  for (std::size_t i = 0; i < n; ++i) {
    const double viscous = m.form_factor * c.c_friction[i] + p.correlation_allowance;
    cw.push_back(c.michell[i].resistance / q(i));
    cw_err.push_back(c.michell[i].error_estimate / q(i));
    ct.push_back(cw.back() + viscous);
    rw.push_back(c.michell[i].resistance);
    rt.push_back(ct.back() * q(i));
    if (corrected) {
      cwc.push_back(c.corrected[i].resistance / q(i));
      ctc.push_back(cwc.back() + viscous);
      rtc.push_back(ctc.back() * q(i));
    }
    if (exact) cwe.push_back(c.exact[i].resistance / q(i));
    cwh.push_back(c.holtrop[i].wave / q(i));
    rth.push_back(c.holtrop[i].total);
    cth.push_back(rth.back() / q(i));
  }
  t.add("froude", "-", c.froude, "Fn");
  t.add("speed", "m/s", c.speed, "Model speed U");
  t.add("c_wave", "-", cw, "C_W Michell");
  t.add("c_wave_error", "-", cw_err, "C_W error estimate");
  if (corrected) t.add("c_wave_corrected", "-", cwc, "C_W corrected");
  if (exact) t.add("c_wave_exact", "-", cwe, "C_W exact Kochin");
  t.add("c_wave_holtrop", "-", cwh, "C_W Holtrop-Mennen");
  t.add("c_friction", "-", c.c_friction, "C_F ITTC-57");
  t.add("c_total", "-", ct, "C_T Michell");
  if (corrected) t.add("c_total_corrected", "-", ctc, "C_T corrected");
  t.add("c_total_holtrop", "-", cth, "C_T Holtrop-Mennen");
  t.add("r_wave", "N", rw, "R_W Michell");
  t.add("r_total", "N", rt, "R_T Michell");
  if (corrected) t.add("r_total_corrected", "N", rtc, "R_T corrected");
  t.add("r_total_holtrop", "N", rth, "R_T Holtrop-Mennen");
  // Full scale at equal Fn: C_TS = C_W + (1+k) C_F(Re_S) + C_A in sea water, S_S = S (L_S/L)².
  const bool full_scale = p.ship_length > 0;
  if (full_scale) {
    const double ratio = p.ship_length / m.hull.length_pp;
    const WaterProperties sea = waterProperties(WaterKind::Sea, p.ship_water_temperature);
    std::vector<double> us, cfs, cts, rts;
    for (std::size_t i = 0; i < n; ++i) {
      us.push_back(c.speed[i] * std::sqrt(ratio));
      cfs.push_back(ittc57FrictionCoefficient(us.back() * m.particulars.length_wl * ratio / sea.kinematic_viscosity));
      cts.push_back(cw[i] + m.form_factor * cfs.back() + p.correlation_allowance);
      rts.push_back(cts.back() * 0.5 * sea.density * us.back() * us.back() * S * ratio * ratio);
    }
    t.add("ship_speed", "m/s", us, "Ship speed U_S");
    t.add("c_friction_ship", "-", cfs, "C_F ship");
    t.add("c_total_ship", "-", cts, "C_T ship");
    t.add("r_total_ship", "N", rts, "R_T ship");
  }
  r.tables.push_back(std::move(t));

  // Plots.
  std::vector<std::string> cw_cols{"c_wave"}, ct_cols{"c_total"}, rt_cols{"r_total"};
  if (corrected) {
    cw_cols.push_back("c_wave_corrected");
    ct_cols.push_back("c_total_corrected");
    rt_cols.push_back("r_total_corrected");
  }
  cw_cols.push_back("c_wave_holtrop");
  ct_cols.push_back("c_total_holtrop");
  rt_cols.push_back("r_total_holtrop");
  r.plots.push_back(makePlot("wave_resistance_coefficient", "Wave resistance coefficient C_W", "resistance_curve", "froude", cw_cols));
  PlotSpec ct_plot = makePlot("total_resistance_coefficient", "Total resistance coefficient C_T", "resistance_curve", "froude", ct_cols);
  if (measured) {
    const MeasuredPoints& mp = *measured;
    Table mt;
    mt.name = "measured";
    mt.title = "Measured points";  // the legend's words; the file is named in the scenario
    mt.add("froude", "-", mp.froude, "Fn");
    mt.add("c_total", "-", mp.c_total, "C_T measured");
    r.tables.push_back(std::move(mt));
    ct_plot.reference_table = "measured";
    ct_plot.reference_y = {"c_total"};
  }
  r.plots.push_back(ct_plot);
  r.plots.push_back(makePlot("friction_coefficient", "ITTC-57 friction coefficient C_F", "resistance_curve", "froude", {"c_friction"}));
  r.plots.push_back(makePlot("total_resistance", "Total resistance R_T", "resistance_curve", "speed", rt_cols));
  if (full_scale)
    r.plots.push_back(makePlot("ship_total_resistance", "Full-scale total resistance (uncorrected Michell)",
                               "resistance_curve", "ship_speed", {"r_total_ship"}));

  r.plots.push_back(waveSpectrumPlot(corrected));
  if (m.tangency) r.plots.push_back(boundaryLayerPlot());
}

}  // namespace

Results buildShipResults(const ShipParameters& p, const ShipModel& m, const ResistanceCurves& c, RunContext& context) {
  Results r;
  const std::size_t n = c.froude.size();
  const double rho = m.water.density;
  const bool corrected = !c.corrected.empty();
  const MeasuredPoints measured = p.measured_file.empty() ? MeasuredPoints{} : readMeasuredPoints(p.measured_file);
  addResistanceCurves(r, p, m, c, p.measured_file.empty() ? nullptr : &measured);
  const Table& t = *r.findTable("resistance_curve");
  auto at = [&](const char* column, std::size_t i) { return t.find(column)->values[i]; };

  // Design speed: scalars and the wave-angle spectrum.
  const std::size_t d = designIndex(c, p.design_froude);
  addParticulars(r, m);
  r.addScalar("design_froude", c.froude[d], "-", "Froude number of the design-speed results", "Design Fn");
  r.addScalar("design_speed", c.speed[d], "m/s", "Speed at the design Froude number", "Design speed U");
  r.addScalar("c_wave", at("c_wave", d), "-", "Michell wave resistance coefficient at the design speed", "C_W");
  r.addScalar("c_wave_error", at("c_wave_error", d), "-", "Error estimate of c_wave (quadrature + tail + grid)", "C_W error estimate");
  if (corrected) r.addScalar("c_wave_corrected", at("c_wave_corrected", d), "-", "Corrected wave resistance coefficient", "C_W corrected");
  r.addScalar("c_friction", c.c_friction[d], "-", "ITTC-57 friction coefficient at the design speed", "C_F");
  r.addScalar("c_total", at("c_total", d), "-", "C_T = C_W + (1+k) C_F + C_A (uncorrected Michell)", "C_T");
  r.addScalar("r_total", at("r_total", d), "N", "Total resistance at the design speed (uncorrected Michell)", "R_T");
  r.addScalar("r_total_holtrop", at("r_total_holtrop", d), "N", "Holtrop-Mennen total resistance at the design speed", "R_T Holtrop-Mennen");
  context.progress(0.95, "wave spectrum");
  {
    std::vector<double> theta, theta_deg;
    for (int k = 0; k < 400; ++k) {
      theta.push_back(0.5 * std::numbers::pi * k / 400.0 * 0.98);
      theta_deg.push_back(theta.back() * 180.0 / std::numbers::pi);
    }
    GridKochin kochin(m.grid, false);
    Table s;
    s.name = "wave_spectrum";
    s.title = "Wave-angle spectrum dR_W/dθ at Fn = " + numberText(c.froude[d]);
    s.add("theta_deg", "deg", theta_deg, "Wave angle θ");
    s.add("dr_dtheta", "N/rad", waveSpectrum(kochin, c.speed[d], p.gravity, rho, michellSettings(p, m, false), theta),
          "dR_W/dθ Michell");
    if (corrected) {
      auto corrected_kochin = correctedKochin(m);
      s.add("dr_dtheta_corrected", "N/rad",
            waveSpectrum(*corrected_kochin, c.speed[d], p.gravity, rho, michellSettings(p, m, true), theta),
            "dR_W/dθ corrected");
    }
    r.tables.push_back(std::move(s));
  }

  // Boundary layer at the design speed on the waterline nearest 0.2 T (the depth of the paper's Fig. 4).
  if (m.tangency) {
    const int j = static_cast<int>(std::lround(0.2 * (m.grid.nz() - 1)));
    const HullGrid corrected_grid = m.tangency->correctedGrid(c.speed[d], m.water.kinematic_viscosity);
    const auto dstar = m.tangency->displacementThickness(j, c.speed[d], m.water.kinematic_viscosity);
    Table b;
    b.name = "boundary_layer";
    b.title = "Displacement thickness at z = " + numberText(m.grid.z(j)) + " m, Fn = " + numberText(c.froude[d]);
    std::vector<double> x, y, ye;
    for (int i = 0; i < m.grid.nx(); ++i) {
      x.push_back(m.grid.x(i));
      y.push_back(m.grid.half_breadth(i, j));
      ye.push_back(corrected_grid.half_breadth(i, j));
    }
    b.add("x", "m", x, "x");
    b.add("half_breadth", "m", y, "Half-breadth y");
    b.add("displacement_thickness", "m", dstar, "Displacement thickness δ*");
    b.add("corrected_half_breadth", "m", ye, "Half-breadth y + δ*");
    r.tables.push_back(std::move(b));
  }

  // 3-D view: the hull, both sides, with the still waterline.
  Frame3D frame = hullFrame(m.hull);
  if (context.wantsView()) {
    // The free surface around and behind the hull at the design speed: the complete linear thin-ship elevation
    // (ship_wave_field.hpp), i.e. the Kelvin waves and the local disturbance at the hull (the bow's pile-up, the
    // draw-down along the sides, the rise at the stern), drawn exaggerated (a 5 cm wave beside a 100 m hull would
    // be flat); the caption names the speed, the exaggeration and what the model leaves out.
    constexpr double kElevationScale = 10.0;
    context.progress(0.97, "free surface");
    const double L = m.hull.length_pp;
    const double x_fore = m.grid.x(m.grid.nx() - 1);
    const WaveFieldRegion region{.x_from = m.grid.x_aft - 2.0 * L, .x_to = x_fore + 0.25 * L, .half_width = 0.8 * L,
                                 .nx = 131, .ny = 41};
    const WavePattern w = thinShipWaveField(m.grid, c.speed[d], p.gravity, region, true,
                                            [&context] { return context.cancelRequested(); })
                              .pattern;
    context.throwIfCancelled();
    Shape3D s;
    s.kind = Shape3D::Kind::Surface;
    s.name = formatText("Free surface (elevation x%g)", kElevationScale);
    s.grid_u = static_cast<int>(w.y.size());
    s.grid_v = static_cast<int>(w.x.size());
    for (Eigen::Index i = 0; i < w.x.size(); ++i)
      for (Eigen::Index j = 0; j < w.y.size(); ++j) {
        s.points.emplace_back(w.x[i], w.y[j], kElevationScale * w.elevation(i, j));
        s.scalars.push_back(w.elevation(i, j));
      }
    s.color = {0.2, 0.4, 0.8};
    s.opacity = 0.75;  // the hull, below the waterline and inside the surface now, shows through the water
    frame.shapes.push_back(std::move(s));
    frame.label = formatText("Free surface at Fn = %.4g, U = %.4g m/s\n"
                             "linear thin-ship elevation: Kelvin waves and the local\n"
                             "bow pile-up, side draw-down and stern rise\n"
                             "elevation drawn × %g; hull at its real proportions\n"
                             "approximate: linear theory, thin ship,\nno viscous or wave-breaking effects",
                             c.froude[d], c.speed[d], kElevationScale);
    r.view.scalar_name = "free-surface elevation";
    r.view.scalar_unit = "m";
  }
  r.view.frames.push_back(std::move(frame));
  r.view.water_level_z = 0.0;

  // Solver statistics: the largest relative error estimate over the sweep.
  double worst = 0;
  long evaluations = 0;
  for (std::size_t i = 0; i < n; ++i) {
    worst = std::max(worst, c.michell[i].error_estimate / c.michell[i].resistance);
    evaluations += c.michell[i].evaluations;
    if (!c.michell[i].converged)
      context.warn("Fn = " + numberText(c.froude[i]) + ": the wave-angle quadrature stopped before the tolerance");
  }
  r.stats.steps = static_cast<long>(n);
  r.stats.rhs_evaluations = evaluations;
  r.stats.error_estimate = worst;
  r.stats.error_unit = "relative (largest over the sweep, uncorrected C_W)";
  r.stats.method = "Michell: exp-fitted trapezoid (z) x Filon-Simpson (x) on " + std::to_string(p.stations) + "x" +
                   std::to_string(p.waterlines) + ", adaptive Gauss-Kronrod 7/15 in lambda = cosh u, rtol " +
                   numberText(p.relative_tolerance);
  for (const auto& note : m.notes) context.warn(note);
  return r;
}

PartialShipResults::PartialShipResults(const ShipParameters& p, const ShipModel& m) : p_(p), m_(m) {
  if (!p.measured_file.empty()) measured_ = readMeasuredPoints(p.measured_file);
  addParticulars(fixed_, m);
  fixed_.view.frames.push_back(hullFrame(m.hull));
  fixed_.view.water_level_z = 0.0;
}

std::shared_ptr<const Results> PartialShipResults::build(const ResistanceCurves& rows_so_far) const {
  auto r = std::make_shared<Results>();
  addResistanceCurves(*r, p_, m_, rows_so_far, p_.measured_file.empty() ? nullptr : &measured_);
  r->scalars = fixed_.scalars;
  r->view = fixed_.view;
  r->stats.steps = static_cast<long>(rows_so_far.froude.size());
  r->stats.method = "Michell sweep running: " + std::to_string(rows_so_far.froude.size()) + " of " +
                    std::to_string(p_.froude_count) + " speeds finished";
  return r;
}

}  // namespace maris::ship
