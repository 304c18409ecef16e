// Results of the detail point: histories, spectra, scalars and the animated 3D view.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fiv/fiv_results.hpp"
#include "fiv/fiv_theory.hpp"
#include "fiv/fiv_timeseries.hpp"

namespace maris::fiv {

namespace {

constexpr std::size_t kMaxHistoryRows = 5000;

// Rest depth of the cylinder centre: h below the surface, or 5 D in the deep case (drawn without surface).
double centreDepth(const FivModel& model, const OperatingPoint& op) {
  return std::isfinite(op.submergence_ratio) ? op.submergence_ratio * model.side : 5.0 * model.side;
}

// A coil spring from `bottom` up to `top` (z), drawn as a zigzag in the x–z plane at span position y.
Shape3D springShape(const std::string& name, double y, double bottom, double top, double width) {
  Shape3D s;
  s.kind = Shape3D::Kind::Polyline;
  s.name = name;
  constexpr int kinks = 16;
  s.points.emplace_back(0.0, y, bottom);
  for (int i = 1; i < kinks; ++i) {
    const double z = bottom + (top - bottom) * i / kinks;
    s.points.emplace_back((i % 2 ? 0.5 : -0.5) * width, y, z);
  }
  s.points.emplace_back(0.0, y, top);
  s.color = {0.85, 0.6, 0.1};
  return s;
}

}  // namespace

View3D buildCylinderView(const FivModel& model, const DetailPoint& detail, int frames) {
  View3D view;
  const History& h = detail.history;
  if (h.time.empty()) return view;
  const double depth = centreDepth(model, detail.point);
  const double d = model.side, span = model.length;
  const double anchor_z = -depth - 6.0 * d;
  if (std::isfinite(detail.point.submergence_ratio)) view.water_level_z = 0.0;
  // Animate the last two response periods (or the whole record if shorter).
  const double period = detail.cycle.frequency > 0.0 ? 1.0 / detail.cycle.frequency : h.time.back();
  const double t0 = std::max(0.0, h.time.back() - 2.0 * period);
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(h.time.begin(), h.time.end(), t0) - h.time.begin());
  const std::size_t count = h.time.size() - first;
  const int n_frames = std::max(1, std::min<int>(frames, static_cast<int>(count)));
  for (int f = 0; f < n_frames; ++f) {
    const std::size_t i = first + (n_frames == 1 ? 0 : (count - 1) * f / (n_frames - 1));
    const double zc = -depth + h.displacement[i];
    Frame3D frame;
    frame.time = h.time[i] - h.time[first];
    Shape3D body;
    body.kind = Shape3D::Kind::Box;
    body.name = "cylinder";
    body.points = {Eigen::Vector3d(0.0, 0.5 * span, zc)};
    body.size = {d, span, d};
    body.color = {0.55, 0.6, 0.65};
    frame.shapes.push_back(body);
    for (double y : {0.1 * span, 0.9 * span})
      frame.shapes.push_back(springShape(y < 0.5 * span ? "spring 1" : "spring 2", y, anchor_z, zc - 0.5 * d, 0.6 * d));
    Shape3D anchor;
    anchor.kind = Shape3D::Kind::Box;
    anchor.name = "anchor";
    anchor.points = {Eigen::Vector3d(0.0, 0.5 * span, anchor_z - 0.05 * d)};
    anchor.size = {2.0 * d, span, 0.1 * d};
    anchor.color = {0.3, 0.3, 0.3};
    frame.shapes.push_back(anchor);
    Shape3D current;
    current.kind = Shape3D::Kind::Polyline;
    current.name = "current";
    current.points = {{-8.0 * d, 0.5 * span, -depth}, {-3.0 * d, 0.5 * span, -depth},
                      {-3.6 * d, 0.5 * span, -depth + 0.4 * d}, {-3.0 * d, 0.5 * span, -depth},
                      {-3.6 * d, 0.5 * span, -depth - 0.4 * d}};
    current.color = {0.2, 0.4, 0.9};
    frame.shapes.push_back(current);
    view.frames.push_back(std::move(frame));
  }
  return view;
}

