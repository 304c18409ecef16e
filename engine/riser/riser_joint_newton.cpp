#include "riser/riser_joint_newton.hpp"

#include <stdexcept>

#include <Eigen/LU>

namespace maris::riser {
namespace {

RiserModel absoluteTwin(const RiserModel& joint) {
  if (joint.formulation != Formulation::Joint) throw std::invalid_argument("JointNewtonMatrix: joint coordinates only");
  RiserModel twin = joint;
  twin.formulation = Formulation::Absolute;
  return twin;
}

// Absolute state of the twin with the pose of a joint state: positions, orientations and velocities of every
// dynamic segment (consistent: Φ = Φ̇ = 0 at the inner joints), the header and work integrals copied.
void twinState(const RiserModel& joint, const RiserModel& twin, const Eigen::VectorXd& y_joint, const RiserPose& pose,
               Eigen::VectorXd& y_twin) {
  y_twin.setZero(stateSize(twin));
  y_twin.head<6>() = y_joint.head<6>();
  for (int i = twin.first_dynamic; i <= twin.last_dynamic; ++i) {
    const Eigen::Quaterniond q(pose.rotation[i]);
    y_twin.segment<3>(segmentStateOffset(twin, i)) = pose.position[i];
    y_twin.segment<4>(orientationStateOffset(twin, i)) << q.w(), q.x(), q.y(), q.z();
    y_twin.segment<3>(velocityStateOffset(twin, i)) = pose.velocity[i];
    y_twin.segment<3>(angularVelocityStateOffset(twin, i)) = pose.omega[i];
  }
  y_twin.tail<kWorkIntegrals>() = y_joint.segment<kWorkIntegrals>(workIntegralOffset(joint));
}

}  // namespace

JointNewtonMatrix::JointNewtonMatrix(const RiserModel& joint, const OrientationChart& chart, double stabilisation_rate)
    : m_(joint),
      chart_(chart),
      twin_(absoluteTwin(joint)),
      twin_chart_(twin_, stabilisation_rate),
      twin_newton_(twin_, twin_chart_),
      pose_ws_(makeWorkspace(joint, 0.0)) {
  f_ = joint.first_dynamic;
  segments_ = joint.last_dynamic - joint.first_dynamic + 1;
  rate_map_.resize(segments_);
  rate_map_inverse_.resize(segments_);
  rot_.resize(segments_);
  arm_.resize(segments_);
}

void JointNewtonMatrix::refresh(const IterationMatrixRequest& request) {
  chart_.toState(request.q, request.v, y_joint_);
  poseFromState(m_, request.t, y_joint_, pose_ws_.pose);
  twinState(m_, twin_, y_joint_, pose_ws_.pose, y_twin_);
  twin_chart_.reset(y_twin_, q_twin_, v_twin_);
  for (int k = 0; k < segments_; ++k) {
    const int i = f_ + k;
    rate_map_[k] = chartMaps(chart_.kind(), request.q.segment<3>(chart_.turnIndex(k))).rate_map;
    rate_map_inverse_[k] = rate_map_[k].inverse();
    rot_[k] = pose_ws_.pose.rotation[i];
    arm_[k] = m_.segments[i].length * rot_[k].col(0);
  }
  // The twin's refresh takes the exact accelerations of its state itself (any acc gives the same matrix).
  acc_twin_.setZero(twin_chart_.size());
}

bool JointNewtonMatrix::solve(const IterationMatrixRequest& request, Eigen::VectorXd& rhs) {
  // β' = γ' = 0 (the initial acceleration): S = ∂r/∂acc = I for r = acc − a(q, v).
  if (request.dq_dacc == 0.0 && request.dv_dacc == 0.0) return true;
  const bool fresh = request.refresh || !have_ || request.dq_dacc != dq_ || request.dv_dacc != dv_;
  if (fresh) refresh(request);
  // Right side T b of the twin: the joint motion of the joint-chart accelerations b. Prescribed top
  // components do not move (their coordinate is decoupled, S = I there), free ones move the top segment.
  rhs_twin_.setZero(twin_chart_.size());
  Vec3 point = Vec3::Zero();
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m_, c)) point[c] = rhs[c];
  for (int k = 0; k < segments_; ++k) {
    const Vec3 theta_acc = rate_map_[k] * rhs.segment<3>(chart_.turnIndex(k));  // twin θ̈ (its chart is at θ = 0: M = I)
    rhs_twin_.segment<3>(twin_chart_.positionIndex(k)) = point;
    rhs_twin_.segment<3>(twin_chart_.turnIndex(k)) = theta_acc;
    point += (rot_[k] * theta_acc).cross(arm_[k]);
  }
  const IterationMatrixRequest twin_request{request.t,       q_twin_, v_twin_, acc_twin_, request.dv_dacc,
                                            request.dq_dacc, fresh};
  have_ = twin_newton_.solve(twin_request, rhs_twin_);
  dq_ = request.dq_dacc;
  dv_ = request.dv_dacc;
  if (!have_) return false;
  // y = Π u: joint rates θ̈_J = M⁻¹ θ̈_twin; free top components from the top segment's acceleration.
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m_, c)) rhs[c] = rhs_twin_[twin_chart_.positionIndex(0) + c];
  for (int k = 0; k < segments_; ++k)
    rhs.segment<3>(chart_.turnIndex(k)) = rate_map_inverse_[k] * rhs_twin_.segment<3>(twin_chart_.turnIndex(k));
  return true;
}

}  // namespace maris::riser
