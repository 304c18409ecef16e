#include "core/portable_random.hpp"

#include <cmath>
#include <numbers>

namespace maris {

double uniform01(std::uint64_t draw) { return static_cast<double>(draw >> 11) * 0x1.0p-53; }

double standardNormal(std::mt19937_64& engine) {
  const double u1 = 1.0 - uniform01(engine());  // (0, 1]: log(u1) is finite
  const double u2 = uniform01(engine());
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace maris
