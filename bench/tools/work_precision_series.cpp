#include "work_precision_series.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace maris::bench {
namespace {

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::stringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();  // getline drops a trailing empty cell
  return cells;
}

// The number in a cell, or NaN if the cell is not entirely a number ("inf" is a number).
double number(const std::string& cell) {
  if (cell.empty()) return std::nan("");
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size() ? value : std::nan("");
}

std::size_t columnIndex(const TextTable& table, const std::string& name) {
  const auto it = std::find(table.names.begin(), table.names.end(), name);
  if (it == table.names.end()) throw std::runtime_error("no column '" + name + "' in the CSV");
  return static_cast<std::size_t>(it - table.names.begin());
}

// A failure note cut before " has " (keeping time, step and quantity), at most 90 characters.
std::string shortNote(const std::string& note) {
  std::string out = note.substr(0, note.find(" has "));
  if (out.size() > 90) out = out.substr(0, 87) + "...";
  return out;
}

}  // namespace

TextTable parseTextCsv(const std::string& text) {
  TextTable table;
  std::stringstream in(text);
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> cells = splitCells(line);
    if (table.names.empty()) {
      table.names = std::move(cells);
    } else if (table.units.empty()) {
      table.units = std::move(cells);
    } else {
      if (cells.size() != table.names.size())
        throw std::runtime_error("line " + std::to_string(line_number) + " has " + std::to_string(cells.size()) +
                                 " cells, the names row " + std::to_string(table.names.size()));
      table.rows.push_back(std::move(cells));
    }
  }
  if (table.units.empty()) throw std::runtime_error("not a Maris CSV: a names row and a units row are needed");
  table.units.resize(table.names.size(), "-");
  return table;
}

WorkPrecisionSet groupWorkPrecision(const TextTable& table, const SeriesSelection& selection) {
  const std::size_t xc = columnIndex(table, selection.x), yc = columnIndex(table, selection.y);
  std::vector<std::pair<std::size_t, std::string>> filters;
  for (const auto& [column, value] : selection.where) filters.push_back({columnIndex(table, column), value});
  std::vector<std::size_t> series_columns, detail_columns;
  for (const auto& c : selection.series_columns) series_columns.push_back(columnIndex(table, c));
  for (const auto& c : selection.detail_columns) detail_columns.push_back(columnIndex(table, c));
  const bool has_note = !selection.note_column.empty() &&
                        std::find(table.names.begin(), table.names.end(), selection.note_column) != table.names.end();
  const std::size_t note_column = has_note ? columnIndex(table, selection.note_column) : 0;

  WorkPrecisionSet set;
  set.x_unit = table.units[xc];
  set.y_unit = table.units[yc];
  for (const auto& row : table.rows) {
    if (!std::all_of(filters.begin(), filters.end(), [&](const auto& f) { return row[f.first] == f.second; })) continue;
    std::string label;
    for (std::size_t c : series_columns) label += (label.empty() ? "" : " ") + row[c];
    const double x = number(row[xc]), y = number(row[yc]);
    if (!(std::isfinite(x) && std::isfinite(y) && x > 0 && y > 0)) {
      std::string line = label;
      for (std::size_t c : detail_columns) line += " " + table.names[c] + " " + row[c];
      const std::string why = has_note && !row[note_column].empty()
                                  ? shortNote(row[note_column])
                                  : selection.y + " = " + row[yc] + ", " + selection.x + " = " + row[xc];
      set.left_out.push_back(line + ": " + why);
      continue;
    }
    auto it = std::find_if(set.series.begin(), set.series.end(), [&](const auto& s) { return s.label == label; });
    if (it == set.series.end()) it = set.series.insert(set.series.end(), WorkPrecisionSeries{label, {}});
    it->points.push_back({x, y});
  }
  for (auto& s : set.series) std::sort(s.points.begin(), s.points.end());
  return set;
}

std::string leftOutNote(const std::vector<std::string>& left_out, std::size_t max_items) {
  if (left_out.empty()) return "";
  std::string note = std::to_string(left_out.size()) + (left_out.size() == 1 ? " row" : " rows") +
                     " left out (failed run or zero error): ";
  for (std::size_t k = 0; k < std::min(max_items, left_out.size()); ++k) note += (k ? "; " : "") + left_out[k];
  if (left_out.size() > max_items) note += "; ...";
  return note;
}

}  // namespace maris::bench
