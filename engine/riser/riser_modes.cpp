#include "riser/riser_modes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "riser/riser_dynamics.hpp"

namespace maris::riser {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool topFree(const RiserModel& m, int c) {
  return m.top == TopCondition::Free || (m.top == TopCondition::Tensioner && c == 2);
}

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
    if (topFree(m, c)) q.top_axes.push_back(c);
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

}  // namespace

RiserModes computeModes(const RiserModel& model, const StaticSolution& statics, int count, Formulation linearisation) {
  const RiserModel m = undampedModel(model, linearisation);
  const Coordinates q = makeCoordinates(m, statics);
  const int n = q.size();
  RiserWorkspace ws = makeWorkspace(m, 0.0);  // Baumgarte off: A keeps Φ̈ = 0 exactly (see header)
  const Eigen::VectorXd y0 = restState(m, statics.orientation, statics.top);
  Eigen::VectorXd dy(y0.size());
  // Generalised accelerations of state y on the coordinates (same scaling as the coordinates).
  auto accelerations = [&](const Eigen::VectorXd& y) {
    evaluateRhs(m, ws, 0.0, y, dy);
    Eigen::VectorXd a(n);
    int k = 0;
    for (int c : q.top_axes) a[k++] = dy[3 + c] / m.length;
    for (const auto& [i, c] : q.positions) a[k++] = ws.acceleration[i][c] / m.element_length;
    for (const auto& [i, axis] : q.rotations) a[k++] = ws.acceleration[i].tail<3>().dot(axis);
    return a;
  };
  // A = ∂(accelerations)/∂q by central differences (step 1e-6: truncation ~1e-12, round-off ~1e-10).
  Eigen::MatrixXd a(n, n);
  const double h = 1e-6;
  for (int k = 0; k < n; ++k)
    a.col(k) = (accelerations(perturbedState(m, statics, q, y0, k, h)) -
                accelerations(perturbedState(m, statics, q, y0, k, -h))) / (2 * h);
  Eigen::EigenSolver<Eigen::MatrixXd> eig(-a);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<std::pair<double, int>> found;
  for (int k = 0; k < n; ++k) {
    const auto lambda = eig.eigenvalues()[k];
    if (lambda.real() > 1e-9 * largest && std::abs(lambda.imag()) < 1e-6 * std::abs(lambda.real()))
      found.push_back({std::sqrt(lambda.real()), k});
  }
  std::sort(found.begin(), found.end());
  RiserModes out;
  RiserPose pose;
  pose.resize(m.segmentCount());
  poseFromState(m, 0.0, y0, pose);
  for (int c = 0; c < std::min<int>(count, static_cast<int>(found.size())); ++c) {
    std::vector<Vec3> shape;
    std::vector<double> twist;
    double share = 0;
    modeShape(m, pose, q, eig.eigenvectors().col(found[c].second).real(), shape, twist, share);
    out.frequencies.push_back(found[c].first);
    out.shapes.push_back(std::move(shape));
    out.twists.push_back(std::move(twist));
    out.torsion_share.push_back(share);
  }
  return out;
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
      const double phase = 2 * kPi * f / frames_per_mode, s = std::sin(phase);
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
      frame.shapes.push_back(std::move(tube));
      view.frames.push_back(std::move(frame));
    }
  }
}

}  // namespace maris::riser
