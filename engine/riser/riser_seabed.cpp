// Sea-bed contact (contract in riser/riser_seabed.hpp).
#include "riser/riser_seabed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/angles.hpp"
#include "core/text_format.hpp"
#include "riser/riser_loads.hpp"
#include "riser/riser_model.hpp"

namespace maris::riser {
namespace {

using P = RiserParameters;

double smoothSign(const RiserSeabed& bed, double v) {
  const double x = v / bed.friction_velocity;
  return bed.linear_ramp ? std::clamp(x, -1.0, 1.0) : std::tanh(x);
}

// Part [lo, hi] of [0, length] where the linear penetration δ0 + ξ·slope is positive (lo > hi: none).
std::pair<double, double> contactInterval(double delta0, double slope, double length) {
  if (slope == 0.0) return delta0 > 0 ? std::pair{0.0, length} : std::pair{1.0, 0.0};
  const double root = -delta0 / slope;  // δ = 0 there
  if (slope > 0) return {std::clamp(root, 0.0, length), length};
  return {0.0, std::clamp(root, 0.0, length)};
}

}  // namespace

double RiserSeabed::heightAt(double x, double y) const {
  // n·(p − p₀) = 0 solved for z.
  return origin.z() - (normal.x() * (x - origin.x()) + normal.y() * (y - origin.y())) / normal.z();
}

Eigen::Vector3d RiserSeabed::lineLoad(const Eigen::Vector3d& point, const Eigen::Vector3d& tangent,
                                      const Eigen::Vector3d& velocity, double diameter) const {
  const double delta = penetration(point, diameter);
  if (delta <= 0) return Eigen::Vector3d::Zero();
  const double normal_force = std::max(0.0, stiffness * delta - damping * velocity.dot(normal));
  Eigen::Vector3d force = normal_force * normal;
  if (normal_force == 0.0 || (axial_friction == 0.0 && lateral_friction == 0.0)) return force;
  // Axis projected on the bed; a segment standing normal to the bed has no axial direction: any one will do.
  Eigen::Vector3d axial = tangent - tangent.dot(normal) * normal;
  if (axial.norm() < 1e-9) axial = normal.unitOrthogonal();
  axial.normalize();
  const Eigen::Vector3d lateral = normal.cross(axial);
  force -= axial_friction * normal_force * smoothSign(*this, velocity.dot(axial)) * axial;
  force -= lateral_friction * normal_force * smoothSign(*this, velocity.dot(lateral)) * lateral;
  return force;
}

std::shared_ptr<const RiserSeabed> buildRiserSeabed(const RiserParameters& p) {
  if (!p.seabed_contact) return nullptr;
  auto bed = std::make_shared<RiserSeabed>();
  const double slope = radiansFromDegrees(p.seabed_slope_deg), heading = radiansFromDegrees(p.seabed_slope_direction_deg);
  bed->origin = Eigen::Vector3d(0, 0, p.seabed_level);
  // Rising towards `heading`: the normal leans the other way.
  bed->normal = Eigen::Vector3d(-std::sin(slope) * std::cos(heading), -std::sin(slope) * std::sin(heading), std::cos(slope));
  bed->stiffness = p.seabed_normal_stiffness;
  bed->damping = p.seabed_normal_damping;
  bed->axial_friction = p.seabed_axial_friction;
  bed->lateral_friction = p.seabed_lateral_friction;
  bed->friction_velocity = p.seabed_friction_velocity;
  bed->linear_ramp = p.seabed_friction_smoothing == "linear";
  return bed;
}

void bindSeabedParameters(SchemaBinder<RiserParameters>& b) {
  b.boolean("seabed.contact", &P::seabed_contact,
            "Contact with the sea bed (a plane through environment.seabed_level at x = y = 0): normal spring and "
            "damper, smoothed Coulomb friction (off: the bed is only drawn)");
  b.real("seabed.slope_deg", &P::seabed_slope_deg, "deg", Range::closed(0, 45), "Slope of the bed");
  b.real("seabed.slope_direction_deg", &P::seabed_slope_direction_deg, "deg", Range::closed(-360, 360),
         "Heading towards which the bed rises, from +x towards +y");
  b.real("seabed.normal_stiffness", &P::seabed_normal_stiffness, "N/m^2", Range::positive(1e10),
         "Normal stiffness per unit length of riser: force per length per metre of penetration");
  b.real("seabed.normal_damping", &P::seabed_normal_damping, "N*s/m^2", Range::nonNegative(1e9),
         "Normal damping per unit length of riser (the bed pushes only: the force is clipped at zero)");
  b.real("seabed.axial_friction_coefficient", &P::seabed_axial_friction, "-", Range::closed(0, 5),
         "Friction coefficient along the riser's axis (smoothed Coulomb)");
  b.real("seabed.lateral_friction_coefficient", &P::seabed_lateral_friction, "-", Range::closed(0, 5),
         "Friction coefficient across the riser's axis (smoothed Coulomb)");
  b.choice("seabed.friction_smoothing", &P::seabed_friction_smoothing, {"tanh", "linear"},
           "Coulomb law smoothed by tanh(v/v_s) or by a linear ramp reaching full friction at v_s");
  b.real("seabed.friction_velocity", &P::seabed_friction_velocity, "m/s", Range::positive(10.0),
         "Smoothing velocity v_s of the friction law (smaller: closer to Coulomb, stiffer equations)");
}

void checkSeabedParameters(const RiserParameters& p, std::vector<FieldError>& e) {
  if (!p.seabed_contact) return;
  const auto bed = buildRiserSeabed(p);
  const double d = p.outer_diameter;
  // An end held below the bed would sit in the spring for good; the top must be above it.
  const bool held = p.bottom_condition == "pinned" || p.bottom_condition == "clamped" || p.bottom_condition == "spring";
  const double anchor_depth = bed->penetration(Eigen::Vector3d(p.bottom_x, p.bottom_y, p.bottom_z), 0.0);
  if (held && anchor_depth > d)
    e.push_back({"bottom.z", formatText("%g", p.bottom_z),
                 "the anchor is " + formatText("%g", anchor_depth) + " m below the sea bed (seabed.contact = true): must be at most "
                 "one outer diameter (" + formatText("%g", d) + " m) below it (bed at z = " +
                     formatText("%g", bed->heightAt(p.bottom_x, p.bottom_y)) + " m there)"});
  if (p.top_condition != "tensioner" && p.top_condition != "free" &&
      bed->penetration(Eigen::Vector3d(p.top_x, p.top_y, p.top_z), 0.0) >= 0)
    e.push_back({"top.z", formatText("%g", p.top_z),
                 "the top is not above the sea bed (z = " + formatText("%g", bed->heightAt(p.top_x, p.top_y)) +
                     " m there; seabed.contact = true)"});
}

void addSeabedContact(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads) {
  const RiserSeabed& bed = *m.seabed;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    const Vec3 t = pose.tangent(i);
    // Quick reject: the whole segment clear of the bed.
    if (bed.penetration(pose.position[i], seg.outer_diameter) <= 0 &&
        bed.penetration(pose.position[i] + seg.length * t, seg.outer_diameter) <= 0)
      continue;
    for (int q = 0; q < 3; ++q) {
      const double xi = kGaussX[q] * seg.length, w = kGaussW[q] * seg.length;
      const Vec3 p = pose.position[i] + xi * t;
      const double delta = bed.penetration(p, seg.outer_diameter);
      if (delta <= 0) continue;
      const Vec3 v = pose.velocity[i] + pose.omega[i].cross(xi * t);
      const Vec3 f = w * bed.lineLoad(p, t, v, seg.outer_diameter);
      loads.force[i] += f;
      loads.moment[i] += (xi * t).cross(f);
      // The elastic part k δ n is conservative (seabedContactEnergy); the rest dissipates.
      loads.power_damping += (f - w * bed.stiffness * delta * bed.normal).dot(v);
    }
  }
}

