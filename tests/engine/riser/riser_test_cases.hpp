// Parameter sets shared by the riser tests, built in code from the parameter struct.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "core/resources.hpp"
#include "core/angles.hpp"
#include "core/scenario.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser::test {

// The parameters of a built-in scenario as the CLI and GUI run it ("scenarios/riser/<id>.json").
inline RiserParameters builtinParameters(const std::string& path) {
  const Scenario s = scenarioFromText(std::string(*builtinResource(path)), path);
  return riserBinder().read(s.parameters);
}

// The paper's case 5 (n = 100, elliptical top motion of period 10 s, 1 m/s current), without the scenario's stress
// convergence study (five more runs; test_riser_stress_convergence.cpp runs it).
inline RiserParameters paperCaseFive() {
  RiserParameters p = builtinParameters("scenarios/riser/riser_paper_case5_j3.json");
  p.convergence_segment_counts.clear();
  return p;
}

// The bench's 3D cable (riser_cable_3d_circle: 30 m, top whirled on a 1 m circle of period 4 s, current at
// 45°, free bottom) in absolute coordinates with torsion, n segments, generalized-α at the given step [s],
// one frame, no stress snapshots.
inline RiserParameters implicitCable(int n, double step) {
  RiserParameters p = builtinParameters("scenarios/riser/riser_cable_3d_circle.json");
  p.formulation = "absolute";
  p.segment_count = n;
  p.integrator = "implicit";
  p.time_step = step;
  p.frame_count = 1;
  p.stress_times.clear();
  return p;
}

// The same cable held at both ends: pinned to an anchor 26.9 m from the top (10 m aside, 25 m down), slack.
inline RiserParameters implicitCableHeldAtBothEnds(int n, double step) {
  RiserParameters p = implicitCable(n, step);
  p.bottom_condition = "pinned";
  p.bottom_x = 10.0;
  p.bottom_z = -15.0;
  return p;
}

// A calm, dry set-up: no current, no top motion, no drag, water far below, nothing moving.
inline RiserParameters calmInAir() {
  RiserParameters p;
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.motion_amplitude_x = p.motion_amplitude_y = p.motion_amplitude_z = 0.0;
  p.motion_ramp_time = 0.0;
  p.water_level = -1e6;
  p.seabed_level = -2e6;
  p.normal_drag_coefficient = p.tangential_drag_coefficient = 0.0;
  p.top_condition = "pinned";
  p.bottom_condition = "free";
  p.end_time = 0.0;
  p.stress_times.clear();
  return p;
}

// A 10 m chain in calm air, n segments: a solid 0.05 m rod with E = 1e-3 Pa (EI ≈ 3e-10 N·m²), no torsion, no
// added mass (it would act along the whole length even above water).
inline RiserParameters chainInAir(int n) {
  RiserParameters p = calmInAir();
  p.length = 10.0;
  p.segment_count = n;
  p.outer_diameter = 0.05;
  p.inner_diameter = 0.0;
  p.youngs_modulus = 1e-3;
  p.torsion = false;
  p.added_mass_coefficient = 0.0;
  return p;
}

// The pinned-pinned tensioned beam of eq (66) of the segment-method paper, n segments: L = 10 m, m* = 1 kg/m,
// EI = 1000 N·m², T = 100 N, in air without gravity, no torsion, no added mass.
inline RiserParameters tensionedBeam(int n) {
  RiserParameters p = calmInAir();
  p.length = 10.0;
  p.segment_count = n;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.0;
  p.added_mass_coefficient = 0.0;
  p.density = 1.0 / (std::numbers::pi / 4 * 0.01);             // m* = 1 kg/m
  p.youngs_modulus = 1000.0 / (std::numbers::pi / 64 * 1e-4);  // EI = 1000 N·m²
  p.torsion = false;
  p.gravity = 0.0;
  p.top_condition = "tensioner";
  p.top_tension = 100.0;
  p.top_z = 0.0;
  p.bottom_condition = "pinned";
  p.bottom_z = -10.0;
  return p;
}

// Horizontal cantilever of length L clamped at the origin along +x, weightless, with a dead tip force
// -P e_z. EI of the default steel tube (D 0.1 / 0.08 m).
inline RiserParameters tipLoadedCantilever(int n, double tip_force, double length = 10.0) {
  RiserParameters p = calmInAir();
  p.length = length;
  p.segment_count = n;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.08;
  p.gravity = 0.0;
  p.top_condition = "clamped";
  p.initial_inclination_deg = 90.0;
  PointLoadRow load;
  load.node = n + 1;
  load.force_z = -tip_force;
  p.point_loads = {load};
  p.probes = {{length}};
  return p;
}

// The default top-tensioned riser (current, elliptical top motion) cut to a 3 s, n = 8 run with the
// current turned off the x axis: a small 3D case with motion in every direction.
inline RiserParameters shortMovingTopRun() {
  RiserParameters p;
  p.segment_count = 8;
  p.end_time = 3.0;
  p.motion_ramp_time = 1.0;
  p.motion_period = 4.0;
  p.current_direction_deg = degreesFromRadians(0.6);
  p.stress_times.clear();
  return p;
}

// 60 m riser from a tensioned top (1e6 N) to a pinned bottom 5 m off the vertical, 2 m above the sea bed,
// starting inclined at 0.3 rad without statics, internal flow 10 m/s or none: the moving states of the
// Newton-matrix tests are built on it.
inline RiserParameters inclinedTensionedRiser(int n, const std::string& formulation, bool flow) {
  RiserParameters p;
  p.length = 60.0;
  p.segment_count = n;
  p.bottom_z = -58.0;
  p.bottom_x = 5.0;
  p.seabed_level = -60.0;
  p.top_tension = 1e6;
  p.formulation = formulation;
  p.internal_flow_speed = flow ? 10.0 : 0.0;
  p.solve_statics = false;
  p.initial_inclination_deg = degreesFromRadians(0.3);
  return p;
}

inline double bendingStiffness(const RiserParameters& p) {
  return p.youngs_modulus * std::numbers::pi / 64 * (std::pow(p.outer_diameter, 4) - std::pow(p.inner_diameter, 4));
}

}  // namespace maris::riser::test
