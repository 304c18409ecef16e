#include "core/formats/wamit.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "core/input_limits.hpp"

namespace maris::formats {

namespace {

struct LineReader {
  std::string_view text;
  std::size_t pos = 0;
  int number = 0;
  bool next(std::string& line) {
    if (pos >= text.size()) return false;
    auto nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    line.assign(text.substr(pos, nl - pos));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos = nl + 1;
    ++number;
    return true;
  }
};

bool blank(const std::string& s) { return s.find_first_not_of(" \t") == std::string::npos; }

[[noreturn]] void fail(const std::string& field, const std::string& file, int line, const std::string& what) {
  throw InputError(field, "\"" + echoText(file) + "\"",
                   (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + what);
}

// After "key" in `line`, the number that follows (skipping '=' and blanks).
bool valueAfter(const std::string& line, const std::string& key, double& value) {
  const auto at = line.find(key);
  if (at == std::string::npos) return false;
  std::istringstream s(line.substr(at + key.size()));
  s >> std::ws;
  if (s.peek() == '=' || s.peek() == ':') s.get();
  return static_cast<bool>(s >> value);
}

}  // namespace

std::vector<WamitCoefficientRow> parseWamit1(std::string_view text, const std::string& field, const std::string& file) {
  std::vector<WamitCoefficientRow> rows;
  LineReader in{text};
  std::string line;
  while (in.next(line)) {
    if (blank(line) || (in.number == 1 && line.find("WAMIT") != std::string::npos)) continue;
    std::istringstream s(line);
    WamitCoefficientRow r;
    r.line = in.number;
    if (!(s >> r.period >> r.i >> r.j >> r.added_mass))
      fail(field, file, in.number, "expected 'PER I J A [B]' (WAMIT .1), found '" + echoText(line) + "'");
    double b = 0.0;
    if (s >> b) r.damping = b;
    rows.push_back(r);
  }
  if (rows.empty()) fail(field, file, 0, "no rows (expected WAMIT .1 lines 'PER I J A [B]')");
  return rows;
}

std::vector<WamitExcitationRow> parseWamit3(std::string_view text, const std::string& field, const std::string& file) {
  std::vector<WamitExcitationRow> rows;
  LineReader in{text};
  std::string line;
  while (in.next(line)) {
    if (blank(line) || (in.number == 1 && line.find("WAMIT") != std::string::npos)) continue;
    std::istringstream s(line);
    WamitExcitationRow r;
    r.line = in.number;
    if (!(s >> r.period >> r.heading >> r.i >> r.modulus >> r.phase_deg >> r.re >> r.im))
      fail(field, file, in.number, "expected 'PER BETA I MOD PHA RE IM' (WAMIT .3), found '" + echoText(line) + "'");
    rows.push_back(r);
  }
  if (rows.empty()) fail(field, file, 0, "no rows (expected WAMIT .3 lines 'PER BETA I MOD PHA RE IM')");
  return rows;
}

WamitReport parseWamitOut(std::string_view text, const std::string& field, const std::string& file) {
  WamitReport report;
  bool gravity = false, length = false;
  report.water_depth = -1.0;
  LineReader in{text};
  std::string line;
  double period = std::nan("");
  enum class Table { none, coefficients, excitation } table = Table::none;
  double heading = 0.0;
  while (in.next(line)) {
    if (line.find("Gravity:") != std::string::npos) {
      gravity = valueAfter(line, "Gravity:", report.gravity);
      length = valueAfter(line, "Length scale:", report.length_scale);
    }
    if (line.find("Water depth:") != std::string::npos && line.find("infinite") == std::string::npos)
      valueAfter(line, "Water depth:", report.water_depth);
    if (line.find("Wave period") != std::string::npos) {
      table = Table::none;
      if (line.find("infinite") != std::string::npos) period = -1.0;  // as in .1 files: zero frequency
      else if (line.find("= zero") != std::string::npos) period = 0.0;  // infinite frequency
      else if (!valueAfter(line, "Wave period (sec)", period) || !(period > 0.0))
        fail(field, file, in.number, "cannot read the wave period from '" + echoText(line) + "'");
      continue;
    }
    if (line.find("ADDED-MASS") != std::string::npos) {
      table = Table::coefficients;
      continue;
    }
    if (line.find("EXCITING FORCES") != std::string::npos) {
      table = line.find("DIFFRACTION") != std::string::npos ? Table::excitation : Table::none;
      continue;
    }
    if (line.find("Wave Heading") != std::string::npos) {
      if (!valueAfter(line, "Wave Heading (deg) :", heading))
        fail(field, file, in.number, "cannot read the wave heading from '" + echoText(line) + "'");
      continue;
    }
    if (line.find("*****") != std::string::npos) table = Table::none;
    if (table == Table::none || blank(line)) continue;
    std::istringstream s(line);
    if (table == Table::coefficients) {
      WamitCoefficientRow r;
      r.line = in.number;
      r.period = period;
      if (!(s >> r.i >> r.j >> r.added_mass)) continue;  // the column titles "I J A(I,J) B(I,J)"
      double b = 0.0;
      if (s >> b) r.damping = b;
      if (std::isnan(period)) fail(field, file, in.number, "coefficients before any 'Wave period' line");
      report.coefficients.push_back(r);
    } else {
      WamitExcitationRow r;
      r.line = in.number;
      r.period = period;
      r.heading = heading;
      if (!(s >> r.i >> r.modulus >> r.phase_deg)) continue;  // column titles
      const double rad = r.phase_deg * std::numbers::pi / 180.0;
      r.re = r.modulus * std::cos(rad);
      r.im = r.modulus * std::sin(rad);
      report.excitation.push_back(r);
    }
  }
  if (!gravity || !length) fail(field, file, 0, "no 'Gravity: ... Length scale: ...' line (is this a WAMIT .out report?)");
  if (report.coefficients.empty()) fail(field, file, 0, "no 'ADDED-MASS' table (is this a WAMIT .out report?)");
  return report;
}

}  // namespace maris::formats
