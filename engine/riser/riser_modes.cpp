#include "riser/riser_modes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "core/text_format.hpp"
#include "riser/riser_dynamics.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;
// Eigenvalues with |Re λ| ≤ kOnAxis |λ| are on the imaginary axis: the differenced Jacobians leave
// ≈ 1e-14 (measured on case 3 with either flow term alone).
constexpr double kOnAxis = 1e-6;
// Up to kSlowGrowth |λ| (0.6 % amplitude growth per period) an oscillatory eigenvalue keeps its frequency and
// counts as slowly growing; the coarse chain with internal flow has such modes (4.5e-6 at n = 10, 10 m/s).
constexpr double kSlowGrowth = 1e-3;

// Perturbation coordinates at the equilibrium, each dimensionless (lengths divided by `scale`):
// J: free top axes (scale L) and rotation increments; A: segment origin positions (scale Δ) and rotations.
struct Coordinates {
  std::vector<int> top_axes;                     // J only
  std::vector<std::pair<int, int>> positions;    // A only: segment, global axis
  std::vector<std::pair<int, Vec3>> rotations;   // segment, global rotation axis
  int size() const { return static_cast<int>(top_axes.size() + positions.size() + rotations.size()); }
};

// The model the modes are computed for: no dampers, no top motion, no timed loads. Drag stays: at rest
// it is the current's load on the static shape, which the equilibrium balances (f(q0) = 0 is needed
// for the linearisation not to depend on the coordinates); only its dependence on the segment
// orientations and depths enters A, its velocity dependence (damping) does not.
RiserModel undampedModel(const RiserModel& model, Formulation linearisation) {
  RiserModel m = model;
  m.formulation = linearisation;
  m.motion_amplitude.setZero();
  for (auto& j : m.joints) j.damping.setZero();
  m.point_loads.erase(std::remove_if(m.point_loads.begin(), m.point_loads.end(),
                                     [](const PointLoadRow& l) { return l.start_time > 0.0; }),
                      m.point_loads.end());
  return m;
}

Coordinates makeCoordinates(const RiserModel& m, const StaticSolution& statics) {
  Coordinates q;
  const bool joint = m.formulation == Formulation::Joint;
  for (int c = 0; c < 3 && joint; ++c)
    if (topForceKnown(m, c)) q.top_axes.push_back(c);
  for (int i = m.first_dynamic; i <= m.last_dynamic && !joint; ++i)
    for (int c = 0; c < 3; ++c) q.positions.push_back({i, c});
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const Mat3 r = statics.orientation[i].toRotationMatrix();
    if (m.torsion) {
      for (int c = 0; c < 3; ++c) q.rotations.push_back({i, Vec3::Unit(c)});
    } else {
      q.rotations.push_back({i, r.col(1)});
      q.rotations.push_back({i, r.col(2)});
    }
  }
  return q;
}

// Offset of segment i's block in the absolute-coordinate state (riser_dynamics.hpp: 6 top entries,
// then [r(3), q(4), v(3), ω(3)] per dynamic segment); checked against stateComponentName.
Eigen::Index absoluteOffset(const RiserModel& m, int i) {
  const Eigen::Index o = 6 + 13 * static_cast<Eigen::Index>(i - m.first_dynamic);
  assert(stateComponentName(m, o) == "segment " + std::to_string(i) + " position x");
  return o;
}

// State with coordinate k moved by h (dimensionless). J rotates segment i and carries the rest of
// the chain along (positions follow by recursion); A rotates segment i alone or moves its origin.
Eigen::VectorXd perturbedState(const RiserModel& m, const StaticSolution& statics, const Coordinates& q,
                               const Eigen::VectorXd& y0, int k, double h) {
  Eigen::VectorXd y = y0;
  const int nt = static_cast<int>(q.top_axes.size()), np = static_cast<int>(q.positions.size());
  if (k < nt) {
    y[q.top_axes[k]] += h * m.length;
    return y;
  }
  if (k < nt + np) {
    const auto& [i, c] = q.positions[k - nt];
    y[absoluteOffset(m, i) + c] += h * m.element_length;
    return y;
  }
  const auto& [i, axis] = q.rotations[k - nt - np];
  const Eigen::Quaterniond turned = (Eigen::Quaterniond(Eigen::AngleAxisd(h, axis)) * statics.orientation[i]).normalized();
  if (m.formulation == Formulation::Joint) {
    std::vector<Eigen::Quaterniond> o = statics.orientation;
    o[i] = turned;
    return restState(m, o, statics.top);
  }
  y.segment<4>(absoluteOffset(m, i) + 3) << turned.w(), turned.x(), turned.y(), turned.z();
  return y;
}