double seabedContactEnergy(const RiserModel& m, const RiserPose& pose) {
  if (!m.seabed) return 0.0;
  const RiserSeabed& bed = *m.seabed;
  double e = 0.0;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    for (int q = 0; q < 3; ++q) {
      const double delta =
          bed.penetration(pose.position[i] + kGaussX[q] * seg.length * pose.tangent(i), seg.outer_diameter);
      if (delta > 0) e += 0.5 * kGaussW[q] * seg.length * bed.stiffness * delta * delta;
    }
  }
  return e;
}

double seabedFrequencyEstimate(const RiserModel& m) {
  if (!m.seabed) return 0.0;
  const RiserSeabed& bed = *m.seabed;
  double rate = 0.0;
  for (const Segment& s : m.segments) {
    const double mu = s.mass / s.length, resting = std::abs(s.weight_per_length - s.buoyancy_per_length);
    const double friction = std::max(bed.axial_friction, bed.lateral_friction) * resting / bed.friction_velocity;
    // 2√(k/μ) as for the anchor spring: at half the RK4 limit of √(k/μ) alone a landing segment bounced off the bed
    // (a heaving chain: 4.5 steps per contact period lifted it clear where 9 steps and more kept it down).
    rate = std::max({rate, 2 * std::sqrt(bed.stiffness / mu), bed.damping / mu, friction / mu});
  }
  return rate;
}

