// Kinematic pose of the segment chain and the external / spring loads acting on each segment.
// Every load is reduced to a force and a moment about the segment's origin A_i (global frame),
// which is what the Newton-Euler blocks of riser_dynamics consume. Optional physics are
// separate functions; computeLoads() calls the ones the model switches on.
#pragma once

#include <memory>
#include <vector>

#include "riser/riser_model.hpp"

namespace maris::riser {

struct StepWaveKinematics;

// Positions, orientations and velocities of all n+1 segments at one instant.
struct RiserPose {
  double time = 0.0;                // [s]
  std::vector<Mat3> rotation;       // R_GS_i, segment frame to global (n+1)
  std::vector<Vec3> position;       // [m] joint A_i, global (n+1)
  std::vector<Vec3> omega;          // [rad/s] angular velocity of segment i, global (n+1)
  std::vector<Vec3> velocity;       // [m/s] velocity of A_i, global (n+1)
  Vec3 end_position = Vec3::Zero(); // [m] bottom end (node n+1)
  Vec3 end_velocity = Vec3::Zero(); // [m/s]
  StepWaveKinematics* step_waves = nullptr;  // set by the implicit integrator: wave kinematics held over its step

  void resize(int segment_count);
  Vec3 tangent(int i) const { return rotation[i].col(0); }
  // Position of node k (0..n+1).
  Vec3 node(int k) const { return k < static_cast<int>(position.size()) ? position[k] : end_position; }
};

// Loads reduced to each segment's origin. Written by computeLoads.
struct SegmentLoads {
  std::vector<Vec3> force;           // [N] resultant external + spring force on segment i (n+1)
  std::vector<Vec3> moment;          // [N·m] resultant moment about A_i (n+1)
  std::vector<Vec3> relative_angle;  // [rad] Δφ_i = ZYX angles of R_{i-1}^T R_i (eq 21), index 1..n
  std::vector<Vec3> spring_moment;   // [N·m] M̄_i = C Δφ_i + B Δφ̇_i (eq 26, the paper's M'), index 1..n
  Vec3 support_force = Vec3::Zero(); // [N] spring/free bottom: force from the support on the bottom end
  double power_drag = 0.0;           // [W] power of drag on the structure
  double power_damping = 0.0;        // [W] power of spring dampers and the anchor damper (<= 0)
  double power_point = 0.0;          // [W] power of the point loads
  double power_flow = 0.0;           // [W] power of the internal-flow forces (eq 46)

  void resize(int segment_count);
};

// ZYX angles (γ, θ, ψ) of a rotation matrix, eq (21): R = R3(ψ) R2(θ) R1(γ).
Vec3 zyxAngles(const Mat3& r);
// Euler-rate matrix G(γ, θ, ψ): spatial angular velocity = G · d(γ, θ, ψ)/dt; det G = cos θ, with |cos θ| held
// at 1e-6 or more (within 1e-6 rad of the 90° singularity).
Mat3 zyxRateMatrix(const Vec3& angles);

// Spring-damping moments (eqs 20-28). For sde i the couple on segment i is -R_{i-1} G(Δφ)^{-T} M̄_i
// and on segment i-1 the opposite; this is -∂V_s/∂(rotation) of V_s = ½ Δφᵀ C Δφ.
void addSpringMoments(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads);
// Weight and buoyancy at Gauss points (eqs 29-33), buoyancy only where the point is below the water.
void addGravityAndBuoyancy(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads);
// Morison drag (eq 34) with tangential and normal coefficients against the current, at Gauss points.
void addDrag(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads);
// Curvature vector k_i = dt/ds at the centre of segment i from a quadratic through the tangents of three
// neighbouring segment centres (eqs 47-49; stencils (0,1,2) at the top, (i-1,i,i+1), (n-2,n-1,n) at the bottom).
Vec3 curvatureVector(const RiserModel& m, const RiserPose& pose, int i);
// Internal flow of constant speed u (eq 46): F_i = -ρ_f A_inn l_i [2u ṫ_i + u² k_i] at the segment centre
// (Coriolis and centrifugal terms of Païdoussis' fluid force (43); the r̈ term is in the mass, eq 11).
void addInternalFlow(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads);
// Point forces and moments active at pose.time.
void addPointLoads(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads);
// Bottom spring (and damper) to the anchor, for BottomCondition::Spring.
void addBottomSpring(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads);

// Mass-proportional damping −c M_i (v_i, ω_i) of every segment (c = m.relaxation_damping): drains 2c times the
// kinetic energy per second from every mode alike. Only statics by dynamic relaxation switches it on.
void addRelaxationDamping(const RiserModel& m, const RiserPose& pose, SegmentLoads& loads);

// All loads at `pose`; `factor` scales the external loads (gravity, drag, point loads) for load stepping.
void computeLoads(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads);

// Energies of the conservative part: rotary springs, weight and buoyancy, anchor spring [J].
double springEnergy(const RiserModel& m, const RiserPose& pose);
// The same from the joint angles computeLoads left in loads.relative_angle (the ZYX angles of R_{i-1}^T R_i): no
// second pass of 3×3 products over the riser (the recorder, at every history sample).
double springEnergy(const RiserModel& m, const SegmentLoads& loads);
double gravityPotential(const RiserModel& m, const RiserPose& pose);
double anchorSpringEnergy(const RiserModel& m, const RiserPose& pose);
double kineticEnergy(const RiserModel& m, const RiserPose& pose);

}  // namespace maris::riser
