// The height at which the linear wave kinematics of a wet point are evaluated, for each Stretching (the
// definitions are in core/ocean_waves.hpp): one formula for WaveField::kinematics and WaveKinematicsBatch.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/ocean_waves.hpp"

namespace maris::ocean {

// z' for a point at height z (z ≤ η) under the surface η in water of depth h (kDeepWater: infinite), clamped at
// the sea bed −h (a point below the bed takes the bed's kinematics).
inline double stretchedZ(double z, double eta, double depth, Stretching stretching) {
  const bool deep = std::isinf(depth);
  switch (stretching) {
    case Stretching::Wheeler:
      z = deep ? z - eta : depth * (z - eta) / (depth + eta);
      break;
    case Stretching::Vertical:
      z = std::min(z, 0.0);
      break;
    case Stretching::None:
      break;
  }
  return deep ? z : std::max(z, -depth);
}

}  // namespace maris::ocean
