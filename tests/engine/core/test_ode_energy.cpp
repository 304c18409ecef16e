// Long-time energy behaviour on the undamped oscillator x'' + x = 0 over 10^4 periods:
// RK4 loses energy exactly as its stability polynomial predicts (drift ∝ h^5 at fixed time);
// generalized-α with ρ∞ = 1 (trapezoidal rule) conserves it; ρ∞ < 1 dissipates it.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/closed_forms.hpp"
#include "core/ode.hpp"
#include "ode_test_problems.hpp"

namespace maris {
namespace {

constexpr double kPeriods = 1e4;
const double kDuration = kPeriods * 2.0 * std::numbers::pi;  // [s] ω = 1 rad/s

// Relative energy change of RK4 after kDuration with step h; also returns the prediction.
double rk4EnergyChange(double h, double* predicted) {
  Eigen::VectorXd y(2);
  y << 1.0, 0.0;
  OdeOptions options;
  options.t1 = kDuration;
  options.step = h;
  RunContext ctx;
  const OdeStats stats = integrateRk4(test::oscillatorRhs(1.0, 0.0), y, options, ctx);
  // Prediction: (steps − 1) full steps of h and one final step of the remainder.
  const double last = kDuration - static_cast<double>(stats.steps - 1) * h;
  *predicted = std::pow(rk4OscillatorEnergyRatioPerStep(h), static_cast<double>(stats.steps - 1)) *
                   rk4OscillatorEnergyRatioPerStep(last) - 1.0;
  return oscillatorEnergy(1.0, {y[0], y[1]}) / 0.5 - 1.0;
}

TEST(OdeEnergy, Rk4EnergyDriftOver1e4PeriodsMatchesItsStabilityPolynomial) {
  double predicted_coarse = 0.0, predicted_fine = 0.0;
  const double coarse = rk4EnergyChange(0.2, &predicted_coarse);
  const double fine = rk4EnergyChange(0.1, &predicted_fine);
  // RK4 is dissipative on the oscillator: energy decreases.
  EXPECT_LT(coarse, 0.0);
  EXPECT_LT(fine, 0.0);
  // Measured against |R(ih)|^(2n): agreement to 1e-3 of the drift (round-off over ~6e5 steps is ~1e-10).
  EXPECT_NEAR(coarse, predicted_coarse, 1e-3 * std::abs(predicted_coarse));
  EXPECT_NEAR(fine, predicted_fine, 1e-3 * std::abs(predicted_fine));
  // Drift order: −ln(E/E0) = n·(ωh)^6/72·(1 + O((ωh)²)) with n = T/h steps, ∝ h^5; from h = 0.2 to 0.1
  // the observed order is 5 up to the (ωh)² correction (≈ 0.01 in the exponent).
  const double order = std::log2(std::log1p(coarse) / std::log1p(fine));
  EXPECT_NEAR(order, 5.0, 0.03) << "drifts " << coarse << " " << fine;
}

double alphaEnergyChange(double rho_inf, double h, double duration) {
  Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
  OdeOptions options;
  options.t1 = duration;
  options.step = h;
  options.rtol = 1e-13;  // Newton to round-off: the test is about the scheme, not the iteration
  options.atol = 1e-15;
  GeneralizedAlphaOptions alpha;
  alpha.rho_inf = rho_inf;
  RunContext ctx;
  integrateGeneralizedAlpha(test::oscillatorSystem(1.0, 0.0), q, v, options, alpha, ctx);
  return oscillatorEnergy(1.0, {q[0], v[0]}) / 0.5 - 1.0;
}

TEST(OdeEnergy, GeneralizedAlphaWithRhoInfOneConservesEnergy) {
  // The trapezoidal rule's amplification matrix is a rotation in the energy norm: |ΔE|/E at round-off
  // level, accumulated over ~3e5 steps (≈ 1e-16 · 3e5 random walk, bounded generously at 1e-9).
  EXPECT_LT(std::abs(alphaEnergyChange(1.0, 0.2, kDuration)), 1e-9);
}

TEST(OdeEnergy, GeneralizedAlphaWithRhoInfBelowOneDissipatesEnergy) {
  // Numerical damping of a resolved mode (ωh = 0.2) is small but accumulates (here over 10^3 periods);
  // it must increase as ρ∞ decreases.
  const double at_08 = alphaEnergyChange(0.8, 0.2, 0.1 * kDuration), at_05 = alphaEnergyChange(0.5, 0.2, 0.1 * kDuration);
  EXPECT_LT(at_08, -1e-6);
  EXPECT_LT(at_05, at_08);
}

}  // namespace
}  // namespace maris
