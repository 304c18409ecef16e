// Angles: scenario files give them in degrees (fields ending in _deg); the engine works in radians.
#pragma once

#include <numbers>

namespace maris {

inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

constexpr double radiansFromDegrees(double degrees) { return degrees * kRadiansPerDegree; }
constexpr double degreesFromRadians(double radians) { return radians / kRadiansPerDegree; }

}  // namespace maris
