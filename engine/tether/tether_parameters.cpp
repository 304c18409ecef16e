#include "tether/tether_parameters.hpp"

#include <cmath>
#include <numbers>

#include "core/angles.hpp"
#include "core/text_format.hpp"

namespace maris::tether {

namespace {

std::string number(double v) { return formatText("%.6g", v); }

SchemaBinder<LeaderLeg> legBinder() {
  SchemaBinder<LeaderLeg> b;
  b.real("duration", &LeaderLeg::duration, "s", Range::positive(1e5), "How long the leg lasts");
  b.real("forward_speed", &LeaderLeg::forward_speed, "m/s", Range::closed(-2, 2), "Leader surge speed (body x)");
  b.real("lateral_speed", &LeaderLeg::lateral_speed, "m/s", Range::closed(-2, 2), "Leader sway speed (body y, left)");
  b.real("vertical_speed", &LeaderLeg::vertical_speed, "m/s", Range::closed(-2, 2), "Leader heave speed (up)");
  b.real("yaw_rate_deg", &LeaderLeg::yaw_rate_deg, "deg/s", Range::closed(-180, 180), "Leader yaw rate");
  return b;
}

SchemaBinder<Disturbance> disturbanceBinder() {
  SchemaBinder<Disturbance> b;
  b.real("start_time", &Disturbance::start_time, "s", Range::nonNegative(1e5), "When the push starts");
  b.real("duration", &Disturbance::duration, "s", Range::positive(1e5), "How long it lasts");
  b.real("velocity_x", &Disturbance::velocity_x, "m/s", Range::closed(-2, 2), "Imposed world x velocity");
  b.real("velocity_y", &Disturbance::velocity_y, "m/s", Range::closed(-2, 2), "Imposed world y velocity");
  b.real("velocity_z", &Disturbance::velocity_z, "m/s", Range::closed(-2, 2), "Imposed world z velocity (up)");
  b.real("yaw_rate_deg", &Disturbance::yaw_rate_deg, "deg/s", Range::closed(-360, 360), "Imposed yaw rate");
  return b;
}

}  // namespace

SchemaBinder<TetherParameters> tetherBinder() {
  using P = TetherParameters;
  SchemaBinder<P> b;
  b.real("tether.length", &P::length, "m", Range::positive(100), "Tether length L (inextensible)");
  b.real("tether.mass_per_length", &P::mass_per_length, "kg/m", Range::positive(100), "Tether mass per length");
  b.real("tether.diameter", &P::diameter, "m", Range::positive(1), "Tether diameter (buoyancy and drag)");
  b.real("environment.water_density", &P::water_density, "kg/m^3", Range::closed(900, 1100), "Water density");
  b.real("environment.gravity", &P::gravity, "m/s^2", Range::positive(100), "Gravitational acceleration");
  b.real("features.sag_max", &P::sag_max, "m", Range::positive(100), "H_max: sag for feature a = 1");
  b.real("features.rise_max", &P::rise_max, "m", Range::positive(100), "dH_max: rise for feature d = 1 (d = 0 at -dH_max)");
  b.real("follower.attachment_x", &P::follower_attachment_x, "m", Range::closed(-5, 5), "Tether attachment on the follower, body x (forward)");
  b.real("follower.attachment_y", &P::follower_attachment_y, "m", Range::closed(-5, 5), "Tether attachment on the follower, body y (left)");
  b.real("follower.attachment_z", &P::follower_attachment_z, "m", Range::closed(-5, 5), "Tether attachment on the follower, body z (up)");
  b.real("leader.attachment_x", &P::leader_attachment_x, "m", Range::closed(-5, 5), "Tether attachment on the leader, body x (forward)");
  b.real("leader.attachment_y", &P::leader_attachment_y, "m", Range::closed(-5, 5), "Tether attachment on the leader, body y (left)");
  b.real("leader.attachment_z", &P::leader_attachment_z, "m", Range::closed(-5, 5), "Tether attachment on the leader, body z (up)");
  b.real("leader.x", &P::leader_x, "m", Range::closed(-1e4, 1e4), "Leader initial position, world x");
  b.real("leader.y", &P::leader_y, "m", Range::closed(-1e4, 1e4), "Leader initial position, world y");
  b.real("leader.z", &P::leader_z, "m", Range::closed(-1e4, 1e4), "Leader initial position, world z (up; surface at 0)");
  b.real("leader.yaw_deg", &P::leader_yaw_deg, "deg", Range::closed(-360, 360), "Leader initial heading");
  b.table("leader.path", &P::leader_path, legBinder(), 0, 1000, "Leader path: legs of constant body twist, in order");
  b.real("initial.a", &P::initial_a, "-", Range::closed(0, 1.5), "Initial sag feature a = H/H_max");
  b.real("initial.b", &P::initial_b, "-", Range::open(-1, 1), "Initial follower angle feature b = sin(alpha2)");
  b.real("initial.d", &P::initial_d, "-", Range::closed(-0.5, 1.5), "Initial rise feature d = (dH + dH_max)/(2 dH_max)");
  b.real("initial.b1", &P::initial_b1, "-", Range::open(-1, 1), "Initial leader angle feature b1 = sin(alpha1)");
  b.real("target.a", &P::target_a, "-", Range::closed(0, 1.5), "Desired sag feature a*");
  b.real("target.b", &P::target_b, "-", Range::open(-1, 1), "Desired follower angle feature b*");
  b.real("target.d", &P::target_d, "-", Range::closed(-0.5, 1.5), "Desired rise feature d*");
  b.real("target.b1", &P::target_b1, "-", Range::open(-1, 1), "Desired leader angle feature b1* (both_cameras law only)");
  b.choice("control.law", &P::law, {"follower_camera", "both_cameras"},
           "follower_camera: 3 features, 3x4 matrix (eq. 50); both_cameras: adds b1, 4x4 (eq. 54)");
  b.choice("control.compensation", &P::compensation, {"none", "minimum_norm", "rigid"},
           "Leader-velocity feed-forward: none (eq. 50), -L+ L1 v1, or move rigidly with the leader (eq. 49)");
  b.realList("control.proportional_gain", &P::proportional_gain, "1/s", Range::positive(100), 4, 4,
             "lambda_p per command component (nu_x, nu_y, nu_z, omega_z)");
  b.realList("control.integral_gain", &P::integral_gain, "1/s", Range::nonNegative(100), 4, 4,
             "lambda_i per component applied to the windowed error sum (eq. 59)");
  b.integer("control.integral_window", &P::integral_window, "-", Range::closed(1, 10000), "k_max: past errors summed");
  b.real("control.rate", &P::control_rate, "Hz", Range::closed(1, 1000), "Control (camera) rate");
  b.real("control.max_linear_speed", &P::max_linear_speed, "m/s", Range::positive(10), "Saturation of each linear command");
  b.real("control.max_yaw_rate_deg", &P::max_yaw_rate_deg, "deg/s", Range::positive(720), "Saturation of the yaw-rate command");
  b.real("control.model_error_a", &P::model_error_a, "-", Range::closed(-0.9, 2), "Relative error of a inside the interaction matrix");
  b.real("control.model_error_b", &P::model_error_b, "-", Range::closed(-0.9, 2), "Relative error of b inside the interaction matrix");
  b.real("simulation.duration", &P::duration, "s", Range::positive(3600), "Simulated time");
  b.table("simulation.disturbances", &P::disturbances, disturbanceBinder(), 0, 100,
          "External pushes on the follower (world-frame velocity added to its command)");
  b.boolean("cable.enabled", &P::cable_enabled, "Simulate the lumped-mass cable beside the catenary");
  b.integer("cable.segments", &P::cable_segments, "-", Range::closed(2, 5000), "Number of rigid links N");
  b.real("cable.damping", &P::cable_damping, "N*s/m^2", Range::nonNegative(1e3), "Linear damping per length on node velocities");
  b.real("cable.drag_coefficient", &P::cable_drag_coefficient, "-", Range::nonNegative(10), "Morison normal drag Cd (0: off)");
  b.integer("cable.substeps", &P::cable_substeps, "-", Range::closed(1, 1000), "Cable time steps per control tick");
  b.boolean("vision.enabled", &P::vision_enabled, "Estimate a and b from a synthetic follower camera by Gauss-Newton");
  b.real("vision.noise", &P::vision_noise, "-", Range::nonNegative(0.1), "Image noise std dev (normalised coordinates)");
  b.real("vision.half_fov_deg", &P::vision_half_fov_deg, "deg", Range::open(5, 85), "Camera half field of view");
  b.real("vision.camera_x", &P::vision_camera_x, "m", Range::closed(-5, 5), "Camera position, follower body x");
  b.real("vision.camera_z", &P::vision_camera_z, "m", Range::closed(-5, 5), "Camera position, follower body z (up)");
  b.integer("vision.points", &P::vision_points, "-", Range::closed(5, 10000), "Tether points imaged per frame");
  b.integer("output.animation_frames", &P::animation_frames, "-", Range::closed(1, 2000), "Maximum number of 3D frames");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"tether.length", "Tether length L"},
      {"tether.mass_per_length", "Tether mass per length"},
      {"tether.diameter", "Tether diameter"},
      {"environment.water_density", "Water density"},
      {"features.sag_max", "Sag for a = 1, H_max"},
      {"features.rise_max", "Rise for d = 1, dH_max"},
      {"target.a", "Desired sag feature a*"},
      {"target.b", "Desired follower angle feature b*"},
      {"target.d", "Desired rise feature d*"},
      {"control.rate", "Control rate"},
      {"control.max_linear_speed", "Linear speed limit"},
      {"simulation.duration", "Simulated time"},
      {"cable.segments", "Cable links N"},
      {"cable.drag_coefficient", "Cable drag coefficient C_d"},
      {"vision.noise", "Image noise"},
  });
  return b;
}

