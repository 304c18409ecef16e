// The unit plots, study plots, the results dock and the 3D view's colour bar show a quantity in, per SI unit: kN for
// N, MPa for Pa, mm for m, as chosen in View ▸ Units (kept with QSettings). The prefixes are the colour bars'
// (view3d/color_bar_scale.hpp). Where nothing was chosen, plots show SI and a colour bar picks the prefix that
// reads best for its range. Only what people read changes: CSV files, summary.json and the data exports stay SI.
#pragma once

#include <string>
#include <vector>

#include <QString>

namespace maris::ui {

struct DisplayUnit {
  double factor = 1.0;  // shown value = SI value × factor
  std::string unit;     // "kN"
};

// How values of `si_unit` are shown now: the chosen prefixed unit, or the SI unit itself.
DisplayUnit displayUnit(const std::string& si_unit);

// True when the user chose how `si_unit` is shown (one of its choices, SI included); false by default.
bool displayUnitChosen(const std::string& si_unit);

// The units `si_unit` can be shown in, smallest first ("N": N, kN, MN, GN; "m": mm, m); empty when it takes no prefix.
std::vector<std::string> displayUnitChoices(const std::string& si_unit);

// Shows `si_unit` as `shown` (one of its choices; anything else shows SI) from now on, and remembers it.
void setDisplayUnit(const std::string& si_unit, const std::string& shown);

// A unit as people read it, wherever the GUI or a plot shows one: powers as superscripts and products with a
// middle dot ("kg/m^3" → "kg/m³", "N*s/m" → "N·s/m"), "deg" → "°", "degC" → "°C"; empty for "-" (no unit) and "".
// Results and scenario files keep the ASCII form the engine declares.
QString unitText(const std::string& unit);

// The choices remembered in QSettings (the GUI calls this at start; the CLI's plots stay SI).
void loadDisplayUnits();

}  // namespace maris::ui
