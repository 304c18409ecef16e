#include "riser/riser_newton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace maris::riser {
namespace {

// Layout of the banded unknowns/equations: reaction block k at 9k (3), dynamic segment k at 9k + 3 (6).
constexpr int kBlock = 9;
Eigen::Index reactionIndex(int k) { return kBlock * static_cast<Eigen::Index>(k); }
Eigen::Index segmentIndex(int k) { return kBlock * static_cast<Eigen::Index>(k) + 3; }

// Forward-difference steps: the residual is linear in the accelerations and reactions at fixed (q, v), so
// only the coordinate change β'ε matters for truncation; it is set to 1e-9 m (or rad) relative to the
// element length: 1e-7 left a truncation error of 2e-6 relative in the test against dense central differences;
// 1e-9 Δ is still far above the rounding of positions ~1e3 m (1e-13 m).
constexpr double kLinearStep = 1e-6;
constexpr double kCoordinateStep = 1e-9;
// Statics (useCoordinateSteps): the balance is nonlinear in the coordinates only (shapes, loads), 1e-7 Δ leaves
// a truncation of ~1e-7 relative, enough for a Newton iteration that converges at that rate.
constexpr double kStaticCoordinateStep = 1e-7;

}  // namespace

ForceSpaceNewtonMatrix::ForceSpaceNewtonMatrix(const RiserModel& m, OrientationChart& chart) : m_(m), chart_(chart) {
  if (m.formulation != Formulation::Absolute)
    throw std::invalid_argument("ForceSpaceNewtonMatrix: absolute coordinates only");
  f_ = m.first_dynamic;
  segments_ = m.last_dynamic - m.first_dynamic + 1;
  size_ = reactionIndex(segments_) + 3;
  // Segment rows reach the coordinates of neighbours ±1 (springs), ±2 with internal flow (end stencils).
  const int reach = m.flow_speed != 0.0 ? 2 : 1;
  band_ = std::min<Eigen::Index>(kBlock * reach + 5, size_ - 1);
}

void ForceSpaceNewtonMatrix::pack(const std::vector<Vec6>& segment_residual, const std::vector<Vec3>& row_residual,
                                  Eigen::VectorXd& out) const {
  out.resize(size_);
  for (int k = 0; k <= segments_; ++k) out.segment<3>(reactionIndex(k)) = row_residual[k];
  for (int k = 0; k < segments_; ++k) out.segment<6>(segmentIndex(k)) = segment_residual[f_ + k];
}

void ForceSpaceNewtonMatrix::refresh(const IterationMatrixRequest& request) {
  const double t = request.t, dq = request.dq_dacc, dv = request.dv_dacc;
  // Exact accelerations and reactions of (q, v): the point at which the implicit-function theorem holds.
  chart_.residual(t, request.q, request.v, request.acc, residual_);
  acc_ = request.acc - residual_;
  reaction_ = chart_.workspace().reaction;
  chart_.accelerationMap(request.q, turn_, arm_);
  chart_.balance(t, request.q, request.v, acc_, reaction_, seg_res_, row_res_);
  pack(seg_res_, row_res_, base_);
  evaluations_ += 2;

  double largest_reaction = 0.0;
  for (const Vec3& r : reaction_) largest_reaction = std::max(largest_reaction, r.lpNorm<Eigen::Infinity>());
  eps_.resize(size_);
  const double length_scale = std::max(1.0, m_.element_length);
  for (int k = 0; k <= segments_; ++k) eps_.segment<3>(reactionIndex(k)).setConstant(kLinearStep * (1 + largest_reaction));
  for (int k = 0; k < segments_; ++k)
    for (int c = 0; c < 6; ++c) {
      const double linear = kLinearStep * (1 + std::abs(acc_[chart_.positionIndex(k) + c]));  // (r, θ) adjacent
      const double scale = c < 3 ? length_scale : 1.0;
      if (coordinate_steps_ && dq > 0)
        eps_[segmentIndex(k) + c] = kStaticCoordinateStep * scale / dq;
      else
        eps_[segmentIndex(k) + c] = dq > 0 ? std::max(linear, kCoordinateStep * scale / dq) : linear;
    }

  // Grouped differences: columns 2·band + 1 apart touch disjoint rows.
  const Eigen::Index groups = std::min(size_, 2 * band_ + 1);
  lu_.resize(size_, band_, band_);
  for (Eigen::Index g = 0; g < groups; ++g) {
    q_ = request.q;
    v_ = request.v;
    acc_pert_ = acc_;
    reaction_pert_ = reaction_;
    for (Eigen::Index col = g; col < size_; col += groups) {
      const double e = eps_[col];
      const int k = static_cast<int>(col / kBlock), c = static_cast<int>(col % kBlock);
      if (c < 3) {
        reaction_pert_[f_ + k][c] += e;
      } else {
        const Eigen::Index ci = chart_.positionIndex(k) + (c - 3);
        acc_pert_[ci] += e;
        q_[ci] += dq * e;
        v_[ci] += dv * e;
      }
    }
    chart_.balance(t, q_, v_, acc_pert_, reaction_pert_, seg_res_, row_res_);
    pack(seg_res_, row_res_, pert_);
    ++evaluations_;
    for (Eigen::Index col = g; col < size_; col += groups) {
      const Eigen::Index lo = std::max<Eigen::Index>(0, col - band_), hi = std::min(size_ - 1, col + band_);
      for (Eigen::Index row = lo; row <= hi; ++row) lu_.at(row, col) = (pert_[row] - base_[row]) / eps_[col];
    }
  }
  dq_ = dq;
  dv_ = dv;
  ++refreshes_;
}

bool ForceSpaceNewtonMatrix::solve(const IterationMatrixRequest& request, Eigen::VectorXd& rhs) {
  // β' = γ' = 0 (the initial acceleration): S = ∂r/∂acc = I for r = acc − a(q, v).
  if (request.dq_dacc == 0.0 && request.dv_dacc == 0.0) return true;
  if (request.refresh || !have_ || request.dq_dacc != dq_ || request.dv_dacc != dv_) {
    refresh(request);
    have_ = lu_.factorize();
    if (!have_) return false;
  }
  // Right side ∂F/∂acc · b: segment rows (b_r, turn b_θ); rows the acceleration-level constraints of that.
  z_.setZero(size_);
  auto far = [&](int k) -> Vec3 {
    return rhs.segment<3>(chart_.positionIndex(k)) + (turn_[k] * rhs.segment<3>(chart_.turnIndex(k))).cross(arm_[k]);
  };
  for (int k = 0; k < segments_; ++k) {
    const Eigen::Index zi = segmentIndex(k);
    z_.segment<3>(zi) = rhs.segment<3>(chart_.positionIndex(k));
    z_.segment<3>(zi + 3) = turn_[k] * rhs.segment<3>(chart_.turnIndex(k));
  }
  for (int c = 0; c < 3; ++c)
    if (!topForceKnown(m_, c)) z_[c] = rhs[chart_.positionIndex(0) + c];
  for (int k = 1; k < segments_; ++k) z_.segment<3>(reactionIndex(k)) = rhs.segment<3>(chart_.positionIndex(k)) - far(k - 1);
  if (bottomHeld(m_))
    z_.segment<3>(reactionIndex(segments_)) = far(segments_ - 1);
  lu_.solve(z_);
  for (int k = 0; k < segments_; ++k) rhs.segment<6>(chart_.positionIndex(k)) = z_.segment<6>(segmentIndex(k));
  return true;
}

}  // namespace maris::riser
