#include "riser/riser_loads.hpp"

#include <algorithm>
#include <cmath>

namespace maris::riser {
namespace {
constexpr double kLeastCosPitch = 1e-6;  // [-] see zyxRateMatrix

// Every row of the profile the same speed and heading (e.g. the linear type with equal speeds at surface and sea
// bed): CurrentProfile::at then gives the same numbers at every height below the water, and addDrag turns them to a
// segment's frame once instead of looking them up and turning them at each Gauss point (bit for bit the same loads).
bool uniformCurrent(const CurrentProfile& c) {
  if (c.speed.empty() || c.direction.size() != c.heading.size()) return false;
  for (std::size_t k = 1; k < c.speed.size(); ++k)
    if (c.speed[k] != c.speed[0] || c.heading[k] != c.heading[0]) return false;
  return true;
}
}  // namespace

void RiserPose::resize(int segment_count) {
  rotation.assign(segment_count, Mat3::Identity());
  position.assign(segment_count, Vec3::Zero());
  omega.assign(segment_count, Vec3::Zero());
  velocity.assign(segment_count, Vec3::Zero());
}

void SegmentLoads::resize(int segment_count) {
  force.assign(segment_count, Vec3::Zero());
  moment.assign(segment_count, Vec3::Zero());
  relative_angle.assign(segment_count, Vec3::Zero());
  spring_moment.assign(segment_count, Vec3::Zero());
}

Vec3 zyxAngles(const Mat3& r) {
  return Vec3(std::atan2(r(2, 1), r(2, 2)), -std::asin(std::clamp(r(2, 0), -1.0, 1.0)), std::atan2(r(1, 0), r(0, 0)));
}

Mat3 zyxRateMatrix(const Vec3& a) {
  // det G = cos θ. At a 90° bend the law itself is singular; there round-off can put θ exactly at ±π/2 (asin
  // of a clamped ±1: cos θ = 6e-17), and the couple of even a chain with EI ≈ 3e-10 N·m² became 1.6e7 N·m (a
  // falling chain, J, RK4 at h = 1e-4 s: energy balance error 0.88). |cos θ| is held at 1e-6 or more: this
  // changes G only within 1e-6 rad of the singularity and bounds the couple by 1e6 C·|Δφ|.
  const double cos_pitch = std::cos(a.y());
  const double ct = std::copysign(std::max(std::abs(cos_pitch), kLeastCosPitch), cos_pitch);
  const double st = std::sin(a.y()), cp = std::cos(a.z()), sp = std::sin(a.z());
  Mat3 g;
  g << ct * cp, -sp, 0, ct * sp, cp, 0, -st, 0, 1;
  return g;
}

void addSpringMoments(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads) {
  for (int i = 1; i <= m.n; ++i) {
    const Mat3& ra = pose.rotation[i - 1];
    const Mat3& rb = pose.rotation[i];
    // The five entries of R_{i-1}ᵀ R_i that the angles and G need (of nine): entry (j, k) is column j of R_{i-1}
    // dotted with column k of R_i, summed in the order of the 3×3 product, so the same numbers.
    auto rel = [&](int j, int k) { return ra.col(j).dot(rb.col(k)); };
    const double r00 = rel(0, 0), r10 = rel(1, 0), r20 = rel(2, 0), r21 = rel(2, 1), r22 = rel(2, 2);
    const Vec3 angles(std::atan2(r21, r22), -std::asin(std::clamp(r20, -1.0, 1.0)), std::atan2(r10, r00));
    // G of zyxRateMatrix(angles) without its sines and cosines (the profile's second-largest item): sin θ, cos θ
    // and (cos ψ, sin ψ) are read off the matrix the angles came from, and G, G^T are solved in closed form (the
    // first two rows of G are a turn by ψ of (cos θ x_0, x_1)) instead of by two LU factorisations.
    const double st = -std::clamp(r20, -1.0, 1.0);
    const double cos_pitch = std::sqrt((1 - st) * (1 + st));
    const double ct = std::max(cos_pitch, kLeastCosPitch);
    const double heading_norm = std::sqrt(r00 * r00 + r10 * r10);
    const double cp = heading_norm > 0 ? r00 / heading_norm : 1.0;
    const double sp = heading_norm > 0 ? r10 / heading_norm : 0.0;
    // Relative angle rates from the relative angular velocity seen in frame i-1: G rates = w.
    const Vec3 w = ra.transpose() * (pose.omega[i] - pose.omega[i - 1]);
    const double rate_x = (cp * w.x() + sp * w.y()) / ct;
    const Vec3 rates(rate_x, -sp * w.x() + cp * w.y(), w.z() + st * rate_x);
    const Vec3& c = m.joints[i].stiffness;
    const Vec3& b = m.joints[i].damping;
    const Vec3 mbar = c.cwiseProduct(angles) + b.cwiseProduct(rates);
    // G^T y = M̄: y_z = M̄_z, cos θ (cos ψ y_x + sin ψ y_y) − sin θ y_z = M̄_x, −sin ψ y_x + cos ψ y_y = M̄_y.
    const double along = (mbar.x() + st * mbar.z()) / ct;
    const Vec3 couple = ra * Vec3(cp * along - sp * mbar.y(), sp * along + cp * mbar.y(), mbar.z());
    loads.moment[i] -= couple;
    loads.moment[i - 1] += couple;
    loads.relative_angle[i] = angles;
    loads.spring_moment[i] = mbar;
    loads.power_damping -= rates.dot(b.cwiseProduct(rates));
  }
}

void addGravityAndBuoyancy(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads) {
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    const Vec3 t = pose.tangent(i);
    for (int q = 0; q < 3; ++q) {
      const double xi = kGaussX[q] * seg.length, w = kGaussW[q] * seg.length;
      const Vec3 p = pose.position[i] + xi * t;
      double fz = -seg.weight_per_length;
      if (p.z() < m.water_level) fz += seg.buoyancy_per_length;
      const Vec3 f(0, 0, factor * fz * w);
      loads.force[i] += f;
      loads.moment[i] += (xi * t).cross(f);
    }
  }
}

