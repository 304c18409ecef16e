// The reef's layers as outlines for the 3D view: the reef's outer boundary (flanks and flat) and each interface
// between two layers, as polylines in the section's plane (x along the section, z up, y = 0), where the wave
// field is drawn. A 2-D view outlines the water and sea bed itself; the layers only the scene knows.
#pragma once

#include <vector>

#include "core/results.hpp"
#include "seismic/seismic_parameters.hpp"

namespace maris::seismic {

// Empty for the box model (no reef). Otherwise the outline first ("reef outline": from the left toe up the flank,
// across the flat, down to the right toe), then one "layer interface" per boundary between two layers.
std::vector<Shape3D> reefLayerOutlines(const SeismicParameters& p);

}  // namespace maris::seismic
