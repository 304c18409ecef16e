#include "riser/riser_model.hpp"
#include "riser/riser_vessel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/angles.hpp"
#include "riser/riser_buoyancy.hpp"
#include "riser/riser_piecewise_catenary.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

// Section properties at arc length s: the last `sections` row covering s, else the uniform section.
SectionRow sectionAt(const RiserParameters& p, double s) {
  SectionRow r{0.0, p.length, p.outer_diameter, p.inner_diameter, p.youngs_modulus, p.shear_modulus, p.density,
               p.normal_drag_coefficient, p.tangential_drag_coefficient, p.added_mass_coefficient,
               p.tangential_added_mass_coefficient};
  for (const auto& row : p.sections)
    if (s >= row.start && s < row.end) r = row;
  return r;
}

// Newton-Euler mass matrix of a uniform straight segment about its origin, in its own frame:
// [[K, -m[c]x], [m[c]x, I_A]] with c = (l/2) e1, K = diag(m_t, m, m), I_A = diag(ι l, m l²/3 + ι l/2, m l²/3 + ι l/2)
// (slender rod about its end, polar inertia ι per length: J = diag(μ l³/3, ι l/2, ι l/2), I' = tr(J) 1 - J).
// m is the mass with the normal added mass, m_t with the tangential one: the axial added mass enters only
// K(0,0), since ω × c and the moments are across the axis.
Mat6 segmentMass(double mass, double axial_mass, double length, double polar_inertia_per_length) {
  const Vec3 c(length / 2, 0, 0);
  const double transverse = mass * length * length / 3.0 + polar_inertia_per_length * length / 2.0;
  Mat6 m = Mat6::Zero();
  m.topLeftCorner<3, 3>() = Vec3(axial_mass, mass, mass).asDiagonal();
  m.topRightCorner<3, 3>() = -mass * skew(c);
  m.bottomLeftCorner<3, 3>() = mass * skew(c);
  m.bottomRightCorner<3, 3>() = Vec3(polar_inertia_per_length * length, transverse, transverse).asDiagonal();
  return m;
}

// Inverse mass; without torsion the spin about x' is not a degree of freedom, so the inverse is
// taken on the 5-dimensional subspace (a, α_y', α_z') and is zero in the spin direction.
Mat6 inverseMass(const Mat6& m, bool torsion) {
  if (torsion) return m.inverse();
  Eigen::Matrix<double, 6, 5> q = Eigen::Matrix<double, 6, 5>::Zero();
  const int keep[5] = {0, 1, 2, 4, 5};
  for (int k = 0; k < 5; ++k) q(keep[k], k) = 1.0;
  const Eigen::Matrix<double, 5, 5> reduced = q.transpose() * m * q;
  return q * reduced.inverse() * q.transpose();
}

// Joint positions of the initial shape: a circular arc of length L from `a` to `b` sagging
// towards -z (the chord must be shorter than L), sampled at the joints' arc lengths.
std::vector<Vec3> arcPoints(const Vec3& a, const Vec3& b, double length, const std::vector<double>& s) {
  const Vec3 chord = b - a;
  const double c = chord.norm();
  const Vec3 along = c > 1e-12 * length ? Vec3(chord / c) : Vec3::UnitX();
  Vec3 bulge = -Vec3::UnitZ() - along * (-along.z());
  if (bulge.norm() < 1e-6) bulge = Vec3::UnitX() - along * along.x();
  bulge.normalize();
  // Half angle φ with sin φ / φ = c/L, by bisection on (0, π].
  double lo = 1e-12, hi = pi;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (std::sin(mid) / mid > c / length ? lo : hi) = mid;
  }
  const double phi = 0.5 * (lo + hi), radius = length / (2 * phi);
  const Vec3 middle = 0.5 * (a + b);
  std::vector<Vec3> out;
  for (double sk : s) {
    const double th = sk / radius - phi;
    out.push_back(middle + radius * std::sin(th) * along + radius * (std::cos(th) - std::cos(phi)) * bulge);
  }
  return out;
}

}  // namespace

