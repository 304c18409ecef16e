// Reference data a user brings to a plot (a paper's points, measurements): read from CSV and
// matched to a plot's columns. The CSV is what Maris writes (names row, units row, data) or what a
// digitiser writes: a names row whose cells may carry their unit ("time [s]", "time (s)"), an
// optional units row (a row without any number), then numbers; separators comma, semicolon or tab; lines starting with '#' skipped.
#pragma once

#include <string>
#include <vector>

#include "core/results.hpp"

namespace maris::ui {

// Parses CSV text into a table named `name` with the engine's table reader (core/table_reader.hpp).
// Throws InputError (a std::runtime_error) naming the line and column of each problem (not a number, wrong
// number of cells, no data rows, fewer than two columns, a file in another known format).
Table tableFromCsv(const std::string& text, const std::string& name);

// Which columns of `reference` to draw on `spec`'s axes: x is the column named like the plot's x
// (else the first column); the y columns are those named like the plot's y columns, or, if none is,
// every other column.
struct ReferenceColumns {
  const Column* x = nullptr;
  std::vector<const Column*> y;
};
ReferenceColumns matchReferenceColumns(const Table& reference, const PlotSpec& spec);

// Notes for the user when units differ from the plot's (no conversion is made): empty if they agree
// or the CSV gives no units.
std::vector<std::string> referenceUnitMismatches(const Table& reference, const Results& results, const PlotSpec& spec);

}  // namespace maris::ui
