// Exact checks of the FIV model's building blocks: free decay, RK4 energy behaviour, the paper's
// power and efficiency definitions (eqs 8–15) and the spectral post-processing (eq 22).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "fiv/fiv_theory.hpp"
#include "fiv/fiv_timeseries.hpp"
#include "fiv_test_support.hpp"

namespace maris::fiv {
namespace {

using std::numbers::pi;

TEST(FivExact, LogarithmicDecrementOfTenPercentDampingIs0_63148) {
  // Closed form: δ = 2πξ/√(1 − ξ²) = 0.63148 for ξ = 0.1 (5 digits given).
  EXPECT_NEAR(logarithmicDecrement(0.1), 0.63148, 5e-6);
}

TEST(FivExact, FreeDecayAtZeroSpeedHasTheClosedFormDecrementAndDampedFrequency) {
  // U = 0: no fluid force, a linear damped oscillator. Successive maxima have ratio e^δ and are one
  // damped period 1/(f_n√(1 − ξ²)) apart. h = T/4000: RK4 error ~1e-13, peak sampling (ωh)²/8 ≈ 3e-7.
  const FivModel model = buildFivModel(testing::gallopingOnly());
  const FivRhs rhs(model, makeOperatingPoint(model, 0.0, kDeep));
  const double period = 1.0 / model.f_n, h = period / 4000.0;
  State s{0.01, 0, 0, 0, 0, 0};
  std::vector<double> peaks, times;
  double t = 0.0;
  for (int i = 0; i < 4 * 4000; ++i) {
    const State prev = s;
    rhs.step(s, h);
    t += h;
    if (prev[1] > 0.0 && s[1] <= 0.0) {
      peaks.push_back(std::max(prev[0], s[0]));
      times.push_back(t);
    }
  }
  ASSERT_GE(peaks.size(), 3u);
  const double decrement = std::log(peaks[0] / peaks[1]);
  EXPECT_NEAR(decrement / logarithmicDecrement(model.damping_ratio), 1.0, 1e-5);
  const double damped_ratio = 1.0 / ((times[2] - times[1]) * model.f_n);
  EXPECT_NEAR(damped_ratio, std::sqrt(1.0 - 0.01), 2.0 * h / period);  // 0.99499, ± one step in the period
  // The limit-cycle driver reports the decay to rest as A = 0.
  State seeded{0.01, 0, 0, 0, 0, 0};
  const LimitCycle c = runToLimitCycle(rhs, seeded, LimitCycleSettings{});
  EXPECT_TRUE(c.at_rest);
  EXPECT_EQ(c.amplitude, 0.0);
}

TEST(FivExact, UndampedRk4EnergyFollowsTheStabilityPolynomial) {
  // ξ = 0, U = 0: in coordinates (ω y, ẏ) one RK4 step is a rotation scaled by |R(iθ)|, θ = ω h,
  // R(z) = 1 + z + z²/2 + z³/6 + z⁴/24, so the energy after N steps is exactly |R(iθ)|^(2N) E0
  // (RK4 dissipates ≈ θ⁶/72 per step; it does not conserve energy as Newmark's average acceleration does).
  FivParameters p = testing::gallopingOnly();
  p.damping_input = "coefficient";
  p.damping_coefficient = 0.0;
  const FivModel model = buildFivModel(p);
  const FivRhs rhs(model, makeOperatingPoint(model, 0.0, kDeep));
  const int steps_per_period = 40, periods = 20;
  const double theta = 2.0 * pi / steps_per_period;
  const double h = theta / model.omega_n;
  State s{0.02, 0.0, 0, 0, 0, 0};
  auto energy = [&](const State& x) { return 0.5 * model.stiffness * x[0] * x[0] + 0.5 * model.total_mass * x[1] * x[1]; };
  const double e0 = energy(s);
  for (int i = 0; i < steps_per_period * periods; ++i) rhs.step(s, h);
  const std::complex<double> z(0.0, theta);
  const double growth = std::norm(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
  const double expected = std::pow(growth, steps_per_period * periods);
  EXPECT_NEAR(energy(s) / e0, expected, 1e-12);  // round-off over 800 steps
  EXPECT_LT(expected, 1.0);
  EXPECT_GT(expected, 1.0 - 1e-3);
}

TEST(FivExact, DamperPowerOfASineIsHalfCOmegaSquaredASquared) {
  // Paper eq 13 on y = A sin ωt: ⟨cẏ²⟩ = ½cω²A². 400 samples per period hit every peak and the
  // trapezoid rule is exact (to round-off) for a periodic integrand over whole periods.
  const double a = 0.25, f = 0.5, c = 30.0, w = 2.0 * pi * f, dt = 1.0 / (400.0 * f);
  ImportedSeries s;
  for (int i = 0; i < 400 * 12; ++i) {
    const double t = i * dt;
    s.time.push_back(t);
    s.y.push_back(a * std::sin(w * t));
    s.ydot.push_back(a * w * std::cos(w * t));
  }
  const SeriesAnalysis r = analyseSeries(s, c, 998.2, 2.2, 1.0, 0.09);
  EXPECT_NEAR(r.amplitude, a, 1e-12);
  EXPECT_NEAR(r.power_damper / sinusoidDamperPower(c, w, a), 1.0, 1e-9);
  EXPECT_NEAR(sinusoidDamperPower(c, w, a), 2.0 * pi * pi * c * f * f * a * a, 1e-12);
  EXPECT_NEAR(r.frequency, f, 1e-9);
}

TEST(FivExact, EfficiencyOfCaseC5MatchesTheWorkedNumbers) {
  // Hand calculation from the paper's definitions (3–4 digits): C5, U = 2.2 m/s, A = 0.25 m, f = 0.48828 Hz,
  // c = 30 N·s/m, L = 1 m, ρ = 998.2 kg/m³: P = 8.82 W, P_fluid = 3135.5 W, η = 0.475 % (± 0.5 %).
  const double power = sinusoidDamperPower(30.0, 2.0 * pi * 0.48828, 0.25);
  const double fluid = sweptFluidPower(998.2, 2.2, 1.0, 0.09, 0.25);
  EXPECT_NEAR(power, 8.82, 0.005 * 8.82);
  EXPECT_NEAR(fluid, 3135.5, 0.05);
  EXPECT_NEAR(betzEfficiency(power, fluid), 0.00475, 0.005 * 0.00475);
  EXPECT_DOUBLE_EQ(kBetzLimit, 16.0 / 27.0);
}

// A record sampled as the paper's (Δt = 0.005 s, 8192 samples: bins k/40.96 Hz).
ImportedSeries paperRecord(double f1, double f2) {
  ImportedSeries s;
  for (int i = 0; i < 8192; ++i) {
    const double t = i * 0.005;
    s.time.push_back(t);
    s.y.push_back(0.25 * std::sin(2.0 * pi * f1 * t));
    s.lift.push_back(40.0 * std::sin(2.0 * pi * f1 * t) + 15.0 * std::sin(2.0 * pi * f2 * t));
  }
  return s;
}

TEST(FivExact, SpectrumReportsThePapersFftBinsExactly) {
  // The paper's frequencies are FFT bins (1/40.96 Hz apart): a sine at bin 20 (0.48828125 Hz) or 22
  // (0.537109375 Hz) of a 8192-sample record at 0.005 s is reported at that bin (no leakage, so the parabolic refinement does not move it).
  for (int bin : {20, 22}) {
    const ImportedSeries s = paperRecord(bin / 40.96, 3.41026);
    const SpectralPeaks p = analyseSpectra(s.y, s.lift, 0.005);
    EXPECT_NEAR(p.f1, bin / 40.96, 1e-9) << "bin " << bin;
  }
}

TEST(FivExact, LiftAlternationCountOfCasesC3AndC5IsSeven) {
  // Paper eq 22, n = round(f2/f1): C3 (0.53711, 3.71265 Hz) and C5 (0.48828, 3.41026 Hz) give 7.
  // f1 on a bin; f2 off-bin, located within one bin (0.0244 Hz), which cannot change the rounding here.
  const struct { double f1, f2; } cases[] = {{22 / 40.96, 3.71265}, {20 / 40.96, 3.41026}};
  for (const auto& c : cases) {
    const SpectralPeaks p = analyseSpectra(paperRecord(c.f1, c.f2).y, paperRecord(c.f1, c.f2).lift, 0.005);
    EXPECT_NEAR(p.f2, c.f2, 1.0 / 40.96);
    EXPECT_EQ(p.alternations, 7.0);
  }
}

}  // namespace
}  // namespace maris::fiv
