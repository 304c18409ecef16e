// Counts computed in floating point (time steps T/h, samples, mesh cells) become integers only through
// checkedCount: a count that is not finite, negative or above its limit is an InputError naming the
// input that sets it, instead of an overflowed integer (a "1 step" run, a negative size, a 32 GB
// allocation). These are hard limits beyond what any run could finish; the work limits
// (core/work_estimate.hpp, 2e8 steps) refuse far smaller runs first, and those a user may override
// (--allow-large), so a hard limit must lie above the overridable one.
#pragma once

#include <string>

namespace maris {

inline constexpr long kMaxTimeSteps = 20'000'000'000;  // steps of one time integration (100× the work limit)
inline constexpr long kMaxStoredSamples = 20'000'000;  // samples of one stored series, nodes of one mesh

// `count` rounded up to a whole number (a remainder below 1e-9 is dropped), checked against [0, limit].
// `field` names the input ("parameters.solver.time_step"), `quantity` the count ("time steps over end_time").
long checkedCount(double count, long limit, const std::string& field, const std::string& quantity);

}  // namespace maris