void addDrag(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads) {
  const bool uniform = uniformCurrent(m.current_profile);
  const Vec3 uniform_current = uniform ? m.currentAt(m.water_level) : Vec3::Zero();
  double power = loads.power_drag;  // summed here, in the same order: the compiler cannot keep a member in a register
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    if (seg.normal_drag == 0.0 && seg.tangential_drag == 0.0) continue;
    const Mat3& r = pose.rotation[i];
    const Vec3 t = r.col(0), n1 = r.col(1), n2 = r.col(2);
    // In the segment's frame, where the Gauss point's arm is ξ e_x: its velocity R^T v + (R^T ω) × ξ e_x, the
    // force's moment ξ e_x × f, both summed over the points and turned to the global frame once (two products
    // with R per segment instead of two per point: addDrag was the largest item of the profile). Written in scalars
    // with the terms that are zero left out (the x component of (R^T ω) × ξ e_x and of ξ e_x × f, and R^T ω's own x):
    // the same operations in the same order on the rest, so bit for bit the loads of the vector form, in under a
    // third of the time (Eigen's 3-vectors, built element by element and read two at a time, stalled on store
    // forwarding by the annotated profile).
    const Vec3& vg = pose.velocity[i];
    const Vec3& wg = pose.omega[i];
    const double vx = t.dot(vg), vy = n1.dot(vg), vz = n2.dot(vg);
    const double wy = n1.dot(wg), wz = n2.dot(wg);
    double ux = 0.0, uy = 0.0, uz = 0.0;
    if (uniform) ux = t.dot(uniform_current), uy = n1.dot(uniform_current), uz = n2.dot(uniform_current);
    const double length = seg.length, z0 = pose.position[i].z(), tz = t.z();
    const double tangential = -seg.tangential_drag, normal = -seg.normal_drag;
    double fx = 0.0, fy = 0.0, fz = 0.0, my = 0.0, mz = 0.0;
#pragma GCC unroll 3
    for (int q = 0; q < 3; ++q) {  // unrolled: rolled, the loop was 14 % slower than the lookups it saves
      const double xi = kGaussX[q] * length, w = kGaussW[q] * length;
      const double z = z0 + xi * tz;
      if (z > m.water_level) continue;
      const double py = vy + xi * wz, pz = vz - xi * wy;  // the point's velocity in the segment's frame (x: vx)
      if (!uniform) {
        const Vec3 c = m.currentAt(z);
        ux = t.dot(c), uy = n1.dot(c), uz = n2.dot(c);
      }
      const double lx = vx - ux, ly = py - uy, lz = pz - uz;
      const double vn = std::sqrt(ly * ly + lz * lz);
      const double scale = factor * w;
      const double gx = scale * (tangential * std::abs(lx) * lx), gy = scale * (normal * vn * ly),
                   gz = scale * (normal * vn * lz);
      fx += gx, fy += gy, fz += gz;
      my -= xi * gz;
      mz += xi * gy;
      power += gx * vx + gy * py + gz * pz;
    }
    loads.force[i] += t * fx + n1 * fy + n2 * fz;
    loads.moment[i] += n1 * my + n2 * mz;
  }
  loads.power_drag = power;
}

