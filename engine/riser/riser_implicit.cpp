#include "riser/riser_implicit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "core/errors.hpp"

namespace maris::riser {
namespace {

Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

Mat3 expMap(const Vec3& theta) {
  const double a = theta.norm();
  return a > 0 ? Mat3(Eigen::AngleAxisd(a, theta / a)) : Mat3::Identity();
}

// Rotations above this within one chunk mean the chunk is far too long for the chart (J_r is singular at 2π).
constexpr double kLargestChartRotation = 5.0;  // [rad]

// Ṁ θ̇ of chartRateMap by a central difference along θ̇ (step 1e-4 rad: error ~1e-8 relative).
Vec3 rateMapRate(ChartKind kind, const Vec3& theta, const Vec3& rate) {
  const double speed = rate.norm();
  if (!(speed > 0)) return Vec3::Zero();
  const double eps = 1e-4 / speed;
  return (chartRateMap(kind, theta + eps * rate) - chartRateMap(kind, theta - eps * rate)) * rate / (2 * eps);
}

Mat3 spinTurn(double angle) { return Mat3(Eigen::AngleAxisd(angle, Vec3::UnitX())); }

}  // namespace

Mat3 rightJacobian(const Vec3& theta) {
  const double a2 = theta.squaredNorm(), a = std::sqrt(a2);
  // (1 − cos a)/a² and (a − sin a)/a³, by their series below 1e-3 rad (cancellation).
  const double c1 = a < 1e-3 ? 0.5 - a2 / 24 : (1 - std::cos(a)) / a2;
  const double c2 = a < 1e-3 ? 1.0 / 6 - a2 / 120 : (a - std::sin(a)) / (a2 * a);
  const Mat3 k = skew(theta);
  return Mat3::Identity() - c1 * k + c2 * k * k;
}

Mat3 chartTurn(ChartKind kind, const Vec3& theta) {
  if (kind == ChartKind::RotationVector) return expMap(theta);
  return expMap(Vec3(0, theta.y(), theta.z())) * spinTurn(theta.x());
}

Mat3 chartRateMap(ChartKind kind, const Vec3& theta) {
  if (kind == ChartKind::RotationVector) return rightJacobian(theta);
  Mat3 m = spinTurn(theta.x()).transpose() * rightJacobian(Vec3(0, theta.y(), theta.z()));
  m.col(0) = Vec3::UnitX();
  return m;
}

Vec3 chartCoordinates(ChartKind kind, const Mat3& turn) {
  if (turn == Mat3::Identity()) return Vec3::Zero();
  if (kind == ChartKind::RotationVector) {
    const Eigen::AngleAxisd a(turn);
    return a.angle() * a.axis();
  }
  // The swing turns e_x to the axis t about e_x × t; atan2 keeps the angle accurate near 0 and π.
  const Vec3 axis = turn.col(0), normal = Vec3::UnitX().cross(axis);
  const double sine = normal.norm();
  const Vec3 swing = sine > 0 ? Vec3(std::atan2(sine, axis.x()) * normal / sine) : Vec3::Zero();
  const Mat3 spin = expMap(swing).transpose() * turn;
  return {std::atan2(spin(2, 1), spin(1, 1)), swing.y(), swing.z()};
}

RotationVectorChart::RotationVectorChart(const RiserModel& m, double stabilisation_rate)
    : m_(m),
      kind_(m.torsion ? ChartKind::RotationVector : ChartKind::SwingTwist),
      ws_(makeWorkspace(m, stabilisation_rate)) {
  const int segments = m.last_dynamic - m.first_dynamic + 1;
  per_segment_ = m.formulation == Formulation::Joint ? 3 : 6;
  work_ = 3 + static_cast<Eigen::Index>(segments) * per_segment_;
  size_ = work_ + kWorkIntegrals;
  reference_.assign(segments, Mat3::Identity());
  y_.resize(stateSize(m));
  dy_.resize(stateSize(m));
}

void RotationVectorChart::reset(const Eigen::VectorXd& y, Eigen::VectorXd& q, Eigen::VectorXd& v) {
  // The current orientations become the references; fromState then gives θ = 0 exactly (see there).
  const bool joint = m_.formulation == Formulation::Joint;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const Eigen::Index o = segmentStateOffset(m_, i), oq = joint ? o : o + 3;
    const Eigen::Quaterniond quat(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
    reference_[i - m_.first_dynamic] = quat.normalized().toRotationMatrix();
  }
  q.setZero(size_);
  v.setZero(size_);
  fromState(y, q, v);
}

void RotationVectorChart::fromState(const Eigen::VectorXd& y, Eigen::VectorXd& q, Eigen::VectorXd& v) const {
  q.head<3>() = y.head<3>();
  v.head<3>() = y.segment<3>(3);
  const bool joint = m_.formulation == Formulation::Joint;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index o = segmentStateOffset(m_, i), oq = joint ? o : o + 3;
    const Eigen::Index g = 3 + k * per_segment_, gt = joint ? g : g + 3;
    const Eigen::Quaterniond quat(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
    const Mat3 rot = quat.normalized().toRotationMatrix();
    // At the reference (right after reset) θ is exactly 0 and M = I, so ω' = Rᵀω unchanged; the
    // angle-axis of Rᵀ·R would give a round-off angle with an arbitrary axis instead.
    const Vec3 theta = rot == reference_[k] ? Vec3::Zero() : chartCoordinates(kind_, reference_[k].transpose() * rot);
    q.segment<3>(gt) = theta;
    v.segment<3>(gt) = chartRateMap(kind_, theta).lu().solve(rot.transpose() * y.segment<3>(joint ? o + 4 : o + 10));
    if (!joint) {
      q.segment<3>(g) = y.segment<3>(o);
      v.segment<3>(g) = y.segment<3>(o + 7);
    }
  }
  const Eigen::Index ow = workIntegralOffset(m_);
  for (int w = 0; w < kWorkIntegrals; ++w) v[work_ + w] = y[ow + w];
}

void RotationVectorChart::toState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
  y.setZero(stateSize(m_));
  y.head<3>() = q.head<3>();
  y.segment<3>(3) = v.head<3>();
  const bool joint = m_.formulation == Formulation::Joint;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index o = segmentStateOffset(m_, i), oq = joint ? o : o + 3;
    const Eigen::Index g = 3 + k * per_segment_, gt = joint ? g : g + 3;
    const Vec3 theta = q.segment<3>(gt);
    const Mat3 r = reference_[k] * chartTurn(kind_, theta);
    const Eigen::Quaterniond quat(r);
    y.segment<4>(oq) << quat.w(), quat.x(), quat.y(), quat.z();
    y.segment<3>(joint ? o + 4 : o + 10) = r * (chartRateMap(kind_, theta) * v.segment<3>(gt));
    if (!joint) {
      y.segment<3>(o) = q.segment<3>(g);
      y.segment<3>(o + 7) = v.segment<3>(g);
    }
  }
  const Eigen::Index ow = workIntegralOffset(m_);
  for (int w = 0; w < kWorkIntegrals; ++w) y[ow + w] = v[work_ + w];
}

