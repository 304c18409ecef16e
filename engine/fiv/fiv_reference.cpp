#include "fiv/fiv_reference.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "core/table_reader.hpp"

namespace maris::fiv {

TextTable parseNumericCsv(const std::string& text, const TableSpec& spec_in) {
  TableSpec spec = spec_in;
  spec.empty_cells = true;  // an empty cell is "not given"
  spec.infinity = true;     // h* = inf is "no free surface"; other columns check finiteness themselves
  refuseForeignFormat(text, spec);
  return parseTable(text, spec);
}

std::vector<ReferencePoint> parseReferencePoints(const std::string& csv_text, const std::string& origin) {
  const TableSpec spec{"parameters.calibration.reference_file", origin,
                       "columns flow_speed, submergence_ratio and optional amplitude, frequency, power with sigmas"};
  const TextTable csv = parseNumericCsv(csv_text, spec);
  auto need = [&](const char* name) {
    const int c = csv.column(name);
    if (c < 0) throw InputError({tableError(spec, 0, std::string("missing column \"") + name + "\" in the names row")});
    return c;
  };
  const int c_speed = need("flow_speed"), c_h = need("submergence_ratio");
  const int c_a = csv.column("amplitude"), c_as = csv.column("amplitude_sigma");
  const int c_f = csv.column("frequency"), c_fs = csv.column("frequency_sigma");
  const int c_p = csv.column("power"), c_ps = csv.column("power_sigma");
  std::vector<ReferencePoint> points;
  for (const auto& row : csv.rows) {
    const auto& r = row.cells;
    if (!r[c_speed]) throw InputError({tableError(spec, row.line, "a value is required", &csv, c_speed)});
    if (!r[c_h]) throw InputError({tableError(spec, row.line, "a value is required", &csv, c_h)});
    // Only the submergence ratio may be infinite (deep water); every measured value must be finite.
    for (std::size_t c = 0; c < r.size(); ++c)
      if (r[c] && !std::isfinite(*r[c]) && static_cast<int>(c) != c_h)
        throw InputError({tableError(spec, row.line, "expected a finite number", &csv, static_cast<int>(c))});
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
