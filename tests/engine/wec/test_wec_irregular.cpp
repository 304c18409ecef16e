// Irregular seas: response spectra of pitch and hinge reactions from the frequency domain
// against the statistics of the time-domain run in the same sea, both formulations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

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
}  // namespace

// In a linear sea state (Hs = 0.2 m, JONSWAP Tp = 6 s, 100 components), over one whole repeat period 2π/Δω after
// the ramp and settling, the time-domain standard deviations of θ, F_h,x, F_h,z and M_y equal the frequency-domain
// sums σ² = Σ ½|H(ω_j)|² a_j² within 1 % (RK4 step and K(t) fit error, as in the regular-wave RAO check, plus the
// sampling of a window that is not a whole number of steps), for the classical and the augmented formulation.
TEST(WecIrregular, TimeDomainDeviationsMatchFrequencyDomain) {
  auto p = wec_test::defaults();
  p.wave_type = "irregular";
  p.component_count = 100;
  p.significant_height = 0.2;
  const WecModel m = wec_test::model(p);
  const WaveField waves = makeIrregularWave(p, 1.0);
  const ResponseDeviations fd = discreteResponseDeviations(m, m.floats[0], waves);
  const double d_omega = waves.components[1].omega - waves.components[0].omega;
  const double repeat = 2.0 * std::numbers::pi / d_omega, settle = p.ramp_duration + settlingTime(m);
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

// The continuous response spectra integrate to the discrete sea's deviations: the wave spectrum to Hs/4 within
// 0.5 % (trapezoid on 0.2–6 ω_p versus the normalisation grid), and pitch and hinge forces to the 200-component
// sums within 2 % (the components cover 0.3–3.5 ω_p, a midpoint rule with Δω = 0.017 rad/s).
TEST(WecIrregular, ResponseSpectraIntegrateToDiscreteDeviations) {
  auto p = wec_test::defaults();
  p.wave_type = "irregular";
  const WecModel m = wec_test::model(p);
  const double wp = 2.0 * std::numbers::pi / p.peak_period;
  std::vector<double> omega;
  for (int i = 0; i <= 2000; ++i) omega.push_back(wp * (0.2 + 5.8 * i / 2000.0));
  const ResponseSpectra s = responseSpectra(m, m.floats[0], p.spectrum, p.significant_height, p.peak_period,
                                            p.peak_enhancement, omega);
  double m0 = 0.0;
  for (std::size_t k = 1; k < omega.size(); ++k) m0 += 0.5 * (omega[k] - omega[k - 1]) * (s.wave[k] + s.wave[k - 1]);
  EXPECT_NEAR(4.0 * std::sqrt(m0) / p.significant_height, 1.0, 0.005);
  const ResponseDeviations d = discreteResponseDeviations(m, m.floats[0], makeIrregularWave(p, 1.0));
  std::printf("continuous/discrete sigma theta %.4f, Fx %.4f, Fz %.4f, My %.4f\n", s.sd_pitch / d.pitch,
              s.sd_fx / d.fx, s.sd_fz / d.fz, s.sd_moment / d.moment);
  EXPECT_NEAR(s.sd_pitch / d.pitch, 1.0, 0.02);
  EXPECT_NEAR(s.sd_fx / d.fx, 1.0, 0.02);
  EXPECT_NEAR(s.sd_fz / d.fz, 1.0, 0.02);
  EXPECT_NEAR(s.sd_moment / d.moment, 1.0, 0.02);
}
