// Parameters of the tether scene: one flat struct in SI units (angles shown to users in degrees carry _deg),
// its schema binder and the cross-field checks. Defaults reproduce the paper's simulation 7.1 (Laranjeira, Dune &
// Hugel 2020): L = 1.5 m, H_max = 0.7 m, dH_max = 0.5 m, 30 Hz, lambda = 1, follower camera only.
#pragma once

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/schema_binder.hpp"
#include "tether/tether_cable.hpp"
#include "tether/tether_servo.hpp"

namespace maris::tether {

// One leg of the leader's path: a constant body twist held for `duration`.
struct LeaderLeg {
  double duration = 10.0;      // [s]
  double forward_speed = 0.0;  // [m/s] nu_x, leader body frame
  double lateral_speed = 0.0;  // [m/s] nu_y (positive to the leader's left)
  double vertical_speed = 0.0; // [m/s] nu_z (positive up)
  double yaw_rate_deg = 0.0;   // [deg/s] omega_z
};

// An external push on the follower: a world-frame velocity added to its command during [start, start + duration].
struct Disturbance {
  double start_time = 2.0;   // [s]
  double duration = 1.0;     // [s]
  double velocity_x = 0.0;   // [m/s] world
  double velocity_y = 0.0;   // [m/s] world
  double velocity_z = 0.0;   // [m/s] world, positive up
  double yaw_rate_deg = 0.0; // [deg/s]
};

struct TetherParameters {
  // Tether
  double length = 1.5;              // [m] L
  double mass_per_length = 0.1;     // [kg/m] mu (paper's simulated tether: 0.150 kg over 1.5 m)
  double diameter = 0.003;          // [m] d (paper: 3 mm)
  double water_density = 1000.0;    // [kg/m^3] rho (pool: fresh water)
  double gravity = 9.81;            // [m/s^2] g
  // Feature normalisation
  double sag_max = 0.7;             // [m] H_max
  double rise_max = 0.5;            // [m] dH_max
  // Robots: attachment points in the body frames (FLU) and the leader's initial pose
  double follower_attachment_x = 0.2;   // [m]
  double follower_attachment_y = 0.0;   // [m]
  double follower_attachment_z = 0.0;   // [m]
  double leader_attachment_x = -0.2;    // [m]
  double leader_attachment_y = 0.0;     // [m]
  double leader_attachment_z = 0.0;     // [m]
  double leader_x = 2.0;                // [m] world
  double leader_y = 0.0;                // [m]
  double leader_z = -0.4;               // [m] (z up, surface at 0)
  double leader_yaw_deg = 0.0;          // [deg]
  std::vector<LeaderLeg> leader_path;   // legs in order; the leader stops after the last one
  // Initial and desired shapes, as features
  double initial_a = 0.855, initial_b = 0.131, initial_d = 0.45, initial_b1 = 0.0;  // [-]
  double target_a = 0.5, target_b = 0.5, target_d = 0.5, target_b1 = 0.0;           // [-]
  // Controller
  std::string law = "follower_camera";   // "follower_camera" (3x4, eq. 50) | "both_cameras" (4x4, eq. 54)
  std::string compensation = "none";     // "none" | "minimum_norm" | "rigid" (leader feed-forward, eq. 49)
  std::vector<double> proportional_gain{1.0, 1.0, 1.0, 1.0};  // [1/s] lambda_p per (nu_x, nu_y, nu_z, omega_z)
  std::vector<double> integral_gain{0.0, 0.0, 0.0, 0.0};      // [1/s] lambda_i per component (eq. 59)
  int integral_window = 40;                                   // [-] k_max ticks summed
  double control_rate = 30.0;           // [Hz]
  double max_linear_speed = 0.3;        // [m/s]
  double max_yaw_rate_deg = 45.0;       // [deg/s]
  double model_error_a = 0.0;           // [-] relative error of a in the interaction matrix (robustness study)
  double model_error_b = 0.0;           // [-] relative error of b in the interaction matrix
  // Simulation
  double duration = 12.0;               // [s]
  std::vector<Disturbance> disturbances;
  // Dynamic cable
  bool cable_enabled = true;
  int cable_segments = 150;             // [-]
  double cable_damping = 0.5;           // [N s/m^2] linear damping per length
  double cable_drag_coefficient = 0.0;  // [-] Morison normal drag (0: off, as the paper's simulator)
  int cable_substeps = 20;              // [-] cable steps per control tick (600 Hz at 30 Hz: below l/sqrt(T/mu))
  // Output
  int animation_frames = 150;           // [-] at most this many 3D frames
};

SchemaBinder<TetherParameters> tetherBinder();
std::vector<FieldError> checkTetherParameters(const TetherParameters& p);

// Derived objects.
TetherRig rigOf(const TetherParameters& p);
ServoSettings servoSettingsOf(const TetherParameters& p);
CableProperties cablePropertiesOf(const TetherParameters& p);
double wetWeightPerLength(const TetherParameters& p);  // [N/m] (mu - rho pi d^2/4) g

}  // namespace maris::tether
