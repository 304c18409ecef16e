// Linear wave kinematics and sea synthesis (contract in core/ocean_waves.hpp).
#include "core/ocean_waves.hpp"
#include "core/ocean_stretching.hpp"
#include "core/portable_random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace maris::ocean {
namespace {

using std::numbers::pi;
constexpr int kCumulativeCells = 20000;  // grid of the equal-energy inversion

// Cumulative variance and first moment of a spectrum on a fine grid over its band, for the equal-energy bins.
struct CumulativeSpectrum {
  std::vector<double> omega, variance, first_moment;
  // Linear interpolation of a cumulative column at ω.
  double at(const std::vector<double>& column, double w) const {
    const double h = omega[1] - omega[0];
    const double s = std::clamp((w - omega.front()) / h, 0.0, static_cast<double>(omega.size() - 1));
    const auto i = std::min(static_cast<std::size_t>(s), omega.size() - 2);
    const double t = s - static_cast<double>(i);
    return (1.0 - t) * column[i] + t * column[i + 1];
  }
  // ω where the cumulative variance reaches `target` (inverse of the piecewise-linear cumulative).
  double inverse(double target) const {
    const auto it = std::lower_bound(variance.begin(), variance.end(), target);
    if (it == variance.begin()) return omega.front();
    if (it == variance.end()) return omega.back();
    const auto j = static_cast<std::size_t>(it - variance.begin());
    const double dv = variance[j] - variance[j - 1];
    const double t = dv > 0.0 ? (target - variance[j - 1]) / dv : 0.0;
    return omega[j - 1] + t * (omega[j] - omega[j - 1]);
  }
};

CumulativeSpectrum cumulate(const WaveSpectrum& spectrum) {
  constexpr double node[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
  constexpr double weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double lo = spectrum.bandLow(), hi = spectrum.bandHigh(), h = (hi - lo) / kCumulativeCells;
  CumulativeSpectrum c;
  c.omega.resize(kCumulativeCells + 1);
  c.variance.assign(kCumulativeCells + 1, 0.0);
  c.first_moment.assign(kCumulativeCells + 1, 0.0);
  for (int i = 0; i <= kCumulativeCells; ++i) c.omega[static_cast<std::size_t>(i)] = lo + h * i;
  for (std::size_t i = 0; i + 1 < c.omega.size(); ++i) {
    double v = 0.0, m = 0.0;
    for (int q = 0; q < 3; ++q) {
      const double w = c.omega[i] + 0.5 * h * (1.0 + node[q]);
      const double s = spectrum.density(w);
      v += 0.5 * h * weight[q] * s;
      m += 0.5 * h * weight[q] * s * w;
    }
    c.variance[i + 1] = c.variance[i] + v;
    c.first_moment[i + 1] = c.first_moment[i] + m;
  }
  return c;
}

void requirePositive(double value, const char* what) {
  if (!(value > 0.0) || std::isnan(value)) throw std::invalid_argument(std::string(what) + " must be positive");
}

}  // namespace

double waveNumber(double omega, double depth, double gravity) {
  requirePositive(omega, "wave angular frequency ω");
  requirePositive(depth, "water depth h");
  requirePositive(gravity, "gravity g");
  const double k0 = omega * omega / gravity;
  if (std::isinf(depth)) return k0;
  // Eckart (1952): k ≈ k0 / √tanh(k0 h), then Newton (quadratic; from Eckart's start 2–4 steps reach 1e-15).
  double k = k0 / std::sqrt(std::tanh(k0 * depth));
  for (int iteration = 0; iteration < 30; ++iteration) {
    const double th = std::tanh(k * depth);
    const double f = k * th - k0, df = th + k * depth * (1.0 - th * th);
    const double step = f / df;
    k -= step;
    if (std::abs(step) <= 1e-15 * k) break;
  }
  return k;
}

double groupVelocity(double omega, double depth, double gravity) {
  const double k = waveNumber(omega, depth, gravity);
  if (std::isinf(depth)) return 0.5 * omega / k;
  const double kh2 = 2.0 * k * depth;
  return 0.5 * omega / k * (1.0 + (kh2 > 700.0 ? 0.0 : kh2 / std::sinh(kh2)));
}

WaveField::WaveField(std::vector<WaveComponent> components, double direction_rad, double depth, double gravity,
                     Stretching stretching)
    : components_(std::move(components)),
      cos_dir_(std::cos(direction_rad)),
      sin_dir_(std::sin(direction_rad)),
      depth_(depth),
      stretching_(stretching) {
  const std::size_t n = components_.size();
  kx_.resize(n), ky_.resize(n), k_.resize(n), a_omega_.resize(n), a_omega2_.resize(n), depth_scale_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const WaveComponent& c = components_[j];
    const double k = waveNumber(c.omega, depth, gravity);
    k_[j] = k;
    kx_[j] = k * cos_dir_;
    ky_[j] = k * sin_dir_;
    a_omega_[j] = c.amplitude * c.omega;
    a_omega2_[j] = c.amplitude * c.omega * c.omega;
    depth_scale_[j] = std::isinf(depth) ? 1.0 : 1.0 / -std::expm1(-2.0 * k * depth);
  }
}

