#include "fiv/fiv_reference.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "core/resources.hpp"
#include "core/scenario.hpp"

namespace maris::fiv {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// Parses a number cell; "inf" / "infinity" allowed. Returns false for non-numeric text.
bool parseNumber(const std::string& cell, double& value) {
  if (cell == "inf" || cell == "Inf" || cell == "infinity") {
    value = std::numeric_limits<double>::infinity();
    return true;
  }
  try {
    std::size_t used = 0;
    value = std::stod(cell, &used);
    return used == cell.size();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

int CsvColumns::column(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

CsvColumns parseNumericCsv(const std::string& text, const std::string& origin) {
  CsvColumns out;
  std::stringstream in(text);
  std::string line;
  int line_no = 0;
  bool units_checked = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    auto cells = splitCells(t);
    if (out.names.empty()) {
      out.names = cells;
      continue;
    }
    std::vector<std::optional<double>> row;
    bool numeric = true;
    for (const auto& c : cells) {
      double v = 0.0;
      if (c.empty()) row.emplace_back();
      else if (parseNumber(c, v) && std::isnan(v))  // NaN is not a measurement: a missing value is an empty cell
        throw InputError(origin, "line " + std::to_string(line_no),
                         "a cell reads \"" + c + "\": give a number, or leave the cell empty for no value");
      else if (parseNumber(c, v)) row.emplace_back(v);
      else numeric = false;
    }
    // The first line after the names may be a units row.
    if (!numeric && !units_checked) {
      units_checked = true;
      continue;
    }
    units_checked = true;
    if (!numeric || cells.size() > out.names.size())
      throw InputError(origin, "line " + std::to_string(line_no),
                       "expected " + std::to_string(out.names.size()) + " numeric cells, found \"" + t + "\"");
    row.resize(out.names.size());
    out.rows.push_back(std::move(row));
  }
  if (out.names.empty()) throw InputError(origin, "\"\"", "no header row with column names");
  return out;
}

std::vector<ReferencePoint> parseReferencePoints(const std::string& csv_text, const std::string& origin) {
  const CsvColumns csv = parseNumericCsv(csv_text, origin);
  auto need = [&](const char* name) {
    const int c = csv.column(name);
    if (c < 0) throw InputError(origin, "header", std::string("missing column \"") + name + "\"");
    return c;
  };
  const int c_speed = need("flow_speed"), c_h = need("submergence_ratio");
  const int c_a = csv.column("amplitude"), c_as = csv.column("amplitude_sigma");
  const int c_f = csv.column("frequency"), c_fs = csv.column("frequency_sigma");
  const int c_p = csv.column("power"), c_ps = csv.column("power_sigma");
  std::vector<ReferencePoint> points;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const auto& r = csv.rows[i];
    if (!r[c_speed] || !r[c_h])
      throw InputError(origin, "row " + std::to_string(i + 1), "flow_speed and submergence_ratio are required");
    // Only the submergence ratio may be infinite (deep water); every measured value must be finite.
    for (std::size_t c = 0; c < r.size(); ++c)
      if (r[c] && !std::isfinite(*r[c]) && static_cast<int>(c) != c_h)
        throw InputError(origin, "row " + std::to_string(i + 1), "column " + csv.names[c] + " must be a finite number");
    ReferencePoint p;
    p.speed = *r[c_speed];
    p.submergence_ratio = *r[c_h];
    auto get = [&](int c) { return c >= 0 ? r[c] : std::nullopt; };
    p.amplitude = get(c_a);
    p.amplitude_sigma = get(c_as);
    p.frequency = get(c_f);
    p.frequency_sigma = get(c_fs);
    p.power = get(c_p);
    p.power_sigma = get(c_ps);
    points.push_back(p);
  }
  return points;
}

std::vector<ReferencePoint> loadReferencePoints(const std::string& file) {
  if (!file.empty()) return parseReferencePoints(readDataText(file, "fiv", "parameters.calibration.reference_file"), file);
  const auto text = builtinResource("data/fiv/paper_points.csv");
  if (!text) throw InputError("calibration.reference_file", "\"\"", "built-in data/fiv/paper_points.csv is missing");
  return parseReferencePoints(std::string(*text), "data/fiv/paper_points.csv");
}

std::string submergenceLabel(double submergence_ratio) {
  if (!std::isfinite(submergence_ratio)) return "hinf";
  std::ostringstream s;
  s << "h" << std::setprecision(4) << submergence_ratio;
  return s.str();
}

}  // namespace maris::fiv
