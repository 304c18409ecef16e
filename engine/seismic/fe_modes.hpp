// Natural modes of the solid part of the FE model (reef + seabed), for the paper's modal table
// (Table 2: global horizontal and vertical modes, then partial modes of the reef layers).
//
// Generalised symmetric problem K x = ω² M x over the solid nodes (plane strain, the same per-cell
// stiffness and lumped mass as the explicit solver), solved by shift-invert Lanczos at σ = 0 in the
// M-inner product with full re-orthogonalisation (K⁻¹M is M-self-adjoint; its largest eigenvalues
// 1/ω² converge first). K is factorised once (Eigen SimplicialLDLT, AMD ordering).
// Boundary conditions (the paper does not state its own, research brief §8.4): the artificial
// boundary's springs K = αG/R stay (dashpots dropped); with `fixed_base` the bottom row is clamped.
// The water is NOT included: the modes are those of the dry reef on its seabed (limit, docs/seismic.md).
#pragma once

#include <vector>

#include "core/run_context.hpp"
#include "seismic/fe_model.hpp"

namespace maris::seismic {

struct SolidMode {
  double frequency = 0.0;         // [Hz] ω/(2π)
  double horizontal_share = 0.0;  // [-] Σ m u_x² / Σ m |u|² (1: purely horizontal motion)
  double reef_share = 0.0;        // [-] share of Σ m |u|² in the reef layers (vs the seabed)
  double top_layer_share = 0.0;   // [-] share of Σ m |u|² in reef layer 1 (the top, low-velocity layer)
  double mass_ratio_x = 0.0;      // [-] effective modal mass in x / total solid mass, clamped nodes included
  double mass_ratio_y = 0.0;      // [-] same in y
  double residual = 0.0;          // [-] ‖K x − ω² M x‖ / ‖K x‖
  std::vector<double> ux, uy;     // [-] mode shape per node (max |u| = 1; 0 at void, water and clamped nodes)
};

struct ModalResult {
  std::vector<SolidMode> modes;  // ascending frequency
  int dof = 0;                   // unknowns of the eigenproblem
  int lanczos_steps = 0;
};

// Lowest `count` modes. Throws SolverError if K is singular (no base and no springs) and RunCancelled.
ModalResult computeSolidModes(const FeModel& model, int count, bool fixed_base, RunContext& ctx);

}  // namespace maris::seismic
