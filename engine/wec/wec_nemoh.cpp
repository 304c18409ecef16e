#include "wec/wec_nemoh.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "wec/wec_radiation.hpp"

namespace maris::wec {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, int line, const std::string& what) {
  throw InputError("hydro.nemoh_directory", "\"" + file.parent_path().string() + "\"",
                   file.filename().string() + (line > 0 ? " line " + std::to_string(line) : std::string()) + ": " +
                       what);
}

// One Tecplot zone: its title and its numeric rows (first column = frequency variable).
struct Zone {
  std::string title;
  int line = 0;  // line of the zone header
  std::vector<std::vector<double>> rows;
};

struct TecFile {
  std::string variables;  // text of the VARIABLES line
  std::vector<Zone> zones;
};

bool isBlank(const std::string& s) { return s.find_first_not_of(" \t\r") == std::string::npos; }

TecFile readTec(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail(file, 0, "cannot open " + file.string());
  TecFile tec;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (isBlank(text)) continue;
    const auto first = text.find_first_not_of(" \t");
    const char c = text[first];
    const bool numeric = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
    if (!numeric) {
      std::string upper = text;
      std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char ch) { return std::toupper(ch); });
      if (upper.find("VARIABLES") != std::string::npos) tec.variables = text;
      if (upper.compare(first, 4, "ZONE") == 0) tec.zones.push_back({text, line, {}});
      continue;  // column-name lines of the header
    }
    if (tec.zones.empty()) fail(file, line, "numbers before the first Zone line");
    std::istringstream s(text);
    std::vector<double> row;
    double v = 0.0;
    while (s >> v) row.push_back(v);
    if (!s.eof()) fail(file, line, "cannot read a number in '" + text + "'");
    if (!tec.zones.back().rows.empty() && row.size() != tec.zones.back().rows.front().size())
      fail(file, line, "expected " + std::to_string(tec.zones.back().rows.front().size()) + " columns, found " +
                           std::to_string(row.size()));
    if (!std::all_of(row.begin(), row.end(), [](double x) { return std::isfinite(x); }))
      fail(file, line, "non-finite value");
    tec.zones.back().rows.push_back(std::move(row));
  }
  return tec;
}

// Integers that follow `word` in a zone title ("Motion of body 1 in DoF 3" → body 1, DoF 3).
int numberAfter(const std::string& title, const std::string& word) {
  const auto at = title.find(word);
  if (at == std::string::npos) return -1;
  std::istringstream s(title.substr(at + word.size()));
  int n = -1;
  s >> n;
  return s ? n : -1;
}

// Converts the first column to ω [rad/s] from what the VARIABLES line says it is.
double toOmega(const std::string& variables, double value) {
  if (variables.find("(Hz)") != std::string::npos) return 2.0 * std::numbers::pi * value;
  if (variables.find("(s)") != std::string::npos && variables.find("rad/s") == std::string::npos)
    return 2.0 * std::numbers::pi / value;
  return value;
}

long long omegaKey(double omega) { return std::llround(omega * 1e9); }

}  // namespace