void RotationVectorChart::residual(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                   const Eigen::VectorXd& acc, Eigen::VectorXd& r) {
  toState(q, v, y_);
  evaluateRhs(m_, ws_, t, y_, dy_);
  const bool joint = m_.formulation == Formulation::Joint;
  r.resize(size_);
  r.head<3>() = acc.head<3>() - dy_.segment<3>(3);
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index o = segmentStateOffset(m_, i);
    const Eigen::Index g = 3 + k * per_segment_, gt = joint ? g : g + 3;
    const Vec3 theta = q.segment<3>(gt), rate = v.segment<3>(gt);
    // An iterate beyond the chart (a Newton iteration running away at too long a step, or a chunk longer
    // than the segment's turning allows): a non-finite residual makes the integrator halve the step;
    // the note names the segment if the halving runs out (chartOverflow).
    if (!(theta.norm() < kLargestChartRotation)) {
      const char* coordinates = kind_ == ChartKind::SwingTwist ? " swing-twist angles" : " rotation vector";
      overflow_ = {t, "segment " + std::to_string(i) + coordinates,
                   "reached |θ| = " + std::to_string(theta.norm()) + " rad, beyond the chart's limit of " +
                       std::to_string(kLargestChartRotation) + " rad"};
      r.setConstant(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    const Mat3 rot = reference_[k] * chartTurn(kind_, theta);
    // θ̈ = M⁻¹ (Rᵀ α − Ṁ θ̇).
    const Vec3 alpha = dy_.segment<3>(joint ? o + 4 : o + 10);
    const Vec3 theta_acc =
        chartRateMap(kind_, theta).lu().solve(rot.transpose() * alpha - rateMapRate(kind_, theta, rate));
    r.segment<3>(gt) = acc.segment<3>(gt) - theta_acc;
    if (!joint) r.segment<3>(g) = acc.segment<3>(g) - dy_.segment<3>(o + 7);
  }
  const Eigen::Index ow = workIntegralOffset(m_);
  for (int w = 0; w < kWorkIntegrals; ++w) r[work_ + w] = acc[work_ + w] - dy_[ow + w];
}

void RotationVectorChart::rebaseAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                              Eigen::VectorXd& acc) const {
  const int off = m_.formulation == Formulation::Joint ? 0 : 3;
  for (int k = 0; k <= m_.last_dynamic - m_.first_dynamic; ++k) {
    const Eigen::Index gt = 3 + k * per_segment_ + off;
    const Vec3 theta = q.segment<3>(gt), rate = v.segment<3>(gt);
    // The body angular acceleration, less the new chart's own rate term at θ' = 0 (zero for the rotation
    // vector, J̇_r(0) θ̇' = −½ θ̇' × θ̇'; not for the swing–twist chart).
    const Vec3 body_rate = chartRateMap(kind_, theta) * rate;
    acc.segment<3>(gt) = chartRateMap(kind_, theta) * acc.segment<3>(gt) + rateMapRate(kind_, theta, rate) -
                         rateMapRate(kind_, Vec3::Zero(), body_rate);
  }
}

