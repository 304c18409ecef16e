// Plots of a study's results: one result scalar against one varied parameter, a line per
// combination of the other varied parameters (markers only when no two cases share one: a table or
// Latin-hypercube sample), or a heat map over two varied parameters of a full grid. Built from
// plain per-case numbers (what study.csv holds), so the GUI's study panel and a headless PNG writer
// draw the same picture. Every drawn point remembers its case, so a click can open that case.
#pragma once

#include <string>
#include <vector>

#include <QPointF>
#include <QString>

#include "plots/study_plot_data.hpp"

class QCustomPlot;

namespace maris::ui {


// Where each drawn point came from, for clicks: per graph the case of each data point (in the
// graph's key order); for a heat map the case of each cell (x fastest) and the grid's values.
struct DrawnStudyPlot {
  StudyPlotKind kind = StudyPlotKind::Lines;
  std::vector<std::vector<int>> graph_cases;
  std::vector<double> cell_x, cell_y;  // heat map: the distinct values along each axis
  std::vector<int> cell_case;          // heat map: case per cell, -1 where none
  int points = 0;                      // points (or filled cells) drawn
};

// A parameter's or result's label for people with its display unit (plots/display_units.hpp): "Length L [m]".
QString studyAxisLabel(const std::string& label, const std::string& unit);
// The same for a varied parameter: its label (the path where it has none) and unit.
QString studyAxisLabel(const StudyParameterData& parameter);
// "Length L [m] = 120": parameter `parameter` in case `c`, in its display unit, to 4 significant digits (more only
// where two of its values would read the same; whole numbers below 1e6 in full): legends and run labels.
QString studyValueLabel(const StudyParameterData& parameter, std::size_t c);
// The significant digits studyValueLabel gives `parameter`'s values (it sorts them: worth keeping for many labels),
// and the label of `value` (SI) of that parameter with them.
int studyValueDigits(const StudyParameterData& parameter);
QString studyParameterValue(const StudyParameterData& parameter, double value, int digits);

// True when parameters `a` and `b` form a full grid (every pair of their distinct values occurs in
// exactly one case) and no other parameter varies: what a heat map needs.
bool isFullGrid(const StudyPlotData& data, int a, int b);

// Clears `plot` and draws the result against parameter `x` (Lines) or over parameters `x` and the
// other one (HeatMap; needs exactly two parameters on a full grid). False (nothing drawn) when the
// data do not allow it. `drawn` (optional) receives where each point came from.
bool fillStudyPlot(QCustomPlot& plot, const StudyPlotData& data, int x, StudyPlotKind kind,
                   DrawnStudyPlot* drawn = nullptr);

// Draws as fillStudyPlot does and writes the picture to a PNG/PDF/SVG file (by suffix), atomically: the
// plots of `maris-cli study run` and `study collect`. False when nothing could be drawn or written.
bool saveStudyPlotImage(const StudyPlotData& data, int x, StudyPlotKind kind, const QString& file, int width_px,
                        int height_px);

// The case whose point (or heat-map cell) is under the widget pixel `pixel` (within `radius_px` for
// points), or -1.
int studyCaseAt(QCustomPlot& plot, const DrawnStudyPlot& drawn, QPointF pixel, double radius_px = 8.0);

// The widget pixel of case `index`'s point (or cell centre); (-1, -1) if it is not drawn.
QPointF studyCasePixel(QCustomPlot& plot, const DrawnStudyPlot& drawn, int index);

}  // namespace maris::ui
