// Offsets tables: half-breadths on stations × waterlines read from CSV, and the monotone cubic (PCHIP,
// Fritsch & Carlson 1980) interpolation that turns them into a smooth surface Y(x, z).
//
// CSV format (that of the tables in resources/data/ship and tests/data/hulls): a header row naming three columns with their units,
//   x_m,z_m,half_breadth_m          (or x,z,half_breadth followed by a units row  m,m,m)
// then one row per offset, station by station (x ascending), any z order within a station. z is measured from
// the design waterline, negative down; rows with z > 0 (above the waterline) are ignored. Every half-breadth
// must be a finite number ≥ 0; 0 means the line misses the hull.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace maris::ship {

struct OffsetsStation {
  double x = 0;                     // [m] from the AP, positive forward
  std::vector<double> z;            // [m] ascending (deepest first), all ≤ 0
  std::vector<double> half_breadth; // [m] at z, ≥ 0
};

struct OffsetsTable {
  std::vector<OffsetsStation> stations;  // x strictly ascending, ≥ 3 stations, ≥ 2 points each
  int ignored_rows_above_waterline = 0;
  double deepest() const;                // [m] most negative z of any station
};

// Parses the CSV text with the shared table reader (core/table_reader.hpp). `field` (a parameter path) and
// `file` name the source in error messages. Throws InputError listing every bad row: missing or non-numeric
// entries, negative or non-finite half-breadths, stations out of order, duplicate z within a station, too few
// stations or points.
OffsetsTable parseOffsetsCsv(std::string_view text, const std::string& field, const std::string& file = "");

// Multiplies every length of the table by `scale`.
OffsetsTable scaledOffsets(const OffsetsTable& table, double scale);

}  // namespace maris::ship