double wetWeightPerLength(const TetherParameters& p) {
  return (p.mass_per_length - p.water_density * std::numbers::pi * 0.25 * p.diameter * p.diameter) * p.gravity;
}

TetherRig rigOf(const TetherParameters& p) {
  TetherRig rig;
  rig.length = p.length;
  rig.sag_max = p.sag_max;
  rig.rise_max = p.rise_max;
  rig.follower_attachment = {p.follower_attachment_x, p.follower_attachment_y, p.follower_attachment_z};
  rig.leader_attachment = {p.leader_attachment_x, p.leader_attachment_y, p.leader_attachment_z};
  return rig;
}

ServoSettings servoSettingsOf(const TetherParameters& p) {
  ServoSettings s;
  s.use_leader_feature = p.law == "both_cameras";
  s.compensation = p.compensation == "minimum_norm" ? LeaderCompensation::MinimumNorm
                   : p.compensation == "rigid"      ? LeaderCompensation::Rigid
                                                    : LeaderCompensation::None;
  for (int i = 0; i < 4; ++i) {
    s.proportional_gain[i] = p.proportional_gain.at(i);
    s.integral_gain[i] = p.integral_gain.at(i);
  }
  s.integral_window = p.integral_window;
  s.max_linear_speed = p.max_linear_speed;
  s.max_yaw_rate = p.max_yaw_rate_deg * kRadiansPerDegree;
  return s;
}