Vec3 curvatureVector(const RiserModel& m, const RiserPose& pose, int i) {
  // Stencil (left, middle, right) and the point where the derivative of the quadratic is taken.
  const int mid = std::clamp(i, 1, m.n - 1);
  auto centre = [&](int k) { return m.segments[k].arc_start + 0.5 * m.segments[k].length; };
  const double h1 = centre(mid) - centre(mid - 1), h2 = centre(mid + 1) - centre(mid);
  const Vec3 tl = pose.tangent(mid - 1), tm = pose.tangent(mid), tr = pose.tangent(mid + 1);
  if (i == mid)
    return -h2 / (h1 * (h1 + h2)) * tl + (h2 - h1) / (h1 * h2) * tm + h1 / (h2 * (h1 + h2)) * tr;
  if (i < mid)
    return -(2 * h1 + h2) / (h1 * (h1 + h2)) * tl + (h1 + h2) / (h1 * h2) * tm - h1 / (h2 * (h1 + h2)) * tr;
  return h2 / (h1 * (h1 + h2)) * tl - (h1 + h2) / (h1 * h2) * tm + (h1 + 2 * h2) / (h2 * (h1 + h2)) * tr;
}

void addInternalFlow(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads) {
  const double u = m.flow_speed;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    if (seg.fluid_mass_per_length == 0.0) continue;
    const Vec3 t = pose.tangent(i), arm = 0.5 * seg.length * t;
    const Vec3 tangent_rate = pose.omega[i].cross(t);
    const Vec3 f = -seg.fluid_mass_per_length * seg.length * (2 * u * tangent_rate + u * u * curvatureVector(m, pose, i));
    loads.force[i] += f;
    loads.moment[i] += arm.cross(f);
    loads.power_flow += f.dot(pose.velocity[i] + pose.omega[i].cross(arm));
  }
}

void addPointLoads(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads) {
  for (const auto& l : m.point_loads) {
    if (pose.time < l.start_time || pose.time >= l.end_time) continue;
    const Vec3 f = factor * Vec3(l.force_x, l.force_y, l.force_z);
    const Vec3 c = factor * Vec3(l.moment_x, l.moment_y, l.moment_z);
    const int seg = std::min(l.node, m.n);
    const Vec3 arm = l.node > m.n ? Vec3(m.segments[m.n].length * pose.tangent(m.n)) : Vec3::Zero();
    loads.force[seg] += f;
    loads.moment[seg] += arm.cross(f) + c;
    const Vec3 v = l.node > m.n ? pose.end_velocity : pose.velocity[seg];
    loads.power_point += f.dot(v) + c.dot(pose.omega[seg]);
  }
}

