// FFT (radix-2 + Bluestein), amplitude spectra and single-harmonic fits (contract in core/spectrum.hpp).
#include "core/spectrum.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/QR>

namespace maris {
namespace {

using Complex = std::complex<double>;

bool isPowerOfTwo(std::size_t n) { return n > 0 && (n & (n - 1)) == 0; }

// In-place iterative radix-2 FFT; sign = −1 forward, +1 inverse (unnormalised). n must be a power of 2.
void radix2(std::vector<Complex>& x, int sign) {
  const std::size_t n = x.size();
  // Bit-reversal permutation.
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i], x[j]);
  }
  // Butterflies; twiddles computed directly (not by repeated multiplication) to keep round-off at eps.
  std::vector<Complex> twiddle;
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::size_t half = len / 2;
    twiddle.resize(half);
    for (std::size_t k = 0; k < half; ++k)
      twiddle[k] = std::polar(1.0, sign * 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(len));
    for (std::size_t start = 0; start < n; start += len) {
      for (std::size_t k = 0; k < half; ++k) {
        const Complex even = x[start + k];
        const Complex odd = x[start + k + half] * twiddle[k];
        x[start + k] = even + odd;
        x[start + k + half] = even - odd;
      }
    }
  }
}

// Bluestein: jk = (j² + k² − (k−j)²)/2 turns the DFT into a convolution with the chirp exp(iπ j²/N),
// done by power-of-two FFTs of length M ≥ 2N − 1.
void bluestein(std::vector<Complex>& x, int sign) {
  const std::size_t n = x.size();
  std::size_t m = 1;
  while (m < 2 * n - 1) m <<= 1;
  // chirp_j = exp(sign·iπ j²/N), with j² reduced mod 2N in integers so the angle stays small and exact.
  std::vector<Complex> chirp(n);
  for (std::size_t j = 0; j < n; ++j) {
    const unsigned long long j2 = (static_cast<unsigned long long>(j) * j) % (2ULL * n);
    chirp[j] = std::polar(1.0, sign * std::numbers::pi * static_cast<double>(j2) / static_cast<double>(n));
  }
  std::vector<Complex> a(m, Complex(0.0)), b(m, Complex(0.0));
  for (std::size_t j = 0; j < n; ++j) a[j] = x[j] * chirp[j];
  b[0] = std::conj(chirp[0]);
  for (std::size_t j = 1; j < n; ++j) b[j] = b[m - j] = std::conj(chirp[j]);
  radix2(a, -1);
  radix2(b, -1);
  for (std::size_t i = 0; i < m; ++i) a[i] *= b[i];
  radix2(a, +1);
  const double inv_m = 1.0 / static_cast<double>(m);
  for (std::size_t k = 0; k < n; ++k) x[k] = a[k] * inv_m * chirp[k];
}

void transform(std::vector<Complex>& x, int sign) {
  if (x.size() <= 1) return;
  if (isPowerOfTwo(x.size()))
    radix2(x, sign);
  else
    bluestein(x, sign);
}

}  // namespace

std::vector<Complex> fft(std::vector<Complex> x) {
  transform(x, -1);
  return x;
}

std::vector<Complex> inverseFft(std::vector<Complex> spectrum) {
  transform(spectrum, +1);
  const double inv_n = spectrum.empty() ? 1.0 : 1.0 / static_cast<double>(spectrum.size());
  for (auto& value : spectrum) value *= inv_n;
  return spectrum;
}

std::vector<Complex> realFft(const Eigen::VectorXd& samples) {
  std::vector<Complex> x(samples.data(), samples.data() + samples.size());
  transform(x, -1);
  if (!x.empty()) x.resize(x.size() / 2 + 1);
  return x;
}

AmplitudeSpectrum amplitudeSpectrum(const Eigen::VectorXd& samples, double sample_interval_s) {
  if (samples.size() == 0) throw std::invalid_argument("amplitudeSpectrum: no samples");
  if (!(sample_interval_s > 0.0) || !std::isfinite(sample_interval_s))
    throw std::invalid_argument("amplitudeSpectrum: sample interval must be positive, got " +
                                std::to_string(sample_interval_s));
  const Eigen::Index n = samples.size();
  const std::vector<Complex> bins = realFft(samples);
  const Eigen::Index count = static_cast<Eigen::Index>(bins.size());
  AmplitudeSpectrum spectrum;
  spectrum.frequency.resize(count);
  spectrum.amplitude.resize(count);
  spectrum.phase.resize(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    // DC and (for even N) Nyquist bins have no mirror image: factor 1, all others 2.
    const bool unpaired = k == 0 || (n % 2 == 0 && k == n / 2);
    spectrum.frequency[k] = static_cast<double>(k) / (static_cast<double>(n) * sample_interval_s);
    spectrum.amplitude[k] = (unpaired ? 1.0 : 2.0) * std::abs(bins[k]) / static_cast<double>(n);
    spectrum.phase[k] = std::arg(bins[k]);
  }
  return spectrum;
}

HarmonicComponent harmonicAt(const Eigen::VectorXd& samples, double sample_interval_s, double frequency_hz,
                             int periods) {
  if (!(frequency_hz > 0.0) || !std::isfinite(frequency_hz))
    throw std::invalid_argument("harmonicAt: frequency must be positive, got " + std::to_string(frequency_hz));
  if (!(sample_interval_s > 0.0) || !std::isfinite(sample_interval_s))
    throw std::invalid_argument("harmonicAt: sample interval must be positive, got " +
                                std::to_string(sample_interval_s));
  const Eigen::Index n = samples.size();
  const double period = 1.0 / frequency_hz;
  const double duration = static_cast<double>(n - 1) * sample_interval_s;
  // Whole periods that fit (a relative slack of 1e-9 absorbs round-off in duration / period).
  const int available = n > 1 ? static_cast<int>(std::floor(duration / period * (1.0 + 1e-9))) : 0;
  if (available < 1 || periods > available)
    throw std::invalid_argument("harmonicAt: record of " + std::to_string(duration) + " s holds " +
                                std::to_string(available) + " whole periods of " + std::to_string(period) +
                                " s, need " + std::to_string(std::max(periods, 1)));
  const int used = periods > 0 ? periods : available;

  // Window: samples with time ≥ t_end − used·period.
  const double window_start = duration - used * period;
  const Eigen::Index first =
      std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::ceil(window_start / sample_interval_s - 1e-9)));
  const Eigen::Index count = n - first;
  if (count < 3) throw std::invalid_argument("harmonicAt: fewer than 3 samples in the fitting window");

  // Least squares for [mean, c, s] in x ≈ mean + c·cos(ωt) + s·sin(ωt).
  const double omega = 2.0 * std::numbers::pi * frequency_hz;
  Eigen::MatrixXd design(count, 3);
  for (Eigen::Index j = 0; j < count; ++j) {
    const double t = static_cast<double>(first + j) * sample_interval_s;
    design(j, 0) = 1.0;
    design(j, 1) = std::cos(omega * t);
    design(j, 2) = std::sin(omega * t);
  }
  const Eigen::VectorXd window = samples.tail(count);
  const Eigen::Vector3d coef = design.colPivHouseholderQr().solve(window);

  // A cos(ωt + φ) = A cos φ cos ωt − A sin φ sin ωt.
  HarmonicComponent result;
  result.mean = coef[0];
  result.amplitude = std::hypot(coef[1], coef[2]);
  result.phase = std::atan2(-coef[2], coef[1]);
  result.periods = used;
  result.residual_rms = std::sqrt((window - design * coef).squaredNorm() / static_cast<double>(count));
  return result;
}

}  // namespace maris