// Node displacements, segment rotations and twist of eigenvector v (dimensionless coordinates).
void modeShape(const RiserModel& m, const RiserPose& pose, const Coordinates& q, const Eigen::VectorXd& v,
               std::vector<Vec3>& shape, std::vector<double>& twist, double& torsion_share) {
  std::vector<Vec3> rotation(m.n + 1, Vec3::Zero()), origin(m.n + 1, Vec3::Zero());
  Vec3 offset = Vec3::Zero();
  int k = 0;
  for (int axis : q.top_axes) offset[axis] = v[k++] * m.length;
  for (const auto& [i, c] : q.positions) origin[i][c] = v[k++] * m.element_length;
  for (const auto& [i, axis] : q.rotations) rotation[i] += v[k++] * axis;
  shape.assign(m.n + 2, Vec3::Zero());
  twist.assign(m.n + 1, 0.0);
  const bool joint = m.formulation == Formulation::Joint;
  for (int node = 0; node <= m.n + 1; ++node) {
    // J: δr accumulates δθ_i × d_i down the chain; A: each dynamic segment carries its own δr_i.
    if (!joint && node <= m.n && m.isDynamic(node)) offset = origin[node];
    shape[node] = offset;
    if (node <= m.n) offset += rotation[node].cross(m.segments[node].length * pose.tangent(node));
  }
  double spin = 0, total = 0;
  for (int i = 0; i <= m.n; ++i) {
    twist[i] = rotation[i].dot(pose.tangent(i));
    spin += twist[i] * twist[i];
    total += rotation[i].squaredNorm();
  }
  torsion_share = total > 0 ? spin / total : 0.0;
  double biggest = 0, biggest_twist = 0;
  for (const auto& s : shape) biggest = std::max(biggest, s.norm());
  for (double t : twist) biggest_twist = std::max(biggest_twist, std::abs(t));
  // A pure torsion mode has no node displacement: only round-off is left, so leave it at zero.
  if (biggest > 1e-9 * m.length * biggest_twist) {
    for (auto& s : shape) s /= biggest;
  } else {
    for (auto& s : shape) s.setZero();
  }
  for (double& t : twist) t /= biggest_twist > 0 ? biggest_twist : 1.0;
}

// Generalised accelerations of state y on the coordinates q (same scaling as the coordinates).
Eigen::VectorXd coordinateAccelerations(const RiserModel& m, RiserWorkspace& ws, const Coordinates& q,
                                        const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  evaluateRhs(m, ws, 0.0, y, dy);
  Eigen::VectorXd a(q.size());
  int k = 0;
  for (int c : q.top_axes) a[k++] = dy[3 + c] / m.length;
  for (const auto& [i, c] : q.positions) a[k++] = ws.acceleration[i][c] / m.element_length;
  for (const auto& [i, axis] : q.rotations) a[k++] = ws.acceleration[i].tail<3>().dot(axis);
  return a;
}

// Rest state y0 with coordinate velocity k set to h (dimensionless per second): the top velocity,
// the origin velocity (A) or the angular velocity about the coordinate's axis.
Eigen::VectorXd movingState(const RiserModel& m, const Coordinates& q, const Eigen::VectorXd& y0, int k, double h) {
  Eigen::VectorXd y = y0;
  const int nt = static_cast<int>(q.top_axes.size()), np = static_cast<int>(q.positions.size());
  if (k < nt) {
    y[3 + q.top_axes[k]] += h * m.length;
  } else if (k < nt + np) {
    const auto& [i, c] = q.positions[k - nt];
    y[segmentStateOffset(m, i) + 7 + c] += h * m.element_length;
  } else {
    const auto& [i, axis] = q.rotations[k - nt - np];
    y.segment<3>(angularVelocityStateOffset(m, i)) += h * axis;
  }
  return y;
}

