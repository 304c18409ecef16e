// Riser model: the constant quantities derived once from RiserParameters (the "compile" step).
//
// Conventions (whole riser scene):
// - Global frame G: origin where the user puts it, z up, x and y horizontal; gravity along -z.
//   (The paper has y vertical; its xz-plane is our xy-plane.)
// - Arc length s runs from the top end (s = 0) to the bottom end (s = L).
// - Primary division: n elements of length Δ = L/n. Secondary division: n+1 rigid segments of
//   lengths Δ/2, Δ, ..., Δ, Δ/2 (segment i from s = (i-1/2)Δ to (i+1/2)Δ, clipped to [0, L]),
//   joined by n spring-damping elements (sde) at joints A_1..A_n (s = (i-1/2)Δ).
// - Segment frame S_i: origin at its joint A_i (A_0 = top end), x' along the segment (tangent
//   t_i = R_GS_i·e1, pointing down the riser, towards increasing s), y', z' across.
// - Nodes: 0 = top end, k = joint A_k (1..n), n+1 = bottom end. Node k <= n is segment k's origin.
// - Orientation state: unit quaternions (no Euler-angle singularity anywhere). The paper's ZYX
//   angles are used for the spring law only, as relative angles of R_{i-1}^T R_i (eq 21), which
//   are singular only at a 90° bend between neighbouring segments.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "riser/riser_current.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_seabed.hpp"
#include "riser/riser_waves.hpp"