NemohImport readNemoh(const std::filesystem::path& directory) {
  const auto rad_file = directory / "RadiationCoefficients.tec";
  const auto exc_file = directory / "ExcitationForce.tec";
  const TecFile rad = readTec(rad_file);
  const TecFile exc = readTec(exc_file);
  std::map<long long, TabulatedHydro::Row> rows;

  // Radiation: zones of body 1, DoF 1 (surge) and 3 (heave); the diagonal pair sits at columns 2i−1, 2i.
  bool have_surge = false, have_heave = false;
  for (const auto& z : rad.zones) {
    const int body = numberAfter(z.title, "body"), dof = numberAfter(z.title, "DoF");
    if (body != 1 || (dof != 1 && dof != 3)) continue;
    (dof == 1 ? have_surge : have_heave) = true;
    for (std::size_t k = 0; k < z.rows.size(); ++k) {
      const auto& r = z.rows[k];
      if (r.size() < static_cast<std::size_t>(2 * dof + 1))
        fail(rad_file, z.line + 1 + static_cast<int>(k), "row too short for DoF " + std::to_string(dof));
      const double omega = toOmega(rad.variables, r[0]);
      if (!(omega > 0.0)) fail(rad_file, z.line + 1 + static_cast<int>(k), "frequency must be positive");
      auto& row = rows[omegaKey(omega)];
      row.omega = omega;
      auto& mode = dof == 1 ? row.hydro.surge : row.hydro.heave;
      mode.added_mass = r[2 * dof - 1];
      mode.damping = r[2 * dof];
    }
  }
  if (!have_surge || !have_heave)
    fail(rad_file, 0, std::string("no zone 'Motion of body 1 in DoF ") + (have_surge ? "3" : "1") + "'");

  // Excitation: the zone of heading 0 (the first one if none says beta = 0).
  const Zone* heading = nullptr;
  for (const auto& z : exc.zones) {
    const auto eq = z.title.find("beta");
    if (eq == std::string::npos) continue;
    std::istringstream s(z.title.substr(z.title.find('=', eq) + 1));
    double beta = 1.0;
    if (s >> beta && std::abs(beta) < 1e-6) heading = &z;
  }
  if (!heading && !exc.zones.empty()) heading = &exc.zones.front();
  if (!heading) fail(exc_file, 0, "no excitation zone");
  std::size_t matched = 0;
  for (std::size_t k = 0; k < heading->rows.size(); ++k) {
    const auto& r = heading->rows[k];
    const int line = heading->line + 1 + static_cast<int>(k);
    if (r.size() < 7) fail(exc_file, line, "row too short for DoF 3 (need w and 3 magnitude/phase pairs)");
    // Same frequency as a radiation row to 1e-6 relative (the two files may print different digits).
    const double omega = toOmega(exc.variables, r[0]);
    auto it = rows.lower_bound(omegaKey(omega * (1.0 - 1e-6)));
    if (it != rows.end() && std::abs(it->second.omega - omega) > 1e-6 * omega) it = rows.end();
    if (it == rows.end()) fail(exc_file, line, "frequency " + std::to_string(r[0]) + " is not in RadiationCoefficients.tec");
    // e^{−iωt} amplitudes → e^{+iωt} (conjugate).
    it->second.hydro.surge.excitation = fromEMinusIwt(std::polar(r[1], r[2]));
    it->second.hydro.heave.excitation = fromEMinusIwt(std::polar(r[5], r[6]));
    ++matched;
  }
  if (matched != rows.size())
    fail(exc_file, heading->line, std::to_string(rows.size() - matched) + " radiation frequencies have no excitation row");

  std::vector<TabulatedHydro::Row> list;
  for (auto& [key, r] : rows) list.push_back(r);
  if (list.size() < 4) fail(rad_file, 0, "need at least 4 frequencies, found " + std::to_string(list.size()));

  // A∞ by Ogilvie over the middle of the table, plus the Kramers–Kronig contribution of B beyond the last row,
  //   ΔA∞(ω) = −(2/π) ∫_{ω_max}^∞ B(ω')/(ω'² − ω²) dω',
  // with B continued by the power law through the last two rows (exponent clamped to [1, 8]): a table cut off
  // where B is still large would otherwise bias A∞. Half of that tail term is added to the error bar.
  const std::string source = "Nemoh files " + directory.string();
  const TabulatedHydro provisional(list, 0.0, 0.0, source);
  const auto& last = list.back();
  const auto& before = list[list.size() - 2];
  const double w_max = last.omega, w_min = list.front().omega;
  const double lo = std::max(w_min, 0.25 * w_max), hi = 0.75 * w_max;
  auto estimate = [&](bool heave) {
    const double b1 = heave ? before.hydro.heave.damping : before.hydro.surge.damping;
    const double b2 = heave ? last.hydro.heave.damping : last.hydro.surge.damping;
    const double slope = b1 > 0.0 && b2 > 0.0 ? -std::log(b2 / b1) / std::log(last.omega / before.omega) : 8.0;
    const double power = std::clamp(slope, 1.0, 8.0);
    // With u = ω_max/ω' the tail integral is ∫₀¹ b2 u^p ω_max/(ω_max² − ω²u²) du (smooth; midpoint rule).
    auto tail = [&](double w) {
      constexpr int n = 400;
      double sum = 0.0;
      for (int i = 0; i < n; ++i) {
        const double u = (i + 0.5) / n;
        sum += b2 * std::pow(u, power) * w_max / (w_max * w_max - w * w * u * u) / n;
      }
      return -2.0 / std::numbers::pi * sum;
    };
    OgilvieEstimate e = ogilvieAddedMassInfinityOverBand(
        [&](double w) { return heave ? provisional.at(w).heave.damping : provisional.at(w).surge.damping; },
        [&](double w) {
          return (heave ? provisional.at(w).heave.added_mass : provisional.at(w).surge.added_mass) + tail(w);
        },
        w_max, lo, hi);
    e.spread += 0.5 * std::abs(tail(0.5 * (lo + hi)));
    return e;
  };
  const OgilvieEstimate surge = estimate(false), heave = estimate(true);
  NemohImport out;
  out.hydro = std::make_shared<TabulatedHydro>(std::move(list), surge.a_inf, heave.a_inf, source);
  out.a_inf_spread_surge = surge.spread;
  out.a_inf_spread_heave = heave.spread;
  return out;
}

}  // namespace maris::wec
