// Explicit central-difference time stepping of the coupled solid–water FE model (fe_model.hpp).
//
// Staggered, fully explicit, as in SPECFEM's potential formulation: at step n the water is advanced
// first with the solid displacement u^n (flux q·u), its φ̈^n then loads the solid (−ρ_f φ̈^n q).
// Velocities live at half steps; the diagonal boundary dashpots use the average of v^{n±1/2}:
//   (M + ½Δt C) v^{n+1/2} = (M − ½Δt C) v^{n−1/2} + Δt (F^n − K u^n),   u^{n+1} = u^n + Δt v^{n+1/2}.
// The step must not exceed the element bound FeModel::stable_step (SolverError otherwise); a state
// that turns non-finite stops the run with a SolverError naming the node, time and step.
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/run_context.hpp"
#include "seismic/fe_drive.hpp"
#include "seismic/fe_model.hpp"

namespace maris::seismic {

// Nodal state, per node: displacement [m] and half-step velocity [m/s]; water potential [m²] and rate.
struct FeState {
  std::vector<double> ux, uy, vx, vy, phi, phi_dot;
  static FeState zero(int node_count);
};

struct FeRunResult;

struct FeRunSettings {
  double time_step = 0.0;             // [s] Δt
  long steps = 0;                     // number of steps
  bool enforce_stable_step = true;    // false only in tests that provoke divergence
  std::vector<int> record_nodes;      // nodes whose displacement is recorded every step (water: ∇φ)
  int snapshot_count = 0;             // frames of |u| over the grid, evenly spaced
  // Optional extra solid loads at step n, added into per-node (fx, fy) [N/m] (e.g. a Lysmer-boundary input).
  std::function<void(long, std::vector<double>&, std::vector<double>&)> extra_solid_forces;
  // Optional read-only look at the run after step n (state u^n, samples 0..n recorded), e.g. to hand
  // the histories so far to a partial-results publisher. Must not change anything the run uses.
  std::function<void(long, const FeState&, const FeRunResult&)> after_step;
};

struct FeSnapshot {
  double time = 0.0;               // [s]
  std::vector<double> magnitude;   // [m] |u| per node (water: |∇φ|, void: 0)
};

struct FeRunResult {
  double time_step = 0.0;                   // [s]
  long steps = 0;
  std::vector<std::vector<double>> ux, uy;  // [m] per recorded node, steps+1 samples (t = n·Δt)
  std::vector<FeSnapshot> snapshots;
  FeState final_state;
};

// Runs the model from `initial` with the boundary drive (nullptr: free vibration). Throws SolverError
// (step above the stable bound, non-finite state) and RunCancelled.
FeRunResult runExplicit(const FeModel& model, BoundaryDrive* drive, FeState initial, const FeRunSettings& settings,
                        RunContext& ctx);

// Displacement at a node: the solid's, or ∇φ by finite differences on the water grid.
Eigen::Vector2d nodalDisplacement(const FeModel& model, const FeState& state, int node);

}  // namespace maris::seismic
