#include "riser/riser_dynamics.hpp"
#include "riser/riser_inverse_mass.hpp"
#include "riser/riser_small_lu.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace maris::riser {
namespace {

constexpr int kHeader = 6;  // r_top, v_top

int stride(const RiserModel& m) { return m.formulation == Formulation::Joint ? 7 : 13; }
int segmentOffset(const RiserModel& m, int i) { return kHeader + (i - m.first_dynamic) * stride(m); }
int workOffset(const RiserModel& m) { return segmentOffset(m, m.last_dynamic + 1); }
// Within a segment's entries (layout in riser_dynamics.hpp).
int quaternionOffset(const RiserModel& m) { return m.formulation == Formulation::Joint ? 0 : 3; }
int angularVelocityOffset(const RiserModel& m) { return m.formulation == Formulation::Joint ? 4 : 10; }
constexpr int kVelocityOffset = 7;  // absolute coordinates only

// D'ᵀ x = a + α × d: acceleration of the far end of a segment from its (a, α).
Vec3 farEnd(const Vec6& x, const Vec3& d) { return x.head<3>() + x.tail<3>().cross(d); }

// Point the bottom end is held at: the anchor (pinned) or the origin of the fixed last segment (clamped).
Vec3 bottomHoldPoint(const RiserModel& m) {
  if (m.bottom != BottomCondition::Clamped) return m.anchor;
  return m.anchor - m.segments[m.n].length * m.initial_orientation[m.n].toRotationMatrix().col(0);
}

}  // namespace

RiserWorkspace makeWorkspace(const RiserModel& m, double stabilisation_rate) {
  RiserWorkspace ws;
  const int s = m.segmentCount();
  ws.pose.resize(s);
  ws.loads.resize(s);
  ws.inverse_mass.assign(s, Mat6::Zero());
  ws.bias.assign(s, Vec6::Zero());
  ws.acceleration.assign(s, Vec6::Zero());
  for (auto* v : {&ws.lower, &ws.diag, &ws.upper, &ws.pivot_upper}) v->assign(s + 1, Mat3::Zero());
  ws.rhs.assign(s + 1, Vec3::Zero());
  ws.reaction.assign(s + 1, Vec3::Zero());
  ws.stabilisation_rate = stabilisation_rate;
  return ws;
}

int stateSize(const RiserModel& m) { return workOffset(m) + kWorkIntegrals; }

Eigen::Index workIntegralOffset(const RiserModel& m) { return workOffset(m); }

Eigen::Index segmentStateOffset(const RiserModel& m, int i) { return segmentOffset(m, i); }

Eigen::Index orientationStateOffset(const RiserModel& m, int i) { return segmentOffset(m, i) + quaternionOffset(m); }

Eigen::Index angularVelocityStateOffset(const RiserModel& m, int i) {
  return segmentOffset(m, i) + angularVelocityOffset(m);
}

Eigen::Index velocityStateOffset(const RiserModel& m, int i) {
  if (m.formulation == Formulation::Joint) throw std::logic_error("velocityStateOffset: absolute coordinates only");
  return segmentOffset(m, i) + kVelocityOffset;
}

std::string stateComponentName(const RiserModel& m, Eigen::Index k) {
  static const char* axis[] = {"x", "y", "z"};
  static const char* quat[] = {"w", "x", "y", "z"};
  if (k < 3) return std::string("top position ") + axis[k];
  if (k < kHeader) return std::string("top velocity ") + axis[k - 3];
  static const char* work[] = {"work of drag", "work of dampers", "work of the supports", "work of internal flow"};
  if (k >= workOffset(m)) return work[std::min<Eigen::Index>(k - workOffset(m), kWorkIntegrals - 1)];
  const int i = m.first_dynamic + static_cast<int>((k - kHeader) / stride(m));
  const int c = static_cast<int>((k - kHeader) % stride(m));
  const std::string seg = "segment " + std::to_string(i) + " ";
  if (m.formulation == Formulation::Joint)
    return c < 4 ? seg + "orientation quaternion " + quat[c] : seg + "angular velocity " + axis[c - 4];
  if (c < 3) return seg + "position " + axis[c];
  if (c < 7) return seg + "orientation quaternion " + quat[c - 3];
  if (c < 10) return seg + "velocity " + axis[c - 7];
  return seg + "angular velocity " + axis[c - 10];
}