// ∂(accelerations)/∂q (stiffness part K) by central differences, step 1e-6: truncation ~1e-12,
// round-off ~1e-10 of the largest entry.
Eigen::MatrixXd positionJacobian(const RiserModel& m, const StaticSolution& statics, const Coordinates& q) {
  RiserWorkspace ws = makeWorkspace(m, 0.0);  // Baumgarte off: A keeps Φ̈ = 0 exactly (see header)
  const Eigen::VectorXd y0 = restState(m, statics.orientation, statics.top);
  Eigen::VectorXd dy(y0.size());
  const int n = q.size();
  const double h = 1e-6;
  Eigen::MatrixXd a(n, n);
  for (int k = 0; k < n; ++k)
    a.col(k) = (coordinateAccelerations(m, ws, q, perturbedState(m, statics, q, y0, k, h), dy) -
                coordinateAccelerations(m, ws, q, perturbedState(m, statics, q, y0, k, -h), dy)) / (2 * h);
  return a;
}

// ∂(accelerations)/∂q̇ at rest (gyroscopic part G). Drag is switched off for it (its velocity
// dependence is damping, not gyroscopic); what remains linear in the velocities at rest is the
// Coriolis force −2 m_f l u ṫ of the internal flow (the other velocity terms are quadratic).
Eigen::MatrixXd velocityJacobian(RiserModel m, const StaticSolution& statics, const Coordinates& q) {
  for (auto& s : m.segments) s.normal_drag = s.tangential_drag = 0.0;
  m.spring_damping = 0.0;
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  const Eigen::VectorXd y0 = restState(m, statics.orientation, statics.top);
  Eigen::VectorXd dy(y0.size());
  const int n = q.size();
  const double h = 1e-6;
  Eigen::MatrixXd g(n, n);
  for (int k = 0; k < n; ++k)
    g.col(k) = (coordinateAccelerations(m, ws, q, movingState(m, q, y0, k, h), dy) -
                coordinateAccelerations(m, ws, q, movingState(m, q, y0, k, -h), dy)) / (2 * h);
  return g;
}

// Orthonormal basis of the coordinate directions that keep the chain connected and the held ends in
// place: the null space of ∂Φ/∂q, Φ = the gaps the reaction solve closes (held top axes and, in A,
// every joint, scaled by Δ; the held bottom end). Rank by column-pivoted QR of (∂Φ/∂q)ᵀ.
Eigen::MatrixXd connectedBasis(const RiserModel& m, const StaticSolution& statics, const Coordinates& q) {
  const Eigen::VectorXd y0 = restState(m, statics.orientation, statics.top);
  RiserPose pose;
  pose.resize(m.segmentCount());
  const int f = m.first_dynamic, last = m.last_dynamic;
  const bool bottom_held = bottomHeld(m);
  auto gaps = [&](const Eigen::VectorXd& y) {
    poseFromState(m, 0.0, y, pose);
    std::vector<double> g;
    auto push = [&](const Vec3& v) { for (int c = 0; c < 3; ++c) g.push_back(v[c] / m.element_length); };
    Vec3 hold = m.topAt(0.0).position;
    if (f == 1) hold += m.segments[0].length * pose.tangent(0);
    for (int c = 0; c < 3; ++c)
      if (!topForceKnown(m, c)) g.push_back((pose.position[f][c] - hold[c]) / m.element_length);
    for (int j = f + 1; j <= last; ++j)
      push(pose.position[j - 1] + m.segments[j - 1].length * pose.tangent(j - 1) - pose.position[j]);
    if (bottom_held) {
      Vec3 anchor = m.anchor;
      if (m.bottom == BottomCondition::Clamped)
        anchor -= m.segments[m.n].length * m.initial_orientation[m.n].toRotationMatrix().col(0);
      push(pose.position[last] + m.segments[last].length * pose.tangent(last) - anchor);
    }
    return Eigen::Map<const Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(g.size())).eval();
  };
  const int n = q.size();
  const double h = 1e-6;
  Eigen::MatrixXd jac(gaps(y0).size(), n);
  for (int k = 0; k < n; ++k)
    jac.col(k) = (gaps(perturbedState(m, statics, q, y0, k, h)) - gaps(perturbedState(m, statics, q, y0, k, -h))) / (2 * h);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jac.transpose());
  qr.setThreshold(1e-8);
  const Eigen::Index rank = qr.rank();
  const Eigen::MatrixXd full = qr.householderQ();
  return full.rightCols(n - rank);
}

