// A study's "table" design: a CSV file with one column per parameter path and one row per case (a
// load-case table, or a design of experiments made elsewhere), read through the data-file gate; with
// "weighted_sum", one more column holds each case's weight.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/input_limits.hpp"
#include "study/study_design.hpp"

namespace maris::study::detail {

namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  std::string cell = text.substr(first, last - first + 1);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = cell.substr(1, cell.size() - 2);
  return cell;
}

std::vector<std::string> splitCells(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (;;) {
    const auto at = line.find(separator, start);
    cells.push_back(trim(line.substr(start, at == std::string::npos ? std::string::npos : at - start)));
    if (at == std::string::npos) return cells;
    start = at + 1;
  }
}

// A cell as a number when the whole cell is one (locale-independent), else nullopt.
std::optional<double> parseNumber(const std::string& cell) {
  double v = 0.0;
  const char* end = cell.data() + cell.size();
  const auto [ptr, ec] = std::from_chars(cell.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
  return v;
}

// A cell's value as the parameter's kind stores it; text otherwise (the case's validation judges it).
Json cellValue(const std::string& cell, ParamKind kind) {
  if (kind == ParamKind::Boolean && (cell == "true" || cell == "false")) return Json(cell == "true");
  if (const auto number = parseNumber(cell); number && kind != ParamKind::Text && kind != ParamKind::Choice) {
    if (kind == ParamKind::Integer && *number != std::floor(*number)) return Json(*number);
    return numberValue(*number, kind);
  }
  return Json(cell);
}

bool unitMatches(const std::string& written, const std::string& unit) {
  auto plain = [](const std::string& u) { return u.empty() || u == "-" ? std::string("-") : u; };
  return plain(written) == plain(unit);
}

// The lines of a table's text that hold cells: (line number, text), without blank and comment lines.
std::vector<std::pair<std::size_t, std::string>> tableLines(const std::string& text) {
  std::vector<std::pair<std::size_t, std::string>> lines;
  std::size_t number = 0, start = 0;
  while (start < text.size()) {
    const auto end = text.find('\n', start);
    const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    ++number;
    if (!trim(line).empty() && trim(line)[0] != '#') lines.emplace_back(number, line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

// The separator a header uses: ',', else ';', else a tab.
char tableSeparator(const std::string& header) {
  return header.find(',') != std::string::npos ? ',' : header.find(';') != std::string::npos ? ';' : '\t';
}

}  // namespace

void readTable(const Json& table, const SceneDefinition& scene, Study& study, std::vector<FieldError>& errors) {
  study.kind = DesignKind::Table;
  if (!table.is_string() || table.get<std::string>().empty()) {
    errors.push_back({"table", jsonSnippet(table), "must name a CSV file (relative to the study's folder)"});
    return;
  }
  study.table_file = (study.folder / table.get<std::string>()).lexically_normal();
  const std::string file = study.table_file.string(), value = "\"" + echoText(table.get<std::string>()) + "\"";
  std::string text;
  try {
    text = readInputFile(study.table_file, "table", InputLimits::kDataFileBytes);
    checkDataShape(text, "table", file);
  } catch (const InputError& e) {
    errors.insert(errors.end(), e.errors().begin(), e.errors().end());
    return;
  }
  const auto lines = tableLines(text);
  if (lines.empty()) {
    errors.push_back({"table", value, "has no header row (one parameter path per column)"});
    return;
  }
  const std::string& header = lines[0].second;
  const char separator = tableSeparator(header);
  const auto names = splitCells(header, separator);
  std::vector<ParamKind> kinds;
  std::vector<std::string> units;
  bool all_numeric = true;
  // The weight column ("weighted_sum"): a dimensionless number per case, no parameter.
  std::size_t weight_index = names.size();
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::string where = "table column " + std::to_string(c + 1) + " (" + echoText(names[c]) + ")";
    if (!study.weight_column.empty() && names[c] == study.weight_column) {
      if (weight_index < names.size()) errors.push_back({where, "", "is the weight column a second time"});
      weight_index = c;
      kinds.push_back(ParamKind::Real);
      units.push_back("-");
      continue;
    }
    const auto spec = lookupParameter(scene, study.base.parameters, names[c], where, errors);
    if (!spec) continue;
    for (const auto& p : study.parameters)
      if (p.path == spec->path) errors.push_back({where, "", "varies " + spec->path + " a second time"});
    study.parameters.push_back(studyParameter(*spec));
    kinds.push_back(spec->kind);
    units.push_back(spec->unit);
    all_numeric = all_numeric && (spec->kind == ParamKind::Real || spec->kind == ParamKind::Integer);
  }
  if (!study.weight_column.empty() && weight_index == names.size()) {
    const auto guess = didYouMean(study.weight_column, names);
    errors.push_back({"weighted_sum.weight", "\"" + echoText(study.weight_column) + "\"",
                      "is not a column of the table" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
  }
  if (kinds.size() != names.size()) return;  // unknown columns: the rows cannot be read

  std::size_t first = 1;
  // A units row (as study.csv and every Maris CSV write it): each cell the column's unit; or, when every
  // column is a number, a row without numbers (whose units must then be the schema's).
  if (lines.size() > 1) {
    const auto cells = splitCells(lines[1].second, separator);
    bool units_row = cells.size() == units.size();
    for (std::size_t c = 0; c < cells.size() && units_row; ++c) units_row = unitMatches(cells[c], units[c]);
    if (units_row || (all_numeric && std::none_of(cells.begin(), cells.end(), [](const std::string& c) {
                        return parseNumber(c).has_value();
                      }))) {
      first = 2;
      for (std::size_t c = 0; c < cells.size() && c < units.size(); ++c)
        if (!unitMatches(cells[c], units[c]))
          errors.push_back({"table line " + std::to_string(lines[1].first) + ", column " + names[c],
                            "\"" + echoText(cells[c]) + "\"",
                            "is not the parameter's unit '" + units[c] + "' (values are in SI units)"});
    }
  }
  if (lines.size() <= first) {
    errors.push_back({"table", value, "has no data rows (one row per case)"});
    return;
  }
  if (lines.size() - first > StudyLimits::kCases) {
    errors.push_back({"table", value, "has " + std::to_string(lines.size() - first) + " rows; the limit is " +
                                          std::to_string(StudyLimits::kCases) + " cases"});
    return;
  }
  for (std::size_t r = first; r < lines.size(); ++r) {
    const auto cells = splitCells(lines[r].second, separator);
    const std::string where = "table line " + std::to_string(lines[r].first);
    if (cells.size() != names.size()) {
      errors.push_back({where, "", "has " + std::to_string(cells.size()) + " cells; the header has " +
                                       std::to_string(names.size())});
      continue;
    }
    std::vector<Json> row;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cells[c].empty()) errors.push_back({where + ", column " + names[c], "", "is empty"});
      if (c == weight_index) {
        const auto weight = parseNumber(cells[c]);
        if (!cells[c].empty() && !(weight && *weight >= 0.0))
          errors.push_back({where + ", column " + names[c], echoText(cells[c]), "must be a weight: a finite number >= 0"});
        study.weights.push_back(weight.value_or(0.0));
        continue;
      }
      row.push_back(cellValue(cells[c], kinds[c]));
    }
    study.rows.push_back(std::move(row));
  }
}

}  // namespace maris::study::detail

namespace maris::study {

std::vector<std::string> tableColumns(const std::filesystem::path& file) {
  const std::string text = readInputFile(file, "table", InputLimits::kDataFileBytes);
  checkDataShape(text, "table", file.string());
  const auto lines = detail::tableLines(text);
  if (lines.empty()) throw InputError("table", "\"" + echoText(file.string()) + "\"", "has no header row (one parameter path per column)");
  return detail::splitCells(lines[0].second, detail::tableSeparator(lines[0].second));
}

}  // namespace maris::study