std::vector<Eigen::Vector3d> seabedInitialPoints(const RiserSeabed& bed, const Eigen::Vector3d& top,
                                                 const Eigen::Vector3d& anchor, double length,
                                                 const std::vector<double>& arc_lengths) {
  // The cable catenary with a grounded length in the vertical plane through top and anchor (the grounded part
  // level with the anchor): suspended length s = √(h(h + 2a)), span X = L − s + a asinh(s/a), a found by
  // bisection. Anchor on the bed: within 5 % of the top's height above it.
  const double h = top.z() - anchor.z();
  Eigen::Vector3d across = anchor - top;
  across.z() = 0;
  const double span = across.norm();
  if (!(h > 0) || span <= 0 || std::abs(bed.penetration(anchor, 0.0)) > 0.05 * h) return {};
  const Eigen::Vector3d e = across / span;
  auto suspended = [&](double a) { return std::sqrt(h * (h + 2 * a)); };
  auto spanOf = [&](double a) { const double s = suspended(a); return length - s + a * std::asinh(s / a); };
  double lo = 1e-9 * h, hi = 0.5 * (length * length / h - h);  // hi: the whole line suspended
  if (!(hi > lo) || !(span > spanOf(lo)) || !(span < spanOf(hi))) return {};
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    (spanOf(mid) < span ? lo : hi) = mid;
  }
  const double a = std::sqrt(lo * hi), s = suspended(a);
  const Eigen::Vector3d touchdown = anchor - (length - s) * e;
  std::vector<Eigen::Vector3d> out;
  for (double sk : arc_lengths) {
    if (sk >= s) {
      out.push_back(touchdown + (sk - s) * e);
    } else {
      const double sigma = s - sk;
      out.push_back(touchdown - a * std::asinh(sigma / a) * e +
                    (std::sqrt(a * a + sigma * sigma) - a) * Eigen::Vector3d::UnitZ());
    }
  }
  return out;
}

