#include "tether/tether_cable.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/LU>

#include "core/errors.hpp"
#include "core/text_format.hpp"

namespace maris::tether {

namespace {

constexpr double kConstraintTolerance = 1e-12;  // [-] relative link-length-squared error accepted per step
constexpr int kMaxProjectionIterations = 60;

// Residual of the discrete chain's closure, (sum l cos phi_j - S, sum l sin phi_j - dH), and its Jacobian in
// (u, kappa) with tan phi_j = u + j kappa.
Eigen::Vector2d chainClosure(double u, double kappa, double link, int n, double span, double rise,
                             Eigen::Matrix2d* jacobian) {
  Eigen::Vector2d f(-span, -rise);
  if (jacobian) jacobian->setZero();
  for (int j = 0; j < n; ++j) {
    const double t = u + j * kappa;
    const double s = 1.0 / std::sqrt(1.0 + t * t);
    f += link * Eigen::Vector2d(s, t * s);
    if (jacobian) {
      const double s3 = s * s * s;  // d(cos)/dt = -t s^3, d(sin)/dt = s^3
      (*jacobian)(0, 0) += -link * t * s3;
      (*jacobian)(0, 1) += -link * t * s3 * j;
      (*jacobian)(1, 0) += link * s3;
      (*jacobian)(1, 1) += link * s3 * j;
    }
  }
  return f;
}

}  // namespace

double catenaryHeightAt(const Catenary& c, double x) {
  const double C = c.constant;
  return 2.0 * std::sinh(0.5 * C * x) * std::sinh(0.5 * C * (x - 2.0 * c.vertex_offset)) * c.inverse_constant;
}

StaticChain staticChainProfile(double span, double rise, double length, int segment_count) {
  const Catenary guess = catenaryFromSpan(span, rise, length);
  if (!guess.has_geometry || guess.regime == CatenaryRegime::VerticalHang)
    throw SolverError("static chain", 0.0, -1, std::string("no hanging chain for this span: ") + guess.message);
  const int n = segment_count;
  const double link = length / n;
  // Start from the continuous catenary's slopes at the link midpoints.
  const double to_vertex = std::sinh(guess.constant * guess.vertex_offset) * guess.inverse_constant;
  Eigen::Vector2d unknown(guess.constant * (0.5 * link - to_vertex), guess.constant * link);
  StaticChain out;
  Eigen::Matrix2d jac;
  Eigen::Vector2d f = chainClosure(unknown[0], unknown[1], link, n, span, rise, &jac);
  for (out.iterations = 0; f.norm() > 1e-14 * length; ++out.iterations) {
    if (out.iterations == 50)
      throw SolverError("static chain closure", 0.0, out.iterations, "Newton did not converge (residual " +
                                                                          numberText(f.norm()) + " m)");
    const Eigen::Vector2d step = jac.partialPivLu().solve(f);
    // Backtracking keeps the residual decreasing far from the solution.
    double factor = 1.0;
    Eigen::Vector2d trial = unknown - step;
    Eigen::Vector2d f_trial = chainClosure(trial[0], trial[1], link, n, span, rise, nullptr);
    while (f_trial.norm() > f.norm() && factor > 1e-4) {
      factor *= 0.5;
      trial = unknown - factor * step;
      f_trial = chainClosure(trial[0], trial[1], link, n, span, rise, nullptr);
    }
    unknown = trial;
    f = chainClosure(unknown[0], unknown[1], link, n, span, rise, &jac);
  }
  out.x.assign(1, 0.0);
  out.z.assign(1, 0.0);
  for (int j = 0; j < n; ++j) {
    const double t = unknown[0] + j * unknown[1];
    const double s = 1.0 / std::sqrt(1.0 + t * t);
    out.x.push_back(out.x.back() + link * s);
    out.z.push_back(out.z.back() + link * t * s);
  }
  // kappa = w l / T_h.
  out.horizontal_tension_per_weight = link / unknown[1];
  return out;
}

LumpedMassCable::LumpedMassCable(const CableProperties& properties) : props_(properties) {
  const auto n = static_cast<std::size_t>(props_.segment_count);
  link_ = props_.length / props_.segment_count;
  node_mass_ = props_.mass_per_length * link_;
  x_.assign(n + 1, Eigen::Vector3d::Zero());
  v_ = x_old_ = x_;
  dir_.assign(n, Eigen::Vector3d::Zero());
  lower_.assign(n, 0.0);
  diag_ = upper_ = rhs_ = mu_ = lower_;
}

void LumpedMassCable::placeOnCatenary(const Eigen::Vector3d& p2, const Eigen::Vector3d& p1, const Catenary& c) {
  const Eigen::Vector3d chord = p1 - p2;
  const double horizontal = std::hypot(chord.x(), chord.y());
  const Eigen::Vector3d along = horizontal > 0.0 ? Eigen::Vector3d(chord.x() / horizontal, chord.y() / horizontal, 0.0)
                                                 : Eigen::Vector3d(1.0, 0.0, 0.0);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const PlanePoint p = catenaryPointAtArcLength(c, static_cast<double>(i) * link_);
    x_[i] = p2 + p.x * along + p.z * Eigen::Vector3d::UnitZ();
    v_[i].setZero();
  }
  x_.back() = p1;
}