Vec3 RiserModel::currentAt(double z) const { return current_profile.at(z); }

TopKinematics TopMotionSpline::at(double t) const {
  const std::size_t last = time.size() - 1;
  if (t < time.front()) return {value.front(), Vec3::Zero(), Vec3::Zero()};
  if (t > time[last]) return {value[last], Vec3::Zero(), Vec3::Zero()};
  const std::size_t above = static_cast<std::size_t>(std::upper_bound(time.begin(), time.end(), t) - time.begin());
  const std::size_t k = std::min(above, last) - 1;  // interval [t_k, t_k+1] containing t (t = t_last: the last one)
  const double h = time[k + 1] - time[k], a = (time[k + 1] - t) / h, b = (t - time[k]) / h;
  const Vec3 &m0 = curvature[k], &m1 = curvature[k + 1];
  TopKinematics out;
  out.position = a * value[k] + b * value[k + 1] + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * (h * h / 6);
  out.velocity = (value[k + 1] - value[k]) / h + ((1 - 3 * a * a) * m0 + (3 * b * b - 1) * m1) * (h / 6);
  out.acceleration = a * m0 + b * m1;
  return out;
}

// Clamped spline (end slopes 0): tridiagonal system for the knot second derivatives, Thomas algorithm.
TopMotionSpline buildTopMotionSpline(const std::vector<TopMotionRow>& rows, bool vertical_free) {
  TopMotionSpline s;
  for (const auto& r : rows) {
    s.time.push_back(r.time);
    s.value.emplace_back(r.x, r.y, vertical_free ? 0.0 : r.z);
  }
  const std::size_t n = s.time.size();
  if (n < 2) return {};
  std::vector<double> lower(n, 0.0), diag(n, 0.0), upper(n, 0.0);
  std::vector<Vec3> rhs(n, Vec3::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    const double hl = k > 0 ? s.time[k] - s.time[k - 1] : 0.0, hr = k + 1 < n ? s.time[k + 1] - s.time[k] : 0.0;
    const Vec3 sl = k > 0 ? Vec3((s.value[k] - s.value[k - 1]) / hl) : Vec3::Zero();
    const Vec3 sr = k + 1 < n ? Vec3((s.value[k + 1] - s.value[k]) / hr) : Vec3::Zero();
    lower[k] = hl;
    diag[k] = 2 * (hl + hr);
    upper[k] = hr;
    rhs[k] = 6 * (sr - sl);
  }
  for (std::size_t k = 1; k < n; ++k) {
    const double w = lower[k] / diag[k - 1];
    diag[k] -= w * upper[k - 1];
    rhs[k] -= w * rhs[k - 1];
  }
  s.curvature.assign(n, Vec3::Zero());
  s.curvature[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t k = n - 1; k-- > 0;) s.curvature[k] = (rhs[k] - upper[k] * s.curvature[k + 1]) / diag[k];
  return s;
}

TopKinematics RiserModel::topAt(double t, VesselMotionCache& cache) const {
  if (!vessel) return topAt(t);
  if (cache.vessel != vessel || !(cache.time == t)) {
    cache.vessel = vessel;
    cache.time = t;
    cache.motion = vessel->at(t);
  }
  TopKinematics k = cache.motion;
  k.position += top_mean;
  return k;
}

