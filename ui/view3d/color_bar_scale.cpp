#include "view3d/color_bar_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace maris::ui {

namespace {

// The step of a 1–2–5 grid nearest to `raw` (on a log scale), so the tick count stays near the target.
double niceStep(double raw) {
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double best = decade;
  for (double m : {2.0, 5.0, 10.0})
    if (std::abs(std::log(m * decade / raw)) < std::abs(std::log(best / raw))) best = m * decade;
  return best;
}

}  // namespace

std::vector<UnitPrefix> unitPrefixes(const std::string& unit) {
  if (unit == "Pa") return {{"", 0}, {"k", 3}, {"M", 6}, {"G", 9}};
  if (unit == "N" || unit == "N/m" || unit == "N m" || unit == "N·m" || unit == "W" || unit == "J")
    return {{"", 0}, {"k", 3}, {"M", 6}, {"G", 9}};
  if (unit == "m") return {{"m", -3}, {"", 0}};
  return {};
}

std::vector<double> niceTicks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) return {lo};
  const double step = niceStep((hi - lo) / std::max(1, target - 1));
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - 1e-9);
  for (double k = first; k * step <= hi + 1e-9 * step && ticks.size() < 100; k += 1) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < 1e-9 * step ? 0.0 : v);
  }
  return ticks;
}

std::string tickLabelFormat(const std::vector<double>& ticks) {
  double largest = 0, step = 0;
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    largest = std::max(largest, std::abs(ticks[i]));
    if (i > 0) step = step == 0 ? ticks[i] - ticks[i - 1] : std::min(step, ticks[i] - ticks[i - 1]);
  }
  if (largest == 0) return "%g";
  if (step <= 0) step = largest;
  // Significant digits: from the largest magnitude's leading digit down to the grid step's.
  const int digits =
      static_cast<int>(std::floor(std::log10(largest) + 1e-9) - std::floor(std::log10(step) + 1e-9)) + 1;
  // %g prints zero as "0" and drops trailing zeros; it needs at least as many digits as the integer part has,
  // or it switches to an exponent (140 as "1.4e+02").
  const int integer_digits = largest >= 1 ? static_cast<int>(std::floor(std::log10(largest) + 1e-9)) + 1 : 0;
  const bool plain = largest >= 1e-3 && largest < 1e5;
  const int precision = plain ? std::max(digits, integer_digits) : digits;
  char format[16];
  std::snprintf(format, sizeof format, "%%.%dg", std::clamp(precision, 1, 15));
  return format;
}

ColorBarScale colorBarScale(double lo, double hi, const std::string& si_unit, int target_ticks) {
  ColorBarScale scale;
  scale.unit = si_unit;
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  const auto prefixes = unitPrefixes(si_unit);
  if (!prefixes.empty() && magnitude > 0 && std::isfinite(magnitude)) {
    // The largest prefix that keeps the magnitude at 1 or more (or the smallest one).
    UnitPrefix chosen = prefixes.front();
    for (const UnitPrefix& p : prefixes)
      if (magnitude >= std::pow(10.0, p.exponent) * (1 - 1e-12)) chosen = p;
    // Plain SI stays when its numbers read well (1 … 9 999) and a prefix would not make them shorter.
    const bool si_reads_well = magnitude >= 1 && magnitude < 1e4;
    if (!(si_reads_well && chosen.exponent > 0)) {
      scale.factor = std::pow(10.0, -chosen.exponent);
      scale.unit = chosen.symbol + si_unit;
    }
  }
  return colorBarScaleIn(lo, hi, scale.factor, scale.unit, target_ticks);
}

ColorBarScale colorBarScaleIn(double lo, double hi, double factor, const std::string& unit, int target_ticks) {
  ColorBarScale scale;
  scale.factor = factor;
  scale.unit = unit;
  scale.ticks = niceTicks(lo * factor, hi * factor, target_ticks);
  scale.label_format = tickLabelFormat(scale.ticks);
  return scale;
}

double colorBarLeft(double view_px, double strip_px, double title_px, double labels_px, double margin_px,
                    double preferred) {
  if (view_px <= 0) return preferred;
  // From the strip's left to its rightmost ink.
  const double right_of_left = std::max(0.5 * strip_px + 0.5 * std::max(strip_px, title_px), labels_px);
  const double left_px = std::min(preferred * view_px, view_px - margin_px - right_of_left);
  return std::max(0.0, left_px / view_px);
}

}  // namespace maris::ui
