// The gravity the ocean-wave tests use [m/s²].
#pragma once

namespace maris::ocean::test {

inline constexpr double kG = 9.81;

}  // namespace maris::ocean::test
