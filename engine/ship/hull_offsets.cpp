#include "ship/hull_offsets.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "core/errors.hpp"

namespace maris::ship {

namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return std::string(s.substr(b, e - b + 1));
}

std::vector<std::string> splitCsvLine(std::string_view line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

bool parseNumber(const std::string& s, double& value) {
  if (s.empty()) return false;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// The unit of a header name "x_m" is "m"; a bare name "x" has none (a units row must follow).
bool headerNamesMetres(const std::vector<std::string>& header) {
  return std::all_of(header.begin(), header.begin() + 3,
                     [](const std::string& h) { return h.size() > 2 && h.substr(h.size() - 2) == "_m"; });
}

}  // namespace

double OffsetsTable::deepest() const {
  double d = 0.0;
  for (const auto& s : stations)
    if (!s.z.empty()) d = std::min(d, s.z.front());
  return d;
}

OffsetsTable parseOffsetsCsv(std::string_view text, const std::string& origin) {
  std::vector<FieldError> errors;
  auto fail = [&](int line, const std::string& value, const std::string& message) {
    if (errors.size() < 20) errors.push_back({origin, value, "line " + std::to_string(line) + ": " + message});
  };
  std::vector<std::string_view> lines;
  for (std::size_t pos = 0; pos <= text.size();) {
    auto nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    lines.push_back(text.substr(pos, nl - pos));
    pos = nl + 1;
  }
  std::size_t row = 0;
  while (row < lines.size() && trim(lines[row]).empty()) ++row;
  if (row == lines.size()) throw InputError(origin, "\"\"", "the offsets table is empty (expected a header x_m,z_m,half_breadth_m)");
  const auto header = splitCsvLine(lines[row]);
  if (header.size() < 3) throw InputError(origin, trim(lines[row]), "line 1: expected 3 columns x_m,z_m,half_breadth_m");
  ++row;
  if (!headerNamesMetres(header)) {
    // A units row must follow and say metres for the three columns.
    const auto units = row < lines.size() ? splitCsvLine(lines[row]) : std::vector<std::string>{};
    if (units.size() < 3 || units[0] != "m" || units[1] != "m" || units[2] != "m")
      throw InputError(origin, row < lines.size() ? trim(lines[row]) : "",
                       "line " + std::to_string(row + 1) +
                           ": the columns need units: name them x_m,z_m,half_breadth_m or add a units row m,m,m");
    ++row;
  }

  OffsetsTable table;
  for (; row < lines.size(); ++row) {
    const int line = static_cast<int>(row) + 1;
    if (trim(lines[row]).empty()) continue;
    const auto f = splitCsvLine(lines[row]);
    double v[3] = {0, 0, 0};
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
      const std::string field = c < static_cast<int>(f.size()) ? f[c] : std::string();
      if (!parseNumber(field, v[c]) || !std::isfinite(v[c])) {
        fail(line, field, "column " + header[c] + (field.empty() ? " is missing" : " is not a finite number"));
        ok = false;
      }
    }
    if (!ok) continue;
    if (v[2] < 0.0) {
      fail(line, f[2], "column " + header[2] + " is negative: half-breadths must be >= 0");
      continue;
    }
    if (v[1] > 0.0) {
      ++table.ignored_rows_above_waterline;
      continue;
    }
    if (table.stations.empty() || v[0] != table.stations.back().x) {
      if (!table.stations.empty() && v[0] < table.stations.back().x) {
        fail(line, f[0], "stations must be listed with x ascending (previous station x = " +
                             std::to_string(table.stations.back().x) + " m)");
        continue;
      }
      table.stations.push_back({v[0], {}, {}});
    }
    table.stations.back().z.push_back(v[1]);
    table.stations.back().half_breadth.push_back(v[2]);
  }

  // Sort each station by z ascending and check it has distinct depths.
  for (auto& s : table.stations) {
    std::vector<std::size_t> order(s.z.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.z[a] < s.z[b]; });
    OffsetsStation sorted{s.x, {}, {}};
    for (auto k : order) {
      if (!sorted.z.empty() && sorted.z.back() == s.z[k]) {
        errors.push_back({origin, std::to_string(s.z[k]),
                          "station x = " + std::to_string(s.x) + " m lists z = " + std::to_string(s.z[k]) + " m twice"});
        continue;
      }
      sorted.z.push_back(s.z[k]);
      sorted.half_breadth.push_back(s.half_breadth[k]);
    }
    if (sorted.z.size() < 2)
      errors.push_back({origin, std::to_string(s.x),
                        "station x = " + std::to_string(s.x) + " m has fewer than 2 points at or below the waterline"});
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
