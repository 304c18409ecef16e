// Tecplot ASCII data files as Nemoh (v2, v3) writes its results (RadiationCoefficients.tec,
// ExcitationForce.tec, ...) and Capytaine exports them (capytaine.io.legacy.write_dataset_as_tecplot_files):
// a VARIABLES line and its continuation lines of quoted column names, then zones, each a line
// "Zone t="<title>",I= <n>,F=POINT" followed by rows of numbers (POINT layout: one row per point).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace maris::formats {

struct TecplotZone {
  std::string title;  // the whole zone line
  int line = 0;       // its line in the file
  std::vector<std::vector<double>> rows;
};

struct TecplotFile {
  std::string variables;  // the VARIABLES line
  std::vector<TecplotZone> zones;
};

// Throws InputError(field, "file", "line N: ...") on numbers before the first zone, rows of differing
// length within a zone, or a value that is not a finite number.
TecplotFile parseTecplot(std::string_view text, const std::string& field, const std::string& file);

}  // namespace maris::formats
