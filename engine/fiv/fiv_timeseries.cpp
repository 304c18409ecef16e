#include "fiv/fiv_timeseries.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "core/spectrum.hpp"
#include "fiv/fiv_reference.hpp"
#include "fiv/fiv_theory.hpp"

namespace maris::fiv {

namespace {

// Frequency of the peak at bin k, refined by a parabola through the three amplitudes around it.
double refinedPeak(const std::vector<double>& f, const std::vector<double>& a, std::size_t k) {
  if (k == 0 || k + 1 >= a.size()) return f[k];
  const double denom = a[k - 1] - 2.0 * a[k] + a[k + 1];
  if (denom >= 0.0) return f[k];
  const double shift = 0.5 * (a[k - 1] - a[k + 1]) / denom;
  return f[k] + std::clamp(shift, -0.5, 0.5) * (f[1] - f[0]);
}

std::vector<double> amplitudesOf(const std::vector<double>& x, double dt) {
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  v.array() -= v.mean();
  const AmplitudeSpectrum s = amplitudeSpectrum(v, dt);
  return std::vector<double>(s.amplitude.data(), s.amplitude.data() + s.amplitude.size());
}

// Indices of zero up-crossings of x − mean.
std::vector<std::size_t> upCrossings(const std::vector<double>& x, double mean) {
  std::vector<std::size_t> idx;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] - mean < 0.0 && x[i] - mean >= 0.0) idx.push_back(i);
  return idx;
}

}  // namespace

SpectralPeaks analyseSpectra(const std::vector<double>& displacement, const std::vector<double>& lift, double dt) {
  if (displacement.size() < 8 || !(dt > 0.0))
    throw std::invalid_argument("analyseSpectra: need at least 8 samples and dt > 0");
  SpectralPeaks out;
  out.displacement_amplitude = amplitudesOf(displacement, dt);
  const std::size_t bins = out.displacement_amplitude.size();
  const double df = 1.0 / (static_cast<double>(displacement.size()) * dt);
  for (std::size_t k = 0; k < bins; ++k) out.frequency.push_back(k * df);
  out.lift_amplitude = lift.size() == displacement.size() ? amplitudesOf(lift, dt) : std::vector<double>(bins, 0.0);
  const auto& ay = out.displacement_amplitude;
  const std::size_t k1 = static_cast<std::size_t>(std::max_element(ay.begin() + 1, ay.end()) - ay.begin());
  out.f1 = refinedPeak(out.frequency, ay, k1);
  // Secondary lift peak: the largest local maximum above 1.5 f1 (the shedding frequency in galloping).
  const auto& al = out.lift_amplitude;
  std::size_t k2 = 0;
  for (std::size_t k = 1; k + 1 < bins; ++k) {
    if (out.frequency[k] <= 1.5 * out.f1 || al[k] < al[k - 1] || al[k] < al[k + 1]) continue;
    if (k2 == 0 || al[k] > al[k2]) k2 = k;
  }
  if (k2 > 0 && al[k2] > 0.0) {
    out.f2 = refinedPeak(out.frequency, al, k2);
    out.alternations = std::round(out.f2 / out.f1);
  }
  return out;
}

