// The acceleration spectral-ratio map H_a(x, f) along the reef flat (paper eq 30, Figs 13–14 and
// 23–24): per station and frequency the Fourier amplitude of the acceleration over that of the
// reference motion, twice the incident acceleration. Written twice:
//   - "spectral_ratio_map", long format (x/L, f, H_a,x, H_a,y; one row per station and frequency), the
//     data of the paper's heat maps, plottable as a colour map by x/L and f;
//   - "spectral_ratio_lines", wide format, H_a against f at x/L = −1/2, −1/4, 0, 1/4, 1/2 (stations
//     nearest to those points), which the GUI plots as lines.
// Frequencies: f ≤ f_cut where the input's spectrum exceeds 5 % of its peak (outside that band the
// ratio divides by almost nothing).
#include <algorithm>
#include <bit>
#include <cmath>

#include "core/spectrum.hpp"
#include "core/text_format.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

std::vector<double> timeRate(const std::vector<double>& u, double dt) {
  std::vector<double> v(u.size(), 0.0);
  for (std::size_t k = 1; k + 1 < u.size(); ++k) v[k] = (u[k + 1] - u[k - 1]) / (2.0 * dt);
  if (u.size() > 1) {
    v.front() = (u[1] - u[0]) / dt;
    v.back() = (u[u.size() - 1] - u[u.size() - 2]) / dt;
  }
  return v;
}

std::vector<double> fourierAmplitude(const std::vector<double>& a, double dt, std::size_t n_fft) {
  std::vector<std::complex<double>> z(n_fft, 0.0);
  for (std::size_t k = 0; k < a.size() && k < n_fft; ++k) z[k] = a[k];
  z = fft(std::move(z));
  std::vector<double> out(n_fft / 2 + 1);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = std::abs(z[k]) * dt;
  return out;
}

SpectralRatioMap spectralRatioMap(const FeCase& c, double cutoff_frequency, double band_fraction) {
  const double dt = c.time_step;
  const std::size_t n_fft = std::bit_ceil(c.incident.size());
  const auto a0 = fourierAmplitude(timeRate(timeRate(c.incident, dt), dt), dt, n_fft);
  const double a0_max = *std::max_element(a0.begin(), a0.end());
  SpectralRatioMap map;
  std::vector<std::size_t> bins;
  for (std::size_t k = 1; k < a0.size(); ++k) {
    const double f = k / (n_fft * dt);
    if (f > cutoff_frequency) break;
    if (a0[k] < band_fraction * a0_max) continue;
    bins.push_back(k);
    map.frequency.push_back(f);
  }
  for (std::size_t s = 0; s < c.ux.size(); ++s) {
    const auto sx = fourierAmplitude(timeRate(timeRate(c.ux[s], dt), dt), dt, n_fft);
    const auto sy = fourierAmplitude(timeRate(timeRate(c.uy[s], dt), dt), dt, n_fft);
    std::vector<double> hx, hy;
    for (std::size_t k : bins) {
      hx.push_back(sx[k] / (2.0 * a0[k]));
      hy.push_back(sy[k] / (2.0 * a0[k]));
    }
    map.hx.push_back(std::move(hx));
    map.hy.push_back(std::move(hy));
  }
  return map;
}

void addSpectralMap(const SeismicParameters& p, const FeCase& c, Results& results) {
  const SpectralRatioMap map = spectralRatioMap(c, p.cutoff_frequency, 0.05);
  if (map.frequency.empty() || c.station_x.empty()) return;
  const double length = p.model == "reef" ? p.flat_width : 1.0;

  // Long format: every station × frequency.
  std::vector<double> xl, f, hx, hy;
  for (std::size_t s = 0; s < c.station_x.size(); ++s)
    for (std::size_t k = 0; k < map.frequency.size(); ++k) {
      xl.push_back(c.station_x[s] / length);
      f.push_back(map.frequency[k]);
      hx.push_back(map.hx[s][k]);
      hy.push_back(map.hy[s][k]);
    }
  Table long_table{"spectral_ratio_map", "Spectral ratio map H_a(x, f) along the flat (one row per station and frequency)",
                   {}};
  long_table.add("x_over_L", "-", xl, "x/L");
  long_table.add("frequency", "Hz", f, "Frequency f");
  long_table.add("H_ax", "-", hx, "H_ax");
  long_table.add("H_ay", "-", hy, "H_ay");
  results.tables.push_back(std::move(long_table));

  // Wide format: H_a(f) at five points of the flat.
  Table lines{"spectral_ratio_lines", "Spectral ratios H_a(f) at x/L = -1/2, -1/4, 0, 1/4, 1/2", {}};
  lines.add("frequency", "Hz", map.frequency, "Frequency f");
  const std::pair<double, const char*> points[] = {
      {-0.5, "m050"}, {-0.25, "m025"}, {0.0, "p000"}, {0.25, "p025"}, {0.5, "p050"}};
  std::vector<std::string> x_names, y_names;
  for (const auto& [where, tag] : points) {
    std::size_t best = 0;
    for (std::size_t s = 1; s < c.station_x.size(); ++s)
      if (std::abs(c.station_x[s] / length - where) < std::abs(c.station_x[best] / length - where)) best = s;
    const std::string at = formatText(", x/L = %g", where);
    lines.add(std::string("Hax_x") + tag, "-", map.hx[best], "H_ax" + at);
    lines.add(std::string("Hay_x") + tag, "-", map.hy[best], "H_ay" + at);
    x_names.push_back(std::string("Hax_x") + tag);
    y_names.push_back(std::string("Hay_x") + tag);
  }
  results.tables.push_back(std::move(lines));
  results.plots.push_back({"spectral_ratio_lines_x", "Horizontal spectral ratio H_a,x(f) along the flat",
                           "spectral_ratio_lines", "frequency", x_names, false, false, "", {}});
  results.plots.push_back({"spectral_ratio_lines_y", "Vertical spectral ratio H_a,y(f) along the flat",
                           "spectral_ratio_lines", "frequency", y_names, false, false, "", {}});
}

}  // namespace maris::seismic
