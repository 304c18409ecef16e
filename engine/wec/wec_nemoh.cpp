#include "wec/wec_nemoh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "core/formats/tecplot.hpp"
#include "core/resources.hpp"
#include "wec/wec_radiation.hpp"
#include "core/text_format.hpp"

namespace maris::wec {

namespace {

[[noreturn]] void failNemohFile(const std::filesystem::path& file, int line, const std::string& what) {
  throw InputError("hydro.nemoh_directory", "\"" + file.parent_path().string() + "\"",
                   file.filename().string() + (line > 0 ? " line " + std::to_string(line) : std::string()) + ": " +
                       what);
}

using Zone = formats::TecplotZone;
using TecFile = formats::TecplotFile;

// Through the input gate, then the shared Tecplot reader; errors name the file and line.
TecFile readTec(const std::filesystem::path& file) {
  return formats::parseTecplot(readDataText(file.string(), "wec", "parameters.hydro.nemoh_directory"),
                               "hydro.nemoh_directory", file.string());
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

// A∞ of one coefficient entry from its table (ω rows, A, B): Ogilvie over the middle of the band, plus the
// Kramers–Kronig contribution of B beyond the last row,
//   ΔA∞(ω) = −(2/π) ∫_{ω_max}^∞ B(ω')/(ω'² − ω²) dω',
// with B continued by the power law through the last two rows (exponent clamped to [1, 8]): a table cut off
// where B is still large would otherwise bias A∞. Half of that tail term is added to the error bar.
// Interpolation as TabulatedHydro / CoupledHydro (PCHIP with an ω = 0 anchor: A held, B = 0).
OgilvieEstimate tableAddedMassInfinity(const std::vector<double>& omega, const std::vector<double>& a,
                                       const std::vector<double>& b) {
  std::vector<double> w{0.0}, av{a.front()}, bv{0.0};
  w.insert(w.end(), omega.begin(), omega.end());
  av.insert(av.end(), a.begin(), a.end());
  bv.insert(bv.end(), b.begin(), b.end());
  const MonotoneCubic a_of(w, av), b_of(w, bv);
  const std::size_t n = omega.size();
  const double w_max = omega[n - 1], w_before = omega[n - 2], b2 = b[n - 1], b1 = b[n - 2];
  const double lo = std::max(omega.front(), 0.25 * w_max), hi = 0.75 * w_max;
  const double slope = b1 > 0.0 && b2 > 0.0 ? -std::log(b2 / b1) / std::log(w_max / w_before) : 8.0;
  const double power = std::clamp(slope, 1.0, 8.0);
  // With u = ω_max/ω' the tail integral is ∫₀¹ b2 u^p ω_max/(ω_max² − ω²u²) du (smooth; midpoint rule).
  auto tail = [&](double x) {
    constexpr int m = 400;
    double sum = 0.0;
    for (int i = 0; i < m; ++i) {
      const double u = (i + 0.5) / m;
      sum += b2 * std::pow(u, power) * w_max / (w_max * w_max - x * x * u * u) / m;
    }
    return -2.0 / std::numbers::pi * sum;
  };
  OgilvieEstimate e = ogilvieAddedMassInfinityOverBand([&](double x) { return b_of(x); },
                                                       [&](double x) { return a_of(x) + tail(x); }, w_max, lo, hi);
  e.spread += 0.5 * std::abs(tail(0.5 * (lo + hi)));
  return e;
}

}  // namespace

NemohImport readNemoh(const std::filesystem::path& directory) {
  const auto rad_file = directory / "RadiationCoefficients.tec";
  const auto exc_file = directory / "ExcitationForce.tec";
  const TecFile rad = readTec(rad_file);
  const TecFile exc = readTec(exc_file);

  // Bodies in the file; our DoF index of (body b, Nemoh DoF 1 or 3) is 2(b − 1) + (0 surge, 1 heave), and its
  // column pair in a row is (2g − 1, 2g) with g = 6(b − 1) + DoF the global Nemoh DoF.
  int bodies = 0;
  for (const auto& z : rad.zones) bodies = std::max(bodies, numberAfter(z.title, "body"));
  if (bodies < 1) failNemohFile(rad_file, 0, "no zone 'Motion of body 1 in DoF 1'");
  const int nd = 2 * bodies;
  auto global = [](int body, int dof) { return 6 * (body - 1) + dof; };
  std::map<long long, CoupledHydro::Row> rows;
  std::vector<bool> seen(static_cast<std::size_t>(nd), false);
  for (const auto& z : rad.zones) {
    const int body = numberAfter(z.title, "body"), dof = numberAfter(z.title, "DoF");
    if (body < 1 || (dof != 1 && dof != 3)) continue;
    const int col = 2 * (body - 1) + (dof == 3 ? 1 : 0);
    seen[static_cast<std::size_t>(col)] = true;
    for (std::size_t k = 0; k < z.rows.size(); ++k) {
      const auto& r = z.rows[k];
      const int line = z.line + 1 + static_cast<int>(k);
      if (r.size() < static_cast<std::size_t>(2 * global(bodies, 3) + 1))
        failNemohFile(rad_file, line, "row too short for DoF 3 of body " + std::to_string(bodies));
      const double omega = toOmega(rad.variables, r[0]);
      if (!(omega > 0.0)) failNemohFile(rad_file, line, "frequency must be positive");
      auto& row = rows[omegaKey(omega)];
      if (row.added_mass.size() == 0) {
        row.omega = omega;
        row.added_mass = row.damping = Eigen::MatrixXd::Zero(nd, nd);
        row.excitation = Eigen::VectorXcd::Zero(nd);
      }
      for (int b = 1; b <= bodies; ++b)
        for (int d : {1, 3}) {
          const int g = global(b, d), rdof = 2 * (b - 1) + (d == 3 ? 1 : 0);
          row.added_mass(rdof, col) = r[static_cast<std::size_t>(2 * g - 1)];
          row.damping(rdof, col) = r[static_cast<std::size_t>(2 * g)];
        }
    }
  }
  for (int i = 0; i < nd; ++i)
    if (!seen[static_cast<std::size_t>(i)])
      failNemohFile(rad_file, 0, "no zone 'Motion of body " + std::to_string(i / 2 + 1) + " in DoF " + (i % 2 ? "3" : "1") + "'");

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
  if (!heading) failNemohFile(exc_file, 0, "no excitation zone");
  std::size_t matched = 0;
  for (std::size_t k = 0; k < heading->rows.size(); ++k) {
    const auto& r = heading->rows[k];
    const int line = heading->line + 1 + static_cast<int>(k);
    if (r.size() < static_cast<std::size_t>(2 * global(bodies, 3) + 1))
      failNemohFile(exc_file, line, "row too short for DoF 3 of body " + std::to_string(bodies) +
                               " (need w and magnitude/phase pairs)");
    // Same frequency as a radiation row to 1e-6 relative (the two files may print different digits).
    const double omega = toOmega(exc.variables, r[0]);
    auto it = rows.lower_bound(omegaKey(omega * (1.0 - 1e-6)));
    if (it != rows.end() && std::abs(it->second.omega - omega) > 1e-6 * omega) it = rows.end();
    if (it == rows.end()) failNemohFile(exc_file, line, "frequency " + numberText(r[0]) + " is not in RadiationCoefficients.tec");
    // e^{−iωt} amplitudes → e^{+iωt} (conjugate).
    for (int b = 1; b <= bodies; ++b)
      for (int d : {1, 3}) {
        const int g = global(b, d);
        it->second.excitation[2 * (b - 1) + (d == 3 ? 1 : 0)] =
            fromEMinusIwt(std::polar(r[static_cast<std::size_t>(2 * g - 1)], r[static_cast<std::size_t>(2 * g)]));
      }
    ++matched;
  }
  if (matched != rows.size())
    failNemohFile(exc_file, heading->line, std::to_string(rows.size() - matched) + " radiation frequencies have no excitation row");
  if (rows.size() < 4) failNemohFile(rad_file, 0, "need at least 4 frequencies, found " + std::to_string(rows.size()));

  // A∞ of every entry by Ogilvie (Nemoh writes none); the error bars reported are the largest of the diagonal.
  std::vector<double> w;
  for (const auto& [key, r] : rows) w.push_back(r.omega);
  Eigen::MatrixXd a_inf(nd, nd);
  NemohImport out;
  for (int i = 0; i < nd; ++i)
    for (int j = 0; j < nd; ++j) {
      std::vector<double> a, b;
      for (const auto& [key, r] : rows) {
        a.push_back(r.added_mass(i, j));
        b.push_back(r.damping(i, j));
      }
      const OgilvieEstimate e = tableAddedMassInfinity(w, a, b);
      a_inf(i, j) = e.a_inf;
      if (i == j) (i % 2 ? out.a_inf_spread_heave : out.a_inf_spread_surge) =
          std::max(i % 2 ? out.a_inf_spread_heave : out.a_inf_spread_surge, e.spread);
    }
  const std::string source = "Nemoh files " + directory.string();
  if (bodies == 1) {
    std::vector<TabulatedHydro::Row> list;
    for (const auto& [key, r] : rows) {
      TabulatedHydro::Row t;
      t.omega = r.omega;
      t.hydro.surge = {r.added_mass(0, 0), r.damping(0, 0), r.excitation[0]};
      t.hydro.heave = {r.added_mass(1, 1), r.damping(1, 1), r.excitation[1]};
      list.push_back(t);
    }
    out.hydro = std::make_shared<TabulatedHydro>(std::move(list), a_inf(0, 0), a_inf(1, 1), source);
  } else {
    std::vector<CoupledHydro::Row> list;
    for (auto& [key, r] : rows) list.push_back(std::move(r));
    // A passive BEM solution is symmetric; average the two triangles so that round-off in the files does not
    // make the mass matrix of the time domain non-symmetric.
    a_inf = 0.5 * (a_inf + a_inf.transpose()).eval();
    out.coupled = std::make_shared<CoupledHydro>(std::move(list), a_inf, source + " (" + std::to_string(bodies) + " bodies)");
  }
  return out;
}

}  // namespace maris::wec
