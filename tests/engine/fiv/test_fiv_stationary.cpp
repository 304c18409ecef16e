// The stationarity test that tells a quasi-periodic response (reported as the mean of its per-cycle
// amplitudes, with their spread) from a growing one (still drifting), on signals with a closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "fiv/fiv_limit_cycle.hpp"
#include "fiv/fiv_timeseries.hpp"

namespace maris::fiv {
namespace {

using std::numbers::pi;

// Per-cycle half peak-to-peak of y(t) = (A0 (1 + g t) + a cos Ωt) sin ωt, ω = 2π (period 1), 200 samples per
// period over `periods` periods. Ω = ω/(10φ), φ the golden ratio: the envelope's period (16.18 cycles) is
// incommensurate with the carrier's, so the cycles sample every phase of the beating (two frequencies, ω and
// ω ± Ω: a quasi-periodic signal).
std::vector<double> modulatedCycleAmplitudes(double a0, double a, double growth, int periods) {
  const double omega = 2.0 * pi, beat = omega / (10.0 * std::numbers::phi);
  std::vector<double> y;
  for (int i = 0; i <= 200 * periods; ++i) {
    const double t = i / 200.0;
    y.push_back((a0 * (1.0 + growth * t) + a * std::cos(beat * t)) * std::sin(omega * t));
  }
  return cycleAmplitudes(y, 0.0);
}

TEST(FivStationary, QuasiPeriodicSignalIsStationaryWithTheMeanOfItsCycleAmplitudes) {
  // Closed form. The half peak-to-peak of cycle k is (A(t_k + T/4) + A(t_k + 3T/4))/2 = A0 + a cos δ cos θ_k,
  // δ = ΩT/4, θ_k equidistributed: its mean is A0 and its standard deviation a cos δ/√2. The mean over N cycles
  // misses A0 by at most a/(N sin(ΩT/2)) = 2.6e-3 (N = 398; geometric sum of the cosines); the peaks' shift
  // by the modulation and the 200-samples-per-period sampling add below 2e-4. Tolerance 3e-3. It tells the
  // mean from the other amplitude statistics: the largest cycle (A0 + a = 1.2) and RMS·√2 (√(A0² + a²/2) =
  // 1.00995).
  const double a0 = 1.0, a = 0.2;
  const std::vector<double> amps = modulatedCycleAmplitudes(a0, a, 0.0, 800);
  ASSERT_EQ(amps.size(), 799u);
  const AmplitudeWindows w = compareAmplitudeWindows(amps, 8);
  EXPECT_TRUE(w.stationary);
  EXPECT_EQ(w.window, 199u);
  EXPECT_EQ(w.first, 799u - 2 * 199u);
  EXPECT_NEAR(w.mean, a0, 3e-3);
  const double delta = 2.0 * pi / (10.0 * std::numbers::phi) / 4.0;
  EXPECT_NEAR(w.spread, a * std::cos(delta) / std::sqrt(2.0), 2e-3);
  // The error estimate covers the mean's actual error, and stays below the bound on the two windows' means
  // apart: each misses A0 by at most a/(W sin(ΩT/2)), so |m2 − m1| <= 2a/(W sin(ΩT/2)) = 1.04e-2.
  EXPECT_GE(w.error(), std::abs(w.mean - a0) - 2e-4);
  EXPECT_LE(w.error(), 2.0 * a / (199.0 * std::sin(pi / (10.0 * std::numbers::phi))));
}

TEST(FivStationary, GrowingResponsesAreNotStationary) {
  // A drift that is linear over the windows moves their mean by √12 ≈ 3.5 times the spread it causes, against
  // the test's limit of half the spread: a growing sine fails whatever its rate (here 1e-4 of A0 per period),
  // and so does a growing beating signal once the growth per window (0.2 A0 at 1e-3 per period) is larger than
  // the beating's spread allows (0.5 · 0.14).
  for (double growth : {1e-4, 1e-2}) {
    const AmplitudeWindows w = compareAmplitudeWindows(modulatedCycleAmplitudes(1.0, 0.0, growth, 800), 8);
    EXPECT_FALSE(w.stationary) << growth;
    EXPECT_NEAR(w.change, growth * 199.0, 1e-3 * growth * 199.0) << growth;
  }
  EXPECT_FALSE(compareAmplitudeWindows(modulatedCycleAmplitudes(1.0, 0.2, 1e-3, 800), 8).stationary);
}

TEST(FivStationary, PeriodTwoCycleIsStationaryAndShortRecordsAreNotJudged) {
  // Alternating amplitudes 1, 1.1 (a period-doubled cycle, which the cycle-to-cycle convergence test never
  // accepts): stationary with mean 1.05 and spread 0.05 exactly (even windows). Fewer than 4·min_window cycles:
  // no verdict.
  std::vector<double> amps;
  for (int k = 0; k < 64; ++k) amps.push_back(k % 2 ? 1.1 : 1.0);
  const AmplitudeWindows w = compareAmplitudeWindows(amps, 8);
  EXPECT_TRUE(w.stationary);
  EXPECT_NEAR(w.mean, 1.05, 1e-12);
  EXPECT_NEAR(w.spread, 0.05, 1e-12);
  EXPECT_NEAR(w.change, 0.0, 1e-12);
  amps.resize(31);
  const AmplitudeWindows short_record = compareAmplitudeWindows(amps, 8);
  EXPECT_FALSE(short_record.stationary);
  EXPECT_EQ(short_record.window, 0u);
}

}  // namespace
}  // namespace maris::fiv
