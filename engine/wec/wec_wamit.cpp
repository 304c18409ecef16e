#include "wec/wec_wamit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "core/resources.hpp"

namespace maris::wec {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, int line, const std::string& what) {
  throw InputError("hydro.wamit_stem", "\"" + file.string() + "\"",
                   (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + what);
}

std::istringstream openFile(const std::filesystem::path& file) {
  return std::istringstream(readDataText(file.string(), "wec", "parameters.hydro.wamit_stem"));
}

// Rows keyed by period (rounded to 1e-9 s to merge the .1 and .3 keys).
long long periodKey(double period) { return std::llround(period * 1e9); }

}  // namespace

std::shared_ptr<TabulatedHydro> readWamit(const std::filesystem::path& stem, double density, double gravity,
                                          double length_scale) {
  const double l3 = std::pow(length_scale, 3), l2 = length_scale * length_scale;
  std::map<long long, TabulatedHydro::Row> rows;
  double a_inf_surge = std::nan(""), a_inf_heave = std::nan("");

  // Added mass and damping.
  const auto file1 = std::filesystem::path(stem.string() + ".1");
  auto in1 = openFile(file1);
  std::string text;
  int line = 0;
  while (std::getline(in1, text)) {
    ++line;
    std::istringstream s(text);
    double per = 0.0, a = 0.0, b = 0.0;
    int i = 0, j = 0;
    if (!(s >> per >> i >> j >> a)) {
      if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
      fail(file1, line, "expected 'PER I J A [B]', found '" + text + "'");
    }
    if (i != j || (i != 1 && i != 3)) continue;
    if (per == 0.0) {  // infinite frequency
      (i == 1 ? a_inf_surge : a_inf_heave) = a * density * l3;
      continue;
    }
    if (per < 0.0) continue;  // zero frequency: not needed
    if (!(s >> b)) fail(file1, line, "damping coefficient missing");
    const double omega = 2.0 * std::numbers::pi / per;
    auto& r = rows[periodKey(per)];
    r.omega = omega;
    auto& mode = i == 1 ? r.hydro.surge : r.hydro.heave;
    mode.added_mass = a * density * l3;
    mode.damping = b * density * omega * l3;
  }
  if (rows.empty()) fail(file1, 0, "no surge or heave rows with a positive period");

  // Excitation, heading 0.
  const auto file3 = std::filesystem::path(stem.string() + ".3");
  auto in3 = openFile(file3);
  line = 0;
  while (std::getline(in3, text)) {
    ++line;
    std::istringstream s(text);
    double per = 0.0, beta = 0.0, mod = 0.0, pha = 0.0, re = 0.0, im = 0.0;
    int i = 0;
    if (!(s >> per >> beta >> i >> mod >> pha >> re >> im)) {
      if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
      fail(file3, line, "expected 'PER BETA I MOD PHA RE IM', found '" + text + "'");
    }
    if ((i != 1 && i != 3) || std::abs(beta) > 1e-6 || per <= 0.0) continue;
    auto it = rows.find(periodKey(per));
    if (it == rows.end()) fail(file3, line, "period " + std::to_string(per) + " s is not in " + file1.string());
    (i == 1 ? it->second.hydro.surge : it->second.hydro.heave).excitation = Complex(re, im) * density * gravity * l2;
  }
  std::vector<TabulatedHydro::Row> list;
  for (auto& [key, r] : rows) list.push_back(r);
  // Without a PER = 0 row, A at the highest frequency stands in for A∞.
  const auto& last = *std::max_element(list.begin(), list.end(),
                                       [](const auto& a, const auto& b) { return a.omega < b.omega; });
  if (std::isnan(a_inf_surge)) a_inf_surge = last.hydro.surge.added_mass;
  if (std::isnan(a_inf_heave)) a_inf_heave = last.hydro.heave.added_mass;
  return std::make_shared<TabulatedHydro>(std::move(list), a_inf_surge, a_inf_heave,
                                          "WAMIT files " + stem.string() + ".1/.3");
}

void convertFromEMinusIwt(std::vector<TabulatedHydro::Row>& rows) {
  for (auto& r : rows) {
    r.hydro.surge.excitation = fromEMinusIwt(r.hydro.surge.excitation);
    r.hydro.heave.excitation = fromEMinusIwt(r.hydro.heave.excitation);
  }
}

}  // namespace maris::wec