Eigen::VectorXd restState(const RiserModel& m, const std::vector<Eigen::Quaterniond>& orientation, const Vec3& top) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(stateSize(m));
  y.head<3>() = top;
  Vec3 r = top;
  for (int i = 0; i <= m.n; ++i) {
    if (m.isDynamic(i)) {
      const int o = segmentOffset(m, i);
      if (m.formulation == Formulation::Absolute) y.segment<3>(o) = r;
      const auto& q = orientation[i];
      y.segment<4>(o + quaternionOffset(m)) << q.w(), q.x(), q.y(), q.z();
    }
    r += m.segments[i].length * orientation[i].toRotationMatrix().col(0);
  }
  return y;
}

double knownTopForce(const RiserModel& m, int c, double t, const Vec3& top_position, const Vec3& top_velocity,
                     double load_factor) {
  if (m.axial_stiffness > 0 && c == 2) {
    const TopKinematics hang_off = m.topAt(t);
    const double stretch = hang_off.position.z() - top_position.z();
    const double rate = hang_off.velocity.z() - top_velocity.z();
    return m.axial_stiffness * (stretch + m.stiffness_damping * rate) + load_factor * m.axial_weight_share;
  }
  return m.top == TopCondition::Tensioner && c == 2 ? load_factor * m.top_tension : 0.0;
}

namespace {
// poseFromState with the top's kinematics at t given (evaluateRhs needs them three times: looked up once).
void poseFromTop(const RiserModel& m, const TopKinematics& top, double t, const Eigen::VectorXd& y, RiserPose& pose) {
  Vec3 rt = top.position, vt = top.velocity;
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m, c)) rt[c] = y[c], vt[c] = y[3 + c];
  pose.time = t;
  const int f = m.first_dynamic, last = m.last_dynamic;
  const bool joint = m.formulation == Formulation::Joint;
  Vec3 r = rt, v = vt;
  if (f == 1) {  // clamped top: segment 0 translates with the top without rotating
    pose.rotation[0] = m.initial_orientation[0].toRotationMatrix();
    pose.omega[0].setZero();
    pose.position[0] = rt;
    pose.velocity[0] = vt;
    r += m.segments[0].length * pose.rotation[0].col(0);
  }
  for (int i = f; i <= last; ++i) {
    const int o = segmentOffset(m, i), oq = o + quaternionOffset(m);
    const Eigen::Quaterniond q(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
    pose.rotation[i] = q.normalized().toRotationMatrix();
    Vec3 w = y.segment<3>(o + angularVelocityOffset(m));
    if (!m.torsion) w -= w.dot(pose.rotation[i].col(0)) * pose.rotation[i].col(0);
    pose.omega[i] = w;
    if (!joint) r = y.segment<3>(o), v = y.segment<3>(o + kVelocityOffset);
    pose.position[i] = r;
    pose.velocity[i] = v;
    const Vec3 d = m.segments[i].length * pose.rotation[i].col(0);
    r += d;
    v += w.cross(d);
  }
  if (last == m.n - 1) {  // clamped bottom: segment n fixed
    pose.rotation[m.n] = m.initial_orientation[m.n].toRotationMatrix();
    pose.omega[m.n].setZero();
    pose.position[m.n] = joint ? r : bottomHoldPoint(m);
    pose.velocity[m.n].setZero();
    pose.end_position = pose.position[m.n] + m.segments[m.n].length * pose.rotation[m.n].col(0);
    pose.end_velocity.setZero();
  } else {
    pose.end_position = r;
    pose.end_velocity = v;
  }
}

}  // namespace

void poseFromState(const RiserModel& m, double t, const Eigen::VectorXd& y, RiserPose& pose) {
  poseFromTop(m, m.topAt(t), t, y, pose);
}

