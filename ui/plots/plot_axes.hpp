// Two decisions about a plot's axes that make it read at a glance: quantities of very different size get
// their own y axis (a 27 MPa bending stress beside a 4 Pa torsional stress would otherwise be a line on zero),
// and the axes' ranges hold every reference point whole (a marker at the edge of the range is cut in half).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/results.hpp"

class QCustomPlot;

namespace maris::ui {

// Columns whose largest magnitudes differ by more than this factor do not share a y axis.
inline constexpr double kSeparateAxisRatio = 100.0;

// Which of `y` (columns of `table`) go on the left y axis and which on the right. A column's size is its
// largest |value| in its display unit; the largest sets the left axis, and every column smaller than it by
// more than `ratio` goes right. Columns that are all zero (or missing) stay left. `right` is empty when all
// sizes are within `ratio` of each other (one axis is enough).
struct AxisSplit {
  std::vector<std::string> left, right;
};
AxisSplit splitByMagnitude(const Table& table, const std::vector<std::string>& y, double ratio = kSeparateAxisRatio);

// The y axes `y` needs: tiers of columns, each within `ratio` of its own largest column, largest tier first (the
// left axis), then one right axis per further tier. A bending stress of 27 MPa, a shear force of 40 kN and a
// torsional stress of 4 Pa make three tiers, so the 40 kN curve is not a line on zero beside the 4 Pa one.
// Columns that are all zero (or missing) go with the first tier. One tier when all sizes are within `ratio`. At most
// kMaxValueAxes tiers: a fourth axis would leave no room for the curves, so anything smaller shares the third.
inline constexpr std::size_t kMaxValueAxes = 3;
std::vector<std::vector<std::string>> magnitudeTiers(const Table& table, const std::vector<std::string>& y,
                                                     double ratio = kSeparateAxisRatio);

// The largest |value| of `column` in its display unit (0 for an empty column; non-finite values skipped).
double displayMagnitude(const Column& column);

// Fits every axis to the plot's data, markers included, then widens an axis end where a marker (a graph
// drawn as points only: reference data, measured points) lies closer to it than `margin` of the axis range
// (in decades on a log axis), so the marker is drawn whole and not on the frame.
void fitAxesToData(QCustomPlot& plot, double margin = 0.04);

}  // namespace maris::ui
