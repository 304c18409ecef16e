#include "riser/riser_labels.hpp"
#include "riser/riser_results.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <utility>

#include "core/text_format.hpp"

namespace maris::riser {
namespace {

Vec3 probePoint(const RiserModel& m, const RiserPose& pose, double s) {
  const auto [i, xi] = m.locate(s);
  return pose.position[i] + xi * pose.tangent(i);
}

// Joint k is at arc length (k − ½)Δ (the end segments are Δ/2 long): the joint at or above s and the weight of
// the one below it for a linear interpolation at s (0 outside [Δ/2, L − Δ/2]).
std::pair<int, double> bracketingJoints(const RiserModel& m, double s) {
  const double x = s / m.element_length + 0.5;  // joint index as a real number
  const int above = std::clamp(static_cast<int>(std::floor(x)), 1, m.n);
  const double weight = above < m.n ? std::clamp(x - above, 0.0, 1.0) : 0.0;
  return {above, weight};
}

// History column of probe k (0-based): the first probe keeps the names probe_dx, ..., the others
// are probe2_dx, probe3_dx, ...
std::string probeColumn(std::size_t k, const char* quantity) {
  return (k == 0 ? std::string("probe_") : "probe" + std::to_string(k + 1) + "_") + quantity;
}

std::string probeLabel(std::size_t k, double s) {
  std::ostringstream label;
  label << "Probe " << k + 1 << " (s = " << s << " m)";
  return label.str();
}

}  // namespace

namespace {

// Which quantities of the profile a caller reads: every history sample needs the tensions and stresses (their
// maxima, the probes, fatigue); positions, arc lengths and curvatures only frames, profile tables and the first
// sample do.
struct ProfileParts {
  bool shape = true;      // arc_length, position
  bool curvature = true;  // curvature
};

// Fills `p` (buffers reused from sample to sample; the right-hand side's derivative goes to `dy`) with the parts
// asked for, by the same arithmetic as evaluateProfile.
void fillProfile(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy,
                 ProfileParts parts, RiserProfile& p) {
  dy.resize(y.size());
  evaluateRhs(m, ws, t, y, dy);
  const RiserPose& pose = ws.pose;
  const int nodes = m.n + 2;
  p.arc_length.resize(nodes);
  p.position.resize(nodes);
  p.tension.assign(nodes, 0.0);
  p.bending_stress.assign(nodes, 0.0);
  p.stress_xy.assign(nodes, 0.0);
  p.stress_xz.assign(nodes, 0.0);
  p.torsional_stress.assign(nodes, 0.0);
  p.curvature.assign(nodes, 0.0);
  if (parts.shape)
    for (int k = 0; k < nodes; ++k) {
      p.arc_length[k] = k <= m.n ? m.segments[k].arc_start : m.length;
      p.position[k] = pose.node(k);
    }
  // Tension from the joint reactions F_k (force on segment k from above): T = -F_k · t_k.
  const int f = m.first_dynamic, last = m.last_dynamic;
  for (int k = f; k <= last + 1; ++k) p.tension[k] = -ws.reaction[k].dot(pose.tangent(std::min(k, m.n)));
  if (m.bottom == BottomCondition::Free || m.bottom == BottomCondition::Spring)
    p.tension[m.n + 1] = ws.loads.support_force.dot(pose.tangent(m.n));
  if (f == 1) p.tension[0] = p.tension[1];
  if (last == m.n - 1) p.tension[m.n + 1] = p.tension[m.n];
  // Stresses from the spring moments M̄ (paper's M', eq 26 and Figs 21-23); curvature from the bend angle.
  for (int k = 1; k <= m.n; ++k) {
    const Vec3& mb = ws.loads.spring_moment[k];
    const Joint& j = m.joints[k];
    p.bending_stress[k] = std::hypot(mb.y(), mb.z()) / j.bending_modulus;
    p.stress_xy[k] = mb.z() / j.bending_modulus;
    p.stress_xz[k] = mb.y() / j.bending_modulus;
    p.torsional_stress[k] = mb.x() / j.torsion_modulus;
    if (parts.curvature) {
      const Vec3& a = ws.loads.relative_angle[k];
      p.curvature[k] = std::hypot(a.y(), a.z()) / m.element_length;
    }
  }
}

}  // namespace

RiserProfile evaluateProfile(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y) {
  Eigen::VectorXd dy;
  RiserProfile p;
  fillProfile(m, ws, t, y, dy, ProfileParts{}, p);
  return p;
}

namespace {
// The sea surface z = water_level + η(x, y, t) on a 25 × 25 grid over a square of half-width `half` about the top.
Shape3D seaSurface(const RiserSea& sea, const Vec3& centre, double half, double t) {
  Shape3D s;
  s.kind = Shape3D::Kind::Surface;
  s.name = "sea surface";
  s.grid_u = s.grid_v = 25;
  for (int v = 0; v < s.grid_v; ++v)
    for (int u = 0; u < s.grid_u; ++u) {
      const double x = centre.x() + half * (2.0 * u / (s.grid_u - 1) - 1.0);
      const double y = centre.y() + half * (2.0 * v / (s.grid_v - 1) - 1.0);
      s.points.emplace_back(x, y, sea.water_level + sea.elevation(x, y, t));
    }
  s.color = Vec3(0.2, 0.45, 0.75);
  s.opacity = 0.45;
  return s;
}
}  // namespace

// The time-history plots (shared by the final and the partial results, so live plots keep their tabs).
void RiserRecorder::addHistoryPlots(Results& out) const {
  for (std::size_t k = 0; k < probes_.size(); ++k)
    out.plots.push_back(makePlot(k == 0 ? "probe_displacement" : probeColumn(k, "displacement"),
                                 probeLabel(k, probes_[k].arc_length) + ": displacement", "history", "time",
                                 {probeColumn(k, "dx"), probeColumn(k, "dy"), probeColumn(k, "dz")}));
  out.plots.push_back(makePlot("top_force", "Top reaction", "history", "time",
                               {"top_force_x", "top_force_y", "top_force_z"}));
  out.plots.push_back(makePlot(
      "energy", "Energy and work", "history", "time",
      {"kinetic_energy", "spring_energy", "work_drag", "work_boundary", "work_flow", "energy_balance_error"}));
  std::vector<std::string> stresses;
  for (std::size_t k = 0; k < probes_.size(); ++k) stresses.push_back(probeColumn(k, "bending_stress"));
  for (std::size_t k = 0; k < probes_.size(); ++k) stresses.push_back(probeColumn(k, "torsional_stress"));
  out.plots.push_back(makePlot("probe_stress", "Stress at the probes", "history", "time", stresses));
  if (m_.sea) out.plots.push_back(makePlot("wave_elevation", "Wave elevation", "history", "time", {"wave_elevation"}));
  if (m_.seabed) seabed_.addPlot(out);
}

// probe_max_displacement (first probe, kept for scripts), probe2_max_displacement, ...
void RiserRecorder::addProbeScalars(Results& out) const {
  for (std::size_t k = 0; k < probes_.size(); ++k)
    out.addScalar(probeColumn(k, "max_displacement"), probes_[k].max_displacement, "m",
                  "Largest displacement from its start of " + probeLabel(k, probes_[k].arc_length),
                  riserColumnLabel(probeColumn(k, "max_displacement")));
}

RiserRecorder::RiserRecorder(const RiserModel& model, const RiserParameters& parameters)
    : m_(model), p_(parameters), ws_(makeWorkspace(model, 0.0)) {
  for (const ProbeRow& row : parameters.probes) {
    Probe probe;
    probe.arc_length = row.arc_length;
    std::tie(probe.joint_above, probe.weight_below) = bracketingJoints(model, row.arc_length);
    probes_.push_back(probe);
  }
  history_.name = "history";
  history_.title = "Probe points, end reactions and energies over time";
  for (const char* c : {"time"}) history_.add(c, "s", {}, riserColumnLabel(c));
  for (const char* c : {"probe_dx", "probe_dy", "probe_dz", "top_x", "top_y", "top_z", "end_x", "end_y", "end_z"})
    history_.add(c, "m", {}, riserColumnLabel(c));
  for (const char* c : {"top_force_x", "top_force_y", "top_force_z", "bottom_force_x", "bottom_force_y",
                        "bottom_force_z"})
    history_.add(c, "N", {}, riserColumnLabel(c));
  for (const char* c : {"kinetic_energy", "spring_energy", "gravity_energy", "total_energy", "work_drag",
                        "work_damping", "work_boundary", "work_flow", "energy_balance_error"})
    history_.add(c, "J", {}, riserColumnLabel(c));
  history_.add("constraint_drift", "m", {}, riserColumnLabel("constraint_drift"));
  history_.add("probe_bending_stress", "Pa", {}, riserColumnLabel("probe_bending_stress"));
  history_.add("probe_torsional_stress", "Pa", {}, riserColumnLabel("probe_torsional_stress"));
  for (std::size_t k = 1; k < probes_.size(); ++k) {
    for (const char* c : {"dx", "dy", "dz"}) history_.add(probeColumn(k, c), "m", {}, riserColumnLabel(probeColumn(k, c)));
    for (const char* c : {"bending_stress", "torsional_stress"}) history_.add(probeColumn(k, c), "Pa", {}, riserColumnLabel(probeColumn(k, c)));
  }
  if (m_.sea) history_.add("wave_elevation", "m", {}, riserColumnLabel("wave_elevation"));  // η at (waves.elevation_x, waves.elevation_y)
  if (m_.seabed) seabed_.addColumns(history_);
  if (parameters.fatigue_enabled)
    for (int k = 1; k <= m_.n; ++k) {
      JointStressSeries s;
      s.arc_length = (k - 0.5) * m_.element_length;
      s.wall_area = m_.joints[k].wall_area;
      s.wall_thickness = m_.joints[k].wall_thickness;
      fatigue_.push_back(std::move(s));
    }
  nodes_.name = "node_positions";
  nodes_.title = "Node positions of every stored frame";
  nodes_.add("time", "s", {}, riserColumnLabel("time"));
  nodes_.add("node", "-", {}, riserColumnLabel("node"));
  nodes_.add("arc_length", "m", {}, riserColumnLabel("arc_length"));
  for (const char* c : {"x", "y", "z"}) nodes_.add(c, "m", {}, riserColumnLabel(c));
  r_.view.scalar_name = "bending stress";
  r_.view.scalar_unit = "Pa";
  r_.view.water_level_z = m_.water_level;
  // A sloped bed is drawn in every frame instead of the level plane.
  if (!m_.seabed || m_.seabed->normal.z() == 1.0) r_.view.seabed_z = m_.seabed_level;
}

void RiserRecorder::recordFatigueSample(double t) {
  if (fatigue_.empty()) return;
  fatigue_time_.push_back(t);
  for (int k = 1; k <= m_.n; ++k) {
    JointStressSeries& s = fatigue_[static_cast<std::size_t>(k - 1)];
    s.tension.push_back(profile_.tension[k]);
    s.stress_xy.push_back(profile_.stress_xy[k]);
    s.stress_xz.push_back(profile_.stress_xz[k]);
  }
}

void RiserRecorder::sample(double t, const Eigen::VectorXd& y, bool frame, const std::optional<std::string>& profile_name,
                           bool history) {
  const bool shape = first_ || frame || profile_name.has_value();
  fillProfile(m_, ws_, t, y, dy_, ProfileParts{shape, profile_name.has_value()}, profile_);
  const RiserProfile& prof = profile_;
  if (!history && !first_ && !frame && !profile_name) {
    recordFatigueSample(t);
    return;
  }
  const RiserPose& pose = ws_.pose;
  const int nodes = m_.n + 2;
  if (first_) initial_nodes_ = prof.position;
  // Energies and the work balance E(t) - E(0) = W_drag + W_damping + W_boundary.
  const double kin = kineticEnergy(m_, pose), spr = springEnergy(m_, ws_.loads);
  const double grav = gravityPotential(m_, pose) + anchorSpringEnergy(m_, pose) + seabedContactEnergy(m_, pose);
  const double total = kin + spr + grav;
  const Eigen::Index ow = workIntegralOffset(m_);
  const double wd = y[ow], wdamp = y[ow + 1], wb = y[ow + 2], wf = y[ow + 3];
  if (first_) energy0_ = total;
  const double balance = total - energy0_ - (wd + wdamp + wb + wf);
  energy_scale_ = std::max({energy_scale_, kin + std::abs(spr),
                            std::abs(wd) + std::abs(wdamp) + std::abs(wb) + std::abs(wf), std::abs(total - energy0_)});
  balance_max_ = std::max(balance_max_, std::abs(balance));
  drift_max_ = std::max(drift_max_, ws_.constraint_drift);
  // Probe displacements from their first sample and stresses interpolated between their bracketing joints.
  Vec3 first_d = Vec3::Zero();
  double first_bending = 0.0, first_torsion = 0.0;
  std::vector<double>& extra = extra_;  // columns of probes 2, 3, ... (dx, dy, dz, bending, torsional)
  extra.clear();
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    Probe& probe = probes_[k];
    const Vec3 at = probePoint(m_, pose, probe.arc_length);
    if (first_) probe.start = at;
    const Vec3 d = at - probe.start;
    probe.max_displacement = std::max(probe.max_displacement, d.norm());
    auto at_probe = [&](const std::vector<double>& along) {
      const double below = probe.weight_below > 0 ? along[probe.joint_above + 1] : 0.0;
      return (1 - probe.weight_below) * along[probe.joint_above] + probe.weight_below * below;
    };
    // σ_b from the interpolated components: |M| has a kink where the moment turns through zero.
    const double bending = std::hypot(at_probe(prof.stress_xy), at_probe(prof.stress_xz));
    const double torsion = at_probe(prof.torsional_stress);
    probe.max_bending = std::max(probe.max_bending, bending);
    if (k == 0) {
      first_d = d;
      first_bending = bending;
      first_torsion = torsion;
    } else {
      extra.insert(extra.end(), {d.x(), d.y(), d.z(), bending, torsion});
    }
  }
  pose_end_ = pose.end_position;
  const int f = m_.first_dynamic, last = m_.last_dynamic;
  const Vec3 bottom = (m_.bottom == BottomCondition::Free || m_.bottom == BottomCondition::Spring)
                          ? Vec3(-ws_.loads.support_force) : ws_.reaction[last + 1];
  std::vector<double>& row = row_;
  row = {t, first_d.x(), first_d.y(), first_d.z(), pose.node(0).x(), pose.node(0).y(), pose.node(0).z(),
         pose.end_position.x(), pose.end_position.y(), pose.end_position.z(),
         ws_.reaction[f].x(), ws_.reaction[f].y(), ws_.reaction[f].z(),
         bottom.x(), bottom.y(), bottom.z(), kin, spr, grav, total, wd, wdamp, wb, wf, balance,
         ws_.constraint_drift, first_bending, first_torsion};
  row.insert(row.end(), extra.begin(), extra.end());
  if (m_.sea) row.push_back(m_.sea->elevation(m_.sea->elevation_x, m_.sea->elevation_y, t));
  SeabedContactState contact;
  if (m_.seabed) {
    contact = seabedContact(m_, pose);
    seabed_.sample(contact, row);
  }
  recordFatigueSample(t);
  for (std::size_t c = 0; c < row.size(); ++c) history_.columns[c].values.push_back(row[c]);
  for (int k = 0; k < nodes; ++k) {
    max_bending_ = std::max(max_bending_, prof.bending_stress[k]);
    max_torsion_ = std::max(max_torsion_, std::abs(prof.torsional_stress[k]));
    max_tension_ = std::max(max_tension_, prof.tension[k]);
  }
  if (frame) {
    Frame3D fr;
    fr.time = t;
    Shape3D tube;
    tube.kind = Shape3D::Kind::Tube;
    tube.name = "riser";
    tube.radius = 0.5 * m_.segments[0].outer_diameter;  // the real size: the 3D view thickens thin tubes and says so
    tube.points = prof.position;
    tube.scalars = prof.bending_stress;
    tube.scalars.front() = tube.scalars[1];
    tube.scalars.back() = tube.scalars[m_.n];
    // The first frame is the start (the static shape when statics ran): the reference of the motion.
    if (r_.view.reference.empty()) r_.view.reference.push_back(tube);
    fr.shapes.push_back(std::move(tube));
    Shape3D top;
    top.kind = Shape3D::Kind::Sphere;
    top.name = "top end";
    top.radius = 2.5 * std::max(0.5 * m_.segments[0].outer_diameter, 0.004 * m_.length);
    top.points = {prof.position.front()};
    top.color = Vec3(0.9, 0.5, 0.1);
    fr.shapes.push_back(std::move(top));
    if (m_.sea) fr.shapes.push_back(seaSurface(*m_.sea, m_.top_mean, 0.5 * m_.length, t));
    if (m_.seabed && !r_.view.seabed_z) fr.shapes.push_back(seabedSurface(*m_.seabed, m_.top_mean, m_.length));
    r_.view.frames.push_back(std::move(fr));
    for (int k = 0; k < nodes; ++k) {
      const double vals[6] = {t, double(k), prof.arc_length[k], prof.position[k].x(), prof.position[k].y(),
                              prof.position[k].z()};
      for (int c = 0; c < 6; ++c) nodes_.columns[c].values.push_back(vals[c]);
    }
  }
  if (profile_name) {
    Table tab;
    tab.name = *profile_name;
    std::ostringstream title;  // 6 significant digits, no trailing zeros: "t = 24 s", "t = 12.5 s"
    title << "Along the riser at t = " << t << " s";
    tab.title = title.str();
    tab.add("arc_length", "m", prof.arc_length, riserColumnLabel("arc_length"));
    std::vector<double> x, yv, z, dx;
    for (int k = 0; k < nodes; ++k) {
      x.push_back(prof.position[k].x());
      yv.push_back(prof.position[k].y());
      z.push_back(prof.position[k].z());
      dx.push_back((prof.position[k] - initial_nodes_[k]).norm());
    }
    tab.add("x", "m", x, riserColumnLabel("x"));
    tab.add("y", "m", yv, riserColumnLabel("y"));
    tab.add("z", "m", z, riserColumnLabel("z"));
    tab.add("displacement", "m", dx, riserColumnLabel("displacement"));
    tab.add("tension", "N", prof.tension, riserColumnLabel("tension"));
    tab.add("bending_stress", "Pa", prof.bending_stress, riserColumnLabel("bending_stress"));
    tab.add("stress_xy", "Pa", prof.stress_xy, riserColumnLabel("stress_xy"));
    tab.add("stress_xz", "Pa", prof.stress_xz, riserColumnLabel("stress_xz"));
    tab.add("torsional_stress", "Pa", prof.torsional_stress, riserColumnLabel("torsional_stress"));
    tab.add("curvature", "1/m", prof.curvature, riserColumnLabel("curvature"));
    if (m_.seabed) seabed_.addProfileColumn(contact, tab);
    r_.tables.push_back(std::move(tab));
  }
  first_ = false;
  if (live_ && history_.rows() > 1 && live_->wantsPartialResults()) live_->publishPartial(partialResults());
}