ImportedSeries parseSeriesCsv(const std::string& text, const std::string& origin) {
  const TableSpec spec{"parameters.analysis.series_file", origin, "columns time, y and optional ydot, lift"};
  const TextTable csv = parseNumericCsv(text, spec);
  const int ct = csv.column("time"), cy = csv.column("y"), cv = csv.column("ydot"), cl = csv.column("lift");
  if (ct < 0 || cy < 0)
    throw InputError({tableError(spec, 0, "needs columns \"time\" and \"y\" (optional \"ydot\", \"lift\") in the names row")});
  ImportedSeries raw;
  for (const auto& row : csv.rows) {
    const auto& r = row.cells;
    for (int c : {ct, cy, cv, cl})
      if (c >= 0 && (!r[c] || !std::isfinite(*r[c])))
        throw InputError({tableError(spec, row.line, "expected a finite number", &csv, c)});
    if (!raw.time.empty() && *r[ct] <= raw.time.back())
      throw InputError({tableError(spec, row.line, "time must increase strictly from row to row", &csv, ct)});
    raw.time.push_back(*r[ct]);
    raw.y.push_back(*r[cy]);
    if (cv >= 0) raw.ydot.push_back(*r[cv]);
    if (cl >= 0) raw.lift.push_back(*r[cl]);
  }
  if (raw.time.size() < 16) throw InputError(origin, std::to_string(raw.time.size()) + " rows", "needs at least 16 samples");
  // Resample onto a uniform grid when the step varies by more than 0.1 % (FFT and averages need it).
  const std::size_t n = raw.time.size();
  const double dt = (raw.time.back() - raw.time.front()) / static_cast<double>(n - 1);
  bool uniform = true;
  for (std::size_t i = 1; i < n && uniform; ++i) uniform = std::abs(raw.time[i] - raw.time[i - 1] - dt) < 1e-3 * dt;
  if (uniform) return raw;
  ImportedSeries out;
  auto resample = [&](const std::vector<double>& v, std::vector<double>& dst) {
    if (v.empty()) return;
    std::size_t j = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = raw.time.front() + dt * static_cast<double>(i);
      while (j + 2 < n && raw.time[j + 1] < t) ++j;
      const double w = std::clamp((t - raw.time[j]) / (raw.time[j + 1] - raw.time[j]), 0.0, 1.0);
      dst.push_back((1.0 - w) * v[j] + w * v[j + 1]);
    }
  };
  for (std::size_t i = 0; i < n; ++i) out.time.push_back(raw.time.front() + dt * static_cast<double>(i));
  resample(raw.y, out.y);
  resample(raw.ydot, out.ydot);
  resample(raw.lift, out.lift);
  return out;
}

std::vector<double> cycleAmplitudes(const std::vector<double>& y, double mean) {
  const auto up = upCrossings(y, mean);
  std::vector<double> amps;
  for (std::size_t c = 0; c + 1 < up.size(); ++c) {
    const auto [lo, hi] = std::minmax_element(y.begin() + static_cast<std::ptrdiff_t>(up[c]),
                                              y.begin() + static_cast<std::ptrdiff_t>(up[c + 1]));
    amps.push_back(0.5 * (*hi - *lo));
  }
  return amps;
}

ImportedSeries readSeriesCsv(const std::string& path) {
  return parseSeriesCsv(readDataText(path, "fiv", "parameters.analysis.series_file"), path);
}

SeriesAnalysis analyseSeries(const ImportedSeries& s, double damping, double density, double speed, double length,
                             double side) {
  const std::size_t n = s.time.size();
  const double dt = (s.time.back() - s.time.front()) / static_cast<double>(n - 1);
  // Velocity: given, or central differences.
  std::vector<double> v = s.ydot;
  if (v.empty()) {
    v.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
      v[i] = (s.y[b] - s.y[a]) / (s.time[b] - s.time[a]);
    }
  }
  const double mean = std::accumulate(s.y.begin(), s.y.end(), 0.0) / static_cast<double>(n);
  const auto up = upCrossings(s.y, mean);
  if (up.size() < 3)
    throw InputError("analysis.series_file", std::to_string(up.size()) + " up-crossings",
                     "the record must hold at least two whole oscillation cycles");
  SeriesAnalysis out;
  const std::vector<double> amps = cycleAmplitudes(s.y, mean);
  out.cycles = static_cast<int>(amps.size());
  out.amplitude = std::accumulate(amps.begin(), amps.end(), 0.0) / amps.size();
  double var = 0.0;
  for (double a : amps) var += (a - out.amplitude) * (a - out.amplitude);
  out.amplitude_spread = std::sqrt(var / amps.size());
  const double span = s.time[up.back()] - s.time[up.front()];
  out.frequency = static_cast<double>(amps.size()) / span;
  // Powers over the whole cycles (trapezoid rule).
  double e_damper = 0.0, e_fluid = 0.0;
  for (std::size_t i = up.front(); i < up.back(); ++i) {
    e_damper += 0.5 * dt * damping * (v[i] * v[i] + v[i + 1] * v[i + 1]);
    if (!s.lift.empty()) e_fluid += 0.5 * dt * (s.lift[i] * v[i] + s.lift[i + 1] * v[i + 1]);
  }
  out.power_damper = e_damper / span;
  out.power_fluid = e_fluid / span;
  out.fluid_power = sweptFluidPower(density, speed, length, side, out.amplitude);
  out.efficiency = betzEfficiency(out.power_damper, out.fluid_power);
  out.spectra = analyseSpectra(s.y, s.lift, dt);
  return out;
}

}  // namespace maris::fiv