// Real displacement pattern of a complex mode x: the phase e^{-iφ} that makes it as real as possible
// (φ = arg(Σ x_k²)/2), then its real part. For a real mode this is the mode itself.
Eigen::VectorXd realPart(const Eigen::VectorXcd& x) {
  const std::complex<double> sum = (x.array() * x.array()).sum();
  return (x * std::exp(std::complex<double>(0.0, -0.5 * std::arg(sum)))).real();
}

// Appends mode (ω, v) to `out`: its node displacements, twists and torsion share about `pose`.
void appendMode(const RiserModel& m, const RiserPose& pose, const Coordinates& q, double omega,
                const Eigen::VectorXd& v, RiserModes& out) {
  std::vector<Vec3> shape;
  std::vector<double> twist;
  double share = 0;
  modeShape(m, pose, q, v, shape, twist, share);
  out.frequencies.push_back(omega);
  out.shapes.push_back(std::move(shape));
  out.twists.push_back(std::move(twist));
  out.torsion_share.push_back(share);
}

}  // namespace

double divergenceFlowSpeed(const RiserModel& model, const StaticSolution& statics) {
  bool contents = false;
  for (const auto& s : model.segments) contents = contents || s.fluid_mass_per_length > 0;
  if (!contents) return std::numeric_limits<double>::infinity();
  RiserModel m = undampedModel(model, Formulation::Joint);
  const Coordinates q = makeCoordinates(m, statics);
  const Eigen::MatrixXd z = connectedBasis(m, statics, q);
  m.flow_speed = 0.0;
  const Eigen::MatrixXd k0 = z.transpose() * positionJacobian(m, statics, q) * z;
  // The flow's shape-dependent force −m_f l u² k is quadratic in u: K(u) = K0 + u² K1 exactly, so K1 may be
  // differenced at any flow speed U. At U = 1 m/s the flow's part of a tensioned riser's stiffness is small
  // beside K0, and (K(U) − K0) was then largely the differencing noise of the two Jacobians: the default riser's
  // divergence speed read 91.8, 21.5 or 113.4 m/s as its water density moved by 1e-13 of itself (the pencil's
  // noise gave spurious small positive u²). U is chosen so that U² K1 is as large as K0: 113.43 m/s then, to
  // 1.1e-5 under the same changes (test DivergenceSpeedOfTheDefaultRiserIsNotDifferencingNoise).
  const auto flowPart = [&](double u) -> Eigen::MatrixXd {
    m.flow_speed = u;
    return (z.transpose() * positionJacobian(m, statics, q) * z - k0) / (u * u);
  };
  Eigen::MatrixXd k1 = flowPart(1.0);
  const double ratio = k0.cwiseAbs().maxCoeff() / std::max(k1.cwiseAbs().maxCoeff(), 1e-300);
  if (ratio > 1.0 && std::isfinite(ratio)) k1 = flowPart(std::sqrt(ratio));
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> eig(-k0, k1, false);
  double smallest = std::numeric_limits<double>::infinity();
  const double scale = k0.cwiseAbs().maxCoeff() / std::max(k1.cwiseAbs().maxCoeff(), 1e-300);
  for (Eigen::Index k = 0; k < eig.alphas().size(); ++k) {
    const std::complex<double> a = eig.alphas()[k];
    const double b = eig.betas()[k];
    if (std::abs(b) < 1e-12 * std::abs(a) || std::abs(a.imag()) > 1e-6 * std::abs(a)) continue;
    const double u2 = a.real() / b;
    if (u2 > 1e-12 * scale) smallest = std::min(smallest, u2);
  }
  return std::sqrt(smallest);
}

