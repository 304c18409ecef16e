// Reference points for comparison and calibration: the numbers printed in the text of Zhang, Song,
// Li, Su & Ding (square cylinder near a free surface; resources/data/fiv/paper_points.csv, each row
// commented with its section) or a user CSV of the same layout:
//   flow_speed [m/s], submergence_ratio [-] (inf = no free surface), amplitude [m], amplitude_sigma [m],
//   frequency [Hz], frequency_sigma [Hz], power [W], power_sigma [W]
// A names row, an optional units row, '#' comment lines; an empty cell means "not given".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/table_reader.hpp"

namespace maris::fiv {

struct ReferencePoint {
  double speed = 0.0;              // [m/s] U
  double submergence_ratio = 0.0;  // [-] h* (infinite: single phase)
  std::optional<double> amplitude, amplitude_sigma;  // [m]
  std::optional<double> frequency, frequency_sigma;  // [Hz]
  std::optional<double> power, power_sigma;          // [W]
};

// Parses the CSV text; throws InputError naming `origin`, the line and the column on bad content.
std::vector<ReferencePoint> parseReferencePoints(const std::string& csv_text, const std::string& origin);

// The built-in paper set, or the file when `file` is non-empty.
std::vector<ReferencePoint> loadReferencePoints(const std::string& file);

// Label of an h* value for column names: "h1.11", "hinf".
std::string submergenceLabel(double submergence_ratio);

// The shared table reader (core/table_reader.hpp) with the fiv conventions: empty cell = not given, "inf" read.
TextTable parseNumericCsv(const std::string& text, const TableSpec& spec);

}  // namespace maris::fiv