namespace {
void prepareSegmentsAt(const RiserModel& m, const TopKinematics& top, RiserWorkspace& ws, double t,
                       const Eigen::VectorXd& y) {
  RiserPose& pose = ws.pose;
  poseFromTop(m, top, t, y, pose);
  computeLoads(m, pose, 1.0, ws.loads);
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const Segment& s = m.segments[i];
    const Mat3& r = pose.rotation[i];
    const Vec3& om = pose.omega[i];
    const Vec3 t = r.col(0);
    const Vec3 c = 0.5 * s.length * t;
    // ω × (I ω): the inertia about A_i is axisymmetric, I = a 1 + b t tᵀ in the global frame (riser_inverse_mass.hpp;
    // symmetric, so no [t]× part), and ω × (I ω) = b (t·ω) ω × t: no product with R at all.
    const double gyroscopic = axialBlockOf(s.mass_local.bottomRightCorner<3, 3>()).b * t.dot(om);
    ws.bias[i] << ws.loads.force[i] - s.mass * om.cross(om.cross(c)), ws.loads.moment[i] - gyroscopic * om.cross(t);
    // Tangential added mass unlike the normal one (K = m 1 + δ t tᵀ, v the velocity of A_i): the velocity terms of
    // Kirchhoff's equations for the kinetic energy ½ vᵀ K v + ..., ω×(Kv) − K(ω×v) in the force and the Munk
    // moment v×(Kv), so that the energy balance still closes; they vanish for an isotropic added mass.
    const double delta = s.axial_mass - s.mass;
    if (delta != 0.0) {
      const Vec3& v = pose.velocity[i];
      const double axial_speed = t.dot(v);
      ws.bias[i].head<3>() -= delta * (axial_speed * om.cross(t) - t.dot(om.cross(v)) * t);
      ws.bias[i].tail<3>() -= delta * axial_speed * v.cross(t);
    }
  }
}

}  // namespace

void prepareSegments(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y) {
  prepareSegmentsAt(m, m.topAt(t, ws.vessel_motion), ws, t, y);
}

namespace {
// constraintViolation into `out` (its vectors reused), the top's kinematics given. Without `inner_rows` the rows of
// the inner joints are left zero: joint coordinates satisfy them exactly, and evaluateRhs uses only the end rows
// there.
void fillConstraintViolation(const RiserModel& m, const RiserPose& pose, const TopKinematics& top, bool inner_rows,
                             ConstraintViolation& out) {
  const int f = m.first_dynamic, last = m.last_dynamic, nb = last - f + 2;
  out.position.assign(nb, Vec3::Zero());
  out.velocity.assign(nb, Vec3::Zero());
  out.largest = 0.0;
  Vec3 hold = top.position, hold_v = top.velocity;
  if (f == 1) hold += m.segments[0].length * pose.rotation[0].col(0);
  for (int c = 0; c < 3; ++c) {
    if (topForceKnown(m, c)) continue;
    out.position[0][c] = pose.position[f][c] - hold[c];
    out.velocity[0][c] = pose.velocity[f][c] - hold_v[c];
  }
  for (int k = 1; inner_rows && k < nb - 1; ++k) {
    const int j = f + k;
    const Vec3 dp = m.segments[j - 1].length * pose.rotation[j - 1].col(0);
    out.position[k] = pose.position[j - 1] + dp - pose.position[j];
    out.velocity[k] = pose.velocity[j - 1] + pose.omega[j - 1].cross(dp) - pose.velocity[j];
  }
  if (bottomHeld(m)) {
    const Vec3 dl = m.segments[last].length * pose.rotation[last].col(0);
    out.position[nb - 1] = pose.position[last] + dl - bottomHoldPoint(m);
    out.velocity[nb - 1] = pose.velocity[last] + pose.omega[last].cross(dl);
  }
  for (const Vec3& p : out.position) out.largest = std::max(out.largest, p.lpNorm<Eigen::Infinity>());
}
}  // namespace

ConstraintViolation constraintViolation(const RiserModel& m, const RiserPose& pose, double t) {
  ConstraintViolation out;
  fillConstraintViolation(m, pose, m.topAt(t), true, out);
  return out;
}

namespace {

// W_i's blocks of the dynamic segments (riser_inverse_mass.hpp) for one right-hand side, made at its start: a few
// operations per segment; per thread, so that nothing allocates per call.
const std::vector<SegmentInverseMass>& inverseMassBlocks(const RiserModel& m) {
  thread_local std::vector<SegmentInverseMass> blocks;
  blocks.resize(m.segmentCount());
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i)
    blocks[i] = segmentInverseMass(m.segments[i].inverse_mass_local, m.segments[i].length);
  return blocks;
}

