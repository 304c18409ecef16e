#include "core/formats/tecplot.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/input_limits.hpp"

namespace maris::formats {

TecplotFile parseTecplot(std::string_view text, const std::string& field, const std::string& file) {
  auto fail = [&](int line, const std::string& what) {
    throw InputError(field, "\"" + echoText(file) + "\"", "line " + std::to_string(line) + ": " + what);
  };
  TecplotFile tec;
  int line = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    auto nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string row(text.substr(pos, nl - pos));
    pos = nl + 1;
    ++line;
    const auto first = row.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const char c = row[first];
    const bool numeric = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
    if (!numeric) {
      std::string upper = row;
      std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char ch) { return std::toupper(ch); });
      if (upper.find("VARIABLES") != std::string::npos) tec.variables = row;
      if (upper.compare(first, 4, "ZONE") == 0) tec.zones.push_back({row, line, {}});
      continue;  // column names continuing the VARIABLES line
    }
    if (tec.zones.empty()) fail(line, "numbers before the first Zone line");
    std::istringstream s(row);
    std::vector<double> values;
    double v = 0.0;
    while (s >> v) values.push_back(v);
    s.clear();
    if (!(s >> std::ws).eof()) fail(line, "cannot read a number in '" + echoText(row) + "'");
    auto& zone = tec.zones.back();
    if (!zone.rows.empty() && values.size() != zone.rows.front().size())
      fail(line, "expected " + std::to_string(zone.rows.front().size()) + " columns, found " + std::to_string(values.size()));
    if (!std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); })) fail(line, "non-finite value");
    zone.rows.push_back(std::move(values));
  }
  return tec;
}

}  // namespace maris::formats
