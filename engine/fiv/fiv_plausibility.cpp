#include "fiv/fiv_plausibility.hpp"

#include <string>

#include "core/text_format.hpp"

namespace maris::fiv {

namespace {

// The paper's runs (Zhang, Song, Li, Su & Ding): D = 0.09 m, U = 0.2–2.5 m/s, and the ν that reproduces its
// Re/U pairs, so Re = UD/ν = 1.61e4–2.01e5. The galloping and wake-oscillator coefficients and the
// free-surface factor are compared with (and calibrated to) data in this range only.
constexpr double kPaperSide = 0.09;                   // [m]
constexpr double kPaperViscosity = 1.118e-6;          // [m²/s]
constexpr double kPaperReynoldsMin = 0.2 * kPaperSide / kPaperViscosity;
constexpr double kPaperReynoldsMax = 2.5 * kPaperSide / kPaperViscosity;
constexpr double kRoundOff = 1e-9;                    // the paper's own end speeds count as inside
// κ(h*) = 1 − a exp(−b (h* − ½)) is fitted to the paper's power ratios at h* = 1.11, 2.22, 3.33, 5.56 (docs/fiv.md);
// deeper it tends to 1 as the deep case does, shallower it is an extrapolation towards a surface-piercing body.
constexpr double kShallowestFittedSubmergence = 1.11;
// Below m* = m/(ρD²L) = 1 the body is lighter than the water it displaces and lighter than its added mass
// (C_a = 1.19): the regime of Govardhan & Williamson's critical mass ratio (0.54 for a circular cylinder,
// J. Fluid Mech. 420 (2000)), where lock-in never ends and neither quasi-steady galloping nor the wake
// oscillator's published coefficients are established. The paper's set-up has m* = 4.7 with our placeholders.
constexpr double kLowestMassRatio = 1.0;

std::string num(double v) { return formatText("%.4g", v); }

}  // namespace

std::vector<FieldError> fivPlausibility(const FivParameters& p) {
  std::vector<FieldError> w;
  if (p.analysis != "sweep") return w;
  const double mass_ratio = p.mass / (p.density * p.side * p.side * p.length);
  if (mass_ratio < kLowestMassRatio)
    w.push_back({"structure.mass", num(p.mass),
                 "mass ratio m* = m/(ρD²L) = " + num(mass_ratio) +
                     " < 1: wake-oscillator coupling and quasi-steady theory are outside their calibrated range"});
  const auto reynolds = [&](const char* path, double speed) {
    const double re = speed * p.side / p.kinematic_viscosity;
    if (re < kPaperReynoldsMin * (1 - kRoundOff) || re > kPaperReynoldsMax * (1 + kRoundOff))
      w.push_back({path, num(speed),
                   "Re = UD/ν = " + num(re) + " is outside " + num(kPaperReynoldsMin) + "–" + num(kPaperReynoldsMax) +
                       ", the range of the paper's data that the force coefficients are compared with"});
  };
  reynolds("sweep.speed_min", p.speed_min);
  reynolds("sweep.speed_max", p.speed_max);
  reynolds("detail.speed", p.detail_speed);
  for (std::size_t i = 0; i < p.submergence_ratios.size(); ++i)
    if (p.submergence_ratios[i] < kShallowestFittedSubmergence * (1 - kRoundOff))
      w.push_back({"free_surface.submergence_ratios[" + std::to_string(i) + "]", num(p.submergence_ratios[i]),
                   "below h* = 1.11, the shallowest submergence the free-surface factor is fitted to"});
  if (!p.detail_deep && p.detail_submergence < kShallowestFittedSubmergence * (1 - kRoundOff))
    w.push_back({"detail.submergence_ratio", num(p.detail_submergence),
                 "below h* = 1.11, the shallowest submergence the free-surface factor is fitted to"});
  return w;
}

}  // namespace maris::fiv
