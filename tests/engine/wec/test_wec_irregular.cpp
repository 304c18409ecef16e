// Irregular seas: response spectra of pitch and hinge reactions from the frequency domain against the statistics
// of time-domain runs, both formulations; the scene's sea against its spectrum; the phase convention of the
// excitation. Every reference here is independent of the random phases: spectral sums and integrals, m0 = Hs²/16,
// and the sampling error of a standard deviation over a finite record.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>

#include "core/ocean_waves.hpp"
#include "core/portable_random.hpp"
#include "wec/wec_frequency.hpp"
#include "wec/wec_response.hpp"
#include "wec/wec_time.hpp"
#include "wec_test_models.hpp"

using namespace maris::wec;

namespace {
// Standard deviation of samples k0..end (mean removed).
double deviation(const std::vector<double>& s, std::size_t k0) {
  double mean = 0.0, sq = 0.0;
  const double n = static_cast<double>(s.size() - k0);
  for (std::size_t k = k0; k < s.size(); ++k) mean += s[k] / n;
  for (std::size_t k = k0; k < s.size(); ++k) sq += (s[k] - mean) * (s[k] - mean) / n;
  return std::sqrt(sq);
}
// The grid of the scene's response spectra: 0.2–6 ω_p, 2001 points.
std::vector<double> spectrumGrid(const WecParameters& p) {
  const double wp = 2.0 * std::numbers::pi / p.peak_period;
  std::vector<double> omega;
  for (int i = 0; i <= 2000; ++i) omega.push_back(wp * (0.2 + 5.8 * i / 2000.0));
  return omega;
}
}  // namespace

// In a linear sea state (Hs = 0.2 m, JONSWAP Tp = 6 s) of 100 components on multiples of one Δω, over one whole
// repeat period 2π/Δω after the ramp and settling, the time-domain standard deviations of θ, F_h,x, F_h,z and M_y
// equal the frequency-domain sums σ² = Σ ½|H(ω_j)|² a_j² within 1 % whatever the phases (RK4 step and K(t) fit
// error, as in the regular-wave RAO check, plus a window that is not a whole number of steps), for the classical
// and the augmented formulation.
TEST(WecIrregular, TimeDomainDeviationsMatchFrequencyDomain) {
  auto p = wec_test::defaults();
  p.wave_type = "irregular";
  p.significant_height = 0.2;
  const WecModel m = wec_test::model(p);
  const IncidentWaves waves = wec_test::commensurateSea(p, 100);
  const ResponseDeviations fd = discreteResponseDeviations(m, m.floats[0], waves);
  const double repeat = wec_test::repeatPeriod(waves), settle = p.ramp_duration + settlingTime(m);
  for (bool augmented : {false, true}) {
    TimeDomainOptions o;
    o.augmented = augmented;
    o.duration = settle + repeat;
    const TimeDomainResult r = simulateTimeDomain(m, waves, o, nullptr);
    std::size_t k0 = 0;
    while (r.time[k0] < settle) ++k0;
    const auto& h = r.floats[0];
    std::printf("augmented %d: TD/FD sigma theta %.4f, Fx %.4f, Fz %.4f, My %.4f\n", augmented,
                deviation(h.theta, k0) / fd.pitch, deviation(h.hinge_fx, k0) / fd.fx, deviation(h.hinge_fz, k0) / fd.fz,
                deviation(h.moment_y, k0) / fd.moment);
    EXPECT_NEAR(deviation(h.theta, k0) / fd.pitch, 1.0, 0.01) << "augmented " << augmented;
    EXPECT_NEAR(deviation(h.hinge_fx, k0) / fd.fx, 1.0, 0.01) << "augmented " << augmented;
    EXPECT_NEAR(deviation(h.hinge_fz, k0) / fd.fz, 1.0, 0.01) << "augmented " << augmented;
    EXPECT_NEAR(deviation(h.moment_y, k0) / fd.moment, 1.0, 0.01) << "augmented " << augmented;
  }
}

