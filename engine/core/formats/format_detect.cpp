#include "core/formats/format_detect.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace maris::formats {

namespace {

// The first `count` lines of `text`, upper-cased, each without its line end.
std::vector<std::string> headLines(std::string_view text, std::size_t count) {
  std::vector<std::string> lines;
  std::size_t pos = 0;
  while (lines.size() < count && pos < text.size()) {
    const auto nl = text.find('\n', pos);
    std::string line(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
    std::transform(line.begin(), line.end(), line.begin(), [](unsigned char c) { return std::toupper(c); });
    lines.push_back(std::move(line));
    if (nl == std::string_view::npos) break;
    pos = nl + 1;
  }
  return lines;
}

bool startsWithWord(const std::string& line, std::string_view word) {
  const auto first = line.find_first_not_of(" \t\"");
  return first != std::string::npos && line.compare(first, word.size(), word) == 0;
}

}  // namespace

FileFormat detectFormat(std::string_view text) {
  if (text.substr(0, 3) == "CDF" || text.substr(0, 4) == "\x89HDF") return FileFormat::netcdf;
  const auto lines = headLines(text, 40);
  for (std::size_t k = 0; k < lines.size() && k < 6; ++k)
    if (lines[k].find("NPTS") != std::string::npos && lines[k].find("DT") != std::string::npos)
      return FileFormat::peer_at2;
  if (!lines.empty() && lines.front().find("WAMIT NUMERIC OUTPUT") != std::string::npos) return FileFormat::wamit_numeric;
  for (const auto& line : lines) {
    if (startsWithWord(line, "VARIABLES") || startsWithWord(line, "ZONE T=")) return FileFormat::tecplot;
    if (line.find("WAMIT") != std::string::npos && line.find("VERSION") != std::string::npos) return FileFormat::wamit_out;
  }
  return FileFormat::table;
}

std::string formatName(FileFormat format) {
  switch (format) {
    case FileFormat::table: return "";
    case FileFormat::peer_at2: return "a PEER NGA .AT2 accelerogram";
    case FileFormat::wamit_numeric: return "WAMIT numeric output (.1, .3)";
    case FileFormat::wamit_out: return "a WAMIT report (.out)";
    case FileFormat::tecplot: return "a Tecplot file (Nemoh or Capytaine output)";
    case FileFormat::netcdf: return "a NetCDF/HDF5 file (such as Capytaine's dataset)";
  }
  return "";
}

}  // namespace maris::formats
