// Structured finite-element grid of the reef–seawater section (or the flat verification box).
//
// Square cells of side Δ on a regular grid; each cell takes the material at its centroid, so the reef
// flanks are staircases of step Δ (the mesh is conforming everywhere, solid–water interfaces follow
// cell edges). Same frame as free_field.hpp: y = 0 is the seabed at the lateral boundaries, the water
// surface is y = h, the seabed is modelled down to y = −H_s; the grid is symmetric about x = 0.
// Cell (i, j), i < nx, j < ny, has index j·nx + i and nodes (i, j), (i+1, j), (i+1, j+1), (i, j+1)
// (counter-clockwise); node (i, j) has index j·(nx+1) + i.
#pragma once

#include <cstdint>
#include <vector>

#include "seismic/free_field.hpp"
#include "seismic/seismic_parameters.hpp"

namespace maris::seismic {

enum class CellKind : std::uint8_t { Void, Solid, Water };

struct FeMesh {
  int nx = 0, ny = 0;          // cells along x and y
  double delta = 0.0;          // [m] cell side Δ
  double x0 = 0.0, y0 = 0.0;   // [m] lower-left corner
  std::vector<CellKind> cell_kind;       // per cell (nx·ny)
  std::vector<int> cell_material;        // per cell: index into `solids` (−1 for water and void)
  std::vector<ElasticMaterial> solids;   // 0 = seabed, 1.. = reef layers from the top down
  WaterLayer water;                      // depth = y of the water surface; 0 = no water
  double reef_height = 0.0;              // [m] top of the reef flat above y = 0 (0: box)
  bool layers_aligned = true;            // every reef-layer interface lies on a grid line
  bool periodic_x = false;               // true: the last cell column connects to node column 0 and there are
                                         // no lateral boundaries (1D column tests); node column nx is unused

  int nodeCount() const { return (nx + 1) * (ny + 1); }
  int cellCount() const { return nx * ny; }
  int node(int i, int j) const { return j * (nx + 1) + i; }
  double nodeX(int i) const { return x0 + i * delta; }
  double nodeY(int j) const { return y0 + j * delta; }
  // Cell kind with Void outside the grid (so neighbours of edge cells are well defined).
  CellKind kindAt(int i, int j) const {
    return (i < 0 || j < 0 || i >= nx || j >= ny) ? CellKind::Void : cell_kind[j * nx + i];
  }
};

// Builds the grid for the scene's parameters: Δ = v_min/(10 f_cut) (paper eq 28), shrunk so that the
// water depth (or the reef height without water) is a whole number of cells, and further (by ≤ 25 % or 6 cells)
// when that also puts every layer interface on a grid line; H_s and the width are rounded to whole cells. `with_water` false removes the water (the paper's sloping platform).
// `coarse_companion`: a grid about twice as coarse (for the discretisation-error estimate), aligned
// to the layers when a grid with 1/3 to 1/2 of the cells per direction allows it.
FeMesh buildMesh(const SeismicParameters& p, bool with_water, bool coarse_companion = false);

// Half-width [m] of the reef at height y ∈ [0, reef_height] (layers stacked horizontally, each with
// its own flank slope); negative outside that range.
double reefHalfWidth(const SeismicParameters& p, double y);

}  // namespace maris::seismic