// Stages 2-4: the block-tridiagonal matrix of the reactions (rows: top, inner joints, bottom). Row k couples
// F_{j-1}, F_j, F_{j+1} (j = f + k) through the segments above and below joint j: the far end of j-1 (D'ᵀ W D'),
// the origin of j (W's force block), W D' of each (riser_inverse_mass.hpp), all from the tangents.
void assembleReactionMatrix(const RiserModel& m, const std::vector<SegmentInverseMass>& w, RiserWorkspace& ws) {
  const RiserPose& pose = ws.pose;
  const int f = m.first_dynamic, last = m.last_dynamic, nb = last - f + 2;
  auto t = [&](int i) -> Vec3 { return pose.rotation[i].col(0); };
  Mat3 far_force_above = w[f].far_force.at(t(f));  // W D' top rows of the segment above row k
  ws.lower[0].setZero();
  ws.diag[0] = w[f].force.at(t(f));
  ws.upper[0] = -far_force_above;
  for (int c = 0; c < 3; ++c) {
    if (!topForceKnown(m, c)) continue;
    ws.diag[0].row(c) = Vec3::Unit(c).transpose();
    ws.upper[0].row(c).setZero();
  }
  for (int k = 1; k < nb - 1; ++k) {
    const int j = f + k;
    const Vec3 t_above = t(j - 1), t_below = t(j);
    const Mat3 far_force_below = w[j].far_force.at(t_below);
    ws.lower[k] = -far_force_above.transpose();
    ws.diag[k] = w[j].force.at(t_below) + w[j - 1].far_end.at(t_above);
    ws.upper[k] = -far_force_below;
    far_force_above = far_force_below;
  }
  const int k = nb - 1;
  ws.upper[k].setZero();
  if (bottomHeld(m)) {
    ws.lower[k] = -far_force_above.transpose();
    ws.diag[k] = w[last].far_end.at(t(last));
  } else {
    ws.lower[k].setZero();
    ws.diag[k].setIdentity();
  }
}

// Stage 5: the assembled system for right side ws.rhs into ws.reaction[f ..], by a block-Thomas sweep from both
// ends at once (a twisted factorisation): rows 0 … p−1 eliminated downwards (F_k = y_k − C_k F_{k+1}), rows
// nb−1 … p+1 upwards (F_k = z_k − E_k F_{k−1}), the two meeting in row p. Each sweep is a chain of dependent 3×3
// solves whose latency, not its arithmetic, sets the time; two independent chains of half the length run side by
// side in the processor, the same work in about half the time. Pivots by SmallLu3 (LU with partial pivoting).
// pivot −= A c and r −= A x, in scalars, each sum in the order of Eigen's 3×3 products (the same numbers): Eigen's
// fixed-size products here mixed packet and scalar accesses of the same stack slots (riser_small_lu.hpp).
inline void subtractCoupling(const Mat3& a, const Mat3& c, const Vec3& x, Mat3& pivot, Vec3& r) {
  for (int i = 0; i < 3; ++i) {
    const double a0 = a(i, 0), a1 = a(i, 1), a2 = a(i, 2);
    for (int j = 0; j < 3; ++j) pivot(i, j) -= a0 * c(0, j) + a1 * c(1, j) + a2 * c(2, j);
    r(i) -= a0 * x(0) + a1 * x(1) + a2 * x(2);
  }
}

// x −= c y in the same way.
inline void subtractProduct(const Mat3& c, const Vec3& y, Vec3& x) {
  const double y0 = y(0), y1 = y(1), y2 = y(2);
  for (int i = 0; i < 3; ++i) x(i) -= c(i, 0) * y0 + c(i, 1) * y1 + c(i, 2) * y2;
}

