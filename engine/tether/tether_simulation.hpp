// Closed-loop simulation of the leader/follower pair: kinematic robots at a fixed control tick, the servo law
// on exact features (optionally through an interaction matrix with model errors), a leader path and external
// pushes, and the lumped-mass cable driven by the attachment points in sub-steps beside the quasi-static catenary.
//
// Tick k (t = k / rate): measure the catenary features -> command -> hold command, leader twist and pushes for
// one period; robots move exactly (integratePose) in `cable_substeps` sub-steps, the cable steps with them.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/run_context.hpp"
#include "tether/tether_parameters.hpp"

namespace maris::tether {

struct TickRecord {
  double time = 0.0;                  // [s]
  Features features;                  // true features of the catenary at the tick
  Features measured;                  // what the controller sees (estimated a, b when vision is on)
  bool vision_held = false;           // the estimator held its previous estimate (degenerate or empty view)
  bool vision_converged = false;      // the shape fit met its tolerance (false when held or stopped early)
  int visible_points = 0;             // tether points inside the camera's field of view
  Vector4 error = Vector4::Zero();    // [-] s - s* (b1 entry 0 for the 3-feature law)
  Vector4 command = Vector4::Zero();  // follower body twist (m/s, rad/s) from the servo
  Vector4 leader_twist = Vector4::Zero();
  RobotPose follower, leader;
  double sag = 0.0, rise = 0.0, span = 0.0, constant = 0.0;  // [m, m, m, 1/m] catenary
  double follower_angle = 0.0, leader_angle = 0.0;             // [rad] alpha2, alpha1
  CatenaryRegime regime = CatenaryRegime::Regular;
  double smallest_singular_value = 0.0, damping = 0.0;
  bool saturated = false, held = false;
  Eigen::VectorXcd eigenvalues;        // [1/s] of L diag(lambda_p) Lhat+ (empty when held)
  double cable_deviation = 0.0;        // [m] max node distance from the catenary point at the same arc length
  double cable_sag = 0.0;              // [m] depth of the cable's lowest node below P2
  double cable_kinetic_energy = 0.0;   // [J]
  int cable_iterations = 0;            // max projection iterations in the tick
};

struct Snapshot {
  double time = 0.0;
  RobotPose follower, leader;
  TetherState tether;
  std::vector<Eigen::Vector3d> cable;  // empty when the cable is off
};

struct SimulationOutput {
  std::vector<TickRecord> ticks;
  std::vector<Snapshot> frames;
  long cable_steps = 0;
  double worst_constraint_error = 0.0;  // [-] max relative link-length-squared error of the cable
};

// Throws SolverError when the robots pull the tether taut (chord >= L) or the cable projection fails.
SimulationOutput simulateTether(const TetherParameters& p, RunContext& context);

// The leader's body twist at time t (legs in order; zero after the last).
Vector4 leaderTwistAt(const TetherParameters& p, double time);

}  // namespace maris::tether
