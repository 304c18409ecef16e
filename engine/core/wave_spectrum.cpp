// Sea-state spectra and their moments (contract in core/wave_spectrum.hpp).
#include "core/wave_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace maris::ocean {
namespace {

using std::numbers::pi;
// 5-point Gauss–Legendre on [−1, 1].
constexpr double kNode[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
constexpr double kWeight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};
constexpr double kPanelWidth = 0.005;  // [-] in u = ω_p/ω; the JONSWAP peak has width σ ≈ 0.07 there
constexpr double kUpperU = 4.0;        // exp(−1.25·4⁴) = 1e-139: nothing below ω_p/4

// Composite Gauss–Legendre of f over [a, b] in panels no wider than kPanelWidth, with a panel edge at u = 1
// (the JONSWAP σ switch: a kink there).
template <class F>
double integrateU(F f, double a, double b) {
  if (b <= a) return 0.0;
  if (a < 1.0 && b > 1.0) return integrateU(f, a, 1.0) + integrateU(f, 1.0, b);
  const int panels = std::max(1, static_cast<int>(std::ceil((b - a) / kPanelWidth)));
  const double h = (b - a) / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int q = 0; q < 5; ++q) sum += kWeight[q] * f(mid + 0.5 * h * kNode[q]);
  }
  return 0.5 * h * sum;
}

double peakFrequency(const WaveSpectrum& s) { return 2.0 * pi / s.peak_period; }

// γ^{exp(−(ω − ω_p)²/(2σ²ω_p²))}, 1 for Pierson–Moskowitz.
double peakFactor(const WaveSpectrum& s, double omega) {
  if (s.kind != SpectrumKind::Jonswap || s.peak_enhancement == 1.0) return 1.0;
  const double wp = peakFrequency(s);
  const double sigma = omega <= wp ? 0.07 : 0.09;
  const double r = (omega - wp) / (sigma * wp);
  return std::pow(s.peak_enhancement, std::exp(-0.5 * r * r));
}

// ∫ ω^n S dω over ω ∈ [ω_p/u_b, ω_p/u_a] written in u: (5/16) Hs² ω_p^n u^{3−n} e^{−1.25u⁴} A G(ω_p/u) du.
double analyticMoment(const WaveSpectrum& s, int order, double u_a, double u_b) {
  const double wp = peakFrequency(s);
  auto integrand = [&](double u) {
    if (u <= 0.0) return order == 3 ? 1.0 : 0.0;
    return std::pow(u, 3 - order) * std::exp(-1.25 * u * u * u * u) * peakFactor(s, wp / u);
  };
  const double scale = 5.0 / 16.0 * s.significant_height * s.significant_height * std::pow(wp, order);
  return s.normalisation * scale * integrateU(integrand, u_a, std::min(u_b, kUpperU));
}

// ∫ ω^n S dω of the piecewise-linear table over [a, b]; 5-point Gauss is exact for these polynomials.
double tableMoment(const WaveSpectrum& s, int order, double a, double b) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < s.table_omega.size(); ++i) {
    const double lo = std::max(a, s.table_omega[i]), hi = std::min(b, s.table_omega[i + 1]);
    if (hi <= lo) continue;
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (int q = 0; q < 5; ++q) {
      const double w = mid + half * kNode[q];
      sum += half * kWeight[q] * std::pow(w, order) * s.density(w);
    }
  }
  return sum;
}

void requirePositiveFinite(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(what) + " must be a positive finite number");
}

}  // namespace

double WaveSpectrum::density(double omega) const {
  if (kind == SpectrumKind::Table) {
    if (table_omega.empty() || omega < table_omega.front() || omega > table_omega.back()) return 0.0;
    const auto it = std::upper_bound(table_omega.begin(), table_omega.end(), omega);
    const std::size_t j = it == table_omega.end() ? table_omega.size() - 1 : static_cast<std::size_t>(it - table_omega.begin());
    const std::size_t i = j - 1;
    const double t = (omega - table_omega[i]) / (table_omega[j] - table_omega[i]);
    return (1.0 - t) * table_density[i] + t * table_density[j];
  }
  if (omega <= 0.0) return 0.0;
  const double wp = peakFrequency(*this), r = wp / omega;
  const double pm = 5.0 / 16.0 * significant_height * significant_height * std::pow(wp, 4) * std::pow(omega, -5) *
                    std::exp(-1.25 * r * r * r * r);
  return normalisation * pm * peakFactor(*this, omega);
}

