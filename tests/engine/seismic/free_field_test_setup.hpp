// The set-up shared by the free-field tests: the paper's verification seabed and water layer (§3.4:
// vp 4500 m/s, vs 1800 m/s, ρ 2700 kg/m³; water 1025 kg/m³, 1450 m/s, 600 m deep).
#pragma once

#include <numbers>

#include "seismic/free_field.hpp"

namespace maris::seismic::testing {

inline constexpr double kDeg = std::numbers::pi / 180.0;
inline const ElasticMaterial kSeabed{2700.0, 4500.0, 1800.0};  // critical angle 23.578°
inline const WaterLayer kWater{1025.0, 1450.0, 600.0};
inline const WaterLayer kNoWater{1025.0, 1450.0, 0.0};

// A real angular frequency [rad/s] from a frequency in Hz.
inline Complex omegaOf(double f_hz) { return Complex(2.0 * std::numbers::pi * f_hz, 0.0); }

}  // namespace maris::seismic::testing