std::shared_ptr<const Results> RiserRecorder::partialResults() const {
  auto out = std::make_shared<Results>();
  out->tables.push_back(history_);
  addHistoryPlots(*out);
  out->view.scalar_name = r_.view.scalar_name;
  out->view.scalar_unit = r_.view.scalar_unit;
  out->view.water_level_z = r_.view.water_level_z;
  out->view.seabed_z = r_.view.seabed_z;
  out->view.reference = r_.view.reference;
  if (!r_.view.frames.empty()) out->view.frames.push_back(r_.view.frames.back());
  out->addScalar("time", history_.columns.front().values.back(), "s", "Simulated time reached so far", "Time reached");
  addProbeScalars(*out);
  out->addScalar("max_bending_stress", max_bending_, "Pa", "Largest bending stress so far", "max σ_b");
  return out;
}

void RiserRecorder::addModes(const RiserModes& modes) {
  Table freq;
  freq.name = "modes";
  freq.title = "Natural frequencies about the static state";
  Table shapes;
  shapes.name = "mode_shapes";
  shapes.title = "Mode shapes (node displacements, largest = 1)";
  for (const char* c : {"mode", "node"}) shapes.add(c, "-", {}, riserColumnLabel(c));
  shapes.add("arc_length", "m", {}, riserColumnLabel("arc_length"));
  for (const char* c : {"dx", "dy", "dz", "twist"}) shapes.add(c, "-", {}, riserColumnLabel(c));
  std::vector<double> index, omega, hertz, period;
  for (std::size_t k = 0; k < modes.frequencies.size(); ++k) {
    const double w = modes.frequencies[k];
    index.push_back(static_cast<double>(k + 1));
    omega.push_back(w);
    hertz.push_back(w / (2 * 3.14159265358979323846));
    period.push_back(2 * 3.14159265358979323846 / w);
    for (int node = 0; node <= m_.n + 1; ++node) {
      const Vec3& d = modes.shapes[k][node];
      const double s = node <= m_.n ? m_.segments[node].arc_start : m_.length;
      const double row[7] = {double(k + 1), double(node), s, d.x(), d.y(), d.z(), modes.twists[k][std::min(node, m_.n)]};
      for (int c = 0; c < 7; ++c) shapes.columns[c].values.push_back(row[c]);
    }
  }
  freq.add("mode", "-", index, riserColumnLabel("mode"));
  freq.add("angular_frequency", "rad/s", omega, riserColumnLabel("angular_frequency"));
  freq.add("frequency", "Hz", hertz, riserColumnLabel("frequency"));
  freq.add("period", "s", period, riserColumnLabel("period"));
  freq.add("torsion_share", "-", modes.torsion_share, riserColumnLabel("torsion_share"));
  if (!omega.empty())
    r_.addScalar("first_natural_frequency", omega.front(), "rad/s", "Lowest natural frequency about the static state", "ω₁");
  if (std::isfinite(modes.divergence_flow_speed))
    r_.addScalar("divergence_flow_speed", modes.divergence_flow_speed, "m/s",
                 "Internal flow speed |u| at which the lowest natural frequency reaches zero (at the static shape)", "Divergence flow speed");
  r_.tables.push_back(std::move(freq));
  r_.tables.push_back(std::move(shapes));
}

