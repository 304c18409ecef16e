// Natural modes of the solid part of the FE model (reef + seabed), for the paper's modal table
// (Table 2: global horizontal and vertical modes, then partial modes of the reef layers).
//
// Generalised symmetric problem K x = ω² M x over the solid nodes (plane strain, the same per-cell
// stiffness and lumped mass as the explicit solver), solved by shift-invert Lanczos at σ = 0 in the
// M-inner product with full re-orthogonalisation (K⁻¹M is M-self-adjoint; its largest eigenvalues
// 1/ω² converge first). K is factorised once (Eigen SimplicialLDLT, AMD ordering).
// Boundary conditions (the paper does not state its own): the artificial
// boundary's springs K = αG/R stay (dashpots dropped); with `fixed_base` the bottom row is clamped.
// computeSolidModes: the dry reef on its seabed. computeCoupledModes: reef, seabed and water together
// (fluid–solid modes, see there).
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
  double water_share = 0.0;       // [-] water's share of the kinetic energy (coupled modes; 0 for dry ones)
  std::vector<double> ux, uy;     // [-] mode shape per node (max |u| = 1; 0 at void, water and clamped nodes)
};

struct ModalResult {
  std::vector<SolidMode> modes;  // ascending frequency
  int dof = 0;                   // unknowns of the eigenproblem
  int lanczos_steps = 0;
};

// Lowest `count` modes. Throws SolverError if K is singular (no base and no springs) and RunCancelled.
ModalResult computeSolidModes(const FeModel& model, int count, bool fixed_base, RunContext& ctx);

// Lowest `count` fluid–solid modes with the water (displacement potential φ, p = −ρ_f φ̈) coupled on
// the wet faces, as in the time stepping: M_s ü + K_s u = −ρ_f Q φ̈, M_f φ̈ + K_f φ = Qᵀu (K_f with the
// radiation boundary's stiffness A/(2R); dashpots dropped; φ = 0 at the surface). The pencil
//   K = [K_s 0; −Qᵀ K_f],  M = [M_s ρ_f Q; 0 M_f],  K x = ω² M x
// is not symmetric (ω² is still real: the system is conservative), so shift-invert Arnoldi at σ = 0
// is used: K is block lower triangular, so K⁻¹ needs only the two SPD factorisations of K_s and K_f.
// Inner product diag(M_s, ρ_f·diag K_f) (balances metres against m² of φ); full re-orthogonalisation.
// Diagnostics as for the dry modes over the solid part (mass ratios normalised by the solid's Σ m u²),
// plus water_share = ρ_f φᵀK_fφ / (uᵀM_s u + ρ_f φᵀK_fφ). Throws SolverError (singular K, or Ritz
// values that stay complex) and RunCancelled.
ModalResult computeCoupledModes(const FeModel& model, int count, bool fixed_base, RunContext& ctx);

}  // namespace maris::seismic