// The scene's sea carries the spectrum's variance: Σ a_j²/2 = Hs²/16 within 1e-3 (the band 0.5–6 ω_p leaves out
// less than 1e-3 of m0), for both discretisations. The continuous response spectra integrate to the discrete sums of
// the 200-component sea within 2 % (each a_j² holds its bin's ∫S dω; |H|² varies across a bin).
TEST(WecIrregular, ResponseSpectraIntegrateToDiscreteDeviations) {
  auto p = wec_test::defaults();
  p.wave_type = "irregular";
  const WecModel m = wec_test::model(p);
  const std::vector<double> omega = spectrumGrid(p);
  const ResponseSpectra s = responseSpectra(m, m.floats[0], p.spectrum, p.significant_height, p.peak_period,
                                            p.peak_enhancement, omega);
  double m0 = 0.0;
  for (std::size_t k = 1; k < omega.size(); ++k) m0 += 0.5 * (omega[k] - omega[k - 1]) * (s.wave[k] + s.wave[k - 1]);
  EXPECT_NEAR(4.0 * std::sqrt(m0) / p.significant_height, 1.0, 0.005);
  for (const char* method : {"random_frequency", "equal_energy"}) {
    p.discretisation = method;
    const IncidentWaves sea = makeIrregularWave(p, 1.0);
    EXPECT_NEAR(16.0 * sea.field.variance() / (p.significant_height * p.significant_height), 1.0, 1e-3) << method;
    const ResponseDeviations d = discreteResponseDeviations(m, m.floats[0], sea);
    std::printf("%s: continuous/discrete sigma theta %.4f, Fx %.4f, Fz %.4f, My %.4f\n", method,
                s.sd_pitch / d.pitch, s.sd_fx / d.fx, s.sd_fz / d.fz, s.sd_moment / d.moment);
    EXPECT_NEAR(s.sd_pitch / d.pitch, 1.0, 0.02) << method;
    EXPECT_NEAR(s.sd_fx / d.fx, 1.0, 0.02) << method;
    EXPECT_NEAR(s.sd_fz / d.fz, 1.0, 0.02) << method;
    EXPECT_NEAR(s.sd_moment / d.moment, 1.0, 0.02) << method;
  }
}

// The sampling error of a standard deviation. For a flat spectrum S = c on [a, b] the formula reduces to
// √(π / (2T(b − a))) (closed form, 0.1 % with the trapezoid's end cells). Over 200 Gaussian seas of the JONSWAP
// spectrum (the scene's sea of 1000 components, spaced 0.0058 rad/s, finer than 2π/T, with Rayleigh amplitudes
// a_j √(−ln U), E a² unchanged; T = 300 s sampled every second) the spread of the measured σ_η about its mean is the
// formula within 25 % (the spread of a spread from 200 samples is ±5 % at one standard deviation). The scene's sea
// has fixed amplitudes a_j = √(2 ∫_bin S dω) and scatters less (M. J. Tucker, P. G. Challenor, D. J. T. Carter,
// Applied Ocean Research 6(2), 1984, 118–122): the formula bounds its spread, and its mean 4σ_η/Hs is 1 within
// three standard errors of that mean.
TEST(WecIrregular, SamplingErrorOfTheDeviationMatchesTheSpreadOverSeeds) {
  std::vector<double> omega, flat;
  for (int i = 0; i <= 1000; ++i) {
    omega.push_back(0.5 + 1.0 * i / 1000.0);
    flat.push_back(2.0);
  }
  EXPECT_NEAR(deviationSamplingError(omega, flat, 600.0) / std::sqrt(std::numbers::pi / (2.0 * 600.0 * 1.0)), 1.0, 1e-3);

  auto p = wec_test::defaults();
  p.wave_type = "irregular";
  p.component_count = 1000;
  const std::vector<double> grid = spectrumGrid(p);
  const auto wave = spectrumDensity(p.spectrum, p.significant_height, p.peak_period, p.peak_enhancement, grid);
  const double record = 300.0, expected = deviationSamplingError(grid, wave, record);
  auto measure = [&](const IncidentWaves& sea) {
    std::vector<double> eta;
    for (double t = p.ramp_duration; t < p.ramp_duration + record; t += 1.0) eta.push_back(sea.elevation(0.0, t));
    return deviation(eta, 0);
  };
  auto meanAndSpread = [](const std::vector<double>& x) {
    double mean = 0.0;
    for (double v : x) mean += v / static_cast<double>(x.size());
    return std::pair{mean, deviation(x, 0) / mean};
  };
  std::vector<double> fixed, gaussian;
  std::mt19937_64 rayleigh(2024);
  for (int seed = 1; seed <= 200; ++seed) {
    p.seed = seed;
    const IncidentWaves sea = makeIrregularWave(p, 1.0);
    fixed.push_back(measure(sea));
    std::vector<maris::ocean::WaveComponent> components = sea.field.components();
    for (auto& c : components) c.amplitude *= std::sqrt(-std::log1p(-maris::uniform01(rayleigh())));
    IncidentWaves random_amplitudes = sea;
    random_amplitudes.field = maris::ocean::WaveField(std::move(components), 0.0, maris::ocean::kDeepWater, p.gravity,
                                                      maris::ocean::Stretching::None);
    gaussian.push_back(measure(random_amplitudes));
  }
  const auto [mean_fixed, spread_fixed] = meanAndSpread(fixed);
  const auto [mean_gaussian, spread_gaussian] = meanAndSpread(gaussian);
  std::printf("sigma_eta over 200 seeds, predicted spread %.4f: Gaussian sea spread %.4f (4 sigma/Hs %.4f), "
              "scene's sea spread %.4f (4 sigma/Hs %.4f)\n", expected, spread_gaussian,
              4.0 * mean_gaussian / p.significant_height, spread_fixed, 4.0 * mean_fixed / p.significant_height);
  EXPECT_NEAR(spread_gaussian / expected, 1.0, 0.25);
  EXPECT_LT(spread_fixed, expected);
  EXPECT_NEAR(4.0 * mean_fixed / p.significant_height, 1.0, 3.0 * expected / std::sqrt(200.0) + 1e-3);
}

