// Builds a QCustomPlot from a run's results and a PlotSpec: axis labels with units, a legend,
// reference points as markers, and optionally the same columns of other runs overlaid. Shared by
// the GUI's plot tabs and the CLI's PNG export.
#pragma once

#include <array>
#include <vector>

#include <QSizeF>
#include <QString>
#include <QStringList>

#include "core/results.hpp"

class QCustomPlot;
class QCPAbstractPlottable;
class QCPAxis;
class QCPAxisRect;

namespace maris::ui {

// Axis label "text [unit]" (no brackets for "-" or no unit); `text` is shown as given.
QString axisLabel(const std::string& text, const std::string& unit);
// A column's axis label and legend entry: its label for people (displayLabel) and unit, "Fn", "R_T [N]".
QString axisLabel(const Column& column);

// A legend entry too wide for a narrow plot is shortened with "…" in the middle; the graph keeps its whole name in
// this property, for the hover read-out and the entry's tooltip.
inline constexpr const char* kFullNameProperty = "full_name";
// The whole name of a graph (its name where it was not shortened).
QString fullGraphName(const QCPAbstractPlottable& graph);

// `text` broken at spaces into lines of at most `max_line` characters (a longer word keeps its own
// line): for titles and notes in places that do not wrap (a VTK colour bar, a QCPTextElement).
QString wrapAtSpaces(const QString& text, int max_line);

// One run's results drawn in a plot; `label` prefixes its legend entries when several are shown.
struct PlotSource {
  QString label;
  const Results* results = nullptr;
};

// Clears `plot` and draws `spec` from `results` (one graph per y column, plus reference markers).
// Returns false (and draws nothing) if the spec names a table or column that does not exist.
bool fillPlot(QCustomPlot& plot, const Results& results, const PlotSpec& spec);
// As above, the first source drawn solid, each further one (an overlaid run) dashed. Sources that
// lack the table are skipped; false if the first one lacks it. `references` (a user's imported
// tables, see plots/reference_data.hpp) are drawn as markers beside the scene's own reference points.
bool fillPlot(QCustomPlot& plot, const std::vector<PlotSource>& sources, const PlotSpec& spec,
              const std::vector<Table>& references = {});

// Background, axes, grid and text in the colours of the plot's palette (light or dark theme).
void applyPlotColors(QCustomPlot& plot);

// Puts the plot's legend where it hides no data: inside the axes at a corner no curve passes through (the top
// right first), else in a row under the axes (entries side by side as the width allows). A legend whose entries are
// too wide or too many for the axes stays under them. Called again after the axes changed (log scale, zoom).
void placePlotLegend(QCustomPlot& plot);

// For each corner of `rect` (top right, top left, bottom right, bottom left), how many of the plot's drawn points
// and line segments a legend of `legend_px` pixels there would cover (0: it covers no curve).
std::array<int, 4> legendCornerCover(const QCustomPlot& plot, const QCPAxisRect& rect, QSizeF legend_px);

// A logarithmic scale with decade ticks.
void setLogScale(QCPAxis* axis);

// A legend of the plot's graphs, placed by placePlotLegend; in the palette's colours.
void addPlotLegend(QCustomPlot& plot, QCPAxisRect& rect);

// Whether `spec` drawn from `results` shows anything: one of its y columns has a finite value that is not zero nor
// round-off (above 1e-12 of the largest magnitude in that unit in the table). A statics-only run's time history is
// one row of zeros; a straight riser's bending stress is zero and its lateral offsets are 1e-14 m.
bool plotCarriesData(const Results& results, const PlotSpec& spec);

// Number of data points of the graphs drawn from the first source's y columns.
int primaryPointCount(const QCustomPlot& plot, const PlotSpec& spec);

// What a drawn plot says in words: its title, its axes' labels (bottom, left, then any others and a colour scale's)
// and its legend's entries (in full), each without the others.
struct PlotWords {
  QString title;
  QStringList axes;
  QStringList legend;
};
PlotWords plotWords(QCustomPlot& plot);

// Writes a drawn plot to a PNG/PDF/SVG file chosen by the suffix, atomically (temporary file in the
// same folder, then rename). A PNG carries plotWords as text chunks ("Title", "Axes" and "Legend", one entry
// a line), so a picture can be searched and checked by what it says. False if the suffix is unknown or writing
// failed.
bool savePlotWidget(QCustomPlot& plot, const QString& file, int width_px, int height_px);

// Renders one plot off-screen to a PNG/PDF/SVG file chosen by the file suffix.
bool savePlotImage(const Results& results, const PlotSpec& spec, const QString& file, int width_px, int height_px);

}  // namespace maris::ui
