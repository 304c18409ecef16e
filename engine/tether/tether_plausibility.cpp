#include "tether/tether_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include "core/text_format.hpp"
#include "tether/tether_catenary.hpp"
#include "tether/tether_kinematics.hpp"

namespace maris::tether {

namespace {

constexpr double kSurfaceZ = 0.0;  // [m] world z of the water surface (z up)

std::string num(double v) { return formatText("%.4g", v); }

// The catenary of a shape given as features a (sag) and d (rise).
Catenary shapeOf(const TetherParameters& p, double a, double d) {
  return catenaryFromShape(a * p.sag_max, (2.0 * d - 1.0) * p.rise_max, p.length);
}

}  // namespace

std::vector<FieldError> tetherPlausibility(const TetherParameters& p) {
  std::vector<FieldError> w;
  const TetherRig rig = rigOf(p);
  RobotPose leader;
  leader.position = {p.leader_x, p.leader_y, p.leader_z};
  leader.yaw = p.leader_yaw_deg * std::numbers::pi / 180.0;
  const double leader_top = std::max(p.leader_z, attachmentPoint(leader, rig.leader_attachment).z());
  if (leader_top > kSurfaceZ)
    w.push_back({"leader.z", num(p.leader_z),
                 "the leader (or its tether attachment) starts " + num(leader_top - kSurfaceZ) +
                     " m above the water surface (z = 0): the model is of two submerged vehicles"});
  try {
    const RobotPose follower =
        followerPoseFromFeatures(rig, leader, Features{p.initial_a, p.initial_b, p.initial_d, p.initial_b1});
    const double top = std::max(follower.position.z(), attachmentPoint(follower, rig.follower_attachment).z());
    if (top > kSurfaceZ && leader_top <= kSurfaceZ)
      w.push_back({"initial.d", num(p.initial_d),
                   "the initial shape puts the follower " + num(top - kSurfaceZ) +
                       " m above the water surface (z = 0): start the leader deeper, or raise d to put the follower lower"});
  } catch (const InputError&) {
    // an infeasible initial shape is an input error reported by the checks
  }
  // The leader's depth along its path (robots are level, so body z is world z), within the simulated time.
  double z = p.leader_z, t = 0.0;
  for (std::size_t i = 0; i < p.leader_path.size() && t < p.duration; ++i) {
    const LeaderLeg& leg = p.leader_path[i];
    const std::string row = "leader.path[" + std::to_string(i) + "]";
    z += leg.vertical_speed * std::min(leg.duration, p.duration - t);
    t += leg.duration;
    if (z > kSurfaceZ && p.leader_z <= kSurfaceZ) {
      w.push_back({row + ".vertical_speed", num(leg.vertical_speed),
                   "takes the leader to z = " + num(z) + " m, above the water surface"});
      break;
    }
  }
  // The follower's linear commands saturate at control.max_linear_speed per axis and its yaw rate at
  // control.max_yaw_rate_deg: a leader leg faster than that on an axis opens the chord until the tether is taut.
  for (std::size_t i = 0; i < p.leader_path.size(); ++i) {
    const LeaderLeg& leg = p.leader_path[i];
    const std::string row = "leader.path[" + std::to_string(i) + "]";
    for (const auto& [field, speed] : {std::pair{".forward_speed", leg.forward_speed},
                                       std::pair{".lateral_speed", leg.lateral_speed},
                                       std::pair{".vertical_speed", leg.vertical_speed}})
      if (std::abs(speed) > p.max_linear_speed)
        w.push_back({row + field, num(speed),
                     "faster than the follower's saturated command control.max_linear_speed = " +
                         num(p.max_linear_speed) + " m/s: the follower falls behind until the tether is taut"});
    if (std::abs(leg.yaw_rate_deg) > p.max_yaw_rate_deg)
      w.push_back({row + ".yaw_rate_deg", num(leg.yaw_rate_deg),
                   "faster than the follower's saturated yaw rate control.max_yaw_rate_deg = " +
                       num(p.max_yaw_rate_deg) + " deg/s"});
  }
  // One control tick moves the follower at most max_linear_speed / rate along an axis. A shape with less chord
  // slack (L − chord) than that can be pulled straight by a single command, which stops the run ("tether
  // chord"); a shape whose span is shorter than that hangs nearly vertically, and a single command can swing
  // the bearing of the tether, and with it the feature b, by up to a right angle.
  const double tick_move = p.max_linear_speed / p.control_rate;
  const std::string tick = " m = control.max_linear_speed / control.rate)";
  for (const auto& [group, a, d] : {std::tuple{std::string("initial"), p.initial_a, p.initial_d},
                                    std::tuple{std::string("target"), p.target_a, p.target_d}}) {
    const Catenary c = shapeOf(p, a, d);
    const double slack = p.length - std::hypot(c.span, c.rise);
    if (slack < tick_move)
      w.push_back({group + ".a", num(a),
                   "the " + group + " shape is nearly taut: its chord is " + num(slack) +
                       " m short of the length L, less than one control tick of the follower (" + num(tick_move) + tick});
    else if (c.span < tick_move)
      w.push_back({group + ".a", num(a),
                   "the " + group + " shape hangs nearly vertically: its span is " + num(c.span) +
                       " m, less than one control tick of the follower (" + num(tick_move) + tick +
                       ", so one command can swing the tether's bearing and the feature b"});
  }
  return w;
}

}  // namespace maris::tether
