// Waves acting on the riser: the `waves` parameter section, the sea built from it (core/ocean_waves), and the
// Morison loads that replace the current-only drag of riser_loads when a sea is present:
//   per unit length, at each Gauss point below the instantaneous surface,
//   drag     f_D = −½ ρ_w D_out (D_yz |v_n| v_n + D_x |v_t| v_t),  v = v_structure − (current + u_wave)
//   inertia  f_I = ρ_w A_out (1 + C_a) (u̇_wave)_n  (Froude–Krylov plus the added mass's fluid part, C_m = 1 + C_a;
//            the added mass's structural part −ρ_w C_a A_out r̈ is in the segment mass, eq 11)
// where ( )_n is the component normal to the segment. Buoyancy stays at the still-water level.
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "core/errors.hpp"
#include "core/ocean_waves.hpp"
#include "core/schema_binder.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::ocean {
class WaveKinematicsBatch;  // core/ocean_kinematics_batch.hpp
}

namespace maris::riser {

struct RiserModel;
struct RiserPose;
struct SegmentLoads;

// The sea of a riser model: the wave field with z measured from the still-water level, its start-up ramp, and
// the batched evaluator of the field that the Morison loads use.
struct RiserSea {
  ocean::WaveField field;
  std::shared_ptr<const ocean::WaveKinematicsBatch> batch;  // of `field`; null: point by point (sea.at)
  double water_level = 0.0;  // [m] global z of the field's z = 0
  // [s] r(t) = τ³(10 − 15τ + 6τ²), τ = t/T_r, for 0 ≤ t < T_r, 0 before, 1 after: r, ṙ and r̈ are continuous, so
  // the vessel's acceleration (r̈ times the RAO motion in it) has no jump at 0 or T_r for a step to straddle.
  double ramp_time = 0.0;
  double elevation_x = 0.0, elevation_y = 0.0;  // [m] the recorded elevation's point

  double ramp(double t) const;
  double rampRate(double t) const;  // [1/s] dr/dt
  double rampAcceleration(double t) const;  // [1/s²] d²r/dt², zero outside (0, T_r) and continuous at both ends
  double elevation(double x, double y, double t) const;  // [m] ramped η above the still-water level
  // Ramped kinematics at a global point (its z relative to water_level inside).
  ocean::FluidKinematics at(const Eigen::Vector3d& point, double t) const;
};

// The wave kinematics at the Gauss points held over one step of the implicit integrator (riser_charted_alpha owns
// them, points its charts' poses at them through RiserPose::step_waves and calls beginStep() when a step begins):
// the first load evaluation of the step fills them at its pose (the step's predictor), its later evaluations (the
// Newton iterations and the Newton matrix's differences) read them. A pose without them evaluates every time.
struct StepWaveKinematics {
  bool filled = false;  // `fluid` holds this step's kinematics
  std::vector<ocean::FluidKinematics> fluid;
  void beginStep() { filled = false; }
};

// The sea of the parameters; nullptr for waves.type = none. Call on validated parameters.
std::shared_ptr<const RiserSea> buildRiserSea(const RiserParameters& p);

// The `waves` section's fields (called by riserBinder) and its cross-field checks (by checkRiserParameters).
void bindWaveParameters(SchemaBinder<RiserParameters>& b);
void checkWaveParameters(const RiserParameters& p, std::vector<FieldError>& errors);

// Drag with the relative velocity and inertia of the fluid acceleration, at the 3 Gauss points of each segment
// (computeLoads calls it instead of addDrag when m.sea is set). Its power on the structure goes to power_drag.
void addMorisonInWaves(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads);

}  // namespace maris::riser
