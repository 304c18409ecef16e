// Parameters of the riser / cable scene (segment method, Adamiec-Wójcik, Brzozowska & Wojciech,
// Acta Mechanica 231, 2020). One flat struct in SI units; its default member initialisers are the
// only defaults. Angles are degrees (fields ending in _deg),
// converted to radians once, in buildRiserModel. Global frame: z up (see riser_model.hpp for all conventions).
#pragma once

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/schema_binder.hpp"

namespace maris::riser {

// A stretch of the riser with its own section, [start, end) in arc length from the top.
// Rows override the uniform `section.*` values; later rows win where rows overlap.
struct SectionRow {
  double start = 0.0;                 // [m] arc length from the top where the section begins
  double end = 1.0e5;                 // [m] arc length from the top where it ends (clipped to L)
  double outer_diameter = 0.5;        // [m]
  double inner_diameter = 0.45;       // [m]
  double youngs_modulus = 2.07e11;    // [Pa]
  double shear_modulus = 7.96e10;     // [Pa]
  double density = 7850.0;            // [kg/m^3] pipe wall
  double normal_drag_coefficient = 1.0;      // [-] D_yz of eq (34)
  double tangential_drag_coefficient = 0.0;  // [-] D_x of eq (34)
  double added_mass_coefficient = 1.0;       // [-] C_a = c_M - 1 of eq (11), normal to the axis
  double tangential_added_mass_coefficient = 0.0;  // [-] C_at along the axis
};

// A force and moment applied at a node for t_start <= t < t_end (a box pulse; t_end large = step).
struct PointLoadRow {
  int node = 0;             // [-] 0 = top end, k = joint k (between segments k-1 and k), n+1 = bottom end
  double force_x = 0.0;     // [N] global frame
  double force_y = 0.0;     // [N]
  double force_z = 0.0;     // [N]
  double moment_x = 0.0;    // [N·m]
  double moment_y = 0.0;    // [N·m]
  double moment_z = 0.0;    // [N·m]
  double start_time = 0.0;  // [s]
  double end_time = 1e9;    // [s]
};

// One row of a top-motion time table: displacement of the top end from its mean position (top.x/y/z).
struct TopMotionRow {
  double time = 0.0;  // [s]
  double x = 0.0;     // [m] displacement along global x
  double y = 0.0;     // [m]
  double z = 0.0;     // [m] (ignored for the tensioner, whose vertical motion is free)
};

// A point on the riser whose displacement and stresses are recorded over time.
struct ProbeRow {
  double arc_length = 50.0;  // [m] arc length from the top (0 = top end, L = bottom end)
};

// One row of a user wave spectrum (waves.type = spectrum_table): S(ω), linear between rows, zero outside.
struct WaveSpectrumRow {
  double omega = 0.5;    // [rad/s]
  double density = 0.0;  // [m^2*s/rad] one-sided S(ω)
};

// Buoyancy modules over [start, end) in arc length from the top (riser_buoyancy.hpp): they replace the pipe's outer
// diameter for buoyancy, drag, added mass and sea-bed contact (not for stiffness or stresses) and add their mass.
struct BuoyancyModuleRow {
  double start = 0.0;                   // [m]
  double end = 1.0;                     // [m]
  double outer_diameter = 1.0;          // [m] equivalent diameter of the modules (buoyancy, drag, added mass)
  double mass_per_length = 100.0;       // [kg/m] mass of the modules in air, per length of riser
  double normal_drag_coefficient = 1.0; // [-] on the modules' diameter
  double added_mass_coefficient = 1.0;  // [-] on the modules' diameter
};

// One row of a current profile table (current.type = table): speed and heading at a depth below the water level.
struct CurrentProfileRow {
  double depth = 0.0;        // [m] below environment.water_level (rows of increasing depth)
  double speed = 0.0;        // [m/s]
  double heading_deg = 0.0;  // [deg] direction the current flows towards, from +x towards +y
};

struct RiserParameters {
  // geometry
  double length = 100.0;   // [m] unstretched length L
  int segment_count = 20;  // [-] n primary elements: n+1 rigid segments (Δ/2, Δ, ..., Δ, Δ/2)
  // uniform section (overridden by `sections` rows)
  double outer_diameter = 0.5;               // [m] D_out
  double inner_diameter = 0.45;              // [m] D_inn (0 for a solid cable)
  double youngs_modulus = 2.07e11;           // [Pa] E
  double shear_modulus = 7.96e10;            // [Pa] G
  double density = 7850.0;                   // [kg/m^3] ρ_r of the wall
  double normal_drag_coefficient = 1.0;      // [-] D_yz
  double tangential_drag_coefficient = 0.0;  // [-] D_x
  double added_mass_coefficient = 1.0;       // [-] C_a: added mass normal to the axis (eq 11)
  double tangential_added_mass_coefficient = 0.0;  // [-] C_at: along the axis (eq 11 has C_at = C_a)
  std::vector<SectionRow> sections;          // non-uniform stretches
  std::vector<BuoyancyModuleRow> buoyancy_modules;  // buoyancy modules (lazy-wave shapes); none by default
  // model
  std::string formulation = "joint";  // "joint" (J) or "absolute" (A)
  bool torsion = true;                // true: J3/A3; false: J2/A2 (no spin about segment axes)
  double stiffness_damping = 0.0;     // [s] β: spring damping moments B = β·C (Rayleigh, stiffness-proportional)
  bool axial_flexibility = false;     // pinned top: the riser's axial stretch as a spring k = 1/Σ(Δ/EA) at the top
  // environment
  double gravity = 9.81;             // [m/s^2]
  double water_density = 1025.0;     // [kg/m^3] ρ_w
  double water_level = 0.0;          // [m] z of the still-water surface (buoyancy and drag only below it)
  double seabed_level = -100.0;      // [m] z of the sea bed (drawn; the contact plane with seabed.contact)
  double internal_fluid_density = 1025.0;  // [kg/m^3] ρ_f of the contents
  double internal_flow_speed = 0.0;        // [m/s] u: constant flow speed of the contents along s (> 0: top to bottom)
  double current_speed_surface = 1.0;      // [m/s] current at the water level
  double current_speed_seabed = 1.0;       // [m/s] current at the sea bed (linear in between)
  double current_direction_deg = 0.0;      // [deg] heading of the current in the xy-plane, from +x towards +y
  std::string current_type = "linear";     // linear (the three fields above) | table (current_profile; riser_current.hpp)
  std::vector<CurrentProfileRow> current_profile;  // table: speed and heading against depth, linear in between
  // top end
  std::string top_condition = "tensioner";  // "pinned", "clamped", "tensioner", "free"
  double top_x = 0.0;                       // [m] mean position of the top end
  double top_y = 0.0;                       // [m]
  double top_z = 0.0;                       // [m] (tensioner: set by the geometry, ignored)
  double top_tension = 2.0e6;               // [N] tensioner: constant upward pull on the top end
  double motion_amplitude_x = 2.0;          // [m] harmonic top motion per axis
  double motion_amplitude_y = 1.0;          // [m]
  double motion_amplitude_z = 0.0;          // [m] (ignored for the tensioner)
  double motion_period = 12.0;              // [s]
  double motion_phase_x_deg = 0.0;          // [deg]
  double motion_phase_y_deg = 90.0;         // [deg] x and y a quarter period apart: an ellipse
  double motion_phase_z_deg = 0.0;          // [deg]
  double motion_ramp_time = 6.0;            // [s] smooth start of the top motion (0 = none)
  std::string top_motion = "harmonic";      // "harmonic" (amplitudes above), "table" (top_motion_table) or "vessel"
  std::vector<TopMotionRow> top_motion_table;  // time table of the top displacement (clamped cubic spline)
  // vessel (riser_vessel.hpp; bound there): top.motion = vessel moves the top with a vessel's RAOs in the waves
  std::string vessel_rao_file;              // CSV of displacement RAOs ("builtin:NAME" or a path)
  std::string vessel_rao_phase = "lag";     // lag | lead: sign of the phases in the file
  std::string vessel_rao_rotation_unit = "deg";  // deg | rad: roll, pitch, yaw amplitudes per metre of wave amplitude
  double vessel_heading_deg = 0.0;          // [deg] vessel x axis (bow) from global +x towards +y
  double vessel_hang_off_x = 0.0;           // [m] hang-off point (the top) from the RAO origin, vessel axes
  double vessel_hang_off_y = 0.0;           // [m]
  double vessel_hang_off_z = 0.0;           // [m]
  double vessel_offset_x = 0.0;             // [m] static vessel offset: moves the top's mean position (global)
  double vessel_offset_y = 0.0;             // [m]
  double vessel_offset_z = 0.0;             // [m] (not for a tensioner, whose top height is set by the geometry)
  // bottom end
  std::string bottom_condition = "pinned";  // "pinned", "clamped", "free", "spring"
  double bottom_x = 0.0;                    // [m] anchor point
  double bottom_y = 0.0;                    // [m]
  double bottom_z = -100.0;                 // [m]
  double bottom_spring_stiffness = 1.0e5;   // [N/m] "spring": linear spring to the anchor
  double bottom_spring_damping = 0.0;       // [N·s/m]
  // initial shape
  double initial_inclination_deg = 0.0;  // [deg] first direction from the top, from straight down (90 = horizontal)
  double initial_azimuth_deg = 0.0;      // [deg] heading of that direction in the xy-plane, from +x towards +y
  bool solve_statics = true;         // start from static equilibrium (top at its mean position, current on)
  // waves (riser_waves.hpp; bound there): linear waves from the still-water level over depth water_level − seabed_level
  std::string wave_type = "none";          // none | airy | jonswap | pierson_moskowitz | spectrum_table
  double wave_height = 2.0;                // [m] airy: crest-to-trough height H
  double wave_period = 10.0;               // [s] airy: period T
  double wave_phase_deg = 0.0;             // [deg] airy: phase (η = H/2 cos(phase) at x = y = 0, t = 0)
  double wave_significant_height = 4.0;    // [m] jonswap, pierson_moskowitz: Hs
  double wave_peak_period = 10.0;          // [s] jonswap, pierson_moskowitz: Tp
  double wave_peak_enhancement = 3.3;      // [-] jonswap: γ
  std::vector<WaveSpectrumRow> wave_spectrum_table;  // spectrum_table: (ω, S) rows
  int wave_component_count = 200;          // [-] irregular seas: number of components
  std::string wave_discretisation = "random_frequency";  // random_frequency | equal_energy
  int wave_seed = 1;                       // [-] irregular seas: phases (and frequencies) from mt19937_64(seed)
  double wave_direction_deg = 0.0;         // [deg] direction the waves travel towards, from +x towards +y
  std::string wave_stretching = "wheeler"; // wheeler | vertical: kinematics up to the instantaneous surface
  double wave_ramp_time = 20.0;            // [s] half-cosine start of the waves (> 0: statics sees calm water)
  double wave_elevation_x = 0.0;           // [m] where the wave_elevation history is recorded
  double wave_elevation_y = 0.0;           // [m]
  // fatigue at the joints (riser_fatigue.hpp; bound there)
  bool fatigue_enabled = false;                  // rainflow + Miner at 8 points around every joint
  std::string fatigue_sn_curve = "F1";           // DNVGL-RP-C203 (2016) curve name, or "user" (the fields below)
  std::string fatigue_environment = "seawater_cathodic_protection";  // air | seawater_cathodic_protection |
                                                                     // seawater_free_corrosion
  // user S–N curve: log N = log a1 − m1 log(Δσ f_t) up to N_t, log a2 − m2 log(Δσ f_t) beyond (Δσ in MPa;
  // f_t = (max(t, t_ref)/t_ref)^k); m2 = 0: one slope. Defaults: DNVGL-RP-C203 F1 in air.
  double fatigue_user_log_a1 = 11.699;           // [-] log10 a1, Δσ in MPa
  double fatigue_user_m1 = 3.0;                  // [-]
  double fatigue_user_log_a2 = 14.832;           // [-]
  double fatigue_user_m2 = 5.0;                  // [-] 0: one slope
  double fatigue_user_transition_cycles = 1e7;   // [-] N_t
  double fatigue_user_thickness_exponent = 0.25; // [-] k
  double fatigue_user_reference_thickness = 25.0;  // [mm] t_ref
  double fatigue_stress_concentration_factor = 1.0;  // [-] SCF on the nominal stress
  double fatigue_start_time = 0.0;               // [s] count cycles from here on (skip start-up transients)
  double fatigue_sample_interval = 0.0;          // [s] joint stresses sampled this often; 0: automatic
                                                 // (riser_fatigue.hpp: fatigueSampleInterval)
  // sea-bed contact (riser_seabed.hpp; bound there): off leaves every run as before
  bool seabed_contact = false;
  double seabed_slope_deg = 0.0;                // [deg]
  double seabed_slope_direction_deg = 0.0;      // [deg] heading towards which the bed rises
  double seabed_normal_stiffness = 1.0e5;       // [N/m^2] per unit length of riser
  double seabed_normal_damping = 0.0;           // [N*s/m^2] per unit length of riser
  double seabed_axial_friction = 0.5;           // [-]
  double seabed_lateral_friction = 0.5;         // [-]
  std::string seabed_friction_smoothing = "tanh";  // tanh | linear
  double seabed_friction_velocity = 0.01;       // [m/s]
  // loads
  std::vector<PointLoadRow> point_loads;  // forces and moments at nodes
  // solver
  double end_time = 24.0;   // [s]
  double time_step = 0.0;   // [s] rk4/implicit step; 0 = automatic (rk4: half the estimated stability limit)
  std::string integrator = "auto";  // "auto", "rk4", "dopri5", "implicit" (see docs/riser.md)
  double tolerance = 1e-6;  // [-] relative local error tolerance (dopri5, implicit Newton, auto's choice)
  // output
  bool modes = true;               // natural frequencies and modes about the static state (riser_modes_krylov.hpp)
  int frame_count = 60;            // [-] View3D frames and position snapshots
  std::vector<ProbeRow> probes = {{50.0}, {25.0}, {75.0}};  // recorded points: L/2 (the probe_* columns), L/4, 3L/4
  std::vector<double> stress_times = {12.0, 24.0};  // [s] times for the stress-along-the-riser table
  // frequency sweeps (paper Sect. 8.2): first two bending frequencies for other pretensions and segment counts
  std::vector<double> sweep_pretension_ratios;  // [-] i_T: top tension T = i_T g m′ (m′ submerged mass of riser + contents)
  std::vector<double> sweep_segment_counts;     // [-] n (whole numbers) at the scenario's top tension
  // convergence of the first probe's bending stress with n (paper Sect. 9, "σ_b(L/2) against n"): the whole time
  // history rerun at each n (riser_stress_convergence)
  std::vector<double> convergence_segment_counts;  // [-] n (whole numbers); empty: no study
  double convergence_tolerance = 1e-4;             // [-] harmonic top motion: expected probe error of each row
};

// The binder declaring path, unit, range and description of every field.
const SchemaBinder<RiserParameters>& riserBinder();

// Speed [m/s] of the prescribed top at t = 0: nonzero only for a harmonic motion without a ramp whose phases do
// not start it at rest (checkRiserParameters refuses that).
double initialTopSpeed(const RiserParameters& p);

// Cross-field checks (D_inn < D_out, section rows inside [0, L], nodes in range, reachable anchor, ...).
// Paths are relative to "parameters". Returns every problem found.
std::vector<FieldError> checkRiserParameters(const RiserParameters& p);

// Rewrites parameters of earlier riser schemas in place (SceneDefinition::upgrade); one note per change:
// output.probe_position [m] (one probe) became the table output.probes of rows {arc_length}; a missing
// stress_convergence section is added without a study; the angles current.direction, top.motion_phase_x/y/z,
// initial.inclination and initial.azimuth [rad] became *_deg [deg]; a missing tangential added-mass
// coefficient (section and sections rows) is set equal to the normal one (the isotropic added mass the file
// was written for); a missing output.modes is true.
std::vector<std::string> upgradeRiserParameters(Json& parameters);

}  // namespace maris::riser