TopKinematics RiserModel::topAt(double t) const {
  if (vessel) {
    TopKinematics k = vessel->at(t);
    k.position += top_mean;
    return k;
  }
  if (!top_table.empty()) {
    TopKinematics k = top_table.at(t);
    k.position += top_mean;
    return k;
  }
  // Quintic smooth step g(τ) = τ³(10 - 15τ + 6τ²) so position, velocity and acceleration start at zero.
  double g = 1, gd = 0, gdd = 0;
  if (ramp_time > 0 && t < ramp_time) {
    const double tau = std::max(t, 0.0) / ramp_time;
    g = tau * tau * tau * (10 - 15 * tau + 6 * tau * tau);
    gd = 30 * tau * tau * (1 - tau) * (1 - tau) / ramp_time;
    gdd = 60 * tau * (1 - tau) * (1 - 2 * tau) / (ramp_time * ramp_time);
  }
  TopKinematics k{top_mean, Vec3::Zero(), Vec3::Zero()};
  for (int a = 0; a < 3; ++a) {
    const double w = motion_omega, ph = w * t + motion_phase[a], amp = motion_amplitude[a];
    const double h = amp * (std::sin(ph) - std::sin(motion_phase[a]));  // zero at t = 0
    const double hd = amp * w * std::cos(ph), hdd = -amp * w * w * std::sin(ph);
    k.position[a] += g * h;
    k.velocity[a] = gd * h + g * hd;
    k.acceleration[a] = gdd * h + 2 * gd * hd + g * hdd;
  }
  return k;
}

std::pair<int, double> RiserModel::locate(double s) const {
  int i = static_cast<int>(std::floor(s / element_length + 0.5));
  i = std::clamp(i, 0, n);
  return {i, std::clamp(s - segments[i].arc_start, 0.0, segments[i].length)};
}

bool topForceKnown(const RiserModel& m, int c) {
  return m.top == TopCondition::Free || ((m.top == TopCondition::Tensioner || m.axial_stiffness > 0) && c == 2);
}

bool bottomHeld(const RiserModel& m) {
  return m.bottom == BottomCondition::Pinned || m.bottom == BottomCondition::Clamped;
}

