// The water of the Michell-integral tests: gravity [m/s²] and fresh-water density [kg/m³].
#pragma once

namespace maris::ship::test_data {

inline constexpr double kG = 9.81, kRho = 1000.0;

}  // namespace maris::ship::test_data
