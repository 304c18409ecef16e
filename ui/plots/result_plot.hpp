// Builds a QCustomPlot from a run's results and a PlotSpec: axis labels with units, a legend,
// reference points as markers. Shared by the GUI's plot tabs and the CLI's PNG export.
#pragma once

#include <QString>

#include "core/results.hpp"

class QCustomPlot;

namespace maris::ui {

// Axis label "name [unit]".
QString axisLabel(const std::string& name, const std::string& unit);

// Clears `plot` and draws `spec` from `results` (one graph per y column, plus reference markers).
// Returns false (and draws nothing) if the spec names a table or column that does not exist.
bool fillPlot(QCustomPlot& plot, const Results& results, const PlotSpec& spec);

// Renders one plot off-screen to a PNG/PDF/SVG file chosen by the file suffix.
bool savePlotImage(const Results& results, const PlotSpec& spec, const QString& file, int width_px, int height_px);

}  // namespace maris::ui
