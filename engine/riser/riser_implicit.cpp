#include "riser/riser_implicit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "core/errors.hpp"
#include "core/text_format.hpp"

namespace maris::riser {
namespace {

// Turns above these within one chunk mean the chunk is far too long for the chart: the rotation vector's
// J_r is singular at |θ| = 2π, the swing–twist rate map at a swing |θ_s| = π (det M ∝ sin|θ_s|/|θ_s|: the
// axis reversed, where swing and spin are no longer apart). Measured: a whipping chain's free end at a swing
// near π failed Newton down to the smallest step, with the largest correction in its swing.
constexpr double kLargestRotationVector = 5.0;  // [rad] |θ|
constexpr double kLargestSwing = 2.8;           // [rad] |θ_s|: sin|θ_s|/|θ_s| ≥ 0.12

}  // namespace

OrientationChart::OrientationChart(const RiserModel& m, double stabilisation_rate)
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

void OrientationChart::reset(const Eigen::VectorXd& y, Eigen::VectorXd& q, Eigen::VectorXd& v) {
  // The current orientations become the references; fromState then gives θ = 0 exactly (see there).
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const Eigen::Index oq = orientationStateOffset(m_, i);
    const Eigen::Quaterniond quat(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
    reference_[i - m_.first_dynamic] = quat.normalized().toRotationMatrix();
  }
  q.setZero(size_);
  v.setZero(size_);
  fromState(y, q, v);
}

void OrientationChart::fromState(const Eigen::VectorXd& y, Eigen::VectorXd& q, Eigen::VectorXd& v) const {
  q.head<3>() = y.head<3>();
  v.head<3>() = y.segment<3>(3);
  const bool joint = m_.formulation == Formulation::Joint;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index o = segmentStateOffset(m_, i), oq = orientationStateOffset(m_, i);
    const Eigen::Index g = positionIndex(k), gt = turnIndex(k);
    const Eigen::Quaterniond quat(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
    const Mat3 rot = quat.normalized().toRotationMatrix();
    // At the reference (right after reset) θ is exactly 0 and M = I, so ω' = Rᵀω unchanged; the
    // angle-axis of Rᵀ·R would give a round-off angle with an arbitrary axis instead.
    const Vec3 theta = rot == reference_[k] ? Vec3::Zero() : chartCoordinates(kind_, reference_[k].transpose() * rot);
    q.segment<3>(gt) = theta;
    const Vec3 omega_body = rot.transpose() * y.segment<3>(angularVelocityStateOffset(m_, i));
    v.segment<3>(gt) = chartMaps(kind_, theta).rate_map.lu().solve(omega_body);
    if (!joint) {
      q.segment<3>(g) = y.segment<3>(o);
      v.segment<3>(g) = y.segment<3>(velocityStateOffset(m_, i));
    }
  }
  const Eigen::Index ow = workIntegralOffset(m_);
  for (int w = 0; w < kWorkIntegrals; ++w) v[work_ + w] = y[ow + w];
}

void OrientationChart::toState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
  writeState(q, v, y, nullptr);
}

void OrientationChart::writeState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& y,
                                     std::vector<ChartMaps>* maps_with_rates) const {
  y.setZero(stateSize(m_));
  if (maps_with_rates) maps_with_rates->resize(m_.last_dynamic - m_.first_dynamic + 1);
  y.head<3>() = q.head<3>();
  y.segment<3>(3) = v.head<3>();
  const bool joint = m_.formulation == Formulation::Joint;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index o = segmentStateOffset(m_, i), oq = orientationStateOffset(m_, i);
    const Eigen::Index g = positionIndex(k), gt = turnIndex(k);
    const ChartMaps maps = maps_with_rates ? chartMaps(kind_, q.segment<3>(gt), v.segment<3>(gt))
                                           : chartMaps(kind_, q.segment<3>(gt));
    if (maps_with_rates) (*maps_with_rates)[k] = maps;
    const Mat3 r = reference_[k] * maps.turn;
    const Eigen::Quaterniond quat(r);
    y.segment<4>(oq) << quat.w(), quat.x(), quat.y(), quat.z();
    y.segment<3>(angularVelocityStateOffset(m_, i)) = r * (maps.rate_map * v.segment<3>(gt));
    if (!joint) {
      y.segment<3>(o) = q.segment<3>(g);
      y.segment<3>(velocityStateOffset(m_, i)) = v.segment<3>(g);
    }
  }
  const Eigen::Index ow = workIntegralOffset(m_);
  for (int w = 0; w < kWorkIntegrals; ++w) y[ow + w] = v[work_ + w];
}

