#include "ship/hull_offsets.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

#include "core/errors.hpp"
#include "core/table_reader.hpp"
#include "core/text_format.hpp"

namespace maris::ship {

double OffsetsTable::deepest() const {
  double d = 0.0;
  for (const auto& s : stations)
    if (!s.z.empty()) d = std::min(d, s.z.front());
  return d;
}

OffsetsTable parseOffsetsCsv(std::string_view text, const std::string& field, const std::string& file) {
  TableSpec spec{field, file, "columns x_m,z_m,half_breadth_m (or x,z,half_breadth and a units row m,m,m)"};
  spec.min_columns = 3;
  refuseForeignFormat(text, spec);
  TextTable csv = parseTable(text, spec, true);
  std::vector<FieldError> errors = std::move(csv.errors);
  // The unit of a name "x_m" is "m"; a bare name "x" needs "m" in the units row.
  for (int c = 0; c < 3; ++c) {
    const std::string& name = csv.names[c];
    const bool metres = csv.units[c] == "m" || (name.size() > 2 && name.compare(name.size() - 2, 2, "_m") == 0);
    if (!metres)
      throw InputError({tableError(spec, 0,
                                   "the columns need units: name them x_m,z_m,half_breadth_m or add a units row m,m,m",
                                   &csv, c)});
  }

  OffsetsTable table;
  for (const auto& row : csv.rows) {
    const auto& v = row.cells;
    if (!v[0] || !v[1] || !v[2]) continue;  // a bad cell, already reported
    if (*v[2] < 0.0) {
      errors.push_back(tableError(spec, row.line, "is negative: half-breadths must be >= 0", &csv, 2));
      continue;
    }
    if (*v[1] > 0.0) {
      ++table.ignored_rows_above_waterline;
      continue;
    }
    if (table.stations.empty() || *v[0] != table.stations.back().x) {
      if (!table.stations.empty() && *v[0] < table.stations.back().x) {
        errors.push_back(tableError(spec, row.line,
                                    "stations must be listed with x ascending (previous station x = " +
                                        numberText(table.stations.back().x) + " m)",
                                    &csv, 0));
        continue;
      }
      table.stations.push_back({*v[0], {}, {}});
    }
    table.stations.back().z.push_back(*v[1]);
    table.stations.back().half_breadth.push_back(*v[2]);
  }
  const std::string origin = field;
  // Sort each station by z ascending and check it has distinct depths.
  for (auto& s : table.stations) {
    std::vector<std::size_t> order(s.z.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.z[a] < s.z[b]; });
    OffsetsStation sorted{s.x, {}, {}};
    for (auto k : order) {
      if (!sorted.z.empty() && sorted.z.back() == s.z[k]) {
        errors.push_back({origin, numberText(s.z[k]),
                          "station x = " + numberText(s.x) + " m lists z = " + numberText(s.z[k]) + " m twice"});
        continue;
      }
      sorted.z.push_back(s.z[k]);
      sorted.half_breadth.push_back(s.half_breadth[k]);
    }
    if (sorted.z.size() < 2)
      errors.push_back({origin, numberText(s.x),
                        "station x = " + numberText(s.x) + " m has fewer than 2 points at or below the waterline"});
    s = std::move(sorted);
  }
  if (errors.empty() && table.stations.size() < 3)
    errors.push_back({origin, std::to_string(table.stations.size()),
                      "the table has " + std::to_string(table.stations.size()) + " stations: at least 3 are needed"});
  if (!errors.empty()) throw InputError(std::move(errors));
  return table;
}

OffsetsTable scaledOffsets(const OffsetsTable& table, double scale) {
  OffsetsTable out = table;
  for (auto& s : out.stations) {
    s.x *= scale;
    for (auto& z : s.z) z *= scale;
    for (auto& y : s.half_breadth) y *= scale;
  }
  return out;
}

}  // namespace maris::ship
