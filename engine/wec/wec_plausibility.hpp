// Valid WEC parameters that are doubtful for what the model covers; warnings, never refusals.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "wec/wec_parameters.hpp"

namespace maris::wec {

// A float reaching the sea bed; waves steeper than a wave can stand or higher than the depth allows; a wave
// amplitude beyond the float's draft (linear hydrostatics); with the built-in Hulme hemisphere, frequencies
// beyond its tables (ka > 10) and waves in shallow water (kh < π/10), where its deep-water values do not hold.
std::vector<FieldError> wecPlausibility(const WecParameters& p);

}  // namespace maris::wec
