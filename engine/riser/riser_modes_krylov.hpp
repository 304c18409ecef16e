// Lowest natural modes of long chains by shift-invert Arnoldi (Spectra's GenEigsSolver) on the banded,
// constrained pencil of the absolute coordinates: O(n) per iteration instead of the dense O(n³) of computeModes.
//
// The linearisation is the absolute one of riser_modes.hpp written before the reactions are eliminated. Per
// dynamic segment i the coordinates u_i are its origin displacement δr_i/Δ and its rotation increments δψ_i (three
// global axes with torsion, else the two transverse axes), and the joint reactions F_j are kept as unknowns:
//     (K − λ M) u = B δF,   C u = 0,   λ = ω²,
// M the segments' 6×6 Newton–Euler masses (block diagonal), K = −∂g/∂u the stiffness of the segment loads g_i =
// b_i + E F⁰_i − D'_i F⁰_{i+1} at the static reactions F⁰ (springs couple neighbours only, so K is block
// tridiagonal), C the linearised joint, top-hold and bottom-hold gaps and B = the reactions' action on the segments
// (riser_dynamics.hpp). Eliminating δF and the constrained directions gives the dense absolute linearisation of
// computeModes; kept, the system is banded. Ordered (F_f, segment f, F_{f+1}, …, F_{last+1}) as in riser_newton,
// the matrix [K − σM, −B; C, 0] has bandwidth 2s + 2 (s = 6 coordinates per segment, 5 without torsion) and is
// factorised once by BandedLu; the operator x ↦ u of
//     (K − σM) u − B μ = M x,   C u = 0
// is (K − σM)⁻¹M on the connected directions (its eigenvalues 1/(λ − σ)) and maps everything into them, so
// the 3(n+2) constraint directions of the dense absolute problem appear as eigenvalue 0 and are never found.
// K is not symmetric in general (current drag follows the segments), hence the non-symmetric Arnoldi solver.
// Internal flow (a gyroscopic, state-space problem) stays with the dense solver.
#pragma once

#include "core/run_context.hpp"
#include "riser/riser_modes.hpp"

namespace maris::riser {

// Largest segment count whose modes the dense solver computes (its order 3(n+1) ≤ 600, a few seconds); above it
// the Krylov solver takes over.
inline constexpr int kDenseModesMaxSegments = 199;

enum class ModesMethod {
  Dense,   // computeModes (Eigen's dense eigen solvers; cannot be interrupted, run abandonable)
  Krylov,  // computeModesKrylov (interruptible between operator applications)
  None,    // internal flow above kDenseModesMaxSegments: not computed
};
ModesMethod modesMethod(const RiserModel& model);

// The `count` lowest modes (same contents and conventions as computeModes with its default joint linearisation:
// frequencies ascending, zero modes dropped, shapes largest = 1). No internal flow (std::invalid_argument).
// Checks context's cancel flag before every operator application (throws RunCancelled). Throws SolverError when
// the pencil is singular at the shift or when Arnoldi does not converge (the message gives how many modes
// converged after how many restarts and operator applications). `method` receives a one-line description.
struct KrylovSettings {
  int max_restarts = 1000;   // implicit restarts of the Arnoldi factorisation before giving up
  double tolerance = 1e-13;  // Spectra's relative accuracy of the Ritz values 1/(λ − σ)
  double difference_step = 1e-6;  // central-difference step of K in the dimensionless coordinates
};
RiserModes computeModesKrylov(const RiserModel& model, const StaticSolution& statics, int count,
                              const RunContext& context, std::string* method = nullptr,
                              const KrylovSettings& settings = {});

// The pencil of computeModesKrylov as dense matrices, for checking the Krylov solve against a dense one at small n:
// (K − λM) u ∈ range(Cᵀ), C u = 0, u the coordinates segment by segment (positions/Δ, then rotations).
struct DensePencil {
  Eigen::MatrixXd stiffness;    // K
  Eigen::MatrixXd mass;         // M
  Eigen::MatrixXd constraints;  // C (rows of known forces are zero)
};
DensePencil denseModesPencil(const RiserModel& model, const StaticSolution& statics, double difference_step = 1e-6);

// Natural modes by the method modesMethod chooses (the dense one through runAbandonable); empty for None.
// `method`, when given, receives how they were computed (for the solver statistics).
RiserModes naturalModes(const RiserModel& model, const StaticSolution& statics, int count, RunContext& context,
                        std::string* method = nullptr);

}  // namespace maris::riser
