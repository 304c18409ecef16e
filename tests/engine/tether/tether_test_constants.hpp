// The tether of the paper's simulations and experiment, as the tether tests use it.
#pragma once

namespace maris::tether::test {

inline constexpr double kL = 1.5;  // [m] tether length

}  // namespace maris::tether::test
