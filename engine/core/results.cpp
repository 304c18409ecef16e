#include "core/results.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/csv_field.hpp"
#include "core/input_limits.hpp"

namespace maris {

Column& Table::add(std::string column_name, std::string unit, std::vector<double> values, std::string label) {
  columns.push_back(Column{std::move(column_name), std::move(unit), std::move(values), std::move(label)});
  return columns.back();
}

const Column* Table::find(const std::string& column_name) const {
  for (const auto& c : columns)
    if (c.name == column_name) return &c;
  return nullptr;
}

std::string csvNumber(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17);
  return std::string(text, result.ptr);
}

void appendCsvField(std::string& out, const std::string& field) {
  if (field.find_first_of(",\"\n") == std::string::npos) {
    out += field;
    return;
  }
  out += '"';
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

std::string Table::toCsv() const {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) out += ',';
    appendCsvField(out, columns[i].name);
  }
  out += '\n';
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) out += ',';
    appendCsvField(out, columns[i].unit.empty() ? "-" : columns[i].unit);
  }
  out += '\n';
  for (std::size_t r = 0; r < rows(); ++r) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i) out += ',';
      const double v = r < columns[i].values.size() ? columns[i].values[r] : std::nan("");
      out += csvNumber(v);
    }
    out += '\n';
  }
  return out;
}

const Table* Results::findTable(const std::string& name) const {
  for (const auto& t : tables)
    if (t.name == name) return &t;
  return nullptr;
}

const Scalar* Results::findScalar(const std::string& name) const {
  for (const auto& s : scalars)
    if (s.name == name) return &s;
  return nullptr;
}

void Results::addScalar(std::string name, double value, std::string unit, std::string description,
                        std::string label) {
  scalars.push_back(Scalar{std::move(name), value, std::move(unit), std::move(description), std::move(label)});
}

std::string readableName(const std::string& name) {
  std::string text = name;
  for (char& c : text)
    if (c == '_') c = ' ';
  if (!text.empty() && text[0] >= 'a' && text[0] <= 'z') text[0] = static_cast<char>(text[0] - 'a' + 'A');
  return text;
}

std::string displayLabel(const Column& column) { return column.label.empty() ? readableName(column.name) : column.label; }

std::string displayLabel(const Scalar& scalar) { return scalar.label.empty() ? readableName(scalar.name) : scalar.label; }

void requireFiniteResults(const Results& results) {
  const double no_time = std::nan("");
  for (const auto& s : results.scalars)
    if (!std::isfinite(s.value)) throw SolverError("result " + s.name, no_time, -1, "is not finite");
  for (const auto& t : results.tables)
    for (const auto& c : t.columns)
      for (std::size_t r = 0; r < c.values.size(); ++r)
        if (!std::isfinite(c.values[r]))
          throw SolverError("result table " + t.name + ", column " + c.name + ", row " + std::to_string(r + 1),
                            no_time, -1, "is not finite");
  if (!std::isfinite(results.stats.error_estimate))
    throw SolverError("result error estimate", no_time, -1, "is not finite");
}

Json summaryJson(const Results& results) {
  Json j;
  j["results"] = Json::object();
  for (const auto& s : results.scalars) {
    Json e;
    e["value"] = std::isfinite(s.value) ? Json(s.value) : Json(nullptr);
    e["unit"] = s.unit;
    e["description"] = s.description;
    if (!s.label.empty()) e["label"] = s.label;
    j["results"][s.name] = e;
  }
  const auto& st = results.stats;
  j["solver"] = {{"method", st.method},
                 {"steps", st.steps},
                 {"rejected_steps", st.rejected_steps},
                 {"rhs_evaluations", st.rhs_evaluations},
                 {"wall_time", {{"value", st.wall_time_s}, {"unit", "s"}}},
                 {"error_estimate", {{"value", st.error_estimate}, {"unit", st.error_unit}}}};
  j["warnings"] = results.warnings;
  return j;
}

PlotSpec makePlot(std::string name, std::string title, std::string table, std::string x, std::vector<std::string> y,
                  bool log_y) {
  PlotSpec p;
  p.name = std::move(name);
  p.title = std::move(title);
  p.table = std::move(table);
  p.x = std::move(x);
  p.y = std::move(y);
  p.log_y = log_y;
  return p;
}

}  // namespace maris