CameraModel cameraOf(const TetherParameters& p) {
  CameraModel c;
  c.position_in_body = {p.vision_camera_x, 0.0, p.vision_camera_z};
  c.half_field_of_view = p.vision_half_fov_deg * kRadiansPerDegree;
  c.noise = p.vision_noise;
  c.sample_count = p.vision_points;
  return c;
}

CableProperties cablePropertiesOf(const TetherParameters& p) {
  CableProperties c;
  c.segment_count = p.cable_segments;
  c.length = p.length;
  c.mass_per_length = p.mass_per_length;
  c.wet_weight_per_length = wetWeightPerLength(p);
  c.damping_per_length = p.cable_damping;
  c.drag_coefficient = p.cable_drag_coefficient;
  c.diameter = p.diameter;
  c.water_density = p.water_density;
  return c;
}

std::vector<FieldError> checkTetherParameters(const TetherParameters& p) {
  std::vector<FieldError> errors;
  const double w = wetWeightPerLength(p);
  if (!(w > 0.0))
    errors.push_back({"tether.mass_per_length", number(p.mass_per_length),
                      "must exceed the displaced water mass rho pi d^2/4 = " +
                          number(p.water_density * std::numbers::pi * 0.25 * p.diameter * p.diameter) +
                          " kg/m: the catenary model needs a negatively buoyant tether"});
  if (!(p.sag_max < 0.5 * p.length))
    errors.push_back({"features.sag_max", number(p.sag_max),
                      "must be below L/2 = " + number(0.5 * p.length) + " m (a level tether cannot sag more)"});
  if (!(p.rise_max < p.length))
    errors.push_back({"features.rise_max", number(p.rise_max), "must be below the length L = " + number(p.length) + " m"});
  if (!errors.empty()) return errors;
  // Initial and desired shapes must be catenaries of the paper's model.
  const TetherRig rig = rigOf(p);
  const auto check = [&](const char* group, const Features& s) {
    if (const auto why = featureInfeasibility(rig, s); !why.empty())
      errors.push_back({std::string(group) + ".a", number(s.a), std::string("infeasible ") + group + " shape: " + why});
  };
  check("initial", Features{p.initial_a, p.initial_b, p.initial_d, p.initial_b1});
  check("target", Features{p.target_a, p.target_b, p.target_d, p.target_b1});
  return errors;
}

}  // namespace maris::tether