double WaveSpectrum::bandLow() const {
  return kind == SpectrumKind::Table ? table_omega.front() : 0.5 * peakFrequency(*this);
}
double WaveSpectrum::bandHigh() const {
  return kind == SpectrumKind::Table ? table_omega.back() : 6.0 * peakFrequency(*this);
}

std::string WaveSpectrum::name() const {
  switch (kind) {
    case SpectrumKind::PiersonMoskowitz: return "Pierson–Moskowitz";
    case SpectrumKind::Jonswap: return "JONSWAP";
    case SpectrumKind::Table: return "spectrum table";
  }
  return "";
}

WaveSpectrum piersonMoskowitz(double significant_height, double peak_period) {
  requirePositiveFinite(significant_height, "significant wave height Hs");
  requirePositiveFinite(peak_period, "peak period Tp");
  WaveSpectrum s;
  s.kind = SpectrumKind::PiersonMoskowitz;
  s.significant_height = significant_height;
  s.peak_period = peak_period;
  return s;
}

WaveSpectrum jonswap(double significant_height, double peak_period, double peak_enhancement) {
  WaveSpectrum s = piersonMoskowitz(significant_height, peak_period);
  if (!(peak_enhancement >= 1.0) || !std::isfinite(peak_enhancement))
    throw std::invalid_argument("JONSWAP peak enhancement γ must be ≥ 1");
  s.kind = SpectrumKind::Jonswap;
  s.peak_enhancement = peak_enhancement;
  // A_γ from m0 = Hs²/16: the un-normalised m0 over the whole axis.
  s.normalisation = 1.0;
  s.normalisation = significant_height * significant_height / 16.0 / analyticMoment(s, 0, 0.0, kUpperU);
  return s;
}

WaveSpectrum spectrumTable(std::vector<double> omega, std::vector<double> density) {
  if (omega.size() < 2 || omega.size() != density.size())
    throw std::invalid_argument("spectrum table needs at least 2 rows of (frequency, density)");
  for (std::size_t i = 0; i < omega.size(); ++i) {
    if (!(omega[i] >= 0.0) || !std::isfinite(omega[i]))
      throw std::invalid_argument("spectrum table frequency must be ≥ 0 (row " + std::to_string(i + 1) + ")");
    if (i > 0 && !(omega[i] > omega[i - 1]))
      throw std::invalid_argument("spectrum table frequencies must increase (row " + std::to_string(i + 1) + ")");
    if (!(density[i] >= 0.0) || !std::isfinite(density[i]))
      throw std::invalid_argument("spectrum table density must be ≥ 0 (row " + std::to_string(i + 1) + ")");
  }
  WaveSpectrum s;
  s.kind = SpectrumKind::Table;
  s.table_omega = std::move(omega);
  s.table_density = std::move(density);
  if (!(tableMoment(s, 0, s.table_omega.front(), s.table_omega.back()) > 0.0))
    throw std::invalid_argument("spectrum table has zero variance");
  return s;
}

double spectralMoment(const WaveSpectrum& spectrum, int order) {
  if (order < 0 || order > 4) throw std::invalid_argument("spectral moment order must be 0 … 4");
  if (spectrum.kind == SpectrumKind::Table)
    return tableMoment(spectrum, order, spectrum.table_omega.front(), spectrum.table_omega.back());
  if (order == 4) throw std::invalid_argument("m4 of a Pierson–Moskowitz or JONSWAP spectrum is infinite (ω⁻⁵ tail)");
  return analyticMoment(spectrum, order, 0.0, kUpperU);
}

double bandVariance(const WaveSpectrum& spectrum, double a, double b) {
  if (spectrum.kind == SpectrumKind::Table) return tableMoment(spectrum, 0, a, b);
  if (b <= a || b <= 0.0) return 0.0;
  const double wp = peakFrequency(spectrum);
  const double u_a = wp / b, u_b = a > 0.0 ? wp / a : kUpperU;
  return analyticMoment(spectrum, 0, u_a, u_b);
}

}  // namespace maris::ocean
