// Discrete Fourier transforms and what scenes read from them: one-sided amplitude spectra of sampled
// signals (frequency axis in Hz) and the amplitude and phase of one harmonic of a steady-state record
// (response amplitude operators by "DFT of the steady state").
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

namespace maris {

// X_k = Σ_{j=0}^{N−1} x_j·exp(−2πi·jk/N), k = 0 … N−1, unnormalised, for any N ≥ 0.
// Computed by FFTW3 (Frigo & Johnson, Proc. IEEE 93(2), 2005), O(N log N) for every N, round-off
// ~ eps·log2(N)·|x|. Thread-safe: plans are made once per length under a mutex (spectrum.cpp).
std::vector<std::complex<double>> fft(std::vector<std::complex<double>> x);

// x_j = (1/N) Σ_k X_k·exp(+2πi·jk/N): the inverse of fft().
std::vector<std::complex<double>> inverseFft(std::vector<std::complex<double>> spectrum);

// fft() of real samples, returning only the bins k = 0 … floor(N/2) (the rest are their conjugates).
std::vector<std::complex<double>> realFft(const Eigen::VectorXd& samples);

// One-sided spectrum of N real samples taken every `sample_interval_s` seconds:
//   frequency_k = k / (N·dt) [Hz],  amplitude_k = c_k·|X_k| / N with c_0 = 1, c_k = 2 for 0 < k < N/2,
//   c_{N/2} = 1 (N even), so a cosine A·cos(2π f_k t + φ) at a bin frequency shows amplitude A and phase φ
//   (phase_k = arg X_k, t measured from the first sample). No window: off-bin frequencies leak.
struct AmplitudeSpectrum {
  Eigen::VectorXd frequency;  // [Hz] floor(N/2) + 1 bins, spacing 1/(N·dt)
  Eigen::VectorXd amplitude;  // [signal unit]
  Eigen::VectorXd phase;      // [rad] in (−π, π]
};
// Throws std::invalid_argument when dt ≤ 0 or there are no samples.
AmplitudeSpectrum amplitudeSpectrum(const Eigen::VectorXd& samples, double sample_interval_s);

// x(t) ≈ mean + amplitude·cos(2π f (t − t_first) + phase), fitted by least squares (mean, cos and sin
// columns) over the LAST `periods` whole periods 1/f of the record (periods = 0: as many as fit).
// Over whole periods the fit is the discrete Fourier coefficient at f; it is exact for a pure harmonic
// plus a constant whatever the sampling, and other harmonics of f leak only through the sampling.
struct HarmonicComponent {
  double amplitude = 0.0;     // [signal unit] ≥ 0
  double phase = 0.0;         // [rad] in (−π, π], relative to t_first (the first sample's time)
  double mean = 0.0;          // [signal unit] offset over the window
  int periods = 0;            // whole periods used
  double residual_rms = 0.0;  // [signal unit] RMS of what the fit leaves: small for a clean steady state
};
// Throws std::invalid_argument when f ≤ 0, dt ≤ 0, or the record is shorter than one period
// (or than the requested periods) or has fewer than 3 samples in the window.
HarmonicComponent harmonicAt(const Eigen::VectorXd& samples, double sample_interval_s, double frequency_hz,
                             int periods = 0);

}  // namespace maris
