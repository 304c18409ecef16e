#include "tether/tether_simulation.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Geometry>

#include "core/angles.hpp"
#include "core/errors.hpp"
#include "core/text_format.hpp"

namespace maris::tether {

namespace {

// World-frame pushes active at `time`, expressed as a follower body twist.
Vector4 disturbanceTwist(const TetherParameters& p, const RobotPose& follower, double time) {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double yaw_rate = 0.0;
  for (const auto& d : p.disturbances)
    if (time >= d.start_time && time < d.start_time + d.duration) {
      velocity += Eigen::Vector3d(d.velocity_x, d.velocity_y, d.velocity_z);
      yaw_rate += d.yaw_rate_deg * kRadiansPerDegree;
    }
  const Eigen::Vector3d body = Eigen::AngleAxisd(-follower.yaw, Eigen::Vector3d::UnitZ()) * velocity;
  return {body.x(), body.y(), body.z(), yaw_rate};
}

Features withModelError(const TetherParameters& p, const Features& s) {
  return {s.a * (1.0 + p.model_error_a), s.b * (1.0 + p.model_error_b), s.d, s.b1};
}

void measureCable(const LumpedMassCable& cable, const TetherState& tether, TickRecord& record) {
  double worst = 0.0, lowest = 0.0;
  const auto& x = cable.positions();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector3d on_catenary = tetherPointAtArcLength(tether, static_cast<double>(i) * cable.linkLength());
    worst = std::max(worst, (x[i] - on_catenary).norm());
    lowest = std::min(lowest, x[i].z() - tether.follower_point.z());
  }
  record.cable_deviation = worst;
  record.cable_sag = -lowest;
  record.cable_kinetic_energy = cable.kineticEnergy();
}

std::vector<Eigen::Vector3d> sampleCatenary(const TetherState& tether, int count) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i)
    points.push_back(tetherPointAtArcLength(tether, tether.catenary.length * (i + 0.5) / count));
  return points;
}

// Every k-th point so that at most `count` remain.
std::vector<Eigen::Vector3d> subsample(const std::vector<Eigen::Vector3d>& points, int count) {
  const std::size_t stride = std::max<std::size_t>(1, points.size() / static_cast<std::size_t>(count));
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = stride / 2; i < points.size(); i += stride) out.push_back(points[i]);
  return out;
}

}  // namespace

Vector4 leaderTwistAt(const TetherParameters& p, double time) {
  double start = 0.0;
  for (const auto& leg : p.leader_path) {
    if (time < start + leg.duration)
      return {leg.forward_speed, leg.lateral_speed, leg.vertical_speed, leg.yaw_rate_deg * kRadiansPerDegree};
    start += leg.duration;
  }
  return Vector4::Zero();
}

