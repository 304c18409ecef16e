// Valid FIV parameters that are doubtful for what the model covers; warnings, never refusals.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "fiv/fiv_parameters.hpp"

namespace maris::fiv {

// A mass ratio m* below 1, speeds whose Reynolds number lies outside the range of the paper's data
// (1.61e4–2.01e5), and submergences below the shallowest one the free-surface factor was fitted to (h* = 1.11).
// Post-processing runs get none.
std::vector<FieldError> fivPlausibility(const FivParameters& p);

}  // namespace maris::fiv
