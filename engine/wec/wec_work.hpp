// What a WEC run will cost, from its parameters alone (the scene's work estimate).
#pragma once

#include "core/work_estimate.hpp"
#include "wec/wec_parameters.hpp"

namespace maris::wec {

WorkEstimate estimateWecWork(const WecParameters& p);

}  // namespace maris::wec
