// Valid riser parameters that are doubtful for what the model covers; warnings, never refusals.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

// For a riser in water (its anchor below the still-water level): the top end in the air, the anchor under or
// well above the sea bed, a current beyond what ocean currents reach, waves steeper than a wave can stand or
// higher than the depth allows. A model in air (anchor above the water) gets none.
std::vector<FieldError> riserPlausibility(const RiserParameters& p);

}  // namespace maris::riser
