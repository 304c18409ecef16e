#include "seismic/fe_mesh.hpp"

#include <cmath>
#include <vector>
#include <numbers>

#include "core/checked_count.hpp"

namespace maris::seismic {

double reefHalfWidth(const SeismicParameters& p, double y) {
  double top = 0.0;
  for (const auto& l : p.layers) top += l.thickness;
  if (p.model != "reef" || y < 0.0 || y > top) return -1.0;
  // Walk down from the flat: each layer widens by (depth below its top)/tan(slope).
  double half = 0.5 * p.flat_width, layer_top = top;
  for (const auto& l : p.layers) {
    const double slope = std::tan(l.slope_deg * std::numbers::pi / 180.0);
    const double layer_bottom = layer_top - l.thickness;
    if (y >= layer_bottom) return half + (layer_top - y) / slope;
    half += l.thickness / slope;
    layer_top = layer_bottom;
  }
  return half;
}

namespace {

// Reef layer (0-based from the top) containing height y, or −1.
int layerAt(const SeismicParameters& p, double y) {
  double top = 0.0;
  for (const auto& l : p.layers) top += l.thickness;
  double layer_top = top;
  for (std::size_t k = 0; k < p.layers.size(); ++k) {
    if (y >= layer_top - p.layers[k].thickness) return static_cast<int>(k);
    layer_top -= p.layers[k].thickness;
  }
  return -1;
}

}  // namespace

FeMesh buildMesh(const SeismicParameters& p, bool with_water, bool coarse_companion) {
  SeismicParameters q = p;
  q.include_water = with_water;
  const ModelExtent box = modelExtent(q);
  const bool reef = p.model == "reef";

  FeMesh m;
  const double target = slowestSpeed(q) / (10.0 * p.cutoff_frequency);
  // Align the water surface (or the reef top when dry) with a grid line, and if a slightly finer
  // grid (≤ 25 % or 6 more cells per direction) puts every layer interface on a grid line too, use it: a
  // layer whose thickness is not a whole number of cells is otherwise thinned or thickened by up to
  // one cell, which made the flat's amplification jump by ~10 % between meshes (B10 test).
  const double align = with_water ? p.water_depth : (reef ? box.reef_height : target);
  const int n_min = std::max(1, static_cast<int>(std::ceil(align / target - 1e-9)));
  std::vector<double> interfaces;  // heights above y = 0 of the layer boundaries
  if (reef) {
    double y = box.reef_height;
    for (const auto& l : p.layers) {
      interfaces.push_back(y);
      y -= l.thickness;
    }
  }
  auto aligned = [&](int n) {
    const double d = align / n;
    for (double y : interfaces)
      if (std::abs(y / d - std::round(y / d)) > 1e-6) return false;
    return true;
  };
  int n_align = n_min;
  for (int n = n_min; n <= n_min + std::max(n_min / 4, 6); ++n)
    if (aligned(n)) {
      n_align = n;
      break;
    }
  if (coarse_companion) {
    // About twice as coarse, aligned if a grid between 1/3 and 1/2 of the cells allows it.
    const int half = std::max(1, n_align / 2);
    int n_coarse = half;
    for (int n = half; n >= std::max(1, n_align / 3); --n)
      if (aligned(n)) {
        n_coarse = n;
        break;
      }
    n_align = n_coarse;
  }
  m.layers_aligned = aligned(n_align);
  m.delta = align / n_align;
  const int n_below = std::max(2, static_cast<int>(std::lround(box.seabed_depth / m.delta)));
  const int n_above = static_cast<int>(std::ceil(box.top / m.delta - 1e-9));
  const int half_cells = std::max(2, static_cast<int>(checkedCount(box.half_width / m.delta, kMaxStoredSamples,
                                                                   "parameters.solver.cutoff_frequency", "cells across half the box")));
  m.nx = 2 * half_cells;
  m.ny = n_below + n_above;
  m.x0 = -half_cells * m.delta;
  m.y0 = -n_below * m.delta;
  m.water = waterLayer(q);
  if (with_water) m.water.depth = n_align * m.delta;
  m.reef_height = reef ? box.reef_height : 0.0;

  m.solids.push_back(seabedMaterial(p));
  if (reef)
    for (const auto& l : p.layers) m.solids.push_back({l.density, l.vp, l.vs});

  m.cell_kind.assign(m.cellCount(), CellKind::Void);
  m.cell_material.assign(m.cellCount(), -1);
  for (int j = 0; j < m.ny; ++j) {
    const double yc = m.y0 + (j + 0.5) * m.delta;
    const int layer = reef ? layerAt(p, yc) : -1;
    const double half = reef ? reefHalfWidth(p, yc) : -1.0;
    for (int i = 0; i < m.nx; ++i) {
      const double xc = m.x0 + (i + 0.5) * m.delta;
      const int c = j * m.nx + i;
      if (yc < 0.0) {
        m.cell_kind[c] = CellKind::Solid;
        m.cell_material[c] = 0;
      } else if (layer >= 0 && std::abs(xc) <= half) {
        m.cell_kind[c] = CellKind::Solid;
        m.cell_material[c] = 1 + layer;
      } else if (with_water && yc < m.water.depth) {
        m.cell_kind[c] = CellKind::Water;
      }
    }
  }
  return m;
}

}  // namespace maris::seismic