void solveReactionSystem(const RiserModel& m, RiserWorkspace& ws) {
  const int f = m.first_dynamic, nb = m.last_dynamic - f + 2, p = nb / 2;
  std::vector<Mat3>& c = ws.pivot_upper;  // C_k above row p, E_k below it
  Vec3* x = ws.reaction.data() + f;
  auto down = [&](int k) {  // row k eliminated with the rows above it
    Mat3 pivot = ws.diag[k];
    Vec3 r = ws.rhs[k];
    if (k > 0) subtractCoupling(ws.lower[k], c[k - 1], x[k - 1], pivot, r);
    const SmallLu3 lu(pivot);
    c[k] = lu.solve(ws.upper[k]);
    x[k] = lu.solve(r);
  };
  auto up = [&](int k) {  // row k eliminated with the rows below it
    Mat3 pivot = ws.diag[k];
    Vec3 r = ws.rhs[k];
    if (k < nb - 1) subtractCoupling(ws.upper[k], c[k + 1], x[k + 1], pivot, r);
    const SmallLu3 lu(pivot);
    c[k] = lu.solve(ws.lower[k]);
    x[k] = lu.solve(r);
  };
  for (int k = 0; k < p; ++k) {
    down(k);
    if (nb - 1 - k > p) up(nb - 1 - k);
  }
  Mat3 pivot = ws.diag[p];
  Vec3 r = ws.rhs[p];
  if (p > 0) subtractCoupling(ws.lower[p], c[p - 1], x[p - 1], pivot, r);
  if (p < nb - 1) subtractCoupling(ws.upper[p], c[p + 1], x[p + 1], pivot, r);
  x[p] = SmallLu3(pivot).solve(r);
  for (int k = p - 1; k >= 0; --k) subtractProduct(c[k], x[k + 1], x[k]);
  for (int k = p + 1; k < nb; ++k) subtractProduct(c[k], x[k - 1], x[k]);
}

// Baumgarte term 2αΦ̇ + α²Φ of row k (absolute coordinates; joint: only the bottom row).
Vec3 stabilisation(const RiserModel& m, const ConstraintViolation& phi, int k, double alpha) {
  const int nb = static_cast<int>(phi.position.size());
  if (m.formulation == Formulation::Joint && k < nb - 1) return Vec3::Zero();
  return 2 * alpha * phi.velocity[k] + alpha * alpha * phi.position[k];
}

}  // namespace

void evaluateRhs(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  const TopKinematics top = m.topAt(t, ws.vessel_motion);
  prepareSegmentsAt(m, top, ws, t, y);
  const RiserPose& pose = ws.pose;
  const int f = m.first_dynamic, last = m.last_dynamic, nb = last - f + 2;
  const bool joint = m.formulation == Formulation::Joint;
  const double alpha = ws.stabilisation_rate;
  ConstraintViolation& phi = ws.constraint_violation;  // its vectors reused: nothing allocates per call
  fillConstraintViolation(m, pose, top, !joint, phi);
  const std::vector<SegmentInverseMass>& w_blocks = inverseMassBlocks(m);
  assembleReactionMatrix(m, w_blocks, ws);
  auto d = [&](int i) -> Vec3 { return m.segments[i].length * pose.rotation[i].col(0); };
  auto kappa = [&](int i) -> Vec3 { return pose.omega[i].cross(pose.omega[i].cross(d(i))); };

  // Right sides: top row (prescribed acceleration, or known force components), continuity, bottom.
  // W_i b_i of the segment above row k, each computed once (written out, not a lambda: GCC kept that a call).
  Vec6 wb_above = w_blocks[f].apply(pose.rotation[f].col(0), ws.bias[f]);
  ws.rhs[0] = top.acceleration - (joint ? Vec3::Zero() : stabilisation(m, phi, 0, alpha)) - wb_above.head<3>();
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m, c)) ws.rhs[0][c] = knownTopForce(m, c, t, pose.position[f], pose.velocity[f]);
  for (int k = 1; k < nb - 1; ++k) {
    const int j = f + k;
    const Vec6 wb_below = w_blocks[j].apply(pose.rotation[j].col(0), ws.bias[j]);
    Vec3 row = kappa(j - 1);
    if (!joint) row += stabilisation(m, phi, k, alpha);  // joint coordinates: zero (their inner rows hold exactly)
    ws.rhs[k] = row + farEnd(wb_above, d(j - 1)) - wb_below.head<3>();
    wb_above = wb_below;
  }
  const bool held = bottomHeld(m);
  ws.rhs[nb - 1] = held ? Vec3(farEnd(wb_above, d(last)) + kappa(last) + stabilisation(m, phi, nb - 1, alpha))
                        : Vec3::Zero();
  solveReactionSystem(m, ws);
  double drift = phi.position[nb - 1].lpNorm<Eigen::Infinity>();
  if (!joint) drift = phi.largest;
  ws.constraint_drift = drift;

  // Stage 6: accelerations x_i = W_i (E F_i - D'_i F_{i+1} + b_i) and the state derivative.
  dy.resize(y.size());  // every entry is written below
  for (int i = f; i <= last; ++i) {
    Vec6 g = ws.bias[i];
    g.head<3>() += ws.reaction[i] - ws.reaction[i + 1];
    g.tail<3>() -= d(i).cross(ws.reaction[i + 1]);
    ws.acceleration[i] = w_blocks[i].apply(pose.rotation[i].col(0), g);
    const int o = segmentOffset(m, i), oq = o + quaternionOffset(m);
    const Vec3& w = pose.omega[i];
    const double qw = y[oq];
    const Vec3 qv = y.segment<3>(oq + 1);
    dy[oq] = -0.5 * w.dot(qv);
    dy.segment<3>(oq + 1) = 0.5 * (qw * w + w.cross(qv));
    dy.segment<3>(o + angularVelocityOffset(m)) = ws.acceleration[i].tail<3>();
    if (!joint) {
      dy.segment<3>(o) = pose.velocity[i];
      dy.segment<3>(o + kVelocityOffset) = ws.acceleration[i].head<3>();
    }
  }
  for (int c = 0; c < 3; ++c) {
    const bool free_c = topForceKnown(m, c);
    dy[c] = free_c ? y[3 + c] : top.velocity[c];
    dy[3 + c] = free_c && joint ? ws.acceleration[f][c] : 0.0;
  }
  const int ow = workOffset(m);
  dy[ow] = ws.loads.power_drag;
  dy[ow + 1] = ws.loads.power_damping;
  dy[ow + 2] = ws.reaction[f].dot(pose.velocity[f]) + ws.loads.power_point;
  dy[ow + 3] = ws.loads.power_flow;
}

