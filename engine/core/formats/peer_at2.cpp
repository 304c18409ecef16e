#include "core/formats/peer_at2.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/errors.hpp"
#include "core/input_limits.hpp"

namespace maris::formats {

namespace {

std::optional<double> numberAt(const std::string& s, std::size_t pos) {
  pos = s.find_first_not_of(" \t=:,", pos);
  if (pos == std::string::npos) return std::nullopt;
  double v = 0.0;
  const char* first = s.data() + pos + (s[pos] == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(first, s.data() + s.size(), v);
  if (error != std::errc()) return std::nullopt;
  return v;
}

}  // namespace

PeerRecord parsePeerAt2(std::string_view text, const std::string& field, const std::string& file) {
  const std::string value = "\"" + echoText(file) + "\"";
  auto fail = [&](int line, const std::string& what) {
    throw InputError(field, value,
                     (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + what +
                         " (a PEER .AT2 record: header lines, NPTS and DT, then accelerations in g)");
  };
  PeerRecord rec;
  std::size_t npts = 0;
  bool have_header = false;
  std::vector<std::string> header;
  int line = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    auto nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string row(text.substr(pos, nl - pos));
    pos = nl + 1;
    ++line;
    if (!row.empty() && row.back() == '\r') row.pop_back();
    if (!have_header) {
      std::string upper = row;
      std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
      const auto at_n = upper.find("NPTS"), at_dt = upper.find("DT");
      if (at_n == std::string::npos || at_dt == std::string::npos) {
        if (line > 6) fail(line, "no NPTS/DT line in the first 6 lines");
        header.push_back(row);
        continue;
      }
      // "NPTS= n, DT= d SEC" (values after the keys) or "n d NPTS, DT" (values before).
      std::optional<double> n, dt;
      if (at_n < at_dt && upper.find_first_not_of(" \t") == at_n) {
        n = numberAt(row, at_n + 4);
        dt = numberAt(row, at_dt + 2);
      } else {
        n = numberAt(row, 0);
        const auto after = row.find_first_of(" \t", row.find_first_not_of(" \t"));
        if (after != std::string::npos) dt = numberAt(row, after);
      }
      if (!n || !dt || !(*n >= 1.0) || *n != std::floor(*n) || !(*dt > 0.0) || !std::isfinite(*dt))
        fail(line, "cannot read NPTS (a positive whole number) and DT (a positive step in s) from \"" + echoText(row) + "\"");
      if (*n > static_cast<double>(InputLimits::kDataRows) * 10.0) fail(line, "NPTS is beyond the data limit");
      npts = static_cast<std::size_t>(*n);
      rec.dt = *dt;
      have_header = true;
      rec.acceleration.reserve(npts);
      continue;
    }
    std::size_t at = 0;
    while ((at = row.find_first_not_of(" \t", at)) != std::string::npos) {
      const auto end = row.find_first_of(" \t", at);
      const std::string cell = row.substr(at, end == std::string::npos ? std::string::npos : end - at);
      double v = 0.0;
      const char* first = cell.data() + (cell.front() == '+' ? 1 : 0);
      const auto [stop, error] = std::from_chars(first, cell.data() + cell.size(), v);
      if (error != std::errc() || stop != cell.data() + cell.size() || !std::isfinite(v))
        fail(line, "expected an acceleration in g, found \"" + echoText(cell) + "\"");
      if (rec.acceleration.size() == npts) fail(line, "more values than NPTS = " + std::to_string(npts));
      rec.acceleration.push_back(v * kStandardGravity);
      at = end;
    }
  }
  if (!have_header) fail(0, "no NPTS/DT line");
  if (rec.acceleration.size() != npts)
    fail(0, "NPTS = " + std::to_string(npts) + " but the file holds " + std::to_string(rec.acceleration.size()) + " values");
  for (const auto& h : header)
    if (h.find(',') != std::string::npos && rec.title.empty()) rec.title = h;
  if (rec.title.empty() && !header.empty()) rec.title = header.front();
  return rec;
}

}  // namespace maris::formats
