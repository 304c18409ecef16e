// Quasi-steady galloping of the model against its theory: linear onset (Den Hartog), the averaged
// amplitude equation of Parkinson's polynomial, its high-speed asymptote and hysteresis band.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/run_context.hpp"
#include "fiv/fiv_sweep.hpp"
#include "fiv/fiv_theory.hpp"
#include "fiv_test_support.hpp"

namespace maris::fiv {
namespace {

TEST(FivGalloping, AveragedParkinsonCoefficientHasTheHandDerivedExtremes) {
  // Derived by hand from Parkinson's polynomial with A1..A7 = 2.69, 168, 6270, 59900:
  // G(r) = A1 − ¾A3 r² + ⅝A5 r⁴ − 35/64 A7 r⁶ has a minimum 1.4657 at r = 0.1494, a maximum 2.1738 at
  // r = 0.2396 and its root at 0.29327. Our G is a quadrature of C_y(r sinθ) sinθ (exact for polynomials).
  const FivModel model = buildFivModel(testing::gallopingOnly());
  auto g = [&](double r) { return averagedForceCoefficient(model.curve, r); };
  EXPECT_NEAR(g(0.1494), 1.4657, 2e-4);
  EXPECT_NEAR(g(0.2396), 2.1738, 2e-4);
  EXPECT_GT(g(0.1494 - 0.01), g(0.1494));
  EXPECT_GT(g(0.1494 + 0.01), g(0.1494));
  const auto roots = harmonicBalanceRoots(model.curve, 0.0);
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_NEAR(roots[0].velocity_ratio, 0.29327, 2e-5);
  EXPECT_TRUE(roots[0].stable);
}

TEST(FivGalloping, OnsetSpeedIsTwiceDampingOverRhoDLA1WithinOnePercent) {
  // Linearised: m_t ÿ + (c − ½ρUDL A1) ẏ + k y = 0, growth changes sign at U_cr = 2c/(ρ D L A1).
  // Marched 60 periods from 0.01 D: below 0.99 U_cr the envelope shrinks, above 1.01 U_cr it grows
  // (growth rate ±0.01 ξω_n gives a factor e^{±0.19} over 60 periods, far above RK4 error).
  const FivModel model = buildFivModel(testing::gallopingOnly());
  const double u_cr = gallopingOnsetSpeed(model.damping, model.density, model.side, model.length, 2.69);
  EXPECT_NEAR(u_cr, 2.0 * model.damping / (model.density * model.side * model.length * 2.69), 1e-12);
  for (const auto& [factor, grows] : {std::pair{0.99, false}, std::pair{1.01, true}}) {
    const FivRhs rhs(model, makeOperatingPoint(model, factor * u_cr, kDeep));
    State s{0.01 * model.side, 0, 0, 0, 0, 0};
    const double first = testing::amplitudeAfter(rhs, s, 1.0);
    const double later = testing::amplitudeAfter(rhs, s, 60.0);
    EXPECT_EQ(later > first, grows) << "U/U_cr = " << factor;
  }
}

TEST(FivGalloping, HighSpeedAmplitudeApproachesTheParkinsonAsymptote) {
  // Weakly nonlinear set (n_m = 1e-4, ξ = 2e-4) at U' = U/(ω_n D) = 100: S = 2ξ/(n_m U') = 0.04, so
  // harmonic balance puts r = Aω_n/U within 0.1 % of the U' → ∞ root 0.29327. Time integration must
  // agree with harmonic balance to 1 % (averaging neglects O(n_m U' A1) ≈ 3 % corrections of the wave
  // form, which move the amplitude much less) and sit within 1 % of 0.2933 (the quasi-steady asymptote).
  const FivParameters p = testing::weaklyNonlinearGalloping(1e-4, 2e-4);
  const FivModel model = buildFivModel(p);
  const double speed = 100.0 * model.omega_n * model.side;
  const FivRhs rhs(model, makeOperatingPoint(model, speed, kDeep));
  const auto hb = harmonicBalanceAtSpeed(model, speed, 1.0);
  ASSERT_FALSE(hb.empty());
  const double r_hb = hb.back().velocity_ratio;
  State s{0.29 * speed / model.omega_n, 0, 0, 0, 0, 0};  // start near the cycle: convergence is slow (rate ~ n_m U')
  LimitCycleSettings settings;
  settings.max_cycles = 3000;
  settings.tolerance = 1e-5;
  const LimitCycle c = runToLimitCycle(rhs, s, settings);
  const double r = c.amplitude * model.omega_n / speed;
  EXPECT_TRUE(c.converged);
  EXPECT_NEAR(r / r_hb, 1.0, 0.01);
  EXPECT_NEAR(r / 0.2933, 1.0, 0.01);
}

TEST(FivGalloping, UpAndDownSweepsShowTheHarmonicBalanceHysteresisBand) {
  // Quasi-steady theory: with S = 2c/(ρDLU), two stable cycles coexist for S in (1.4657, 2.1738). The up-sweep
  // (from a small seed) stays on the small branch until S < 1.4657, the down-sweep on the large branch
  // until S > 2.1738. Branch amplitudes agree with the harmonic-balance roots within 3 % (weak
  // nonlinearity n_m U' A1 ≈ 0.1 leaves averaging errors of a few per mille to ~2 %).
  const FivParameters p = testing::weaklyNonlinearGalloping(2e-3, 0.04);
  const FivModel model = buildFivModel(p);
  const double balance_per_speed = 2.0 * model.damping / (model.density * model.side * model.length);  // S·U
  SweepSettings settings;
  for (double s_target : {2.5, 2.3, 2.0, 1.8, 1.6, 1.3}) settings.speeds.push_back(balance_per_speed / s_target);
  settings.submergence_ratios = {kDeep};
  settings.seed_amplitude_ratio = 1e-3;
  settings.cycle.max_cycles = 1500;
  settings.cycle.tolerance = 2e-4;
  RunContext ctx;
  const SweepResult sweep = runSweep(model, settings, ctx);
  const SweepBranch& b = sweep.branches[0];
  for (std::size_t i = 0; i < settings.speeds.size(); ++i) {
    const double u = settings.speeds[i], s = balance_per_speed / u;
    const auto roots = harmonicBalanceAtSpeed(model, u, 1.0);
    std::vector<double> stable;
    for (const auto& r : roots)
      if (r.stable) stable.push_back(r.velocity_ratio * u / model.omega_n);
    ASSERT_FALSE(stable.empty()) << "S = " << s;
    const bool in_band = s > 1.4657 && s < 2.1738;
    EXPECT_EQ(stable.size(), in_band ? 2u : 1u) << "S = " << s;
    // Up-sweep: the smallest stable cycle while it exists; down-sweep: the largest.
    const double up_expected = s > 1.4657 ? stable.front() : stable.back();
    const double down_expected = s < 2.1738 ? stable.back() : stable.front();
    EXPECT_NEAR(b.up[i].amplitude / up_expected, 1.0, 0.03) << "up, S = " << s;
    EXPECT_NEAR(b.down[i].amplitude / down_expected, 1.0, 0.03) << "down, S = " << s;
    // Energy balance on the cycle (paper eq 8 = eq 13): ⟨Fẏ⟩ = ⟨cẏ²⟩ within 1 %.
    EXPECT_NEAR(b.up[i].power_fluid / b.up[i].power_damper, 1.0, 0.01) << "S = " << s;
  }
}

}  // namespace
}  // namespace maris::fiv