// The scene's own sea (core's random-frequency synthesis, 200 components, seed 1) over a long record: after the
// ramp and settling, 3000 s, the time-domain standard deviations of η, θ, F_h,x and F_h,z agree with the continuous
// frequency-domain values (Hs/4 and √∫|H|² S dω) within 3.5 standard errors of a Gaussian sea for the record
// length (deviationSamplingError of each response spectrum; the scene's fixed-amplitude sea scatters less, see
// above) plus 1 % for the integrator and the kernel fit. A linear sea state (Hs = 0.2 m); classical formulation.
TEST(WecIrregular, SceneSeaDeviationsMatchTheSpectrumWithinTheSamplingError) {
  auto p = wec_test::defaults();
  p.wave_type = "irregular";
  p.significant_height = 0.2;
  const WecModel m = wec_test::model(p);
  const std::vector<double> omega = spectrumGrid(p);
  const ResponseSpectra s = responseSpectra(m, m.floats[0], p.spectrum, p.significant_height, p.peak_period,
                                            p.peak_enhancement, omega);
  const double settle = p.ramp_duration + settlingTime(m), record = 3000.0;
  TimeDomainOptions o;
  o.duration = settle + record;
  const TimeDomainResult r = simulateTimeDomain(m, makeIrregularWave(p, 1.0), o, nullptr);
  std::size_t k0 = 0;
  while (r.time[k0] < settle) ++k0;
  const double duration = r.time.back() - r.time[k0];
  struct Check {
    const char* name;
    double td, fd;
    const std::vector<double>& spectrum;
  };
  const auto& h = r.floats[0];
  for (const Check& c : {Check{"eta", deviation(r.wave_at_origin, k0), p.significant_height / 4.0, s.wave},
                         Check{"theta", deviation(h.theta, k0), s.sd_pitch, s.pitch},
                         Check{"Fx", deviation(h.hinge_fx, k0), s.sd_fx, s.hinge_fx},
                         Check{"Fz", deviation(h.hinge_fz, k0), s.sd_fz, s.hinge_fz}}) {
    const double error = deviationSamplingError(omega, c.spectrum, duration);
    std::printf("%s: TD/FD %.4f, sampling error %.4f\n", c.name, c.td / c.fd, error);
    EXPECT_NEAR(c.td / c.fd, 1.0, 3.5 * error + 0.01) << c.name;
  }
}

// Phase convention: core writes a component as a cos(k x cos β − ωt + φ), the scene's excitation uses â = a e^{−iφ}.
// A component of phase φ is the phase-0 component delayed by φ/ω, so its elevation and its excitation at t equal the
// phase-0 ones at t − φ/ω (1e-9 relative), for waves along +x and −x (a sign error in â would advance them instead).
TEST(WecIrregular, ExcitationFollowsTheComponentPhase) {
  const WecModel& m = wec_test::defaultModel();
  const double omega = 1.1, phi = 1.0, delay = phi / omega;
  for (double direction : {1.0, -1.0}) {
    const double beta = direction < 0.0 ? std::numbers::pi : 0.0;
    auto field = [&](double phase) {
      IncidentWaves w;
      w.field = maris::ocean::WaveField({{omega, 0.5, phase}}, beta, maris::ocean::kDeepWater, m.gravity,
                                        maris::ocean::Stretching::None);
      return w;
    };
    const IncidentWaves zero = field(0.0), shifted = field(phi);
    const ExcitationSeries e0 = makeExcitation(m, m.floats[0], zero), e1 = makeExcitation(m, m.floats[0], shifted);
    const double x = m.floats[0].x_f0;
    for (double t : {3.0, 7.5, 12.0}) {
      double fx0 = 0.0, fz0 = 0.0, fx1 = 0.0, fz1 = 0.0;
      e0.evaluate(t - delay, 1.0, fx0, fz0);
      e1.evaluate(t, 1.0, fx1, fz1);
      const double scale = std::hypot(fx0, fz0) + 1.0;
      EXPECT_NEAR(fx1, fx0, 1e-9 * scale) << direction << " t " << t;
      EXPECT_NEAR(fz1, fz0, 1e-9 * scale) << direction << " t " << t;
      EXPECT_NEAR(shifted.elevation(x, t), zero.elevation(x, t - delay), 1e-12) << direction << " t " << t;
    }
  }
}