double WaveField::elevation(double x, double y, double t) const {
  double eta = 0.0;
  for (std::size_t j = 0; j < components_.size(); ++j)
    eta += components_[j].amplitude * std::cos(kx_[j] * x + ky_[j] * y - components_[j].omega * t + components_[j].phase);
  return eta;
}

double WaveField::variance() const {
  double v = 0.0;
  for (const auto& c : components_) v += 0.5 * c.amplitude * c.amplitude;
  return v;
}

double WaveField::meanPeriod() const {
  double m0 = 0.0, m1 = 0.0;
  for (const auto& c : components_) {
    m0 += 0.5 * c.amplitude * c.amplitude;
    m1 += 0.5 * c.amplitude * c.amplitude * c.omega;
  }
  return m1 > 0 ? 2.0 * std::numbers::pi * m0 / m1 : 0.0;
}

void WaveField::linearAt(double z, const double* cos_psi, const double* sin_psi, FluidKinematics& out) const {
  const bool deep = std::isinf(depth_);
  double u = 0.0, w = 0.0, du = 0.0, dw = 0.0;
  for (std::size_t j = 0; j < components_.size(); ++j) {
    // C = cosh k(z+h)/sinh kh = (e^{kz} + e^{−k(z+2h)})/(1 − e^{−2kh}), S likewise with −: no overflow at any kh.
    const double e1 = std::exp(k_[j] * z);
    const double e2 = deep ? 0.0 : std::exp(-k_[j] * (z + 2.0 * depth_));
    const double ch = (e1 + e2) * depth_scale_[j], sh = (e1 - e2) * depth_scale_[j];
    u += a_omega_[j] * ch * cos_psi[j];
    w += a_omega_[j] * sh * sin_psi[j];
    du += a_omega2_[j] * ch * sin_psi[j];
    dw -= a_omega2_[j] * sh * cos_psi[j];
  }
  out.velocity = Eigen::Vector3d(u * cos_dir_, u * sin_dir_, w);
  out.acceleration = Eigen::Vector3d(du * cos_dir_, du * sin_dir_, dw);
}

