#include "riser/riser_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/ocean_waves.hpp"
#include "core/text_format.hpp"

namespace maris::riser {

namespace {

using std::numbers::pi;
constexpr double kFastestOceanCurrent = 3.0;  // [m/s] beyond the strongest tidal and loop currents met offshore
// Limiting steepness of a periodic deep-water wave, H/λ ≈ 0.142 (Michell 1893); a design sea's significant
// steepness stays near 1/15 (DNV-RP-C205, sect. 3.5.5.4).
constexpr double kLimitingSteepness = 1.0 / 7.0;
constexpr double kSeaStateSteepness = 1.0 / 15.0;
constexpr double kBreakingDepthRatio = 0.78;  // H/d of a solitary wave at breaking (McCowan 1894)

std::string fourDigits(double v) { return formatText("%.4g", v); }

double topZ(const RiserParameters& p) {
  if (p.top_condition != "tensioner") return p.top_z;
  const double h = std::hypot(p.top_x - p.bottom_x, p.top_y - p.bottom_y);
  return p.bottom_z + std::sqrt(std::max(p.length * p.length - h * h, 0.0));
}

}  // namespace

std::vector<FieldError> riserPlausibility(const RiserParameters& p) {
  std::vector<FieldError> w;
  const bool in_water = p.bottom_z < p.water_level;
  if (!in_water) return w;
  const double depth = p.water_level - p.seabed_level;
  const double top = topZ(p);
  if (top > p.water_level + 1e-9) {
    const std::string path = p.top_condition == "tensioner" ? "geometry.length" : "top.z";
    w.push_back({path, fourDigits(p.top_condition == "tensioner" ? p.length : p.top_z),
                 "the top end is " + fourDigits(top - p.water_level) +
                     " m above the still-water level: that part of the riser is in air (no buoyancy, current, "
                     "waves or added mass), as for a riser hung off a deck; a riser meant to end in the water is "
                     "too long for the depth"});
  }
  const bool fixed_bottom = p.bottom_condition == "pinned" || p.bottom_condition == "clamped";
  if (fixed_bottom && p.bottom_z < p.seabed_level - 1e-9)
    w.push_back({"bottom.z", fourDigits(p.bottom_z),
                 "the anchor is " + fourDigits(p.seabed_level - p.bottom_z) + " m below the sea bed (environment.seabed_level = " +
                     fourDigits(p.seabed_level) + " m)"});
  if (fixed_bottom && depth > 0 && p.bottom_z > p.seabed_level + 0.05 * depth)
    w.push_back({"bottom.z", fourDigits(p.bottom_z),
                 "the anchor is " + fourDigits(p.bottom_z - p.seabed_level) + " m above the sea bed (environment.seabed_level = " +
                     fourDigits(p.seabed_level) + " m): a riser anchored in mid-water"});
  std::vector<std::pair<std::string, double>> speeds;
  if (p.current_type == "table")
    for (std::size_t k = 0; k < p.current_profile.size(); ++k)
      speeds.emplace_back("current.profile[" + std::to_string(k) + "].speed", p.current_profile[k].speed);
  else
    speeds = {{"current.speed_surface", p.current_speed_surface}, {"current.speed_seabed", p.current_speed_seabed}};
  for (const auto& [path, speed] : speeds)
    if (std::abs(speed) > kFastestOceanCurrent)
      w.push_back({path, fourDigits(speed), "beyond " + fourDigits(kFastestOceanCurrent) +
                                         " m/s, faster than ocean currents met offshore; the drag coefficients are "
                                         "for subcritical to critical flow"});
  if (p.wave_type == "none" || depth <= 0) return w;
  const bool regular = p.wave_type == "airy";
  const bool spectral = p.wave_type == "jonswap" || p.wave_type == "pierson_moskowitz";
  if (!regular && !spectral) return w;
  const double height = regular ? p.wave_height : p.wave_significant_height;
  const double period = regular ? p.wave_period : p.wave_peak_period;
  const double length = 2 * pi / ocean::waveNumber(2 * pi / period, depth, p.gravity);
  const double steepness = height / length;
  const double limit = regular ? kLimitingSteepness : kSeaStateSteepness;
  const std::string field = regular ? "waves.height" : "waves.significant_height";
  if (steepness > limit)
    w.push_back({field, fourDigits(height),
                 "steepness H/λ = " + fourDigits(steepness) + " (λ = " + fourDigits(length) + " m) is beyond " +
                     (regular ? "the limiting steepness 1/7 of a periodic wave: it would break"
                              : "1/15, the steepness of the steepest design sea states") +
                     "; linear wave theory is far outside its range"});
  if (height > kBreakingDepthRatio * depth)
    w.push_back({field, fourDigits(height), "higher than 0.78 × the depth " + fourDigits(depth) +
                                         " m: waves break in water this shallow"});
  return w;
}

}  // namespace maris::riser
