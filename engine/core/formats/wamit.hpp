// WAMIT output (WAMIT User Manual v7, ch. 4), read as the files hold it (non-dimensional, WAMIT's conventions);
// dimensionalising and choosing modes is the caller's business.
//   .1    added mass and damping:  PER  I  J  Ā(I,J)  [B̄(I,J)]   (PER = 0: infinite frequency, PER < 0: zero
//         frequency; both without B̄)
//   .3    diffraction excitation:  PER  β  I  |X̄|  phase[deg]  Re X̄  Im X̄
//   .out  the text report: gravity, length scale, water depth, and for each wave period the tables
//         "ADDED-MASS AND DAMPING COEFFICIENTS" (I J A B) and "DIFFRACTION EXCITING FORCES AND MOMENTS"
//         (per wave heading: I |X̄| phase[deg]).
// Numeric files may start with WAMIT's "WAMIT Numeric Output -- Filename ..." line. Errors name field, file
// and line.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace maris::formats {

struct WamitCoefficientRow {  // one line of a .1 file
  int line = 0;               // in the file
  double period = 0.0;        // [s]; 0 = infinite frequency, < 0 = zero frequency
  int i = 0, j = 0;
  double added_mass = 0.0;
  std::optional<double> damping;
};

struct WamitExcitationRow {  // one line of a .3 file
  int line = 0;              // in the file
  double period = 0.0;       // [s]
  double heading = 0.0;      // [deg]
  int i = 0;
  double modulus = 0.0, phase_deg = 0.0, re = 0.0, im = 0.0;
};

std::vector<WamitCoefficientRow> parseWamit1(std::string_view text, const std::string& field, const std::string& file);
std::vector<WamitExcitationRow> parseWamit3(std::string_view text, const std::string& field, const std::string& file);

struct WamitReport {
  double gravity = 0.0, length_scale = 0.0, water_depth = 0.0;  // water_depth < 0: infinite
  std::vector<WamitCoefficientRow> coefficients;  // the .1 rows the report holds (same conventions)
  std::vector<WamitExcitationRow> excitation;     // modulus and phase only (re, im computed from them)
};

WamitReport parseWamitOut(std::string_view text, const std::string& field, const std::string& file);

}  // namespace maris::formats