void LumpedMassCable::setPositions(const std::vector<Eigen::Vector3d>& positions) {
  x_ = positions;
  for (auto& v : v_) v.setZero();
}

void LumpedMassCable::setVelocities(const std::vector<Eigen::Vector3d>& velocities) { v_ = velocities; }

double LumpedMassCable::kineticEnergy() const {
  double e = 0.0;
  for (std::size_t i = 1; i + 1 < v_.size(); ++i) e += 0.5 * node_mass_ * v_[i].squaredNorm();
  return e;
}

void LumpedMassCable::applyLoads(double dt) {
  const double weight = props_.wet_weight_per_length * link_;
  const double damping = props_.damping_per_length * link_;
  const double drag = 0.5 * props_.water_density * props_.drag_coefficient * props_.diameter * link_;
  for (std::size_t i = 1; i + 1 < x_.size(); ++i) {
    Eigen::Vector3d force(0.0, 0.0, -weight);
    force -= damping * v_[i];
    if (drag > 0.0) {
      // Morison drag on the velocity normal to the local tangent (central difference of the neighbours).
      const Eigen::Vector3d tangent = (x_[i + 1] - x_[i - 1]).normalized();
      const Eigen::Vector3d normal_velocity = v_[i] - v_[i].dot(tangent) * tangent;
      force -= drag * normal_velocity.norm() * normal_velocity;
    }
    v_[i] += (dt / node_mass_) * force;
  }
}

CableStepReport LumpedMassCable::project() {
  // Inverse masses: interior nodes 1/m, the driven ends 0.
  const std::size_t n = dir_.size();
  const double w = 1.0 / node_mass_;
  const auto inv_mass = [&](std::size_t node) { return node == 0 || node == n ? 0.0 : w; };
  const double l2 = link_ * link_;
  CableStepReport report;
  for (report.iterations = 0; report.iterations < kMaxProjectionIterations; ++report.iterations) {
    // Constraint errors c_j = |x_{j+1} - x_j|^2 - l^2 and the tridiagonal J(x~) M^-1 J(x_old)^T.
    double worst = 0.0;
    // After the SHAKE step along the old links, Newton steps along the current ones.
    if (report.iterations > 0)
      for (std::size_t j = 0; j < n; ++j) dir_[j] = x_[j + 1] - x_[j];
    for (std::size_t j = 0; j < n; ++j) {
      const Eigen::Vector3d now = x_[j + 1] - x_[j];
      const double c = now.squaredNorm() - l2;
      worst = std::max(worst, std::abs(c) / l2);
      rhs_[j] = -c;
      diag_[j] = 2.0 * now.dot(dir_[j]) * (inv_mass(j) + inv_mass(j + 1));
      upper_[j] = j + 1 < n ? -2.0 * now.dot(dir_[j + 1]) * inv_mass(j + 1) : 0.0;
      lower_[j] = j > 0 ? -2.0 * now.dot(dir_[j - 1]) * inv_mass(j) : 0.0;
    }
    report.constraint_error = worst;
    if (worst <= kConstraintTolerance) {
      report.converged = true;
      return report;
    }
    // Thomas algorithm (the matrix is a weighted discrete Laplacian: diagonally dominant for small steps).
    for (std::size_t j = 1; j < n; ++j) {
      const double m = lower_[j] / diag_[j - 1];
      diag_[j] -= m * upper_[j - 1];
      rhs_[j] -= m * rhs_[j - 1];
    }
    mu_[n - 1] = rhs_[n - 1] / diag_[n - 1];
    for (std::size_t j = n - 1; j-- > 0;) mu_[j] = (rhs_[j] - upper_[j] * mu_[j + 1]) / diag_[j];
    // Corrections along the old link directions: dx_i = w_i (d_{i-1} mu_{i-1} - d_i mu_i).
    for (std::size_t i = 1; i < n; ++i) x_[i] += inv_mass(i) * (dir_[i - 1] * mu_[i - 1] - dir_[i] * mu_[i]);
  }
  return report;
}

CableStepReport LumpedMassCable::step(const Eigen::Vector3d& p2_next, const Eigen::Vector3d& p1_next, double dt) {
  x_old_ = x_;
  for (std::size_t j = 0; j < dir_.size(); ++j) dir_[j] = x_[j + 1] - x_[j];
  // Unconstrained update: loads, then positions; the ends follow the robots.
  applyLoads(dt);
  for (std::size_t i = 1; i + 1 < x_.size(); ++i) x_[i] += dt * v_[i];
  x_.front() = p2_next;
  x_.back() = p1_next;
  // Constraint projection, then velocities consistent with the projected positions.
  const CableStepReport report = project();
  for (std::size_t i = 0; i < x_.size(); ++i) v_[i] = (x_[i] - x_old_[i]) / dt;
  return report;
}

}  // namespace maris::tether