void balanceResidual(const RiserModel& m, const RiserWorkspace& ws, double t, const std::vector<Vec6>& x,
                     const std::vector<Vec3>& reaction, std::vector<Vec6>& segment_residual,
                     std::vector<Vec3>& row_residual) {
  const RiserPose& pose = ws.pose;
  const int f = m.first_dynamic, last = m.last_dynamic, nb = last - f + 2;
  const ConstraintViolation phi = constraintViolation(m, pose, t);
  const double alpha = ws.stabilisation_rate;
  auto d = [&](int i) -> Vec3 { return m.segments[i].length * pose.rotation[i].col(0); };
  auto kappa = [&](int i) -> Vec3 { return pose.omega[i].cross(pose.omega[i].cross(d(i))); };
  segment_residual.resize(m.segmentCount());
  row_residual.resize(nb);
  for (int i = f; i <= last; ++i) {
    Vec6 g = ws.bias[i];
    g.head<3>() += reaction[i] - reaction[i + 1];
    g.tail<3>() -= d(i).cross(reaction[i + 1]);
    const SegmentInverseMass w = segmentInverseMass(m.segments[i].inverse_mass_local, m.segments[i].length);
    segment_residual[i] = x[i] - w.apply(pose.rotation[i].col(0), g);
  }
  const TopKinematics top = m.topAt(t);
  const bool joint = m.formulation == Formulation::Joint;
  row_residual[0] = x[f].head<3>() - top.acceleration + (joint ? Vec3::Zero() : stabilisation(m, phi, 0, alpha));
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m, c)) row_residual[0][c] = reaction[f][c] - knownTopForce(m, c, t, pose.position[f], pose.velocity[f]);
  for (int k = 1; k < nb - 1; ++k) {
    const int j = f + k;
    row_residual[k] = x[j].head<3>() - farEnd(x[j - 1], d(j - 1)) - kappa(j - 1) - stabilisation(m, phi, k, alpha);
  }
  const bool held = bottomHeld(m);
  row_residual[nb - 1] = held ? Vec3(farEnd(x[last], d(last)) + kappa(last) + stabilisation(m, phi, nb - 1, alpha))
                              : Vec3(reaction[last + 1]);
}

