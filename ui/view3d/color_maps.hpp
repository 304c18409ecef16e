// Colour maps for the 3D view's per-point scalars and the settings a user picks for one quantity:
// which map, and an automatic range (all frames' min … max) or a fixed min … max of their own.
#pragma once

#include <optional>
#include <string>

#include <QString>
#include <QStringList>

class vtkColorTransferFunction;

namespace maris::ui {

enum class ColorMap {
  CoolWarm,   // diverging blue–white–red (Moreland 2009): signed quantities, deviations from a middle
  Viridis,    // perceptually uniform dark blue → green → yellow: magnitudes, readable in grey print
  Rainbow,    // hue from blue to red: familiar, but not uniform (bands appear at cyan and yellow)
  Greyscale,  // dark grey → near-white: print, and for colour-blind readers
};

// Display names in enum order (the control's combo box lists these).
QStringList colorMapNames();

// The one stable name of each map ("cool-warm", "viridis", "rainbow", "greyscale"): the value of
// `maris --colormap` and of the settings file. colorMapKeys() lists them in enum order.
QString colorMapKey(ColorMap map);
QStringList colorMapKeys();
// The map named `key` (one of colorMapKeys()), nullopt for any other text.
std::optional<ColorMap> colorMapFromKey(const QString& key);

struct ColorSettings {
  ColorMap map = ColorMap::CoolWarm;
  bool automatic = true;  // range from the data; else [min, max]
  double min = 0.0;       // [unit of the quantity] used when !automatic
  double max = 1.0;
  // Automatic: the shown frame's min … max, else all frames'. Per frame by default: the frame shown (a run's last,
  // as it opens) uses the whole colour map, where the range of the run can leave it one colour.
  bool per_frame = true;
  bool operator==(const ColorSettings&) const = default;
};

// The user's choice for a coloured quantity (View3D::scalar_name), kept across sessions with
// QSettings under "colorMaps/<quantity, percent-encoded>"; nullopt if none was saved.
std::optional<ColorSettings> loadColorSettings(const std::string& quantity);
void saveColorSettings(const std::string& quantity, const ColorSettings& settings);

// Replaces the points of `colors` by `map` spread over [lo, hi] (hi > lo) and builds it.
void fillColorMap(vtkColorTransferFunction* colors, ColorMap map, double lo, double hi);

}  // namespace maris::ui
