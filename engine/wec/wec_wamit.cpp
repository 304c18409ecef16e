#include "wec/wec_wamit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/errors.hpp"
#include "core/formats/wamit.hpp"
#include "core/resources.hpp"
#include "core/text_format.hpp"

namespace maris::wec {

namespace {

[[noreturn]] void failWamitFile(const std::filesystem::path& file, int line, const std::string& what) {
  throw InputError("hydro.wamit_stem", "\"" + file.string() + "\"",
                   (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + what);
}

std::string readFile(const std::filesystem::path& file) {
  return readDataText(file.string(), "wec", "parameters.hydro.wamit_stem");
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
  for (const auto& r : formats::parseWamit1(readFile(file1), "hydro.wamit_stem", file1.string())) {
    if (r.i != r.j || (r.i != 1 && r.i != 3)) continue;
    if (r.period == 0.0) {  // infinite frequency
      (r.i == 1 ? a_inf_surge : a_inf_heave) = r.added_mass * density * l3;
      continue;
    }
    if (r.period < 0.0) continue;  // zero frequency: not needed
    if (!r.damping) failWamitFile(file1, r.line, "damping coefficient missing");
    const double omega = 2.0 * std::numbers::pi / r.period;
    auto& row = rows[periodKey(r.period)];
    row.omega = omega;
    auto& mode = r.i == 1 ? row.hydro.surge : row.hydro.heave;
    mode.added_mass = r.added_mass * density * l3;
    mode.damping = *r.damping * density * omega * l3;
  }
  if (rows.empty()) failWamitFile(file1, 0, "no surge or heave rows with a positive period");

  // Excitation, heading 0.
  const auto file3 = std::filesystem::path(stem.string() + ".3");
  for (const auto& r : formats::parseWamit3(readFile(file3), "hydro.wamit_stem", file3.string())) {
    if ((r.i != 1 && r.i != 3) || std::abs(r.heading) > 1e-6 || r.period <= 0.0) continue;
    auto it = rows.find(periodKey(r.period));
    if (it == rows.end()) failWamitFile(file3, r.line, "period " + numberText(r.period) + " s is not in " + file1.string());
    (r.i == 1 ? it->second.hydro.surge : it->second.hydro.heave).excitation =
        Complex(r.re, r.im) * density * gravity * l2;
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