namespace {
// Turns the orientation quaternion at state offset oq by the small rotation vector θ (global).
void turnSegment(Eigen::VectorXd& y, Eigen::Index oq, const Vec3& theta) {
  const Eigen::Quaterniond q(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
  const double angle = theta.norm();
  const Eigen::Quaterniond turn =
      angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle)) : Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond rotated = (turn * q).normalized();
  y.segment<4>(oq) << rotated.w(), rotated.x(), rotated.y(), rotated.z();
}

// Translates every segment so that it starts where the one above ends, the first to the top's held
// coordinates. Orientations are kept, so positions become the ones joint coordinates would give them.
void closeJointsByTranslation(const RiserModel& m, RiserWorkspace& ws, double t, Eigen::VectorXd& y) {
  poseFromState(m, t, y, ws.pose);
  const ConstraintViolation phi = constraintViolation(m, ws.pose, t);
  Vec3 shift = -phi.position[0];
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const int k = i - m.first_dynamic;
    if (k > 0) shift += phi.position[k];
    y.segment<3>(segmentOffset(m, i)) += shift;
  }
}

// Removes a held bottom's mismatch (after closeJointsByTranslation, the sum of every joint's drift): the
// components the top may move in (force-known, e.g. a tensioner's z) by moving the whole chain, the others by
// turning all segments a little, δθ_i = λ × d_i / I_i (the least Σ I_i|δθ_i|² with P Σ δθ_i × d_i = −P Φ_bottom,
// P the held top components; a 3×3 system), the chain below each turn translated after it. The least-squares
// solve leaves what no turn can remove (along a straight chain) to Baumgarte.
void spreadBottomMismatch(const RiserModel& m, RiserWorkspace& ws, double t, Eigen::VectorXd& y) {
  const int f = m.first_dynamic, last = m.last_dynamic, nb = last - f + 2;
  Mat3 held = Mat3::Identity();
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m, c)) held(c, c) = 0.0;
  poseFromState(m, t, y, ws.pose);
  const ConstraintViolation phi = constraintViolation(m, ws.pose, t);
  const Vec3 mismatch = held * phi.position[nb - 1];
  auto inverseInertia = [&](int i) { return 12.0 / (m.segments[i].mass * m.segments[i].length * m.segments[i].length); };
  Mat3 a = Mat3::Zero();
  for (int i = f; i <= last; ++i) {
    const Vec3 d = m.segments[i].length * ws.pose.rotation[i].col(0);
    a += (d.squaredNorm() * Mat3::Identity() - d * d.transpose()) * inverseInertia(i);
  }
  const Vec3 lambda = held * (held * a * held).completeOrthogonalDecomposition().solve(mismatch);
  for (int i = f; i <= last; ++i) {
    const Vec3 turn = lambda.cross(m.segments[i].length * ws.pose.rotation[i].col(0)) * inverseInertia(i);
    turnSegment(y, orientationStateOffset(m, i), turn);
  }
  closeJointsByTranslation(m, ws, t, y);
  if (held == Mat3::Identity()) return;
  poseFromState(m, t, y, ws.pose);
  const ConstraintViolation after = constraintViolation(m, ws.pose, t);
  const Vec3 shift = -(Mat3::Identity() - held) * after.position[nb - 1];
  for (int i = f; i <= last; ++i) y.segment<3>(segmentOffset(m, i)) += shift;
}
}  // namespace