std::string slowGrowthNote(int count, double growth_rate, double growth_per_radian) {
  return formatText("%d linearised modes grow slowly (largest Re λ = %.2g 1/s, %.2g per radian, e-folding time %.2g s): "
                    "the discrete internal-flow force (curvature fit of eqs 47-49 with the Coriolis term) is not exactly "
                    "conservative on a coarse chain, an O(u³Δ³) artefact, not flutter of the pipe (docs/riser.md); "
                    "frequencies kept",
                    count, growth_rate, growth_per_radian, 1.0 / growth_rate);
}

int modesEigenOrder(const RiserModel& model) {
  const int per_segment = model.torsion ? 3 : 2;
  const int order = per_segment * (model.last_dynamic - model.first_dynamic + 1) + 3;
  return model.flow_speed != 0.0 ? 2 * order : order;
}

double modesSolveSeconds(const RiserModel& model) {
  // Eigen::EigenSolver (real, non-symmetric, with eigenvectors), one core: 2.5e-8 s·N⁻³ measured at N = 300…900
  // on a loaded 2-core machine (5.3 s at N = 600); taken as 1e-8 for an unloaded core.
  constexpr double kSecondsPerOrderCubed = 1e-8;
  return kSecondsPerOrderCubed * std::pow(static_cast<double>(modesEigenOrder(model)), 3);
}

RiserModes computeModes(const RiserModel& model, const StaticSolution& statics, int count, Formulation linearisation) {
  const RiserModel m = undampedModel(model, linearisation);
  const Coordinates q = makeCoordinates(m, statics);
  const int n = q.size();
  const Eigen::MatrixXd a = positionJacobian(m, statics, q);
  RiserModes out;
  out.divergence_flow_speed = divergenceFlowSpeed(model, statics);
  RiserPose pose;
  pose.resize(m.segmentCount());
  poseFromState(m, 0.0, restState(m, statics.orientation, statics.top), pose);
  auto add = [&](double omega, const Eigen::VectorXd& v) { appendMode(m, pose, q, omega, v, out); };
  if (m.flow_speed == 0.0) {
    // No gyroscopic term: ω² are the positive real eigenvalues of −A.
    Eigen::EigenSolver<Eigen::MatrixXd> eig(-a);
    const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
    std::vector<std::pair<double, int>> found;
    for (int k = 0; k < n; ++k) {
      const auto lambda = eig.eigenvalues()[k];
      if (lambda.real() > 1e-9 * largest && std::abs(lambda.imag()) < 1e-6 * std::abs(lambda.real()))
        found.push_back({std::sqrt(lambda.real()), k});
    }
    std::sort(found.begin(), found.end());
    for (int c = 0; c < std::min<int>(count, static_cast<int>(found.size())); ++c)
      add(found[c].first, eig.eigenvectors().col(found[c].second).real());
    return out;
  }
  // Internal flow: q̈ = A q + G q̇ with the Coriolis coupling G. On the connected directions
  // q = Z ξ (A and G map into them, so Zᵀ is exact) the first-order system
  //   d/dt [ξ; ξ̇] = [0 I; ZᵀAZ ZᵀGZ] [ξ; ξ̇]
  // has eigenvalues ±iω for stable modes (gyroscopic, conservative), real pairs past divergence
  // and complex quadruples in flutter. Frequencies are Im λ of the eigenvalues on the imaginary axis.
  const Eigen::MatrixXd z = connectedBasis(m, statics, q);
  const Eigen::Index p = z.cols();
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(2 * p, 2 * p);
  s.topRightCorner(p, p).setIdentity();
  s.bottomLeftCorner(p, p) = z.transpose() * a * z;
  s.bottomRightCorner(p, p) = z.transpose() * velocityJacobian(m, statics, q) * z;
  Eigen::EigenSolver<Eigen::MatrixXd> eig(s);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<std::pair<double, Eigen::Index>> found;
  for (Eigen::Index k = 0; k < 2 * p; ++k) {
    const std::complex<double> lambda = eig.eigenvalues()[k];
    const double size = std::abs(lambda);
    if (size < 1e-7 * largest) continue;  // rigid-body (zero) directions
    const bool slow = lambda.real() > kOnAxis * size && lambda.real() <= kSlowGrowth * size;
    if (std::abs(lambda.real()) <= kOnAxis * size || slow) {
      if (lambda.imag() > 0) found.push_back({lambda.imag(), k});
      if (slow && lambda.imag() > 0) ++out.slowly_growing_count;
      if (lambda.imag() > 0 && lambda.real() > out.largest_growth_rate) {
        out.largest_growth_rate = lambda.real();
        out.largest_growth_per_radian = lambda.real() / size;
      }
    } else if (lambda.real() > 0) {
      ++out.unstable_count;
    }
  }
  std::sort(found.begin(), found.end());
  for (int c = 0; c < std::min<int>(count, static_cast<int>(found.size())); ++c)
    add(found[c].first, realPart(z * eig.eigenvectors().col(found[c].second).head(p)));
  return out;
}