void OrientationChart::residual(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                   const Eigen::VectorXd& acc, Eigen::VectorXd& r) {
  writeState(q, v, y_, &maps_);
  evaluateRhs(m_, ws_, t, y_, dy_);
  const bool joint = m_.formulation == Formulation::Joint;
  r.resize(size_);
  r.head<3>() = acc.head<3>() - dy_.segment<3>(3);
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const Eigen::Index g = positionIndex(k), gt = turnIndex(k);
    const Vec3 theta = q.segment<3>(gt);
    // An iterate beyond the chart (a Newton iteration running away at too long a step, or a chunk longer
    // than the segment's turning allows): a non-finite residual makes the integrator halve the step;
    // the note names the segment if the halving runs out (chartOverflow).
    const bool swing_twist = kind_ == ChartKind::SwingTwist;
    const double reach = swing_twist ? theta.tail<2>().norm() : theta.norm();
    const double limit = swing_twist ? kLargestSwing : kLargestRotationVector;
    if (!(reach < limit)) {
      const char* coordinates = swing_twist ? " swing-twist angles" : " rotation vector";
      overflow_ = {t, "segment " + std::to_string(i) + coordinates,
                   std::string(swing_twist ? "reached a swing |θ_s| = " : "reached |θ| = ") + numberText(reach) +
                       " rad, beyond the chart's limit of " + numberText(limit) + " rad"};
      r.setConstant(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    const ChartMaps& maps = maps_[k];
    const Mat3 rot = reference_[k] * maps.turn;
    // θ̈ = M⁻¹ (Rᵀ α − Ṁ θ̇).
    const Vec3 alpha = dy_.segment<3>(angularVelocityStateOffset(m_, i));
    const Vec3 theta_acc = maps.rate_map.lu().solve(rot.transpose() * alpha - maps.rate_term);
    r.segment<3>(gt) = acc.segment<3>(gt) - theta_acc;
    if (!joint) r.segment<3>(g) = acc.segment<3>(g) - dy_.segment<3>(velocityStateOffset(m_, i));
  }
  const Eigen::Index ow = workIntegralOffset(m_);
  for (int w = 0; w < kWorkIntegrals; ++w) r[work_ + w] = acc[work_ + w] - dy_[ow + w];
}

void OrientationChart::rebaseAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                              Eigen::VectorXd& acc) const {
  for (int k = 0; k <= m_.last_dynamic - m_.first_dynamic; ++k) {
    const Eigen::Index gt = turnIndex(k);
    const Vec3 theta = q.segment<3>(gt), rate = v.segment<3>(gt);
    // The body angular acceleration, less the new chart's own rate term at θ' = 0 (zero for the rotation
    // vector, J̇_r(0) θ̇' = −½ θ̇' × θ̇'; not for the swing–twist chart).
    const ChartMaps maps = chartMaps(kind_, theta, rate);
    const Vec3 body_rate = maps.rate_map * rate;
    acc.segment<3>(gt) =
        maps.rate_map * acc.segment<3>(gt) + maps.rate_term - chartMaps(kind_, Vec3::Zero(), body_rate).rate_term;
  }
}

void OrientationChart::accelerationMap(const Eigen::VectorXd& q, std::vector<Mat3>& turn, std::vector<Vec3>& arm) const {
  const int segments = m_.last_dynamic - m_.first_dynamic + 1;
  turn.resize(segments);
  arm.resize(segments);
  for (int k = 0; k < segments; ++k) {
    const Vec3 theta = q.segment<3>(turnIndex(k));
    const ChartMaps maps = chartMaps(kind_, theta);
    const Mat3 rot = reference_[k] * maps.turn;
    turn[k] = rot * maps.rate_map;
    arm[k] = m_.segments[m_.first_dynamic + k].length * rot.col(0);
  }
}

void OrientationChart::balance(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                                  const std::vector<Vec3>& reaction, std::vector<Vec6>& segment_residual,
                                  std::vector<Vec3>& row_residual) {
  writeState(q, v, y_, &maps_);
  prepareSegments(m_, ws_, t, y_);
  x_.resize(m_.segmentCount());
  const bool joint = m_.formulation == Formulation::Joint;
  for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
    const int k = i - m_.first_dynamic;
    const ChartMaps& maps = maps_[k];
    const Vec3 alpha = reference_[k] * maps.turn * (maps.rate_map * acc.segment<3>(turnIndex(k)) + maps.rate_term);
    x_[i] << (joint ? Vec3::Zero() : Vec3(acc.segment<3>(positionIndex(k)))), alpha;
  }
  balanceResidual(m_, ws_, t, x_, reaction, segment_residual, row_residual);
}

std::string OrientationChart::name(Eigen::Index k) const {
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