double projectConstraints(const RiserModel& m, RiserWorkspace& ws, double t, Eigen::VectorXd& y, int iterations) {
  if (m.formulation == Formulation::Joint) return 0.0;
  // Measured with generalized-α, A3. The mass-weighted projection of every row closes a joint by turning the
  // short segments next to it (a rotation moves a far end at 1/12 of a translation's kinetic cost), which
  // kinks the chain; the bending springs answer with accelerations of 1e7 and Newton fails: the free 3D cable
  // of riser_work_precision at n = 400, 0.16 s steps: 213 of 1062 steps rejected (by translation: 13, none);
  // case 5 at n = 400, 0.4 s: 764 steps for 90 (spread over all rotations: 153); a slack cable held at both
  // ends, n = 100, T/25: 441 steps, 107 rejected (spread: 90, 12). Spreading cost case 5 12 % of accuracy at
  // 50 ms (5.8e-4 against 5.2e-4) and saved 30 % of the time at n = 400.
  // Velocities are not projected: their joint mismatch is left to Baumgarte. Removed by translation, which is
  // not the mass-orthogonal projection, it changed the momentum at every step and made the method first order
  // where segments turn fast. Measured on a falling, whipping chain (n = 10, A2, h = 2.5 ms to 0.156 ms halved
  // four times): end-point error before the snap 1.3e-3 … 8.3e-5 of L (ratio 2.0) with the velocities
  // translated, 2.8e-5 … 1.8e-6 (ratio 4) without; on the cables and case 5 the errors, steps and rejections
  // changed by under 15 % (bench rows of docs/riser_work_precision.md). Earlier, the top's velocity mismatch
  // carried down the chain made the cable first order (n = 20: 4.6e-3 at 20 ms against 1.6e-4), and projected
  // mass-weighted it kinked the top (n = 400: 41 of 204 steps rejected).
  // spreadBottomMismatch closes the joints it opens itself, so each sweep starts from closed joints.
  const bool held = bottomHeld(m);
  closeJointsByTranslation(m, ws, t, y);
  for (int it = 0; held && it < std::max(iterations, 1); ++it) spreadBottomMismatch(m, ws, t, y);
  poseFromState(m, t, y, ws.pose);
  return constraintViolation(m, ws.pose, t).largest;
}

void normaliseState(const RiserModel& m, Eigen::VectorXd& y) {
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const int o = segmentOffset(m, i), oq = o + quaternionOffset(m);
    y.segment<4>(oq).normalize();
    if (m.torsion) continue;
    const Eigen::Quaterniond q(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
    const Vec3 t = q.toRotationMatrix().col(0);
    auto w = y.segment<3>(o + angularVelocityOffset(m));
    w -= w.dot(t) * t;
  }
}

double totalEnergy(const RiserModel& m, const RiserPose& pose) {
  return kineticEnergy(m, pose) + springEnergy(m, pose) + gravityPotential(m, pose) + anchorSpringEnergy(m, pose) +
         seabedContactEnergy(m, pose);
}

double highestFrequencyEstimate(const RiserModel& m) {
  const double delta = m.element_length;
  double tension = m.top == TopCondition::Tensioner ? m.top_tension : 0.0;
  if (m.axial_stiffness > 0) {
    // The spring's pull at rest plus the stretch of the top's largest horizontal excursion a, a²/(2L).
    const double a = m.motion_amplitude.head<2>().norm();
    const double stretch = m.top_mean.z() - m.initial_top.z() + m.motion_amplitude.z() + a * a / (2 * m.length);
    tension = m.axial_stiffness * std::max(stretch, 0.0) + m.axial_weight_share;
  }
  double mu_min = 1e300;
  for (const auto& s : m.segments) {
    tension += std::abs(s.weight_per_length - s.buoyancy_per_length) * s.length;
    mu_min = std::min(mu_min, s.mass / s.length);
  }
  for (const auto& l : m.point_loads) tension += Vec3(l.force_x, l.force_y, l.force_z).norm();
  double w = 4 * std::sqrt(tension / mu_min) / delta;
  for (int i = 1; i <= m.n; ++i) {
    const Segment& s = m.segments[i];
    const double mu = s.mass / s.length, polar = s.mass_local(3, 3) / s.length;
    w = std::max(w, 9 * std::sqrt(m.joints[i].stiffness[1] * delta / mu) / (delta * delta));
    if (m.torsion && polar > 0) w = std::max(w, 2 * std::sqrt(m.joints[i].stiffness[0] * delta / polar) / delta);
  }
  if (m.bottom == BottomCondition::Spring) w = std::max(w, 2 * std::sqrt(m.spring_stiffness / m.segments[m.n].mass));
  w = std::max(w, seabedFrequencyEstimate(m));
  // Overdamped spring dampers add a real eigenvalue of about -β ω².
  return w * std::max(1.0, m.stiffness_damping * w);
}

}  // namespace maris::riser