SimulationOutput simulateTether(const TetherParameters& p, RunContext& context) {
  const TetherRig rig = rigOf(p);
  const ServoSettings settings = servoSettingsOf(p);
  TetherServo servo(rig, settings);
  const Features target{p.target_a, p.target_b, p.target_d, p.target_b1};

  // Initial poses: the leader as given, the follower where the initial features put it.
  RobotPose leader{{p.leader_x, p.leader_y, p.leader_z}, p.leader_yaw_deg * kRadiansPerDegree};
  RobotPose follower = followerPoseFromFeatures(rig, leader, Features{p.initial_a, p.initial_b, p.initial_d, p.initial_b1});
  LumpedMassCable cable(cablePropertiesOf(p));
  TetherState tether = tetherState(rig, follower, leader);
  if (p.cable_enabled) cable.placeOnCatenary(tether.follower_point, tether.leader_point, tether.catenary);

  // Vision: a fixed seed keeps runs reproducible; the first estimate starts from the initial shape's guess.
  const CameraModel camera = cameraOf(p);
  std::mt19937_64 rng(20200107u);
  ShapeEstimate estimate;
  estimate.a = 0.5;
  estimate.b = 0.0;

  const double period = 1.0 / p.control_rate;
  const double substep = period / p.cable_substeps;
  const long tick_count = std::lround(p.duration * p.control_rate);
  const long frame_stride = std::max<long>(1, (tick_count + p.animation_frames - 1) / p.animation_frames);
  SimulationOutput out;
  out.ticks.reserve(static_cast<std::size_t>(tick_count + 1));

  for (long k = 0; k <= tick_count; ++k) {
    const double t = static_cast<double>(k) * period;
    context.throwIfCancelled();
    context.progress(static_cast<double>(k) / static_cast<double>(tick_count + 1), "closed loop");
    if (!tether.catenary.has_geometry) {
      throw SolverError("tether chord", t, k,
                        std::string(toString(tether.catenary.regime)) + ": " + tether.catenary.message +
                            "; the kinematic robots pulled the inextensible tether taut (soften the push or raise "
                            "the target sag)");
    }

    // Measure and command.
    TickRecord rec;
    rec.time = t;
    rec.features = featuresOf(rig, tether);
    rec.follower = follower;
    rec.leader = leader;
    rec.sag = tether.catenary.sag;
    rec.rise = tether.rise;
    rec.span = tether.span;
    rec.constant = tether.catenary.regime == CatenaryRegime::VerticalHang ? 0.0 : tether.catenary.constant;
    rec.follower_angle = tether.follower_angle;
    rec.leader_angle = tether.leader_angle;
    rec.regime = tether.catenary.regime;
    rec.leader_twist = leaderTwistAt(p, t);
    rec.measured = rec.features;
    if (p.vision_enabled) {
      // The camera sees the cable when it is simulated, else the catenary; d (depth) and b1 stay exact.
      const std::vector<Eigen::Vector3d> points =
          p.cable_enabled ? cable.positions() : sampleCatenary(tether, p.vision_points);
      const auto image = projectTether(camera, follower, subsample(points, p.vision_points), &rng);
      estimate = estimateShape(rig, camera, image, tether.rise, estimate);
      rec.measured.a = estimate.a;
      rec.measured.b = estimate.b;
      rec.vision_held = estimate.held;
      rec.vision_converged = !estimate.held && estimate.converged;
      rec.visible_points = static_cast<int>(image.size());
    }
    const Features model = withModelError(p, rec.measured);
    const bool fits = tether.catenary.fitsPaperModel();
    const ServoCommand cmd = servo.update(rec.measured, model, target, rec.leader_twist);
    rec.error = cmd.error;
    rec.command = fits ? cmd.twist : Vector4::Zero();
    rec.held = cmd.held || !fits;
    rec.saturated = cmd.saturated;
    rec.smallest_singular_value = cmd.smallest_singular_value;
    rec.damping = cmd.damping;
    if (!rec.held) rec.eigenvalues = closedLoopEigenvalues(rig, settings, rec.features, model);
    if (p.cable_enabled) measureCable(cable, tether, rec);
    if (k % frame_stride == 0 || k == tick_count)
      out.frames.push_back({t, follower, leader, tether, p.cable_enabled ? cable.positions() : std::vector<Eigen::Vector3d>{}});
    if (k == tick_count) {
      out.ticks.push_back(std::move(rec));
      break;
    }

    // Move the robots (and the cable) over one period with the command held.
    const Vector4 follower_twist = rec.command + disturbanceTwist(p, follower, t);
    for (int s = 0; s < p.cable_substeps; ++s) {
      follower = integratePose(follower, follower_twist, substep);
      leader = integratePose(leader, rec.leader_twist, substep);
      if (!p.cable_enabled) continue;
      const CableStepReport r =
          cable.step(attachmentPoint(follower, rig.follower_attachment), attachmentPoint(leader, rig.leader_attachment), substep);
      ++out.cable_steps;
      rec.cable_iterations = std::max(rec.cable_iterations, r.iterations);
      out.worst_constraint_error = std::max(out.worst_constraint_error, r.constraint_error);
      if (!r.converged || !std::isfinite(r.constraint_error)) {
        throw SolverError("cable link lengths", t + (s + 1) * substep, k,
                          formatText("link constraints not met after %d iterations (relative error %.3g); the ends "
                                     "moved too far in one sub-step of %.3g s",
                                     r.iterations, r.constraint_error, substep));
      }
    }
    tether = tetherState(rig, follower, leader);
    out.ticks.push_back(std::move(rec));
  }
  context.progress(1.0, "closed loop");
  return out;
}

}  // namespace maris::tether