RiserModel buildRiserModel(const RiserParameters& p) {
  RiserModel m;
  m.n = p.segment_count;
  m.length = p.length;
  m.element_length = p.length / p.segment_count;
  const double d = m.element_length;
  m.formulation = p.formulation == "absolute" ? Formulation::Absolute : Formulation::Joint;
  m.torsion = p.torsion;
  m.stiffness_damping = p.stiffness_damping;
  m.gravity = p.gravity;
  m.water_level = p.water_level;
  m.seabed_level = p.seabed_level;
  // Segments: lengths Δ/2, Δ, ..., Δ/2; each takes the section at its centre.
  for (int i = 0; i <= m.n; ++i) {
    Segment g;
    g.length = (i == 0 || i == m.n) ? d / 2 : d;
    g.arc_start = i == 0 ? 0.0 : (i - 0.5) * d;
    const SectionRow sec = sectionAt(p, g.arc_start + g.length / 2);
    const double a_out = pi / 4 * sec.outer_diameter * sec.outer_diameter;
    const double a_inn = pi / 4 * sec.inner_diameter * sec.inner_diameter;
    const double wall_mass = sec.density * (a_out - a_inn), contents = p.internal_fluid_density * a_inn;
    double mu = wall_mass + contents + p.water_density * sec.added_mass_coefficient * a_out;  // eq (11)
    double mu_axial = wall_mass + contents + p.water_density * sec.tangential_added_mass_coefficient * a_out;
    const double polar = sec.density * pi / 32 * (std::pow(sec.outer_diameter, 4) - std::pow(sec.inner_diameter, 4));
    g.outer_diameter = sec.outer_diameter;
    g.weight_per_length = (wall_mass + contents) * p.gravity;
    g.buoyancy_per_length = p.water_density * p.gravity * a_out;
    g.normal_drag = 0.5 * p.water_density * sec.outer_diameter * sec.normal_drag_coefficient;
    g.tangential_drag = 0.5 * p.water_density * sec.outer_diameter * sec.tangential_drag_coefficient;
    g.fluid_mass_per_length = contents;
    g.fluid_inertia_per_length = p.water_density * (1.0 + sec.added_mass_coefficient) * a_out;
    // Buoyancy modules: covered fraction f of the segment takes the modules' diameter and mass (riser_buoyancy.hpp).
    const ModuleShare modules = buoyancyModuleShare(p, g.arc_start, g.arc_start + g.length);
    if (modules.fraction > 0) {
      const double bare = 1.0 - modules.fraction, area = bare * a_out + modules.area;
      const double added = bare * sec.added_mass_coefficient * a_out + modules.added_mass_area;
      mu = wall_mass + contents + modules.mass_per_length + p.water_density * added;
      mu_axial = wall_mass + contents + modules.mass_per_length +
                 p.water_density * sec.tangential_added_mass_coefficient * area;
      g.outer_diameter = std::sqrt(4 * area / pi);
      g.weight_per_length = (wall_mass + contents + modules.mass_per_length) * p.gravity;
      g.buoyancy_per_length = p.water_density * p.gravity * area;
      g.normal_drag =
          0.5 * p.water_density * (bare * sec.outer_diameter * sec.normal_drag_coefficient + modules.drag_width);
      g.tangential_drag = 0.5 * p.water_density * g.outer_diameter * sec.tangential_drag_coefficient;
      g.fluid_inertia_per_length = p.water_density * (area + added);
    }
    g.mass = mu * g.length;
    g.axial_mass = mu_axial * g.length;
    g.mass_local = segmentMass(g.mass, g.axial_mass, g.length, polar);
    g.inverse_mass_local = inverseMass(g.mass_local, m.torsion);
    m.segments.push_back(g);
  }
  // Joints: stiffness of the primary element they represent, C = (GJ, EI, EI)/Δ (rigid-FE rule; the paper prints none).
  m.joints.resize(m.n + 1);
  for (int i = 1; i <= m.n; ++i) {
    const SectionRow sec = sectionAt(p, (i - 0.5) * d);
    const double i4 = std::pow(sec.outer_diameter, 4) - std::pow(sec.inner_diameter, 4);
    const double second_moment = pi / 64 * i4;
    Joint& j = m.joints[i];
    j.stiffness = Vec3(sec.shear_modulus * 2 * second_moment * (m.torsion ? 1.0 : 0.0),
                       sec.youngs_modulus * second_moment, sec.youngs_modulus * second_moment) / d;
    j.damping = p.stiffness_damping * j.stiffness;
    j.bending_modulus = pi / 32 * i4 / sec.outer_diameter;
    j.torsion_modulus = pi / 16 * i4 / sec.outer_diameter;
    j.wall_area = pi / 4 * (sec.outer_diameter * sec.outer_diameter - sec.inner_diameter * sec.inner_diameter);
    j.wall_thickness = 0.5 * (sec.outer_diameter - sec.inner_diameter);
  }
  // Boundary conditions and loads.
  const auto& tc = p.top_condition;
  m.top = tc == "pinned" ? TopCondition::Pinned : tc == "clamped" ? TopCondition::Clamped
        : tc == "free"   ? TopCondition::Free   : TopCondition::Tensioner;
  const auto& bc = p.bottom_condition;
  m.bottom = bc == "pinned" ? BottomCondition::Pinned : bc == "clamped" ? BottomCondition::Clamped
           : bc == "free"   ? BottomCondition::Free   : BottomCondition::Spring;
  m.first_dynamic = m.top == TopCondition::Clamped ? 1 : 0;
  m.last_dynamic = m.bottom == BottomCondition::Clamped ? m.n - 1 : m.n;
  m.top_tension = p.top_tension;
  m.anchor = Vec3(p.bottom_x, p.bottom_y, p.bottom_z);
  m.spring_stiffness = p.bottom_spring_stiffness;
  m.spring_damping = p.bottom_spring_damping;
  if (p.axial_flexibility) {
    double compliance = 0.0, submerged = 0.0;  // Σ Δ/(E A) [m/N]; submerged weight [N]
    for (int i = 1; i <= m.n; ++i) compliance += d / (sectionAt(p, (i - 0.5) * d).youngs_modulus * m.joints[i].wall_area);
    for (const Segment& g : m.segments) submerged += (g.weight_per_length - g.buoyancy_per_length) * g.length;
    m.axial_stiffness = compliance > 0 ? 1.0 / compliance : 0.0;
    m.axial_weight_share = 0.5 * submerged;
  }
  m.motion_amplitude = Vec3(p.motion_amplitude_x, p.motion_amplitude_y, p.motion_amplitude_z);
  if (m.top == TopCondition::Tensioner) m.motion_amplitude.z() = 0.0;
  if (m.top == TopCondition::Free) m.motion_amplitude.setZero();
  m.motion_phase = Vec3(p.motion_phase_x_deg, p.motion_phase_y_deg, p.motion_phase_z_deg) * kRadiansPerDegree;
  m.motion_omega = 2 * pi / p.motion_period;
  m.ramp_time = p.motion_ramp_time;
  if (p.top_motion == "table" && m.top != TopCondition::Free)
    m.top_table = buildTopMotionSpline(p.top_motion_table, m.top == TopCondition::Tensioner);
  m.flow_speed = p.internal_flow_speed;
  m.current_surface = p.current_speed_surface;
  m.current_seabed = p.current_speed_seabed;
  m.current_direction = radiansFromDegrees(p.current_direction_deg);
  m.current_profile = buildCurrentProfile(p);
  m.point_loads = p.point_loads;
  m.sea = buildRiserSea(p);
  m.seabed = buildRiserSeabed(p);

  // Initial shape: joint positions, then frames by parallel transport of the tangents.
  std::vector<double> s(m.n + 2);
  for (int i = 0; i <= m.n; ++i) s[i] = m.segments[i].arc_start;
  s[m.n + 1] = m.length;
  Vec3 top(p.top_x + p.vessel_offset_x, p.top_y + p.vessel_offset_y, p.top_z + p.vessel_offset_z);
  const bool fixed_bottom = bottomHeld(m);
  std::vector<Vec3> points;
  const Vec3 hang_off = top;
  const bool axial = m.axial_stiffness > 0;
  if (m.top == TopCondition::Tensioner || axial) {
    const double h = std::hypot(top.x() - m.anchor.x(), top.y() - m.anchor.y());
    top.z() = m.anchor.z() + std::sqrt(std::max(p.length * p.length - h * h, 0.0));
  }
  if (m.top == TopCondition::Tensioner || axial) {
    const Vec3 dir = (m.anchor - top).normalized();
    for (double sk : s) points.push_back(top + sk * dir);
  } else if (fixed_bottom && m.top != TopCondition::Free && (m.anchor - top).norm() < p.length) {
    // Weight changing along the riser (buoyancy modules): the catenary piece by piece, sag and hog bends in place.
    if (submergedWeightVaries(m.segments)) {
      if (const auto line = piecewiseCatenary(m.segments, m.seabed.get(), top, m.anchor, p.length, s)) points = line->points;
    }
    // On a bed the sagging arc would bury its lower part: start from the cable catenary resting on the bed.
    if (m.seabed && points.empty()) points = seabedInitialPoints(*m.seabed, top, m.anchor, p.length, s);
    if (points.empty()) points = arcPoints(top, m.anchor, p.length, s);
  } else {
    const double inclination = radiansFromDegrees(p.initial_inclination_deg);
    const double azimuth = radiansFromDegrees(p.initial_azimuth_deg);
    const Vec3 dir(std::sin(inclination) * std::cos(azimuth), std::sin(inclination) * std::sin(azimuth),
                   -std::cos(inclination));
    for (double sk : s) points.push_back(top + sk * dir);
  }
  m.initial_top = top;
  m.top_mean = axial ? hang_off : top;
  if (p.top_motion == "vessel" && m.top != TopCondition::Free && m.sea)
    m.vessel = buildVesselMotion(p, m.sea, m.top_mean, m.top == TopCondition::Tensioner);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Vec3 previous = Vec3::UnitX();
  for (int i = 0; i <= m.n; ++i) {
    Vec3 t = points[i + 1] - points[i];
    t = t.norm() > 0 ? Vec3(t.normalized()) : previous;
    q = (Eigen::Quaterniond::FromTwoVectors(previous, t) * q).normalized();
    m.initial_orientation.push_back(q);
    previous = t;
  }
  return m;
}

}  // namespace maris::riser
