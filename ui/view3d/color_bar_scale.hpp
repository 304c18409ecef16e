// What a colour bar writes beside its colours: the range in an engineering unit (2.7e7 Pa as 27 MPa), tick
// values on a 1–2–5 grid, and a label format that prints them exactly, zero as "0".
#pragma once

#include <string>
#include <vector>

namespace maris::ui {

// Tick values on a 1, 2 or 5 × 10^k grid inside [lo, hi], about `target` of them (at least two when the range
// allows, the ends included when they fall on the grid). A value within 1e-9 steps of zero is exactly 0.
std::vector<double> niceTicks(double lo, double hi, int target = 5);

// A printf format that shows every tick with the digits its grid needs and no more ("%.2g" for 0.01, 0.02, …;
// zero prints as "0"); never an exponent for values from 0.001 to 99 999.
std::string tickLabelFormat(const std::vector<double>& ticks);

// A prefixed unit: symbol + SI unit, worth 10^exponent of the SI unit ("k", 3 for kN).
struct UnitPrefix {
  std::string symbol;
  int exponent = 0;
};

// The prefixes an engineer reads `si_unit` in, smallest first: Pa, N, N/m, N m, W, J with none, k, M, G; m with m
// (mm) and none; empty for any other unit. The colour bars choose among them, and so do the display units.
std::vector<UnitPrefix> unitPrefixes(const std::string& si_unit);

struct ColorBarScale {
  double factor = 1.0;        // display value = SI value × factor
  std::string unit;           // the display unit ("MPa" for "Pa" × 1e-6)
  std::vector<double> ticks;  // in the display unit
  std::string label_format;   // printf format of a tick
};

// The display unit for values of `si_unit` spanning [lo, hi]: a prefixed unit (k, M, G; m for lengths) when the
// larger magnitude would need 4 or more digits or leading zeros, the SI unit otherwise and for units without
// prefixes; then the ticks and their format in that unit.
ColorBarScale colorBarScale(double lo, double hi, const std::string& si_unit, int target_ticks = 5);

// The same in a unit the user chose (View ▸ Units): display value = SI value × `factor`, written as `unit`.
ColorBarScale colorBarScaleIn(double lo, double hi, double factor, const std::string& unit, int target_ticks = 5);

// Where the colour bar's strip starts, as a fraction of the view's width: at `preferred` unless its ink would come
// nearer than `margin_px` to the view's right edge; then as far left as that margin needs (never left of the view).
// The ink is the title, centred over the strip and wider than it for a long quantity name, and the tick labels,
// which end `labels_px` right of the strip's left edge. Widths in pixels.
double colorBarLeft(double view_px, double strip_px, double title_px, double labels_px, double margin_px,
                    double preferred);

}  // namespace maris::ui
