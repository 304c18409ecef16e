#include "seismic/free_field_synthesis.hpp"

#include <bit>
#include <cmath>
#include <numbers>

#include "core/checked_count.hpp"
#include "core/spectrum.hpp"

namespace maris::seismic {

FreeFieldSynthesis::FreeFieldSynthesis(const FreeField& field, const std::vector<double>& incident, double t0,
                                       double dt, const RunContext* context)
    : field_(field), t0_(t0), dt_(dt), n_out_(static_cast<int>(incident.size())), context_(context) {
  if (field.reflectedPEvanescent()) {
    // Beyond the SV critical angle the reflection coefficients are complex constants: the reflected
    // waves carry a Hilbert-transformed copy of the input whose tails reach before the arrival (the
    // head-wave precursor of an infinite plane wave). A damped frequency would amplify the part of
    // that tail wrapped from before t0 by e^{εN dt}, so real frequencies are used with a longer
    // window: 8× the record, and ≥ 64 s with water, whose reverberation (≈ 0.78 per round trip in
    // the paper's set-up) then decays below 1e-6 before it wraps.
    const std::size_t span = field.hasWater() ? static_cast<std::size_t>(checkedCount(
                                                    64.0 / dt, kMaxStoredSamples, "time step", "synthesis samples"))
                                              : 0;
    n_fft_ = std::bit_ceil(std::max<std::size_t>({64, 8 * incident.size(), span}));
    eps_ = 0.0;
  } else {
    n_fft_ = std::bit_ceil(std::max<std::size_t>(64, 2 * incident.size()));
    eps_ = std::log(1.0e6) / (static_cast<double>(n_fft_) * dt);
  }
  const double window = static_cast<double>(n_fft_) * dt;

  // Damped input spectrum in the e^{+iωt} transform: U(ω+iε) = Σ u_k e^{-ε t_k} e^{iω t_k} dt (t from t0).
  std::vector<Complex> buffer(n_fft_, Complex(0.0));
  for (int k = 0; k < n_out_; ++k) buffer[k] = incident[k] * std::exp(-eps_ * k * dt);
  // Σ x e^{+iωt} of real samples = conj(Σ x e^{−iωt}).
  buffer = fft(std::move(buffer));
  for (auto& b : buffer) b = std::conj(b);
  const std::size_t half = n_fft_ / 2;
  omega_.resize(half + 1);
  input_spectrum_.resize(half + 1);
  amplitudes_.resize(half + 1);
  for (std::size_t k = 0; k <= half; ++k) {
    checkCancel(k);
    omega_[k] = Complex(2.0 * std::numbers::pi * static_cast<double>(k) / window, eps_);
    // Undamped: the water potential φ = a/(iω) has a finite limit at ω → 0 that the formula cannot
    // evaluate at 0 itself; the zero bin is taken 1e-6 of a bin above it (relative error ~1e-6 in that bin).
    if (k == 0 && eps_ == 0.0) omega_[k] = Complex(2.0e-6 * std::numbers::pi / window, 0.0);
    input_spectrum_[k] = buffer[k] * dt;
    amplitudes_[k] = field_.solve(omega_[k]);
  }
}

void FreeFieldSynthesis::invertPair(const std::vector<Complex>& first, const std::vector<Complex>& second,
                                    std::vector<double>& out_first, std::vector<double>& out_second) const {
  const std::size_t half = n_fft_ / 2;
  const Complex i(0.0, 1.0);
  checkCancel(0);
  std::vector<Complex> z(n_fft_);
  for (std::size_t k = 0; k <= half; ++k) {
    // The Nyquist bin of a real signal is real; dropping its imaginary part keeps the pair separable.
    const Complex a = k == half ? Complex(first[k].real()) : first[k];
    const Complex b = k == half ? Complex(second[k].real()) : second[k];
    z[k] = a + i * b;
    if (k > 0 && k < half) z[n_fft_ - k] = std::conj(a) + i * std::conj(b);
  }
  // e^{-iωt} synthesis: y(t_n) = (1/(N dt)) Σ_k Y_k e^{-2πi kn/N}.
  z = fft(std::move(z));
  out_first.resize(n_out_);
  out_second.resize(n_out_);
  const double scale = 1.0 / (static_cast<double>(n_fft_) * dt_);
  for (int n = 0; n < n_out_; ++n) {
    const double undamp = std::exp(eps_ * n * dt_) * scale;
    out_first[n] = z[n].real() * undamp;
    out_second[n] = z[n].imag() * undamp;
  }
}

SolidHistory FreeFieldSynthesis::solid(double y) const {
  const std::size_t m = omega_.size();
  std::vector<Complex> ux(m), uy(m), vx(m), vy(m), ax(m), ay(m), sxx(m), syy(m), sxy(m);
  const Complex i(0.0, 1.0);
  for (std::size_t k = 0; k < m; ++k) {
    checkCancel(k);
    const FreeFieldPoint f = field_.solidAt(amplitudes_[k], omega_[k], 0.0, y);
    const Complex u0 = input_spectrum_[k];
    const Complex d = -i * omega_[k];  // time derivative
    ux[k] = f.ux * u0;
    uy[k] = f.uy * u0;
    vx[k] = d * ux[k];
    vy[k] = d * uy[k];
    ax[k] = d * vx[k];
    ay[k] = d * vy[k];
    sxx[k] = f.sxx * u0;
    syy[k] = f.syy * u0;
    sxy[k] = f.sxy * u0;
  }
  SolidHistory h;
  std::vector<double> unused;
  invertPair(ux, uy, h.ux, h.uy);
  invertPair(vx, vy, h.vx, h.vy);
  invertPair(ax, ay, h.ax, h.ay);
  invertPair(sxx, syy, h.sxx, h.syy);
  invertPair(sxy, std::vector<Complex>(m, Complex(0.0)), h.sxy, unused);
  return h;
}

WaterHistory FreeFieldSynthesis::water(double y) const {
  const std::size_t m = omega_.size();
  std::vector<Complex> phi(m), phi_dot(m), phi_ddot(m), pressure(m), ux(m), uy(m);
  const Complex i(0.0, 1.0);
  for (std::size_t k = 0; k < m; ++k) {
    checkCancel(k);
    const FreeFieldPoint f = field_.waterAt(amplitudes_[k], omega_[k], 0.0, y);
    const Complex u0 = input_spectrum_[k];
    const Complex d = -i * omega_[k];
    phi[k] = f.potential * u0;
    phi_dot[k] = d * phi[k];
    phi_ddot[k] = d * phi_dot[k];
    pressure[k] = f.pressure * u0;
    ux[k] = f.ux * u0;
    uy[k] = f.uy * u0;
  }
  WaterHistory h;
  invertPair(phi, phi_dot, h.phi, h.phi_dot);
  invertPair(phi_ddot, pressure, h.phi_ddot, h.pressure);
  invertPair(ux, uy, h.ux, h.uy);
  return h;
}

double sampleDelayed(const std::vector<double>& history, double t0, double dt, double t) {
  const int n = static_cast<int>(history.size());
  if (n == 0) return 0.0;
  const double s = (t - t0) / dt;
  if (s <= 0.0) return s < -1.0 ? 0.0 : history[0] * (1.0 + s);
  if (s >= n - 1) return history[n - 1];
  const int k = static_cast<int>(s);
  const double f = s - k;
  const double p0 = k > 0 ? history[k - 1] : 0.0;
  const double p1 = history[k], p2 = history[k + 1];
  const double p3 = k + 2 < n ? history[k + 2] : p2;
  // Catmull–Rom: exact for quadratics, interpolation error O(dt^3).
  return p1 + 0.5 * f * (p2 - p0 + f * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + f * (3.0 * (p1 - p2) + p3 - p0)));
}

}  // namespace maris::seismic
