// Valid ship parameters that are doubtful for what the model covers; warnings, never refusals.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "ship/ship_parameters.hpp"

namespace maris::ship {

// A hull too full for thin-ship theory (L/B below 8, where Michell's integral over-predicts the humps), and
// Froude numbers below 0.08 on an offsets table with a grid too coarse to resolve them.
std::vector<FieldError> shipPlausibility(const ShipParameters& p);

}  // namespace maris::ship
