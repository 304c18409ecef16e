#include "wec/wec_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/ocean_waves.hpp"
#include "core/text_format.hpp"

namespace maris::wec {

namespace {

using std::numbers::pi;
// Limiting steepness of a periodic wave, H/λ ≈ 1/7 (Michell 1893); a design sea's significant steepness stays
// near 1/15 (DNV-RP-C205, sect. 3.5.5.4); a wave breaks where H > 0.78 d (McCowan 1894).
constexpr double kLimitingSteepness = 1.0 / 7.0;
constexpr double kSeaStateSteepness = 1.0 / 15.0;
constexpr double kBreakingDepthRatio = 0.78;
// Hulme (1982) tabulates the hemisphere's heave and surge coefficients up to ka = ω²a/g = 10 (wec_hydro.cpp);
// beyond, the scene continues them by power-law tails towards the exact high-frequency limits.
constexpr double kHulmeLastKa = 10.0;
// Shallow water begins where the depth is below 1/20 of the wave length (kh < π/10), the usual division of
// linear wave theory (e.g. Dean & Dalrymple, Water Wave Mechanics for Engineers and Scientists, 1991, ch. 3).
constexpr double kShallowKh = pi / 10.0;

std::string num(double v) { return formatText("%.4g", v); }

}  // namespace

std::vector<FieldError> wecPlausibility(const WecParameters& p) {
  std::vector<FieldError> w;
  double largest_radius = 0.0;
  for (std::size_t i = 0; i < p.floats.size(); ++i) {
    const double a = p.floats[i].radius;
    largest_radius = std::max(largest_radius, a);
    if (a >= p.depth)
      w.push_back({"floats[" + std::to_string(i) + "].radius", num(a),
                   "the hemisphere's draft equals its radius, so at water.depth = " + num(p.depth) +
                       " m the float reaches the sea bed; the coefficients are for a float far above it"});
  }
  const bool hulme = p.hydro_source == "hemisphere_hulme";
  if (hulme && largest_radius > 0) {
    const double omega_limit = std::sqrt(kHulmeLastKa * p.gravity / largest_radius);
    const auto beyond = [&](const std::string& path, double omega) {
      if (omega > omega_limit)
        w.push_back({path, num(omega),
                     "beyond " + num(omega_limit) + " rad/s (ka = 10 for a = " + num(largest_radius) +
                         " m), the end of Hulme's tables: the coefficients there are extrapolated"});
    };
    beyond("frequency.omega_max", p.omega_max);
    if (p.wave_type == "regular") beyond("waves.frequency", p.wave_frequency);
    for (std::size_t i = 0; i < p.check_frequencies.size(); ++i)
      beyond("frequency.check_frequencies[" + std::to_string(i) + "]", p.check_frequencies[i]);
  }
  if (p.wave_type == "none") return w;
  const bool regular = p.wave_type == "regular";
  const std::string field = regular ? "waves.height" : "waves.significant_height";
  const double height = regular ? p.wave_height : p.significant_height;
  const double omega = regular ? p.wave_frequency : 2 * pi / p.peak_period;
  const double k = ocean::waveNumber(omega, p.depth, p.gravity);
  const double length = 2 * pi / k;
  const double steepness = height / length;
  if (steepness > (regular ? kLimitingSteepness : kSeaStateSteepness))
    w.push_back({field, num(height),
                 "steepness H/λ = " + num(steepness) + " (λ = " + num(length) + " m) is beyond " +
                     (regular ? "the limiting steepness 1/7 of a periodic wave: it would break"
                              : "1/15, the steepness of the steepest design sea states") +
                     "; linear wave theory is far outside its range"});
  if (height > kBreakingDepthRatio * p.depth)
    w.push_back({field, num(height), "higher than 0.78 × water.depth = " + num(kBreakingDepthRatio * p.depth) +
                                         " m: waves break in water this shallow"});
  for (std::size_t i = 0; i < p.floats.size(); ++i)
    if (0.5 * height > p.floats[i].radius) {
      w.push_back({field, num(height),
                   "the wave amplitude " + num(0.5 * height) + " m exceeds the draft of float " +
                       std::to_string(i + 1) + " (its radius " + num(p.floats[i].radius) +
                       " m): the float would leave the water or go under, far from the linear hydrostatics "
                       "and wave forces of the model"});
      break;
    }
  if (hulme && k * p.depth < kShallowKh)
    w.push_back({regular ? "waves.frequency" : "waves.peak_period", num(regular ? p.wave_frequency : p.peak_period),
                 "kh = " + num(k * p.depth) + " at water.depth = " + num(p.depth) +
                     " m is shallow water (kh < π/10): Hulme's deep-water coefficients do not hold there; "
                     "import coefficients computed at this depth (hydro.source)"});
  return w;
}

}  // namespace maris::wec
