#include "plots/reference_data.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>
#include <stdexcept>

namespace maris::ui {
namespace {

std::string trim(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

std::vector<std::string> splitCells(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator)) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == separator) cells.emplace_back();
  return cells;
}

bool parseNumber(const std::string& cell, double& value) {
  if (cell.empty()) return false;
  const char* first = cell.data() + (cell.front() == '+' ? 1 : 0);
  const char* last = cell.data() + cell.size();
  const auto [end, error] = std::from_chars(first, last, value);
  return error == std::errc() && end == last;
}

// "time [s]" or "time (s)" -> name "time", unit "s"; otherwise the whole cell is the name.
void splitNameAndUnit(const std::string& cell, std::string& name, std::string& unit) {
  name = cell;
  unit.clear();
  if (cell.size() < 3) return;
  const char close = cell.back();
  const char open = close == ']' ? '[' : close == ')' ? '(' : '\0';
  if (!open) return;
  const auto at = cell.rfind(open);
  if (at == std::string::npos || at == 0) return;
  name = trim(cell.substr(0, at));
  unit = trim(cell.substr(at + 1, cell.size() - at - 2));
}

}  // namespace

Table tableFromCsv(const std::string& text, const std::string& name) {
  std::vector<std::pair<int, std::string>> lines;  // (line number, text) of the non-empty, non-comment lines
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte-order mark
    if (trim(line).empty() || trim(line).front() == '#') continue;
    lines.emplace_back(number, line);
  }
  if (lines.empty()) throw std::runtime_error(name + ": the file holds no table");
  const std::string& header = lines.front().second;
  const char separator = header.find('\t') != std::string::npos ? '\t'
                         : header.find(';') != std::string::npos && header.find(',') == std::string::npos ? ';'
                                                                                                            : ',';
  const std::vector<std::string> names = splitCells(header, separator);
  if (names.size() < 2)
    throw std::runtime_error(name + ": line " + std::to_string(lines.front().first) +
                             ": need at least two columns (x and y), separated by commas, semicolons or tabs");
  Table table;
  table.name = name;
  table.title = name;
  for (const auto& cell : names) {
    std::string column_name, unit;
    splitNameAndUnit(cell, column_name, unit);
    if (column_name.empty()) column_name = "column_" + std::to_string(table.columns.size() + 1);
    table.add(column_name, unit);
  }
  std::size_t first_data = 1;
  if (lines.size() > 1) {
    const std::vector<std::string> second = splitCells(lines[1].second, separator);
    double ignored = 0.0;
    // A units row has no number in it ("s,m" or "-,m"); a row with some numbers is data (bad cells reported).
    const bool units_row = std::none_of(second.begin(), second.end(),
                                        [&](const std::string& c) { return parseNumber(c, ignored); });
    if (units_row) {
      for (std::size_t c = 0; c < table.columns.size() && c < second.size(); ++c)
        if (!second[c].empty()) table.columns[c].unit = second[c];
      first_data = 2;
    }
  }
  for (std::size_t r = first_data; r < lines.size(); ++r) {
    const auto& [number, text_line] = lines[r];
    const std::vector<std::string> cells = splitCells(text_line, separator);
    if (cells.size() != table.columns.size())
      throw std::runtime_error(name + ": line " + std::to_string(number) + " has " + std::to_string(cells.size()) +
                               " cells, the names row " + std::to_string(table.columns.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double value = 0.0;
      if (!parseNumber(cells[c], value))
        throw std::runtime_error(name + ": line " + std::to_string(number) + ", column " + std::to_string(c + 1) +
                                 " ('" + table.columns[c].name + "'): '" + cells[c] + "' is not a number");
      table.columns[c].values.push_back(value);
    }
  }
  if (table.rows() == 0) throw std::runtime_error(name + ": the file has names but no rows of numbers");
  return table;
}

ReferenceColumns matchReferenceColumns(const Table& reference, const PlotSpec& spec) {
  ReferenceColumns out;
  if (reference.columns.size() < 2) return out;
  out.x = reference.find(spec.x);
  if (!out.x) out.x = &reference.columns.front();
  for (const auto& name : spec.y)
    if (const Column* c = reference.find(name); c && c != out.x) out.y.push_back(c);
  if (out.y.empty())
    for (const auto& c : reference.columns)
      if (&c != out.x) out.y.push_back(&c);
  return out;
}

std::vector<std::string> referenceUnitMismatches(const Table& reference, const Results& results, const PlotSpec& spec) {
  std::vector<std::string> notes;
  const Table* table = results.findTable(spec.table);
  if (!table) return notes;
  const ReferenceColumns match = matchReferenceColumns(reference, spec);
  auto check = [&](const Column* ref, const Column* plotted) {
    if (!ref || !plotted || ref->unit.empty() || plotted->unit.empty() || ref->unit == plotted->unit) return;
    notes.push_back("column '" + ref->name + "' is in " + ref->unit + ", the plot's axis in " + plotted->unit +
                    " (drawn as given, not converted)");
  };
  check(match.x, table->find(spec.x));
  const Column* first_y = spec.y.empty() ? nullptr : table->find(spec.y.front());
  for (const Column* y : match.y) check(y, table->find(y->name) ? table->find(y->name) : first_y);
  return notes;
}

}  // namespace maris::ui