Results RiserRecorder::finish(const SolverStats& stats, const StaticSolution& statics) {
  Results out = std::move(r_);
  out.stats = stats;
  const double scale = std::max(energy_scale_, 1e-300);
  out.tables.push_back(history_);
  out.tables.push_back(nodes_);
  if (!fatigue_.empty()) {
    const auto joints = jointFatigue(fatigue_time_, fatigue_, fatigueCurve(p_), p_.fatigue_stress_concentration_factor,
                                     p_.fatigue_start_time);
    auto first = std::lower_bound(fatigue_time_.begin(), fatigue_time_.end(), p_.fatigue_start_time);
    const double window = first == fatigue_time_.end() ? 0.0 : fatigue_time_.back() - *first;
    addFatigueResults(joints, fatigueCurve(p_), window, out);
    if (fatigue_time_.size() > 1)
      out.addScalar("fatigue_sample_interval",
                    (fatigue_time_.back() - fatigue_time_.front()) / static_cast<double>(fatigue_time_.size() - 1), "s",
                    "Mean spacing of the joint-stress samples that rainflow counts (fatigue.sample_interval)",
                    "Fatigue sample spacing");
  }
  Table probes;
  probes.name = "probes";
  probes.title = "Probe points: largest displacement and bending stress over the run (stresses interpolated "
                 "between joint_above and the joint below it, weight_below on the lower one)";
  for (const char* c : {"probe", "joint_above", "weight_below"}) probes.add(c, "-", {}, riserColumnLabel(c));
  probes.add("arc_length", "m", {}, riserColumnLabel("arc_length"));
  probes.add("max_displacement", "m", {}, riserColumnLabel("max_displacement"));
  probes.add("max_bending_stress", "Pa", {}, riserColumnLabel("max_bending_stress"));
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const double row[6] = {double(k + 1), double(probes_[k].joint_above), probes_[k].weight_below, probes_[k].arc_length,
                           probes_[k].max_displacement, probes_[k].max_bending};
    for (int c = 0; c < 6; ++c) probes.columns[c].values.push_back(row[c]);
  }
  out.tables.push_back(std::move(probes));
  const auto& h = history_;
  const std::size_t last = h.rows() - 1;
  out.addScalar("end_x", h.find("end_x")->values[last], "m", "Bottom end position x at the end of the run", "Bottom end x");
  out.addScalar("end_y", h.find("end_y")->values[last], "m", "Bottom end position y at the end of the run", "Bottom end y");
  out.addScalar("end_z", h.find("end_z")->values[last], "m", "Bottom end position z at the end of the run", "Bottom end z");
  addProbeScalars(out);
  if (m_.seabed) seabed_.addScalars(out);
  out.addScalar("max_bending_stress", max_bending_, "Pa", "Largest bending stress σ_b over joints and samples", "max σ_b");
  out.addScalar("max_torsional_stress", max_torsion_, "Pa", "Largest |σ_t| over joints and samples", "max τ_t");
  out.addScalar("max_tension", max_tension_, "N", "Largest tension over nodes and samples", "max T");
  const Vec3 end_displacement = pose_end_ - initial_nodes_.back();
  out.addScalar("tip_deflection", end_displacement.norm(), "m", "Displacement of the bottom end from its start at the end", "Tip deflection");
  for (const char* c : {"top_force_x", "top_force_y", "top_force_z", "bottom_force_x", "bottom_force_y",
                        "bottom_force_z"})
    out.addScalar(std::string(c) + "_final", h.find(c)->values[last], "N",
                  "Reaction at the end of the run (top: on the riser from the support; bottom: on the support)",
                  riserColumnLabel(c) + " at the end");
  out.addScalar("energy_drift", balance_max_, "J",
                "max |E(t) - E(0) - W_drag - W_damping - W_boundary - W_flow| over the run", "Energy drift");
  out.addScalar("energy_balance_error", balance_max_ / scale, "-",
                "max |E(t) - E(0) - W_drag - W_damping - W_boundary| relative to the energy scale of the run", "Energy balance error");
  out.addScalar("constraint_drift", drift_max_, "m", "Largest constraint violation |Φ| (bottom end; A: all joints)", "Constraint drift |Φ|");
  out.addScalar("statics_iterations", statics.iterations, "-", "Newton iterations of the static solution", "Statics iterations");
  out.addScalar("statics_residual", statics.residual, "-", "Final scaled residual of the static solution", "Statics residual");
  out.addScalar("statics_relaxation_time", statics.relaxation_time, "s",
                "Damped motion (dynamic relaxation) before the static Newton converged; 0: none needed", "Statics relaxation time");
  out.addScalar("steps", static_cast<double>(stats.steps), "-", "Accepted time steps", "Steps");
  out.addScalar("rhs_evaluations", static_cast<double>(stats.rhs_evaluations), "-", "Right-hand side evaluations", "Right-hand side evaluations");
  out.addScalar("integrator_error_estimate", stats.error_estimate, "-",
                "Error estimate: implicit runs under a harmonic top motion or in a sea, the expected probe error "
                "relative to the motion, C (h/T)² with T the top's period or the sea's mean period T_m01 "
                "(docs/riser.md); other runs, the integrator's relative global estimate (sum of local estimates, "
                "docs/numerics.md)", "Integrator error estimate");
  // Plots.
  if (h.rows() > 1) addHistoryPlots(out);
  for (const auto& t : out.tables) {
    if (t.name.rfind("profile", 0) != 0) continue;
    out.plots.push_back(makePlot(t.name + "_stress", t.title + ": stress", t.name, "arc_length",
                                 {"bending_stress", "torsional_stress"}));
    out.plots.push_back(makePlot(t.name + "_shape", t.title + ": shape", t.name, "arc_length", {"x", "y"}));
  }
  return out;
}

std::vector<std::string> accuracyWarnings(const Results& results) {
  std::vector<std::string> out;
  const Scalar* balance = results.findScalar("energy_balance_error");
  if (balance && !(balance->value <= 0.05))
    out.push_back(formatText("the energy balance is off by %.3g of the run's energy scale (energy_balance_error; an "
                             "accurate run stays below 1e-3): the time integration is not accurate; lower "
                             "solver.tolerance or solver.time_step, or use solver.integrator = implicit",
                             balance->value));
  const Scalar* estimate = results.findScalar("integrator_error_estimate");
  if (estimate && !(estimate->value <= 0.1))
    out.push_back(formatText("the integrator's own error estimate is %.3g (relative, integrator_error_estimate): the "
                             "histories are not accurate; lower solver.tolerance or solver.time_step",
                             estimate->value));
  return out;
}

}  // namespace maris::riser
