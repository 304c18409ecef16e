// FFT (FFTW3), amplitude spectra and single-harmonic fits (contract in core/spectrum.hpp).
#include "core/spectrum.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/QR>
#include <fftw3.h>

namespace maris {
namespace {

using Complex = std::complex<double>;

// FFTW plans for in-place complex transforms of one length and direction, and out-of-place real-to-complex
// ones, made once per length with FFTW_ESTIMATE (the same plan, hence the same bits, on every run) and
// FFTW_UNALIGNED (so any std::vector's storage can be passed to the new-array execute functions).
// Creating or destroying a plan is not thread-safe in FFTW; executing one is. Runs happen on worker
// threads and studies run scenes in parallel, so plan lookup and creation hold one mutex; execution does not.
// Plans live until the program exits (one per length and kind used: a few kilobytes each).
class PlanCache {
 public:
  // The plans live as long as the program; at exit they are given back to FFTW (and FFTW's own planner
  // memory with fftw_cleanup), so a leak checker sees nothing left behind.
  ~PlanCache() {
    for (auto* plans : {&complex_[0], &complex_[1], &real_})
      for (auto& [n, plan] : *plans) fftw_destroy_plan(plan);
    fftw_cleanup();
  }
  fftw_plan complexPlan(std::size_t n, int sign) {
    return find(complex_[sign < 0 ? 0 : 1], n, [&] {
      auto* scratch = fftw_alloc_complex(n);
      fftw_plan plan = fftw_plan_dft_1d(static_cast<int>(n), scratch, scratch, sign < 0 ? FFTW_FORWARD : FFTW_BACKWARD,
                                        FFTW_ESTIMATE | FFTW_UNALIGNED);
      fftw_free(scratch);
      return plan;
    });
  }
  fftw_plan realPlan(std::size_t n) {
    return find(real_, n, [&] {
      double* in = fftw_alloc_real(n);
      fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
      fftw_plan plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), in, out, FFTW_ESTIMATE | FFTW_UNALIGNED);
      fftw_free(in);
      fftw_free(out);
      return plan;
    });
  }

 private:
  template <class Make>
  fftw_plan find(std::map<std::size_t, fftw_plan>& plans, std::size_t n, Make make) {
    if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw std::invalid_argument("fft: length " + std::to_string(n) + " exceeds FFTW's int range");
    const std::lock_guard<std::mutex> lock(mutex_);
    auto it = plans.find(n);
    if (it != plans.end()) return it->second;
    fftw_plan plan = make();
    if (!plan) throw std::runtime_error("fft: FFTW could not plan a transform of length " + std::to_string(n));
    plans.emplace(n, plan);
    return plan;
  }
  std::mutex mutex_;
  std::map<std::size_t, fftw_plan> complex_[2];
  std::map<std::size_t, fftw_plan> real_;
};

PlanCache& plans() {
  static PlanCache cache;
  return cache;
}

// std::complex<double> and fftw_complex (double[2]) share their layout (FFTW manual §4.1.1).
fftw_complex* asFftw(std::vector<Complex>& x) { return reinterpret_cast<fftw_complex*>(x.data()); }

void transform(std::vector<Complex>& x, int sign) {
  if (x.size() <= 1) return;
  fftw_execute_dft(plans().complexPlan(x.size(), sign), asFftw(x), asFftw(x));
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
  const auto n = static_cast<std::size_t>(samples.size());
  if (n <= 1) return std::vector<Complex>(samples.data(), samples.data() + samples.size());
  std::vector<double> in(samples.data(), samples.data() + samples.size());
  std::vector<Complex> out(n / 2 + 1);
  fftw_execute_dft_r2c(plans().realPlan(n), in.data(), asFftw(out));
  return out;
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