FluidKinematics WaveField::kinematics(const Eigen::Vector3d& point, double t, double ramp, double ramp_rate) const {
  thread_local std::vector<double> cos_psi, sin_psi;
  const std::size_t n = components_.size();
  cos_psi.resize(n);
  sin_psi.resize(n);
  double eta = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double psi = kx_[j] * point.x() + ky_[j] * point.y() - components_[j].omega * t + components_[j].phase;
    cos_psi[j] = std::cos(psi);
    sin_psi[j] = std::sin(psi);
    eta += components_[j].amplitude * cos_psi[j];
  }
  eta *= ramp;
  FluidKinematics out;
  out.elevation = eta;
  out.wet = point.z() <= eta;
  if (!out.wet) return out;
  linearAt(stretchedZ(point.z(), eta, depth_, stretching_), cos_psi.data(), sin_psi.data(), out);
  if (ramp != 1.0 || ramp_rate != 0.0) {
    out.acceleration = ramp * out.acceleration + ramp_rate * out.velocity;
    out.velocity *= ramp;
  }
  return out;
}

void WaveField::kinematics(const std::vector<Eigen::Vector3d>& points, double t, std::vector<FluidKinematics>& out) const {
  out.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = kinematics(points[i], t);
}

WaveField airyWave(double height, double period, double direction_rad, double phase_rad, double depth, double gravity,
                   Stretching stretching) {
  requirePositive(height, "wave height H");
  requirePositive(period, "wave period T");
  return WaveField({{2.0 * pi / period, 0.5 * height, phase_rad}}, direction_rad, depth, gravity, stretching);
}

WaveField irregularSea(const WaveSpectrum& spectrum, int component_count, Discretisation discretisation,
                       std::uint64_t seed, double direction_rad, double depth, double gravity, Stretching stretching) {
  if (component_count < 1) throw std::invalid_argument("component count must be at least 1");
  std::mt19937_64 rng(seed);
  const double lo = spectrum.bandLow(), hi = spectrum.bandHigh();
  const auto n = static_cast<std::size_t>(component_count);
  std::vector<WaveComponent> components(n);
  if (discretisation == Discretisation::EqualEnergy) {
    const CumulativeSpectrum c = cumulate(spectrum);
    const double total = c.variance.back(), share = total / static_cast<double>(n);
    double left = lo;
    for (std::size_t j = 0; j < n; ++j) {
      const double right = j + 1 == n ? hi : c.inverse(share * static_cast<double>(j + 1));
      const double v = c.at(c.variance, right) - c.at(c.variance, left);
      const double m = c.at(c.first_moment, right) - c.at(c.first_moment, left);
      components[j].omega = v > 0.0 ? m / v : 0.5 * (left + right);
      components[j].amplitude = std::sqrt(2.0 * share);
      components[j].phase = 2.0 * pi * uniform01(rng());
      left = right;
    }
  } else {
    const double width = (hi - lo) / static_cast<double>(n);
    for (std::size_t j = 0; j < n; ++j) {
      const double left = lo + width * static_cast<double>(j);
      components[j].omega = left + width * uniform01(rng());
      if (components[j].omega <= 0.0) components[j].omega = 0.5 * width;  // a table from ω = 0: no ω = 0 wave
      components[j].amplitude = std::sqrt(2.0 * bandVariance(spectrum, left, left + width));
      components[j].phase = 2.0 * pi * uniform01(rng());
    }
  }
  return WaveField(std::move(components), direction_rad, depth, gravity, stretching);
}

double startRamp(double t, double ramp_time) {
  if (t >= ramp_time) return 1.0;
  if (t <= 0.0) return 0.0;
  return 0.5 * (1.0 - std::cos(pi * t / ramp_time));
}

double startRampRate(double t, double ramp_time) {
  if (t <= 0.0 || t >= ramp_time) return 0.0;
  return 0.5 * pi / ramp_time * std::sin(pi * t / ramp_time);
}

double smallestSpacing(const WaveField& field) {
  std::vector<double> omega;
  for (const auto& c : field.components()) omega.push_back(c.omega);
  std::sort(omega.begin(), omega.end());
  double spacing = std::numeric_limits<double>::infinity();
  for (std::size_t j = 1; j < omega.size(); ++j) spacing = std::min(spacing, omega[j] - omega[j - 1]);
  return spacing;
}

}  // namespace maris::ocean
