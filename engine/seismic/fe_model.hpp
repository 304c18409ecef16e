// Assembled-once data of the explicit finite-element model (everything diagonal or per cell; no
// global matrix is formed).
//
// Solid: plane-strain bilinear squares, 2×2 Gauss, K_e = λ·K_λ + μ·K_μ (one 8×8 per material),
// row-sum lumped mass ρΔ²/4 per node and cell.
// Water: displacement potential φ (u = ∇φ, p = −ρ_f φ̈), φ̈/c² = ∇²φ; bilinear squares with
// K_f = ∫∇N·∇N and lumped mass Δ²/(4c²); φ = 0 on the free surface.
// Coupling on solid–water edges (lumped, per node q = Σ_edges (Δ/2)·n_f, n_f pointing out of the
// water): the water sees the flux +q·u, the solid the force −ρ_f φ̈ q (= −p n_s).
// Boundaries (left, right, bottom): solid viscous-spring nodes (Liu et al. 2006),
// K = α G/R, C = ρc per unit length (α_N = 1, α_T = 0.5; normal c = v_p, tangential v_s), R the
// distance to the scattering centre (0, 0); water: first-order radiation condition
// ∂φ/∂n = −φ̇/c − φ/(2R), i.e. damping A/c and stiffness A/(2R) per node (the velocity-potential form of the
// paper's series mass–damper).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "seismic/fe_mesh.hpp"

namespace maris::seismic {

using ElementMatrix8 = Eigen::Matrix<double, 8, 8>;

struct FeModel {
  FeMesh mesh;
  std::vector<ElementMatrix8> solid_stiffness;  // per solid material [N/m per m thickness]
  Eigen::Matrix4d water_stiffness;              // ∫∇N·∇N (independent of Δ for squares)
  std::vector<int> solid_cells, water_cells;    // cell indices

  // Per node (size nodeCount), written by buildFeModel:
  std::vector<double> solid_mass;    // [kg/m] 0 where the node has no solid cell
  std::vector<double> water_mass;    // [s^2] ∫N/c² lumped; 0 where no water cell
  std::vector<std::uint8_t> water_fixed;  // 1: φ = 0 (free surface)
  std::vector<double> spring_x, spring_y, dashpot_x, dashpot_y;  // [N/m², N·s/m²] solid boundary, per m thickness
  std::vector<double> water_damping, water_spring;              // [s/m · m], [1/m · m] water boundary
  std::vector<Eigen::Vector2d> coupling;  // [m] q per node (zero away from the interface)

  // Boundary substructure: b nodes (on the outer boundary), the cells touching them and their nodes.
  std::vector<int> boundary_nodes;
  std::vector<int> layer_solid_cells, layer_water_cells;
  std::vector<int> layer_nodes;  // every node of a layer cell (b and n nodes)

  double stable_step = 0.0;  // [s] 2/ω_max from the element (Irons) bound: max over cells of λ_max(M_e⁻¹K_e)
};

// Spring coefficients of the viscous-spring boundary (paper: α_N = 1.0, α_T = 0.5).
inline constexpr double kAlphaNormal = 1.0;
inline constexpr double kAlphaTangential = 0.5;

FeModel buildFeModel(const FeMesh& mesh);

// Corner nodes of cell c, counter-clockwise from the lower left (the periodic column wraps its last
// cell column onto node column 0).
inline void cellNodes(const FeMesh& m, int c, int (&n)[4]) {
  const int i = c % m.nx, j = c / m.nx;
  n[0] = j * (m.nx + 1) + i;
  n[1] = n[0] + 1;
  n[2] = n[0] + m.nx + 2;
  n[3] = n[0] + m.nx + 1;
  if (m.periodic_x && i == m.nx - 1) {
    n[1] -= m.nx;
    n[2] -= m.nx;
  }
}

// Internal force contributions −K u of the listed solid cells, added into (fx, fy); −K_f φ of water
// cells into fphi. Arrays are per node.
void addSolidInternalForces(const FeModel& model, const std::vector<int>& cells, const std::vector<double>& ux,
                            const std::vector<double>& uy, std::vector<double>& fx, std::vector<double>& fy);
void addWaterInternalForces(const FeModel& model, const std::vector<int>& cells, const std::vector<double>& phi,
                            std::vector<double>& fphi);

}  // namespace maris::seismic