void addDetailResults(Results& results, const FivModel& model, const DetailPoint& detail, int animation_frames) {
  const OperatingPoint& op = detail.point;
  const LimitCycle& c = detail.cycle;
  const History& h = detail.history;
  const double fluid = sweptFluidPower(model.density, op.speed, model.length, model.side, c.amplitude);
  results.addScalar("detail_speed", op.speed, "m/s", "Current speed of the detail point", "U at the detail point");
  results.addScalar("detail_amplitude", c.amplitude, "m", "Limit-cycle amplitude A at the detail point", "A at the detail point");
  results.addScalar("detail_amplitude_ratio", c.amplitude / model.side, "-", "A/D at the detail point", "A/D at the detail point");
  results.addScalar("detail_frequency", c.frequency, "Hz", "Response frequency (zero up-crossings)", "f at the detail point");
  results.addScalar("detail_power", c.power_damper, "W", "⟨cẏ²⟩ at the detail point (paper eq 13)", "P at the detail point");
  results.addScalar("detail_power_fluid", c.power_fluid, "W", "⟨Fẏ⟩ at the detail point (paper eq 8)", "⟨F ẏ⟩ at the detail point");
  results.addScalar("detail_efficiency", betzEfficiency(c.power_damper, fluid), "-", "η at the detail point", "η at the detail point");
  results.addScalar("detail_residual", c.residual, "-", "Estimated relative error of A at the detail point", "Residual at the detail point");
  results.addScalar("detail_amplitude_spread", c.amplitude_spread, "m",
                    "Standard deviation of the per-cycle amplitude at the detail point (0 on a periodic cycle)",
                    "A spread at the detail point");
  results.addScalar("detail_response", static_cast<double>(static_cast<int>(c.response)), "-",
                    "Response at the detail point: 0 at rest, 1 periodic, 2 quasi-periodic (stationary), 3 drifting",
                    "Response at the detail point");
  if (h.time.empty()) return;
  // Histories, thinned to a plottable number of rows.
  const std::size_t stride = std::max<std::size_t>(1, h.time.size() / kMaxHistoryRows);
  Table t;
  t.name = "detail_history";
  t.title = "Time history at the detail point (after convergence)";
  std::vector<double> ct, cy, cv, cq, cf, cg, cw;
  for (std::size_t i = 0; i < h.time.size(); i += stride) {
    ct.push_back(h.time[i]);
    cy.push_back(h.displacement[i]);
    cv.push_back(h.velocity[i]);
    cq.push_back(h.wake[i]);
    cf.push_back(h.force_galloping[i] + h.force_vortex[i]);
    cg.push_back(h.force_galloping[i]);
    cw.push_back(h.force_vortex[i]);
  }
  t.add("time", "s", ct, "Time");
  t.add("y", "m", cy, "Displacement y");
  t.add("ydot", "m/s", cv, "Velocity ẏ");
  t.add("wake_q", "-", cq, "Wake variable q");
  t.add("lift", "N", cf, "Lift F");
  t.add("force_galloping", "N", cg, "Galloping force");
  t.add("force_vortex", "N", cw, "Vortex force");
  results.tables.push_back(std::move(t));
  const PlotSpec py = makePlot("detail_displacement", "Displacement y(t) at the detail point", "detail_history", "time", {"y"});
  const PlotSpec pf = makePlot("detail_lift", "Fluid force components at the detail point", "detail_history", "time",
              {"lift", "force_galloping", "force_vortex"});
  results.plots.push_back(py);
  results.plots.push_back(pf);
  // Spectra of y and lift, and the lift-alternation count n = round(f2/f1) (paper eq 22).
  std::vector<double> lift(h.time.size());
  for (std::size_t i = 0; i < lift.size(); ++i) lift[i] = h.force_galloping[i] + h.force_vortex[i];
  const double dt = h.time.size() > 1 ? h.time[1] - h.time[0] : 1.0;
  const SpectralPeaks peaks = analyseSpectra(h.displacement, lift, dt);
  Table s;
  s.name = "detail_spectrum";
  s.title = "Amplitude spectra of y and lift at the detail point";
  s.add("frequency", "Hz", peaks.frequency, "Frequency f");
  s.add("y_amplitude", "m", peaks.displacement_amplitude, "|Y(f)|");
  s.add("lift_amplitude", "N", peaks.lift_amplitude, "|F(f)|");
  results.tables.push_back(std::move(s));
  results.plots.push_back(makePlot("detail_spectrum", "Amplitude spectra at the detail point", "detail_spectrum", "frequency",
                           {"y_amplitude", "lift_amplitude"}, true));
  results.addScalar("detail_f1", peaks.f1, "Hz", "Main (response) peak of the y spectrum", "f₁ at the detail point");
  if (peaks.f2 > 0.0) {
    results.addScalar("detail_f2", peaks.f2, "Hz", "Secondary (shedding) peak of the lift spectrum above 1.5 f1", "f₂ at the detail point");
    results.addScalar("detail_lift_alternations", peaks.alternations, "-", "n = round(f2/f1), paper eq 22", "Lift alternations n at the detail point");
  }
  results.view = buildCylinderView(model, detail, animation_frames);
}

}  // namespace maris::fiv
