#include "core/table_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/formats/format_detect.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"

namespace maris {

namespace {

std::string trim(std::string_view s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  const auto b = s.find_last_not_of(" \t\r");
  std::string cell(s.substr(a, b - a + 1));
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = cell.substr(1, cell.size() - 2);
  return cell;
}

// '\0' splits at runs of blanks.
std::vector<std::string> splitCells(std::string_view line, char separator) {
  std::vector<std::string> cells;
  if (separator == '\0') {
    std::size_t pos = 0;
    while (true) {
      const auto a = line.find_first_not_of(" \t\r", pos);
      if (a == std::string_view::npos) break;
      const auto b = line.find_first_of(" \t\r", a);
      cells.emplace_back(line.substr(a, b == std::string_view::npos ? std::string_view::npos : b - a));
      if (b == std::string_view::npos) break;
      pos = b;
    }
    return cells;
  }
  std::size_t start = 0;
  while (true) {
    const auto at = line.find(separator, start);
    cells.push_back(trim(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return cells;
}

char separatorOf(std::string_view line) {
  if (line.find('\t') != std::string_view::npos && line.find(',') == std::string_view::npos) return '\t';
  if (line.find(',') != std::string_view::npos) return ',';
  if (line.find(';') != std::string_view::npos) return ';';
  return '\0';
}

// A number in C syntax, without locale; "inf"/"infinity" read as infinity, "nan" as NaN (refused later).
bool parseNumber(const std::string& cell, double& value) {
  if (cell.empty()) return false;
  const char* first = cell.data() + (cell.front() == '+' ? 1 : 0);
  const char* last = cell.data() + cell.size();
  const auto [end, error] = std::from_chars(first, last, value);
  return error == std::errc() && end == last;
}

// "time [s]" / "time (s)" -> ("time", "s").
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

std::string quoted(const std::string& s) { return "\"" + echoText(s) + "\""; }

}  // namespace

int TextTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

FieldError tableError(const TableSpec& spec, int line, const std::string& message, const TextTable* table, int column) {
  std::string where;
  if (line > 0) where = "line " + std::to_string(line);
  if (column >= 0) {
    where += (where.empty() ? "" : ", ") + std::string("column ") + std::to_string(column + 1);
    if (table && static_cast<std::size_t>(column) < table->names.size()) where += " (" + table->names[column] + ")";
  }
  return FieldError{spec.field, spec.file.empty() ? std::string() : quoted(spec.file),
                    where.empty() ? message : where + ": " + message};
}

TextTable parseTable(std::string_view text, const TableSpec& spec, bool keep_errors) {
  TextTable table;
  std::vector<std::pair<int, std::string_view>> lines;  // (line number, text) of lines with content
  int number = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    auto nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++number;
    if (line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // UTF-8 byte-order mark (also after a join)
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    lines.emplace_back(number, line);
  }
  const std::string expected = spec.expected.empty() ? "" : " (expected " + spec.expected + ")";
  if (lines.empty()) throw InputError({tableError(spec, 0, "holds no table" + expected)});

  const char separator = separatorOf(lines.front().second);
  std::size_t next = 0;
  auto anyNumber = [](const std::vector<std::string>& cells) {
    double ignored = 0.0;
    return std::any_of(cells.begin(), cells.end(), [&](const std::string& c) { return parseNumber(c, ignored); });
  };
  const std::vector<std::string> head = splitCells(lines.front().second, separator);
  const bool has_names = spec.names == TableSpec::Names::required ||
                         (spec.names == TableSpec::Names::optional && !anyNumber(head));
  if (has_names) {
    if (anyNumber(head) && head.size() > 0) {
      double v = 0.0;
      if (std::all_of(head.begin(), head.end(), [&](const std::string& c) { return parseNumber(c, v); }))
        throw InputError({tableError(spec, lines.front().first, "expected a row of column names, found numbers" + expected)});
    }
    for (const auto& cell : head) {
      std::string name, unit;
      splitNameAndUnit(cell, name, unit);
      table.names.push_back(name.empty() ? "column_" + std::to_string(table.names.size() + 1) : name);
      table.units.push_back(unit);
    }
    next = 1;
    if (next < lines.size()) {
      const auto units = splitCells(lines[next].second, separator);
      if (!anyNumber(units)) {
        for (std::size_t c = 0; c < units.size() && c < table.units.size(); ++c)
          if (!units[c].empty()) table.units[c] = units[c];
        ++next;
      }
    }
  } else {
    for (std::size_t c = 0; c < head.size(); ++c) table.names.push_back("column_" + std::to_string(c + 1));
    table.units.assign(head.size(), "");
  }
  if (table.columns() < spec.min_columns)
    throw InputError({tableError(spec, lines.front().first,
                                 "has " + std::to_string(table.columns()) + " column(s); at least " +
                                     std::to_string(spec.min_columns) + " are needed, separated by commas, semicolons, "
                                     "tabs or blanks" + expected)});

  for (; next < lines.size(); ++next) {
    const auto& [line, content] = lines[next];
    const std::vector<std::string> cells = splitCells(content, separator);
    if (cells.size() > table.columns() || (cells.size() < table.columns() && !spec.empty_cells)) {
      table.errors.push_back(tableError(spec, line,
                                        "expected " + std::to_string(table.columns()) + " cells (as the first row), found " +
                                            std::to_string(cells.size()) + expected));
      continue;
    }
    TextTable::Row row{line, std::vector<std::optional<double>>(table.columns())};
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double v = 0.0;
      const int col = static_cast<int>(c);
      if (cells[c].empty()) {
        if (!spec.empty_cells) table.errors.push_back(tableError(spec, line, "expected a number, found an empty cell", &table, col));
      } else if (!parseNumber(cells[c], v)) {
        table.errors.push_back(tableError(spec, line, "expected a number, found " + quoted(cells[c]) + expected, &table, col));
      } else if (std::isnan(v) || (std::isinf(v) && !spec.infinity)) {
        table.errors.push_back(tableError(spec, line,
                                          "expected a finite number" +
                                              std::string(spec.empty_cells ? " (an empty cell for no value)" : "") +
                                              ", found " + quoted(cells[c]),
                                          &table, col));
      } else {
        row.cells[c] = v;
      }
    }
    table.rows.push_back(std::move(row));
  }
  if (!keep_errors && !table.errors.empty()) throw InputError(std::move(table.errors));
  return table;
}

void refuseForeignFormat(std::string_view text, const TableSpec& spec) {
  const formats::FileFormat format = formats::detectFormat(text);
  if (format == formats::FileFormat::table) return;
  throw InputError({tableError(spec, 0,
                               "looks like " + formats::formatName(format) +
                                   "; this format is not supported here; expected a table" +
                                   (spec.expected.empty() ? std::string() : " of " + spec.expected))});
}

TextTable readTable(std::string_view path, std::string_view scene, const TableSpec& spec) {
  const std::string text = readDataText(path, scene, spec.field);
  refuseForeignFormat(text, spec);
  return parseTable(text, spec);
}

}  // namespace maris
