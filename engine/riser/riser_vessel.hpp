// Vessel motion at the riser top (top.motion = vessel): a vessel's first-order displacement RAOs applied to the
// same wave train that loads the riser (the components, phases and start-up ramp of riser_waves), so the top and
// the waves stay in phase.
//
// RAO convention (the one of Orcina's OrcaFlex with its default conventions page, documentation "Vessel theory:
// RAOs and phases" and "Vessel types: Conventions"): vessel axes x forward (bow), y to port, z up, rotations
// right-handed about them (roll > 0 starboard down, pitch > 0 bow down, yaw > 0 bow to port); the RAO direction is
// the direction the waves travel towards relative to the vessel, from its x axis towards y (0: waves from astern);
// amplitudes per unit wave amplitude (translations m/m, rotations deg/m, or rad/m with vessel.rao_rotation_unit =
// rad); phases in degrees, lagging (vessel.rao_phase = lag): for a wave η = a cos(ωt) at the RAO origin the motion
// of degree of freedom j is x_j = a R_j cos(ωt − ε_j). A table whose phases lead (WAMIT-style) is read with
// vessel.rao_phase = lead (ε → −ε).
//
// Kinematics: per component i of the sea, ψ_i(t) = k_i·x_ref − ω_i t + φ_i at the RAO origin's mean position x_ref,
// x_j(t) = r(t) Σ_i a_i R_j(ω_i) cos(ψ_i + ε_j(ω_i)) with the sea's ramp r(t); the hang-off point (offset r_h from
// the RAO origin, vessel axes) then moves rigidly with exact rotations:
//   x_top = x_mean + H [ξ + (R(θ) − I) r_h],  v = H [ξ̇ + Ṙ r_h],  a = H [ξ̈ + R̈ r_h],
// with ξ = (surge, sway, heave), θ = (roll, pitch, yaw), R = R_z(yaw) R_y(pitch) R_x(roll) and H = R_z(heading).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "core/schema_binder.hpp"
#include "core/table_reader.hpp"
#include "riser/riser_model.hpp"

namespace maris::riser {

// A displacement RAO table: every heading has the same frequencies.
struct RaoTable {
  std::vector<double> heading;  // [deg] strictly increasing, last − first ≤ 360
  std::vector<double> omega;    // [rad/s] strictly increasing
  // [dof][h * omega.size() + f]; dof 0..5 = surge, sway, heave, roll, pitch, yaw. Amplitude: m/m, rotations rad/m;
  // phase: lag [rad] relative to the wave crest at the RAO origin.
  std::array<std::vector<double>, 6> amplitude, phase_lag;
};

// RAO amplitude [m/m, rad/m] and phase lag [rad] of the six degrees of freedom at one frequency and heading.
struct RaoValue {
  std::array<double, 6> amplitude{}, phase_lag{};
};

// Parses the CSV layout of docs/riser.md ("Vessel motion"): a names row with heading, omega or period, and
// <dof>_amplitude, <dof>_phase for dof surge, sway, heave, roll, pitch, yaw (units in brackets are allowed); one
// row per heading and frequency, rows in blocks of one heading (increasing headings), each block in increasing
// omega (or period) with the same frequencies. Every problem goes into `errors` (field spec.field, the file, the
// line and column); the table is usable only when none was added.
RaoTable raoTableFromText(std::string_view text, const TableSpec& spec, bool phase_lead, bool rotations_in_radians,
                          std::vector<FieldError>& errors);

// The RAO at `heading_deg` (relative wave direction) and `omega`: amplitude and phase linear in frequency, then in
// heading, separately (phases along the shorter arc). Frequencies outside the table take the end row's value
// (`outside` set); headings are periodic (360°): between the last heading and the first + 360 the table wraps
// when that gap is no wider than its widest heading step, else the nearer end heading is used (`clamped` set).
RaoValue interpolateRao(const RaoTable& table, double heading_deg, double omega, bool* outside = nullptr,
                        bool* clamped = nullptr);

class VesselMotion {
 public:
  Vec3 reference = Vec3::Zero();  // [m] mean position of the RAO origin (the wave phase reference), global; the
                                  // phases are formed from it when the motion is built
  std::vector<std::string> warnings;  // frequencies or heading outside the table (scene warnings)
  double mean_period = 0.0;  // [s] T_m01 = 2π Σa²/Σa²ω of the wave train (sets the automatic time step)

  // Displacement of the hang-off point from its mean position, its velocity and acceleration (global).
  TopKinematics at(double t) const;
  // The six ramped degrees of freedom at t (translations [m], rotations [rad]) and their first two derivatives.
  void degreesOfFreedom(double t, Vec6& x, Vec6& v, Vec6& a) const;

 private:
  friend std::shared_ptr<const VesselMotion> buildVesselMotion(const RiserParameters&,
                                                               std::shared_ptr<const RiserSea>, const Vec3&, bool);
  std::shared_ptr<const RiserSea> sea_;
  // Per wave component: ω and the phase k·x_ref + φ at the RAO origin's mean position (set with `reference`).
  std::vector<double> omega_, reference_phase_;
  Eigen::Matrix<double, 6, Eigen::Dynamic> cos_part_, sin_part_;  // a R cos ε, a R sin ε per dof and component
  Mat3 heading_ = Mat3::Identity();
  Vec3 hang_off_ = Vec3::Zero();
  bool vertical_free_ = false;  // tensioner: the top's vertical motion is free, not prescribed
};

// The vessel motion of validated parameters with top.motion = vessel (reads vessel.rao_file; throws InputError on a
// bad file). `top_mean` is the top's mean position (offset included).
std::shared_ptr<const VesselMotion> buildVesselMotion(const RiserParameters& p, std::shared_ptr<const RiserSea> sea,
                                                      const Vec3& top_mean, bool vertical_free);

// The `vessel` section (called by riserBinder), its checks (by checkRiserParameters: reads and checks the RAO file),
// and the upgrade of files written before it existed.
void bindVesselParameters(SchemaBinder<RiserParameters>& b);
void checkVesselParameters(const RiserParameters& p, std::vector<FieldError>& errors);
void upgradeVesselParameters(Json& parameters, std::vector<std::string>& notes);

}  // namespace maris::riser
