// Sea-bed contact of the riser: the `seabed` parameter section, the bed built from it, and the contact loads.
//
// The bed is a plane through z = environment.seabed_level above the global origin (x = y = 0), rising at
// `slope_deg` towards the heading `slope_direction_deg` (from +x towards +y, the project's angle convention);
// n is its upward unit normal. The pipe's outer surface touches it: at a point p of the axis on a segment of
// outer diameter D the penetration is δ = D/2 − n·(p − p₀). Per unit length, where δ > 0,
//   normal     f_n = max(0, k δ − c v·n)                         (k [N/m²], c [N·s/m²]; the bed never pulls)
//   friction   f_a = −μ_a f_n s(v_a / v_s),  f_l = −μ_l f_n s(v_l / v_s)
// with v_a, v_l the velocity components along the riser's axis projected on the bed and across it, v_s the
// smoothing velocity and s = tanh or the linear ramp clamp(x, −1, 1) (smoothed Coulomb: no force at rest, so
// statics sees no friction). The loads act at the same three Gauss points per segment as weight and drag. The
// elastic part has the potential ½ k δ² per length (seabedContactEnergy, in the energy balance); the damper's
// and the friction's power (≤ 0) go to power_damping.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/schema_binder.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

struct RiserModel;
struct RiserPose;
struct SegmentLoads;

struct RiserSeabed {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();     // [m] a point of the plane (x = y = 0)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();    // [-] upward unit normal
  double stiffness = 0.0;         // [N/m²] k per unit length
  double damping = 0.0;           // [N·s/m²] c per unit length
  double axial_friction = 0.0;    // [-] μ_a
  double lateral_friction = 0.0;  // [-] μ_l
  double friction_velocity = 0.01;  // [m/s] v_s
  bool linear_ramp = false;         // s = clamp(x, −1, 1) instead of tanh(x)

  // Height of the plane's point below (x, y) [m].
  double heightAt(double x, double y) const;
  // Penetration [m] of a point of the axis of a pipe of outer diameter `diameter` (> 0: contact).
  double penetration(const Eigen::Vector3d& point, double diameter) const {
    return 0.5 * diameter - normal.dot(point - origin);
  }
  // Contact force per unit length [N/m] at a point of the axis with tangent t moving at v.
  Eigen::Vector3d lineLoad(const Eigen::Vector3d& point, const Eigen::Vector3d& tangent, const Eigen::Vector3d& velocity,
                           double diameter) const;
};

// The bed of the parameters; nullptr for seabed.contact = false. Call on validated parameters.
std::shared_ptr<const RiserSeabed> buildRiserSeabed(const RiserParameters& p);

// The `seabed` section's fields (called by riserBinder) and its cross-field checks (by checkRiserParameters).
void bindSeabedParameters(SchemaBinder<RiserParameters>& b);
void checkSeabedParameters(const RiserParameters& p, std::vector<FieldError>& errors);

// Contact loads at the 3 Gauss points of each segment (computeLoads calls it when m.seabed is set).
void addSeabedContact(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads);
// Elastic energy ½ k δ² of the contact, integrated by the same Gauss points [J] (0 without a bed).
double seabedContactEnergy(const RiserModel& m, const RiserPose& pose);
// Highest rate [1/s] the contact adds (bed spring √(k/μ), its damper c/μ, the friction ramp μ f_n/(v_s μ) with
// f_n the submerged weight), for the automatic explicit step; 0 without a bed.
double seabedFrequencyEstimate(const RiserModel& m);

// Initial joint positions for a riser held at both ends whose anchor lies on the bed: straight from the top down to
// a point on the bed, then along the bed to the anchor, with the total length L (the sagging arc would bury the lower
// part in the bed). Empty when the anchor is not on the bed or no such point exists.
std::vector<Eigen::Vector3d> seabedInitialPoints(const RiserSeabed& bed, const Eigen::Vector3d& top,
                                                 const Eigen::Vector3d& anchor, double length,
                                                 const std::vector<double>& arc_lengths);

// Contact along the riser at one instant.
struct SeabedContactState {
  double touchdown = 0.0;       // [m] arc length of the first point of the axis in contact (L when none)
  double contact_length = 0.0;  // [m] length of the axis in contact
  double normal_force = 0.0;    // [N] total normal force of the bed on the riser (Gauss points)
  std::vector<double> node_line_load;  // [N/m] |contact force per length| at each node 0..n+1
};
SeabedContactState seabedContact(const RiserModel& m, const RiserPose& pose);

// Records the contact over a run (riser_results): history columns, a profile column, plot and scalars.
class SeabedRecorder {
 public:
  void addColumns(Table& history) const;
  // Appends this sample's history values; remembers the extremes.
  void sample(const SeabedContactState& state, std::vector<double>& row);
  void addProfileColumn(const SeabedContactState& state, Table& profile) const;
  void addPlot(Results& out) const;
  void addScalars(Results& out) const;

 private:
  bool first_ = true;
  double touchdown_start_ = 0.0, touchdown_min_ = 0.0, touchdown_max_ = 0.0, max_line_load_ = 0.0;
};

// The bed as a surface for the 3D view (2 × 2 grid over a square of half-width `half` about `centre`).
Shape3D seabedSurface(const RiserSeabed& bed, const Eigen::Vector3d& centre, double half);

}  // namespace maris::riser