SeabedContactState seabedContact(const RiserModel& m, const RiserPose& pose) {
  SeabedContactState c;
  if (!m.seabed) return c;
  const RiserSeabed& bed = *m.seabed;
  c.touchdown = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    const Vec3 t = pose.tangent(i);
    const auto [lo, hi] =
        contactInterval(bed.penetration(pose.position[i], seg.outer_diameter), -bed.normal.dot(t), seg.length);
    if (lo <= hi && hi > lo) {
      c.touchdown = std::min(c.touchdown, seg.arc_start + lo);
      c.contact_length += hi - lo;
    }
    for (int q = 0; q < 3; ++q) {
      const double xi = kGaussX[q] * seg.length;
      const Vec3 v = pose.velocity[i] + pose.omega[i].cross(xi * t);
      c.normal_force +=
          kGaussW[q] * seg.length * bed.lineLoad(pose.position[i] + xi * t, t, v, seg.outer_diameter).dot(bed.normal);
    }
  }
  if (!std::isfinite(c.touchdown)) c.touchdown = m.length;
  c.node_line_load.resize(m.n + 2);
  for (int k = 0; k <= m.n + 1; ++k) {
    const int i = std::min(k, m.n);
    const Vec3 v = k <= m.n ? pose.velocity[k] : pose.end_velocity;
    c.node_line_load[k] = bed.lineLoad(pose.node(k), pose.tangent(i), v, m.segments[i].outer_diameter).norm();
  }
  return c;
}

void SeabedRecorder::addColumns(Table& history) const {
  history.add("touchdown_arc_length", "m", {}, "Touchdown s_TD");
  history.add("seabed_contact_length", "m", {}, "Length on the bed");
  history.add("seabed_normal_force", "N", {}, "Bed normal force");
}

void SeabedRecorder::sample(const SeabedContactState& state, std::vector<double>& row) {
  row.insert(row.end(), {state.touchdown, state.contact_length, state.normal_force});
  if (first_) touchdown_start_ = touchdown_min_ = touchdown_max_ = state.touchdown;
  touchdown_min_ = std::min(touchdown_min_, state.touchdown);
  touchdown_max_ = std::max(touchdown_max_, state.touchdown);
  for (double f : state.node_line_load) max_line_load_ = std::max(max_line_load_, f);
  first_ = false;
}

void SeabedRecorder::addProfileColumn(const SeabedContactState& state, Table& profile) const {
  profile.add("seabed_line_load", "N/m", state.node_line_load, "Bed line load");
}

void SeabedRecorder::addPlot(Results& out) const {
  out.plots.push_back(makePlot("touchdown", "Touchdown point (arc length from the top) and length on the bed",
                               "history", "time", {"touchdown_arc_length", "seabed_contact_length"}));
}

void SeabedRecorder::addScalars(Results& out) const {
  out.addScalar("touchdown_arc_length", touchdown_start_, "m",
                "Arc length from the top of the first contact with the sea bed at the start (the static shape when "
                "statics ran; L when nothing touches)",
                "Touchdown s_TD at the start");
  out.addScalar("touchdown_arc_length_min", touchdown_min_, "m", "Smallest touchdown arc length over the run",
                "min s_TD");
  out.addScalar("touchdown_arc_length_max", touchdown_max_, "m", "Largest touchdown arc length over the run",
                "max s_TD");
  out.addScalar("max_seabed_line_load", max_line_load_, "N/m",
                "Largest contact force per unit length (normal and friction) at a node over the samples",
                "max bed line load");
}

Shape3D seabedSurface(const RiserSeabed& bed, const Eigen::Vector3d& centre, double half) {
  Shape3D s;
  s.kind = Shape3D::Kind::Surface;
  s.name = "sea bed";
  s.grid_u = s.grid_v = 2;
  for (int v = 0; v < 2; ++v)
    for (int u = 0; u < 2; ++u) {
      const double x = centre.x() + half * (2.0 * u - 1.0), y = centre.y() + half * (2.0 * v - 1.0);
      s.points.emplace_back(x, y, bed.heightAt(x, y));
    }
  s.color = Eigen::Vector3d(0.62, 0.52, 0.38);
  s.opacity = 0.9;
  return s;
}

}  // namespace maris::riser
