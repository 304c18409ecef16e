// Plots of a design study's results, drawn with the same look as the result plots: a result against a
// varied parameter (points, or a line through them when only that parameter varies), and a heat map of a
// result over a grid of two parameters (cells at the grid's values, whatever their spacing).
#pragma once

#include <vector>

#include <QString>

class QCustomPlot;

namespace maris::ui {

struct StudyPoints {
  QString title, x_label, y_label;  // labels with units: axisLabel(name, unit)
  std::vector<double> x, y;
  bool line = false;  // connect the points (in the order given)
};

struct StudyHeatMap {
  QString title, x_label, y_label, z_label;
  std::vector<double> x, y;  // the grid's values along each axis (ascending)
  std::vector<double> z;     // z[iy * x.size() + ix]; NaN cells are left blank
};

// Draw into `plot` (cleared first); false when there is nothing to draw.
bool fillStudyPoints(QCustomPlot& plot, const StudyPoints& points);
bool fillStudyHeatMap(QCustomPlot& plot, const StudyHeatMap& map);

// Render off-screen to a PNG/PDF/SVG file (by suffix), atomically.
bool saveStudyPointsImage(const StudyPoints& points, const QString& file, int width_px, int height_px);
bool saveStudyHeatMapImage(const StudyHeatMap& map, const QString& file, int width_px, int height_px);

}  // namespace maris::ui
