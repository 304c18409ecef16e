// Parameters of the hinged-float wave energy converter scene (S. Heo, W. Koo, Ocean Engineering 200 (2020) 107070).
// SI units beside every field; angles in degrees only in fields named *_deg (converted in buildWecModel).
#pragma once

#include <string>
#include <vector>

#include "core/schema_binder.hpp"

namespace maris::wec {

// One float on its arm. The hinge height is not an input: it follows from the float centre lying on the
// still-water plane at equilibrium, z_h = −L sin θ0.
struct FloatRow {
  double hinge_x = 0.0;             // [m] hinge position along the wave direction axis x
  double arm_length = 10.0;         // [m] L, hinge to float centre
  double arm_angle_deg = -30.0;     // [deg] θ0, equilibrium arm angle from +x towards +z (−90: float below hinge)
  double radius = 3.0;              // [m] hemisphere radius a
  double mass = 57962.0;            // [kg] float mass (ρV when ballasted to half submergence)
  double inertia_cg = 2.09e5;       // [kg·m²] moment of inertia about the float centre (pitch axis y)
  double pto_damping = 3.52e6;      // [N·m·s/rad] linear rotational PTO damper B_PTO
  double pto_stiffness = 0.0;       // [N·m/rad] optional PTO spring about θ0
};

struct WecParameters {
  // water
  double density = 1025.0;  // [kg/m³] ρ
  double gravity = 9.81;    // [m/s²] g
  double depth = 20.0;      // [m] water depth (hydrodynamics are deep-water; depth flags where kh < π)
  // hydrodynamic coefficients
  std::string hydro_source = "hemisphere_hulme";  // hemisphere_hulme | wamit_files | nemoh_files
  std::string wamit_stem;                          // path without extension of WAMIT .1/.3 files
  double wamit_length_scale = 1.0;                 // [m] ULEN used to nondimensionalise the WAMIT files
  std::string nemoh_directory;                     // folder with Nemoh/Capytaine RadiationCoefficients.tec, ExcitationForce.tec
  // floats
  std::vector<FloatRow> floats = {FloatRow{}};
  // waves
  std::string wave_type = "regular";     // none | regular | irregular
  std::string wave_direction = "+x";     // +x | -x: direction of travel
  double wave_height = 2.0;              // [m] H of regular waves (amplitude H/2)
  double wave_frequency = 1.0;           // [rad/s] ω of regular waves
  double ramp_duration = 30.0;           // [s] half-cosine ramp on the excitation
  std::string spectrum = "jonswap";      // jonswap | pierson_moskowitz (irregular waves)
  double significant_height = 2.0;       // [m] H_s
  double peak_period = 6.0;              // [s] T_p
  double peak_enhancement = 3.3;         // [-] JONSWAP γ
  int seed = 1;                          // [-] phases (and random_frequency's frequencies) of the irregular sea
  int component_count = 200;             // [-] irregular wave components
  std::string discretisation = "random_frequency";  // random_frequency | equal_energy (core's ocean::irregularSea)
  // time domain
  std::string formulation = "both";      // classical | augmented | both
  std::string radiation = "state_space"; // state_space | direct
  std::string augmented_integrator = "newmark_two_loop";  // newmark_two_loop (the paper's) | rk4 (augmented only)
  std::string constraint_control = "projection";  // projection | baumgarte (augmented with rk4 only)
  double baumgarte_rate = 10.0;          // [1/s] α of C̈ + 2αĊ + α²C = 0
  double duration = 200.0;               // [s]
  double time_step = 0.05;               // [s] integrator step (RK4 or Newmark)
  double kernel_duration = 40.0;         // [s] length of the radiation kernel K(t)
  double initial_offset_deg = 0.0;       // [deg] θ(0) − θ0 (free-decay runs)
  int animation_frames = 120;            // [-] frames of the 3D view
  // frequency domain
  double omega_min = 0.2;                // [rad/s]
  double omega_max = 3.0;                // [rad/s]
  int frequency_count = 281;             // [-]
  std::vector<double> check_frequencies = {0.6, 1.0, 1.4, 1.8};  // [rad/s] time-domain RAO points
  double check_wave_height = 0.1;        // [m] H of the time-domain RAO runs (linear regime)
  std::vector<double> power_hs = {1.0, 2.0, 3.0};            // [m] power matrix rows H_s
  std::vector<double> power_tp = {4.0, 6.0, 8.0, 10.0, 12.0};  // [s] power matrix columns T_p
};

SchemaBinder<WecParameters> wecBinder();
// Cross-field checks: hinge above the water for the chosen angle, time step vs. duration, frequency
// band, restoring present, WAMIT stem given when needed.
std::vector<FieldError> checkWecParameters(const WecParameters& p);
// Scenario files from before waves.discretisation: the field is added as random_frequency, with a note.
std::vector<std::string> upgradeWecParameters(Json& parameters);

}  // namespace maris::wec
