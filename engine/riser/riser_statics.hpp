// Static equilibrium of the segment chain (initial shapes: hanging catenary, riser in current,
// cantilever under tip load). Not in the paper, which starts from given shapes.
#pragma once

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/run_context.hpp"
#include "riser/riser_model.hpp"

namespace maris::riser {

struct StaticSolution {
  std::vector<Eigen::Quaterniond> orientation;  // R_GS_i of all n+1 segments at equilibrium
  Vec3 top = Vec3::Zero();         // [m] top end position
  Vec3 end_reaction = Vec3::Zero();// [N] force the riser exerts on a pinned/clamped bottom support (F_{n+1})
  int iterations = 0;              // Newton iterations over all load steps
  int load_steps = 0;              // accepted load levels (1 when full load converged at once)
  double residual = 0.0;           // [-] final scaled residual (max norm)
  bool banded = false;             // true: the O(n) Newton found it (no dense fallback)
  double relaxation_time = 0.0;    // [s] damped motion before the O(n) Newton converged (0: none needed)
  long relaxation_steps = 0;       // its time steps
};

// A part of the riser that is buoyant in water (buoyancy per length above its weight per length) held at the
// still-water level by the damped motion of dynamic relaxation: the riser floats. The model applies buoyancy at
// the pipe's centre line, all or nothing (riser_loads), so at the water line the load jumps from a net lift below
// to the weight in air above and a floating pipe has no equilibrium in it: Newton cannot converge there and the
// relaxation's step collapses on the jump. Thrown by solveStatics as soon as it is seen; the scene turns it into
// an InputError naming the fields that make that part buoyant (riser_scene).
class FloatingRiserError : public SolverError {
 public:
  FloatingRiserError(double time, long step, std::string detail, double first, double last, double lift)
      : SolverError("static equilibrium", time, step, std::move(detail)), first_(first), last_(last), lift_(lift) {}
  double first() const { return first_; }  // [m] arc length of the first and last point held at the surface
  double last() const { return last_; }
  double lift() const { return lift_; }     // [N/m] largest net lift (buoyancy − weight) per length among them

 private:
  double first_, last_, lift_;
};

// Accepted steps the dynamic relaxation of `m` may take: 10⁶ segment-steps, at least 2000 (24 390 at n = 40,
// 2000 from n = 500 on). The slack cable held at both ends relaxes in 390–490 steps per period.
long relaxationStepLimit(const RiserModel& m);

enum class StaticMethod {
  Automatic,  // O(n) Newton first, the dense method only if it fails (with a warning)
  Dense,      // the dense method only (reference for tests; O(n³) per iteration)
};

// Statics of the model at rest at its t = 0 top position (prescribed top motion removed).
// First an O(n) Newton at full load (pseudo-time steps with the joint Newton matrix of riser_joint_newton, damped
// by the natural monotonicity test, see riser_statics.cpp); if that fails from the initial shape, dynamic
// relaxation (riser_relaxation: damped motion, O(n) per step) and the same Newton from where it ends (warned);
// only if both fail, the dense method below (warned).
// Dense: Newton's method on the generalised forces of joint coordinates: unknowns are a rotation
// increment per dynamic segment (2 without torsion), the free top coordinates (tensioner: z) and,
// for a pinned/clamped bottom, the end reaction as Lagrange multiplier. Residuals: for each segment
// i the moment about A_i of everything from segment i down, n_i + d_i × Σ_{k>i} f_k = 0; the net
// force on a free top; the bottom position error. Jacobian by forward differences (dense, O(n³):
// statics runs once); backtracking line search on the scaled residual; if Newton fails at full
// load, the external loads are applied in steps (halved on failure).
// Starts from m.initial_orientation. Throws SolverError if no equilibrium is found, also when the dynamic
// relaxation does not settle within its work limit (relaxationStepLimit: the message names the residual that did
// not settle, the step and the time), and FloatingRiserError when a buoyant part floats at the water line.
StaticSolution solveStatics(const RiserModel& m, RunContext& context, StaticMethod method = StaticMethod::Automatic);

}  // namespace maris::riser
