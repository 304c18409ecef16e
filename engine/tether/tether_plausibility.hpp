// Valid tether parameters that are doubtful for what the model covers; warnings, never refusals.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "tether/tether_parameters.hpp"

namespace maris::tether {

// A robot above the water surface (at the start or along the leader's path), a leader faster than the
// follower's saturated command, and an initial or desired shape so nearly taut that one control tick of the
// follower can pull the inextensible tether straight, or hanging so nearly vertically that one tick can swing
// its bearing.
std::vector<FieldError> tetherPlausibility(const TetherParameters& p);

}  // namespace maris::tether