namespace maris::riser {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// [v]×: the matrix of the cross product, [v]× w = v × w.
inline Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

class VesselMotion;

enum class TopCondition { Pinned, Clamped, Tensioner, Free };
enum class BottomCondition { Pinned, Clamped, Free, Spring };
enum class Formulation { Joint, Absolute };

// One rigid segment: mass properties about its joint point, in its own frame S_i.
struct Segment {
  double length = 0.0;        // [m] l_i
  double arc_start = 0.0;     // [m] s at the segment's origin A_i
  double mass = 0.0;          // [kg] m_i = ρ̄ l_i (wall + contents + normal added mass, eq 11)
  double axial_mass = 0.0;    // [kg] wall + contents + tangential added mass: accelerations along the axis
  Mat6 mass_local;            // [kg, kg·m, kg·m²] 6x6 Newton-Euler mass about A_i in S_i, order (a, α)
  Mat6 inverse_mass_local;    // its inverse; torsion off: inverse on the subspace without spin about x'
  double outer_diameter = 0.0;      // [m] D_out (section at the segment centre)
  double weight_per_length = 0.0;   // [N/m] (ρ_r A_r + ρ_f A_inn) g, without buoyancy
  double buoyancy_per_length = 0.0; // [N/m] ρ_w g A_out where submerged
  double normal_drag = 0.0;         // [kg/m²] ½ ρ_w D_out D_yz
  double tangential_drag = 0.0;     // [kg/m²] ½ ρ_w D_out D_x
  double fluid_mass_per_length = 0.0;  // [kg/m] ρ_f A_inn of the contents (internal flow, eq 46)
  double fluid_inertia_per_length = 0.0;  // [kg/m] ρ_w A_out (1 + C_a): Morison inertia on the wave acceleration
};

// One spring-damping element between segments i-1 and i (i = 1..n).
struct Joint {
  Vec3 stiffness = Vec3::Zero();  // [N·m/rad] (C_1 torsion GJ/Δ, C_2 = C_3 bending EI/Δ)
  Vec3 damping = Vec3::Zero();    // [N·m·s/rad] β·C
  double bending_modulus = 0.0;   // [m³] w_B = π(D_out⁴ - D_inn⁴)/(32 D_out)
  double torsion_modulus = 0.0;   // [m³] w_T = π(D_out⁴ - D_inn⁴)/(16 D_out)
  double wall_area = 0.0;         // [m²] π(D_out² - D_inn²)/4 (tension stress, fatigue)
  double wall_thickness = 0.0;    // [m] (D_out - D_inn)/2 (S-N thickness correction)
};

// Prescribed top position, velocity and acceleration at one time.
struct TopKinematics {
  Vec3 position, velocity, acceleration;  // [m], [m/s], [m/s²] global
};

// The vessel's motion (VesselMotion::at) at the last time a caller asked for it: a step's residuals and the
// differences of its Newton matrix share their time, and the vessel's harmonic synthesis over the sea's components is
// then done once (RiserModel::topAt). Per caller (each RiserWorkspace holds one); holding the vessel keeps it from
// being replaced by another at the same address.
struct VesselMotionCache {
  std::shared_ptr<const VesselMotion> vessel;
  double time = std::numeric_limits<double>::quiet_NaN();
  TopKinematics motion;
};

// Clamped cubic spline through a time table of top displacements (zero velocity at the first and last
// rows, so velocity is continuous everywhere; the first/last row is held outside the table).
// Position is C², velocity C¹ inside; interpolation error O(Δt⁴) for smooth motions.
struct TopMotionSpline {
  std::vector<double> time;     // [s] knots (strictly increasing)
  std::vector<Vec3> value;      // [m] displacement at the knots
  std::vector<Vec3> curvature;  // [m/s²] second derivative at the knots, written by buildTopMotionSpline
  bool empty() const { return time.empty(); }
  // Displacement, velocity and acceleration at time t.
  TopKinematics at(double t) const;
};
TopMotionSpline buildTopMotionSpline(const std::vector<TopMotionRow>& rows, bool vertical_free);

struct RiserModel {
  int n = 0;                     // primary elements; segments 0..n, joints 1..n
  double length = 0.0;           // [m] L
  double element_length = 0.0;  // [m] Δ = L/n
  std::vector<Segment> segments; // n+1
  std::vector<Joint> joints;     // n+1, index 0 unused
  Formulation formulation = Formulation::Joint;
  bool torsion = true;
  double stiffness_damping = 0.0;  // [s] β of the spring dampers (B = β C)
  double relaxation_damping = 0.0; // [1/s] c of a mass-proportional damper −c M v: statics' dynamic relaxation only
  TopCondition top = TopCondition::Tensioner;
  BottomCondition bottom = BottomCondition::Pinned;
  int first_dynamic = 0;         // 1 when the top is clamped (segment 0 moves with the top)
  int last_dynamic = 0;          // n-1 when the bottom is clamped (segment n fixed)
  double gravity = 9.81;         // [m/s²]
  double water_level = 0.0;      // [m]
  double seabed_level = -100.0;  // [m]
  double top_tension = 0.0;      // [N]
  Vec3 top_mean = Vec3::Zero();  // [m] top position at rest
  Vec3 anchor = Vec3::Zero();    // [m] bottom anchor
  double spring_stiffness = 0.0, spring_damping = 0.0;  // bottom spring [N/m], [N·s/m]
  // model.axial_flexibility: the riser's stretch as a spring between the top's prescribed point and the chain's top
  // (k = 1/Σ Δ/(E A_wall) [N/m], 0 = off), carrying half the submerged weight on top of k·stretch [N] (the mean
  // tension of a vertical riser sets its stretch); damped like the joints, β k.
  double axial_stiffness = 0.0, axial_weight_share = 0.0;
  Vec3 motion_amplitude = Vec3::Zero(), motion_phase = Vec3::Zero();  // [m], [rad]
  double motion_omega = 0.0, ramp_time = 0.0;  // [rad/s], [s]
  TopMotionSpline top_table;                   // non-empty: top motion from the time table (replaces harmonic)
  double flow_speed = 0.0;                     // [m/s] u of the internal flow (eqs 43-52)
  double current_surface = 0.0, current_seabed = 0.0, current_direction = 0.0;  // [m/s], [m/s], [rad]
  CurrentProfile current_profile;              // what currentAt evaluates (riser_current.hpp)
  std::vector<PointLoadRow> point_loads;
  std::shared_ptr<const RiserSea> sea;                  // waves (riser_waves.hpp); null: none
  std::shared_ptr<const RiserSeabed> seabed;            // sea-bed contact (riser_seabed.hpp); null: none
  std::shared_ptr<const VesselMotion> vessel;           // top.motion = vessel (riser_vessel.hpp); null: none
  std::vector<Eigen::Quaterniond> initial_orientation;  // n+1 segment orientations R_GS of the initial shape
  Vec3 initial_top = Vec3::Zero();                      // [m] top position of the initial shape

  int segmentCount() const { return n + 1; }
  bool isDynamic(int i) const { return i >= first_dynamic && i <= last_dynamic; }
  // Current velocity at height z (current_profile: a table or linear between surface and sea bed; zero above the water).
  Vec3 currentAt(double z) const;
  // Prescribed top motion at time t (mean position + ramped harmonic motion per axis, the table, or the vessel).
  TopKinematics topAt(double t) const;
  // The same, the vessel's motion looked up in `cache` when it holds this time's (the same numbers).
  TopKinematics topAt(double t, VesselMotionCache& cache) const;
  // Segment index and local coordinate ξ of arc length s.
  std::pair<int, double> locate(double s) const;
};

// Top components whose force is known (free top: all; tensioner and axial spring: z) instead of their motion.
bool topForceKnown(const RiserModel& m, int c);
// Bottom end held at a point (pinned or clamped): its position is a constraint with a reaction.
bool bottomHeld(const RiserModel& m);

// Derived quantities from validated parameters: segments, mass matrices, stiffnesses, initial shape.
RiserModel buildRiserModel(const RiserParameters& p);

// 3-point Gauss-Legendre abscissae (in [0, 1]) and weights for loads along a segment.
inline constexpr double kGaussX[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
inline constexpr double kGaussW[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

}  // namespace maris::riser