void RotationVectorChart::accelerationMap(const Eigen::VectorXd& q, std::vector<Mat3>& turn, std::vector<Vec3>& arm) const {
  const int segments = m_.last_dynamic - m_.first_dynamic + 1;
  const int off = m_.formulation == Formulation::Joint ? 0 : 3;
  turn.resize(segments);
  arm.resize(segments);
  for (int k = 0; k < segments; ++k) {
    const Vec3 theta = q.segment<3>(3 + k * per_segment_ + off);
    const Mat3 rot = reference_[k] * chartTurn(kind_, theta);
    turn[k] = rot * chartRateMap(kind_, theta);
    arm[k] = m_.segments[m_.first_dynamic + k].length * rot.col(0);
  }
}

void RotationVectorChart::balance(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                                  const std::vector<Vec3>& reaction, std::vector<Vec6>& segment_residual,
                                  std::vector<Vec3>& row_residual) {
  toState(q, v, y_);
  prepareSegments(m_, ws_, t, y_);
  x_.resize(m_.segmentCount());
  const int off = m_.formulation == Formulation::Joint ? 0 : 3;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index g = 3 + k * per_segment_, gt = g + off;
    const Vec3 theta = q.segment<3>(gt), rate = v.segment<3>(gt);
    const Mat3 rot = reference_[k] * chartTurn(kind_, theta);
    const Vec3 alpha = rot * (chartRateMap(kind_, theta) * acc.segment<3>(gt) + rateMapRate(kind_, theta, rate));
    x_[i] << (off ? Vec3(acc.segment<3>(g)) : Vec3::Zero()), alpha;
  }
  balanceResidual(m_, ws_, t, x_, reaction, segment_residual, row_residual);
}

double RotationVectorChart::largestRotation(const Eigen::VectorXd& q) const {
  double largest = 0;
  const int off = m_.formulation == Formulation::Joint ? 0 : 3;
  for (int k = 0; k <= m_.last_dynamic - m_.first_dynamic; ++k)
    largest = std::max(largest, q.segment<3>(3 + k * per_segment_ + off).norm());
  return largest;
}

std::string RotationVectorChart::name(Eigen::Index k) const {
  static const char* axis[] = {"x", "y", "z"};
  if (k < 3) return std::string("top position ") + axis[k];
  if (k >= work_) return "work integral " + std::to_string(k - work_);
  const int i = m_.first_dynamic + static_cast<int>((k - 3) / per_segment_);
  const int c = static_cast<int>((k - 3) % per_segment_);
  const std::string seg = "segment " + std::to_string(i) + " ";
  if (per_segment_ == 6 && c < 3) return seg + "position " + axis[c];
  if (kind_ == ChartKind::SwingTwist)
    return seg + (c % 3 == 0 ? std::string("spin angle") : std::string("swing vector ") + axis[c % 3]);
  return seg + "rotation vector " + axis[c % 3];
}

}  // namespace maris::riser
