#include "tether/tether_servo.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace maris::tether {

DampedInverse dampedPseudoInverse(const Eigen::MatrixXd& matrix, double threshold, double max_damping) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(matrix, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  DampedInverse out;
  out.smallest_singular_value = sigma.size() ? sigma.minCoeff() : 0.0;
  // Damping fades in smoothly as the smallest singular value drops below the threshold (Nakamura & Hanafusa).
  double mu2 = 0.0;
  if (out.smallest_singular_value < threshold) {
    const double ratio = out.smallest_singular_value / threshold;
    mu2 = (1.0 - ratio * ratio) * max_damping * max_damping;
  }
  out.damping = std::sqrt(mu2);
  Eigen::VectorXd inverse_sigma(sigma.size());
  for (Eigen::Index i = 0; i < sigma.size(); ++i) {
    const double denominator = sigma[i] * sigma[i] + mu2;
    inverse_sigma[i] = denominator > 0.0 ? sigma[i] / denominator : 0.0;
  }
  out.inverse = svd.matrixV() * inverse_sigma.asDiagonal() * svd.matrixU().transpose();
  return out;
}

TetherServo::TetherServo(TetherRig rig, ServoSettings settings) : rig_(std::move(rig)), settings_(settings) {
  window_.assign(static_cast<std::size_t>(std::max(1, settings_.integral_window)), Vector4::Zero());
}

void TetherServo::reset() {
  std::fill(window_.begin(), window_.end(), Vector4::Zero());
  next_ = 0;
  window_sum_.setZero();
}

Vector4 rigidFollowerTwist(const InteractionMatrices& interaction, const Vector4& leader_twist) {
  // Follower origin moves as a point of the leader body: v = R21 nu1 + omega1 x (c2 - c1), with c2 - c1 = -^{r2}c1.
  const double cy = std::cos(interaction.relative_yaw), sy = std::sin(interaction.relative_yaw);
  const Eigen::Vector3d& c1 = interaction.leader_centre_in_follower;
  const double w = leader_twist[3];
  return {cy * leader_twist[0] - sy * leader_twist[1] + w * c1.y(),
          sy * leader_twist[0] + cy * leader_twist[1] - w * c1.x(), leader_twist[2], w};
}

ServoCommand TetherServo::update(const Features& measured, const Features& model, const Features& target,
                                 const Vector4& leader_twist) {
  ServoCommand cmd;
  const int n = featureCount();
  cmd.error = measured.vector() - target.vector();
  if (n == 3) cmd.error[3] = 0.0;

  // Integral window: replace the oldest error.
  window_sum_ += cmd.error - window_[next_];
  window_[next_] = cmd.error;
  next_ = (next_ + 1) % window_.size();

  // Singularity guard (eq. 43): near |b| = 1 the forward column vanishes and the estimate is unreliable.
  if (std::abs(model.b) > settings_.singular_sine || (n == 4 && std::abs(model.b1) > settings_.singular_sine) ||
      !featureInfeasibility(rig_, model).empty()) {
    cmd.held = true;
    return cmd;
  }
  const InteractionMatrices im = interactionMatrices(rig_, model);
  const Eigen::MatrixXd L = im.follower.topRows(n);
  const DampedInverse inv = dampedPseudoInverse(L, settings_.rank_threshold, settings_.max_damping);
  cmd.smallest_singular_value = inv.smallest_singular_value;
  cmd.damping = inv.damping;

  const Vector4 proportional = inv.inverse * cmd.error.head(n);
  const Vector4 integral = inv.inverse * window_sum_.head(n);
  cmd.twist = -settings_.proportional_gain.cwiseProduct(proportional) - settings_.integral_gain.cwiseProduct(integral);

  // Leader-velocity compensation.
  if (settings_.compensation == LeaderCompensation::MinimumNorm)
    cmd.twist -= inv.inverse * (im.leader.topRows(n) * leader_twist);
  else if (settings_.compensation == LeaderCompensation::Rigid)
    cmd.twist += rigidFollowerTwist(im, leader_twist);

  // Saturation by uniform scaling keeps the direction of the command.
  double scale = 1.0;
  for (int i = 0; i < 3; ++i)
    if (std::abs(cmd.twist[i]) > settings_.max_linear_speed)
      scale = std::min(scale, settings_.max_linear_speed / std::abs(cmd.twist[i]));
  if (std::abs(cmd.twist[3]) > settings_.max_yaw_rate)
    scale = std::min(scale, settings_.max_yaw_rate / std::abs(cmd.twist[3]));
  if (scale < 1.0) {
    cmd.twist *= scale;
    cmd.saturated = true;
  }
  return cmd;
}

Eigen::VectorXcd closedLoopEigenvalues(const TetherRig& rig, const ServoSettings& settings, const Features& truth,
                                       const Features& model) {
  const int n = settings.use_leader_feature ? 4 : 3;
  const Eigen::MatrixXd L = interactionMatrices(rig, truth).follower.topRows(n);
  const Eigen::MatrixXd L_model = interactionMatrices(rig, model).follower.topRows(n);
  const DampedInverse inv = dampedPseudoInverse(L_model, settings.rank_threshold, settings.max_damping);
  const Eigen::MatrixXd loop = L * settings.proportional_gain.asDiagonal() * inv.inverse;
  Eigen::VectorXcd values = Eigen::EigenSolver<Eigen::MatrixXd>(loop, false).eigenvalues();
  std::sort(values.data(), values.data() + values.size(),
            [](const auto& x, const auto& y) { return x.real() < y.real() || (x.real() == y.real() && x.imag() < y.imag()); });
  return values;
}

}  // namespace maris::tether
