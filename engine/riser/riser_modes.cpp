#include "riser/riser_modes.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "riser/riser_dynamics.hpp"

namespace maris::riser {
namespace {

bool topFree(const RiserModel& m, int c) {
  return m.top == TopCondition::Free || (m.top == TopCondition::Tensioner && c == 2);
}

// Perturbation basis at the equilibrium: free top axes, then per dynamic segment the rotation axes
// (global x, y, z with torsion; the two normals R e2, R e3 without).
struct Coordinates {
  std::vector<int> top_axes;
  std::vector<std::pair<int, Vec3>> rotations;  // segment, axis
  int size() const { return static_cast<int>(top_axes.size() + rotations.size()); }
};

}  // namespace

RiserModes computeModes(const RiserModel& model, const StaticSolution& statics, int count) {
  RiserModel m = model;
  m.formulation = Formulation::Joint;
  m.motion_amplitude.setZero();
  for (auto& s : m.segments) s.normal_drag = s.tangential_drag = 0.0;
  for (auto& j : m.joints) j.damping.setZero();
  m.point_loads.erase(std::remove_if(m.point_loads.begin(), m.point_loads.end(),
                                     [](const PointLoadRow& l) { return l.start_time > 0.0; }),
                      m.point_loads.end());
  Coordinates q;
  for (int c = 0; c < 3; ++c)
    if (topFree(m, c)) q.top_axes.push_back(c);
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const Mat3 r = statics.orientation[i].toRotationMatrix();
    if (m.torsion) {
      for (int c = 0; c < 3; ++c) q.rotations.push_back({i, Vec3::Unit(c)});
    } else {
      q.rotations.push_back({i, r.col(1)});
      q.rotations.push_back({i, r.col(2)});
    }
  }
  const int n = q.size();
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  const Eigen::VectorXd y0 = restState(m, statics.orientation, statics.top);
  Eigen::VectorXd dy(y0.size());
  // Generalised accelerations of state y: top accelerations and angular accelerations on the basis.
  auto accelerations = [&](const Eigen::VectorXd& y) {
    evaluateRhs(m, ws, 0.0, y, dy);
    Eigen::VectorXd a(n);
    int k = 0;
    for (int c : q.top_axes) a[k++] = dy[3 + c];
    for (const auto& [i, axis] : q.rotations) a[k++] = ws.acceleration[i].tail<3>().dot(axis);
    return a;
  };
  auto perturbed = [&](int k, double h) {
    Eigen::VectorXd y = y0;
    const int nt = static_cast<int>(q.top_axes.size());
    if (k < nt) {
      y[q.top_axes[k]] += h * m.length;
      return y;
    }
    std::vector<Eigen::Quaterniond> o = statics.orientation;
    const auto& [i, axis] = q.rotations[k - nt];
    o[i] = (Eigen::Quaterniond(Eigen::AngleAxisd(h, axis)) * o[i]).normalized();
    y = restState(m, o, statics.top);
    return y;
  };
  // A = ∂(accelerations)/∂q by central differences (step 1e-6: truncation ~1e-12, round-off ~1e-10).
  Eigen::MatrixXd a(n, n);
  const double h = 1e-6;
  for (int k = 0; k < n; ++k) {
    const double scale = k < static_cast<int>(q.top_axes.size()) ? m.length : 1.0;
    a.col(k) = (accelerations(perturbed(k, h)) - accelerations(perturbed(k, -h))) / (2 * h * scale);
  }
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
    const Eigen::VectorXd v = eig.eigenvectors().col(found[c].second).real();
    // Node displacements: free top motion plus δθ_i × d_i accumulated down the chain (J kinematics).
    std::vector<Vec3> shape(m.n + 2, Vec3::Zero());
    Vec3 offset = Vec3::Zero();
    int k = 0;
    for (int axis : q.top_axes) offset[axis] = v[k++] * m.length;
    std::vector<Vec3> rotation(m.n + 1, Vec3::Zero());
    for (const auto& [i, axis] : q.rotations) rotation[i] += v[k++] * axis;
    for (int node = 0; node <= m.n + 1; ++node) {
      shape[node] = offset;
      if (node <= m.n) offset += rotation[node].cross(m.segments[node].length * pose.tangent(node));
    }
    double biggest = 0;
    for (const auto& s : shape) biggest = std::max(biggest, s.norm());
    for (auto& s : shape) s /= biggest > 0 ? biggest : 1.0;
    out.frequencies.push_back(found[c].first);
    out.shapes.push_back(std::move(shape));
  }
  return out;
}

}  // namespace maris::riser