void addBottomSpring(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads) {
  const Vec3 f = -m.spring_stiffness * (pose.end_position - m.anchor) - m.spring_damping * pose.end_velocity;
  const Vec3 arm = m.segments[m.n].length * pose.tangent(m.n);
  loads.force[m.n] += f;
  loads.moment[m.n] += arm.cross(f);
  loads.support_force = f;
  loads.power_damping -= m.spring_damping * pose.end_velocity.squaredNorm();
}

void addRelaxationDamping(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads) {
  for (int i = 0; i <= m.n; ++i) {
    const Mat3& r = pose.rotation[i];
    Vec6 v;
    v << r.transpose() * pose.velocity[i], r.transpose() * pose.omega[i];
    const Vec6 f = -m.relaxation_damping * (m.segments[i].mass_local * v);
    loads.force[i] += r * f.head<3>();
    loads.moment[i] += r * f.tail<3>();
    loads.power_damping += f.dot(v);
  }
}

void computeLoads(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads) {
  for (int i = 0; i <= m.n; ++i) {
    loads.force[i].setZero();
    loads.moment[i].setZero();
  }
  loads.support_force.setZero();
  loads.power_drag = loads.power_damping = loads.power_point = loads.power_flow = 0.0;
  addSpringMoments(m, pose, loads);
  if (m.gravity > 0) addGravityAndBuoyancy(m, pose, factor, loads);
  if (m.sea)
    addMorisonInWaves(m, pose, factor, loads);
  else
    addDrag(m, pose, factor, loads);
  if (!m.point_loads.empty()) addPointLoads(m, pose, factor, loads);
  if (m.flow_speed != 0.0) addInternalFlow(m, pose, loads);
  if (m.bottom == BottomCondition::Spring) addBottomSpring(m, pose, loads);
  if (m.relaxation_damping > 0) addRelaxationDamping(m, pose, loads);
  if (m.seabed) addSeabedContact(m, pose, loads);
}

namespace {

double jointSpringEnergy(const Joint& joint, const Vec3& angles) {
  return 0.5 * angles.dot(joint.stiffness.cwiseProduct(angles));
}

}  // namespace

double springEnergy(const RiserModel& m, const RiserPose& pose) {
  double e = 0;
  for (int i = 1; i <= m.n; ++i)
    e += jointSpringEnergy(m.joints[i], zyxAngles(pose.rotation[i - 1].transpose() * pose.rotation[i]));
  return e;
}

double springEnergy(const RiserModel& m, const SegmentLoads& loads) {
  double e = 0;
  for (int i = 1; i <= m.n; ++i) e += jointSpringEnergy(m.joints[i], loads.relative_angle[i]);
  return e;
}

double gravityPotential(const RiserModel& m, const RiserPose& pose) {
  double e = 0;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    for (int q = 0; q < 3; ++q) {
      const double xi = kGaussX[q] * seg.length, w = kGaussW[q] * seg.length;
      const double z = (pose.position[i] + xi * pose.tangent(i)).z();
      // Buoyancy potential -ρ_w g A (z - z_w) below the surface, zero above: continuous, gradient = force.
      e += w * (seg.weight_per_length * z - seg.buoyancy_per_length * std::min(z - m.water_level, 0.0));
    }
  }
  return m.gravity > 0 ? e : 0.0;
}

double anchorSpringEnergy(const RiserModel& m, const RiserPose& pose) {
  if (m.bottom != BottomCondition::Spring) return 0.0;
  return 0.5 * m.spring_stiffness * (pose.end_position - m.anchor).squaredNorm();
}

double kineticEnergy(const RiserModel& m, const RiserPose& pose) {
  double e = 0;
  for (int i = 0; i <= m.n; ++i) {
    Vec6 v;
    v << pose.rotation[i].transpose() * pose.velocity[i], pose.rotation[i].transpose() * pose.omega[i];
    e += 0.5 * v.dot(m.segments[i].mass_local * v);
  }
  return e;
}

}  // namespace maris::riser
