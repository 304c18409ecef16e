// Work–precision series from a benchmark CSV (no Qt: shared by bench/tools/work_precision_plot and its test).
// The CSV is Maris's layout: a names row, a units row, then data rows whose cells may be text ("J3", "rk4",
// a failure note) or numbers ("inf" for a failed run). A series is the rows with equal values in the chosen
// series columns (e.g. variant, method); its points are (x, y) sorted by x (cost), so that a line joins them
// from cheap to dear and not in the order the bench happened to run them.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace maris::bench {

struct TextTable {
  std::vector<std::string> names, units;
  std::vector<std::vector<std::string>> rows;  // every row has names.size() cells
};

// Parses CSV text (comma separated, no quoting: the bench writes no commas inside cells). Throws
// std::runtime_error if the names or units row is missing or a data row has the wrong number of cells
// (naming the line).
TextTable parseTextCsv(const std::string& text);

struct SeriesSelection {
  std::string x, y;                                        // columns of the axes
  std::vector<std::string> series_columns;                 // a series = equal values in these
  std::vector<std::pair<std::string, std::string>> where;  // keep rows with column == value only
  std::vector<std::string> detail_columns;                 // shown beside a left-out row (e.g. "setting")
  std::string note_column;                                 // a failed row's reason, if the CSV has one
};

struct WorkPrecisionSeries {
  std::string label;                           // series values joined by spaces ("A2 rk4")
  std::vector<std::pair<double, double>> points;  // (x, y), x ascending
};

struct WorkPrecisionSet {
  std::vector<WorkPrecisionSeries> series;  // in order of first appearance in the CSV
  std::vector<std::string> left_out;        // one line per row whose x or y is not a finite positive number
  std::string x_unit, y_unit;
};

// Groups the rows that pass `where` into series. Rows whose x or y is not finite and positive (a failed run's
// "inf", an error of exactly 0) are left out of the series and described in left_out as
// "<label> <detail columns>: <note or the value>". Throws std::runtime_error naming an unknown column.
WorkPrecisionSet groupWorkPrecision(const TextTable& table, const SeriesSelection& selection);

// One note for the plot: "n rows left out (failed or zero): a; b; …", at most max_items listed; "" if none.
std::string leftOutNote(const std::vector<std::string>& left_out, std::size_t max_items);

}  // namespace maris::bench
