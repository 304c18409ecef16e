// FFT against a direct DFT, the one-sided amplitude spectrum's scaling and frequency axis, and the
// single-harmonic fit used for response amplitude operators.
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/spectrum.hpp"

namespace maris {
namespace {

using Complex = std::complex<double>;
constexpr double kEps = 2.220446049250313e-16;

// Direct O(N²) DFT in long double with the angle reduced exactly (jk mod N): an independent reference.
std::vector<Complex> directDft(const std::vector<Complex>& x) {
  const std::size_t n = x.size();
  std::vector<Complex> out(n);
  const long double two_pi = 2.0L * std::numbers::pi_v<long double>;
  for (std::size_t k = 0; k < n; ++k) {
    long double re = 0.0L, im = 0.0L;
    for (std::size_t j = 0; j < n; ++j) {
      const long double angle = -two_pi * static_cast<long double>((j * k) % n) / static_cast<long double>(n);
      re += x[j].real() * std::cos(angle) - x[j].imag() * std::sin(angle);
      im += x[j].real() * std::sin(angle) + x[j].imag() * std::cos(angle);
    }
    out[k] = Complex(static_cast<double>(re), static_cast<double>(im));
  }
  return out;
}

TEST(Spectrum, FftMatchesDirectDftForPowerOfTwoAndOtherLengths) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (std::size_t n : {1u, 2u, 7u, 64u, 100u, 1000u}) {
    std::vector<Complex> x(n);
    double l1 = 0.0;
    for (auto& value : x) {
      value = Complex(uniform(rng), uniform(rng));
      l1 += std::abs(value);
    }
    const std::vector<Complex> fast = fft(x), reference = directDft(x);
    // Round-off bound of an FFT: ~ eps·log2(M)·Σ|x| (M ≤ 2048 the Bluestein length); factor 20 of slack.
    const double tolerance = 20.0 * kEps * std::max(1.0, std::log2(2.0 * n)) * l1;
    double max_difference = 0.0;
    for (std::size_t k = 0; k < n; ++k) max_difference = std::max(max_difference, std::abs(fast[k] - reference[k]));
    EXPECT_LT(max_difference, tolerance) << "N = " << n;
    // And the inverse gives the samples back.
    const std::vector<Complex> back = inverseFft(fast);
    for (std::size_t j = 0; j < n; ++j) EXPECT_LT(std::abs(back[j] - x[j]), tolerance) << "N = " << n;
  }
}

TEST(Spectrum, AmplitudeSpectrumShowsACosineAtItsBinWithItsAmplitudeAndPhase) {
  // N = 100 samples, dt = 0.05 s: bins every 1/(N dt) = 0.2 Hz; a 1 Hz cosine sits in bin 5.
  const int n = 100;
  const double dt = 0.05, amplitude = 1.7, phase = 0.4, offset = 0.3;
  Eigen::VectorXd x(n);
  for (int j = 0; j < n; ++j) x[j] = offset + amplitude * std::cos(2.0 * std::numbers::pi * 1.0 * j * dt + phase);
  const AmplitudeSpectrum s = amplitudeSpectrum(x, dt);
  ASSERT_EQ(s.frequency.size(), 51);
  EXPECT_NEAR(s.frequency[5], 1.0, 1e-15);
  EXPECT_NEAR(s.frequency[50], 10.0, 1e-13);  // Nyquist 1/(2 dt)
  // Round-off only: 1e-13 on amplitudes of order 1.
  EXPECT_NEAR(s.amplitude[5], amplitude, 1e-13);
  EXPECT_NEAR(s.phase[5], phase, 1e-13);
  EXPECT_NEAR(s.amplitude[0], offset, 1e-13);
  for (int k = 1; k < 51; ++k) {
    if (k == 5) continue;
    EXPECT_LT(s.amplitude[k], 1e-13) << "bin " << k;
  }
}

TEST(Spectrum, NyquistBinOfAnEvenLengthIsNotDoubled) {
  // x_j = A·(−1)^j is the Nyquist cosine: amplitude A in the last bin.
  Eigen::VectorXd x(64);
  for (int j = 0; j < 64; ++j) x[j] = (j % 2 == 0 ? 1.0 : -1.0) * 0.75;
  const AmplitudeSpectrum s = amplitudeSpectrum(x, 0.1);
  EXPECT_NEAR(s.amplitude[32], 0.75, 1e-14);
  EXPECT_NEAR(s.frequency[32], 5.0, 1e-14);
}

TEST(Spectrum, HarmonicFitRecoversAmplitudeAndPhaseToRoundOff) {
  // 0.37 Hz is not commensurate with dt = 0.01 s (270.27 samples per period): the least-squares fit is
  // still exact for a pure harmonic plus offset, so round-off (1e-12) is the tolerance.
  const double dt = 0.01, f = 0.37, amplitude = 2.5, phase = -2.2, mean = 0.2;
  Eigen::VectorXd x(3001);
  for (int j = 0; j < x.size(); ++j) x[j] = mean + amplitude * std::cos(2.0 * std::numbers::pi * f * j * dt + phase);
  const HarmonicComponent h = harmonicAt(x, dt, f);
  EXPECT_EQ(h.periods, 11);  // floor(30 s · 0.37 Hz)
  EXPECT_NEAR(h.amplitude, amplitude, 1e-12);
  EXPECT_NEAR(h.phase, phase, 1e-12);
  EXPECT_NEAR(h.mean, mean, 1e-12);
  EXPECT_LT(h.residual_rms, 1e-12);
}

TEST(Spectrum, HarmonicFitOverLastPeriodsIgnoresAnEarlierTransient) {
  // A decaying transient at another frequency during the first 20 s; the last 5 periods of 0.5 Hz
  // (10 s) see e^{−20/2} ≈ 4.5e-5 of it at most, and the fit suppresses off-frequency content further.
  const double dt = 0.02, f = 0.5;
  Eigen::VectorXd x(1501);
  for (int j = 0; j < x.size(); ++j) {
    const double t = j * dt;
    x[j] = 1.2 * std::sin(2.0 * std::numbers::pi * f * t) + std::exp(-t / 2.0) * std::cos(2.0 * std::numbers::pi * 1.3 * t);
  }
  const HarmonicComponent h = harmonicAt(x, dt, f, 5);
  EXPECT_EQ(h.periods, 5);
  EXPECT_NEAR(h.amplitude, 1.2, 5e-5);
  EXPECT_NEAR(h.phase, -std::numbers::pi / 2.0, 5e-5);  // sin = cos(· − π/2)
}

TEST(Spectrum, HarmonicFitRejectsARecordShorterThanOnePeriod) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(50);  // 0.49 s at dt = 0.01
  EXPECT_THROW(harmonicAt(x, 0.01, 1.0), std::invalid_argument);
  EXPECT_THROW(harmonicAt(x, 0.01, 2.5, 3), std::invalid_argument);  // only 1 whole period of 0.4 s
  EXPECT_THROW(amplitudeSpectrum(Eigen::VectorXd(), 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace maris