RiserModel modesModel(const RiserModel& model, Formulation linearisation) { return undampedModel(model, linearisation); }

void appendAbsoluteMode(const RiserModel& m, const StaticSolution& statics, double omega, const Eigen::VectorXd& v,
                        RiserModes& out) {
  assert(m.formulation == Formulation::Absolute);
  const Coordinates q = makeCoordinates(m, statics);
  assert(v.size() == q.size());
  RiserPose pose;
  pose.resize(m.segmentCount());
  poseFromState(m, 0.0, restState(m, statics.orientation, statics.top), pose);
  appendMode(m, pose, q, omega, v, out);
}

void appendModeFrames(const RiserModel& model, const StaticSolution& statics, const RiserModes& modes,
                      int frames_per_mode, View3D& view) {
  RiserPose pose;
  pose.resize(model.segmentCount());
  poseFromState(model, 0.0, restState(model, statics.orientation, statics.top), pose);
  const double amplitude = 0.05 * model.length;
  const double radius = std::max(0.5 * model.segments[0].outer_diameter, 0.004 * model.length);
  view.scalar_name = "modal amplitude (displacement, or twist for torsion modes)";
  view.scalar_unit = "-";
  for (std::size_t k = 0; k < modes.frequencies.size(); ++k) {
    const bool torsion = modes.torsion_share[k] > 0.5;
    for (int f = 0; f < frames_per_mode; ++f) {
      const double phase = 2 * pi * f / frames_per_mode, s = std::sin(phase);
      Shape3D tube;
      tube.kind = Shape3D::Kind::Tube;
      tube.name = "mode " + std::to_string(k + 1) + ", " + std::to_string(modes.frequencies[k]) + " rad/s";
      tube.radius = radius;
      for (int node = 0; node <= model.n + 1; ++node) {
        tube.points.push_back(pose.node(node) + amplitude * s * modes.shapes[k][node]);
        const double twist = modes.twists[k][std::min(node, model.n)];
        tube.scalars.push_back(std::abs(s) * (torsion ? std::abs(twist) : modes.shapes[k][node].norm()));
      }
      Frame3D frame;
      frame.time = static_cast<double>(k) + static_cast<double>(f) / frames_per_mode;
      frame.label = formatText("mode %zu%s: %.4g rad/s (%.4g Hz), phase %.0f°", k + 1, torsion ? " (torsion)" : "",
                               modes.frequencies[k], modes.frequencies[k] / (2 * pi), 360.0 * f / frames_per_mode);
      frame.shapes.push_back(std::move(tube));
      view.frames.push_back(std::move(frame));
    }
  }
}

}  // namespace maris::riser
