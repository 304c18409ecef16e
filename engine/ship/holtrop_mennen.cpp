#include "ship/holtrop_mennen.hpp"

#include <algorithm>
#include <cmath>

#include "core/text_format.hpp"
#include "ship/viscous_resistance.hpp"

namespace maris::ship {

namespace {

// Length of run L_R [m] (Holtrop & Mennen 1982).
double lengthOfRun(const HoltropHull& h) {
  const double cp = h.prismatic();
  return h.length_wl * (1.0 - cp + 0.06 * cp * h.lcb_percent / (4.0 * cp - 1.0));
}

// Bulb factor c2 (1.0 without a bulb).
double bulbFactor(const HoltropHull& h) {
  if (h.bulb_area <= 0) return 1.0;
  const double c3 = 0.56 * std::pow(h.bulb_area, 1.5) /
                    (h.beam * h.draft * (0.31 * std::sqrt(h.bulb_area) + h.draft - h.bulb_centre_height));
  return std::exp(-1.89 * std::sqrt(c3));
}

// Wave resistance. 1984 re-analysis: low-speed formula (a), high-speed formula (b), linear blend between
// Fn 0.40 and 0.55. 1982 original: formula (a) with the m2 term instead of m4, at every speed.
double waveResistance(const HoltropHull& h, double fn, double density, double gravity, HoltropEdition edition) {
  const double L = h.length_wl, B = h.beam, T = h.draft, V = h.volume, cp = h.prismatic();
  const double c2 = bulbFactor(h);
  const double c5 = 1.0 - 0.8 * h.transom_area / (B * T * h.midship_coefficient);
  const double lambda = L / B < 12.0 ? 1.446 * cp - 0.03 * L / B : 1.446 * cp - 0.36;
  const double l3v = L * L * L / V;
  const double c15 = l3v < 512.0 ? -1.69385 : (l3v > 1726.91 ? 0.0 : -1.69385 + (L / std::cbrt(V) - 8.0) / 2.36);
  constexpr double d = -0.9;
  auto m4 = [&](double f) {
    if (edition == HoltropEdition::Original1982) return c15 * cp * cp * std::exp(-0.1 / (f * f));  // m2
    return c15 * 0.4 * std::exp(-0.034 * std::pow(f, -3.29));
  };
  auto low = [&](double f) {
    const double bl = B / L;
    const double c7 = bl < 0.11 ? 0.229577 * std::pow(bl, 1.0 / 3.0) : (bl < 0.25 ? bl : 0.5 - 0.0625 * L / B);
    const double ie = 1.0 + 89.0 * std::exp(-std::pow(L / B, 0.80856) * std::pow(1.0 - h.waterplane_coefficient, 0.30484) *
                                            std::pow(1.0 - cp - 0.0225 * h.lcb_percent, 0.6367) *
                                            std::pow(lengthOfRun(h) / B, 0.34574) * std::pow(100.0 * V / (L * L * L), 0.16302));
    const double c1 = 2223105.0 * std::pow(c7, 3.78613) * std::pow(T / B, 1.07961) * std::pow(90.0 - ie, -1.37565);
    const double c16 = cp < 0.8 ? 8.07981 * cp - 13.8673 * cp * cp + 6.984388 * cp * cp * cp : 1.73014 - 0.7067 * cp;
    const double m1 = 0.0140407 * L / T - 1.75254 * std::cbrt(V) / L - 4.79323 * B / L - c16;
    return c1 * c2 * c5 * V * density * gravity * std::exp(m1 * std::pow(f, d) + m4(f) * std::cos(lambda / (f * f)));
  };
  auto high = [&](double f) {
    const double c17 = 6919.3 * std::pow(h.midship_coefficient, -1.3346) * std::pow(V / (L * L * L), 2.00977) *
                       std::pow(L / B - 2.0, 1.40692);
    const double m3 = -7.2035 * std::pow(B / L, 0.326869) * std::pow(T / B, 0.605375);
    return c17 * c2 * c5 * V * density * gravity * std::exp(m3 * std::pow(f, d) + m4(f) * std::cos(lambda / (f * f)));
  };
  if (fn <= 0.4 || edition == HoltropEdition::Original1982) return low(fn);
  if (fn >= 0.55) return high(fn);
  const double a = low(0.4), b = high(0.55);
  return a + (20.0 * fn - 8.0) * (b - a) / 3.0;
}

}  // namespace

double holtropFormFactor(const HoltropHull& h, HoltropEdition edition) {
  const double L = h.length_wl, cp = h.prismatic();
  if (edition == HoltropEdition::Original1982) {
    const double tl = h.draft / L;
    const double c12 = tl > 0.05 ? std::pow(tl, 0.2228446) : (tl > 0.02 ? 48.20 * std::pow(tl - 0.02, 2.078) + 0.479948 : 0.479948);
    const double c13 = 1.0 + 0.003 * h.stern_shape;
    // C_P ≥ 0.95 or a far-aft LCB leave the regression (holtropRangeNotes warns); keep the powers defined.
    return c13 * (0.93 + c12 * std::pow(h.beam / lengthOfRun(h), 0.92497) *
                             std::pow(std::max(0.95 - cp, 1e-3), -0.521448) *
                             std::pow(std::max(1.0 - cp + 0.0225 * h.lcb_percent, 1e-3), 0.6906));
  }
  const double c14 = 1.0 + 0.011 * h.stern_shape;
  return 0.93 + 0.487118 * c14 * std::pow(h.beam / L, 1.06806) * std::pow(h.draft / L, 0.46106) *
                    std::pow(L / lengthOfRun(h), 0.121563) * std::pow(L * L * L / h.volume, 0.36486) *
                    std::pow(1.0 - cp, -0.604247);
}

double holtropCorrelationAllowance(const HoltropHull& h) {
  const double L = h.length_wl;
  const double cb = h.volume / (L * h.beam * h.draft);
  const double c4 = std::min(h.draft / L, 0.04);
  return 0.006 * std::pow(L + 100.0, -0.16) - 0.00205 +
         0.003 * std::sqrt(L / 7.5) * std::pow(cb, 4) * bulbFactor(h) * (0.04 - c4);
}

HoltropResistance holtropMennen(const HoltropHull& h, double speed, double density, double viscosity,
                                double gravity, bool with_correlation_allowance, HoltropEdition edition) {
  HoltropResistance r;
  const double q = 0.5 * density * speed * speed;
  const double fn = speed / std::sqrt(gravity * h.length_wl);
  r.form_factor = holtropFormFactor(h, edition);
  r.friction = ittc57FrictionCoefficient(speed * h.length_wl / viscosity) * q * h.wetted_surface;
  r.wave = waveResistance(h, fn, density, gravity, edition);
  if (h.bulb_area > 0) {
    const double sa = std::sqrt(h.bulb_area);
    // P_B measures the bow emergence; a bulb centre above T/1.5 makes it infinite (exp(−3/P_B²) → 1).
    const double emergence = h.draft - 1.5 * h.bulb_centre_height;
    const double pb_factor = emergence > 0 ? std::exp(-3.0 * std::pow(emergence / (0.56 * sa), 2)) : 1.0;
    const double head = std::max(0.0, gravity * (h.draft - h.bulb_centre_height - 0.25 * sa)) + 0.15 * speed * speed;
    const double fni = speed / std::sqrt(head);
    r.bulb = 0.11 * pb_factor * fni * fni * fni * std::pow(h.bulb_area, 1.5) * density * gravity / (1.0 + fni * fni);
  }
  if (h.transom_area > 0) {
    const double fnt = speed / std::sqrt(2.0 * gravity * h.transom_area / (h.beam + h.beam * h.waterplane_coefficient));
    const double c6 = fnt < 5.0 ? 0.2 * (1.0 - 0.2 * fnt) : 0.0;
    r.transom = q * h.transom_area * c6;
  }
  if (with_correlation_allowance) r.correlation = holtropCorrelationAllowance(h) * q * h.wetted_surface;
  r.total = r.form_factor * r.friction + r.wave + r.bulb + r.transom + r.correlation;
  return r;
}

std::vector<std::string> holtropRangeNotes(const HoltropHull& h) {
  std::vector<std::string> notes;
  auto check = [&](const char* name, double v, double lo, double hi) {
    if (v >= lo && v <= hi) return;
    notes.push_back(formatText("Holtrop-Mennen: %s = %.3g is outside the regression's range [%.3g, %.3g]", name, v, lo, hi));
  };
  check("C_P", h.prismatic(), 0.55, 0.85);
  check("L/B", h.length_wl / h.beam, 3.9, 14.9);
  check("B/T", h.beam / h.draft, 2.1, 4.0);
  return notes;
}

}  // namespace maris::ship
