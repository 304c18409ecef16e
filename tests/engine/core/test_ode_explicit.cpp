// Accuracy of the explicit integrators (RK4, DOPRI5): observed convergence orders against the
// oscillator's closed form, dense output, the observer's schedule, and Van der Pol against an
// independent tight reference.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/closed_forms.hpp"
#include "core/ode.hpp"
#include "ode_test_problems.hpp"

namespace maris {
namespace {

using test::kOmega, test::kZeta, test::kX0, test::kV0;

// Max-norm error of (x, v) at t1 against the damped oscillator's closed form.
double oscillatorError(const Eigen::VectorXd& y, double t1) {
  const OscillatorState exact = dampedOscillator(kOmega, kZeta, kX0, kV0, t1);
  return std::max(std::abs(y[0] - exact.position), std::abs(y[1] - exact.velocity));
}

double rk4ErrorAtStep(double h) {
  Eigen::VectorXd y(2);
  y << kX0, kV0;
  OdeOptions options;
  options.t1 = 5.0;
  options.step = h;
  RunContext ctx;
  integrateRk4(test::oscillatorRhs(kOmega, kZeta), y, options, ctx);
  return oscillatorError(y, options.t1);
}

TEST(OdeExplicit, Rk4ConvergesAtFourthOrderOnDampedOscillator) {
  // Halving h divides the error by 2^4; the asymptotic range starts near ωh ≈ 0.1.
  const double e1 = rk4ErrorAtStep(0.04), e2 = rk4ErrorAtStep(0.02), e3 = rk4ErrorAtStep(0.01);
  const double order12 = std::log2(e1 / e2), order23 = std::log2(e2 / e3);
  EXPECT_NEAR(order12, 4.0, 0.1) << "errors " << e1 << " " << e2;
  EXPECT_NEAR(order23, 4.0, 0.1) << "errors " << e2 << " " << e3;
}

double dopri5FixedStepError(double h) {
  Eigen::VectorXd y(2);
  y << kX0, kV0;
  OdeOptions options;
  options.t1 = 5.0;
  options.step = h;
  options.max_step = h;  // tolerances far above any local error: every step is accepted at h
  options.rtol = options.atol = 1e3;
  RunContext ctx;
  const OdeStats stats = integrateDopri5(test::oscillatorRhs(kOmega, kZeta), y, options, ctx);
  EXPECT_EQ(stats.rejected_steps, 0);
  EXPECT_EQ(stats.steps, static_cast<long>(std::ceil(options.t1 / h - 1e-9)));
  return oscillatorError(y, options.t1);
}

TEST(OdeExplicit, Dopri5ConvergesAtFifthOrderWithFixedSteps) {
    // ωh from 0.1 to 0.025: inside the asymptotic range, above round-off (errors 1e-8 … 1e-11).
  const double e1 = dopri5FixedStepError(0.05), e2 = dopri5FixedStepError(0.025), e3 = dopri5FixedStepError(0.0125);
  EXPECT_NEAR(std::log2(e1 / e2), 5.0, 0.15) << "errors " << e1 << " " << e2;
  EXPECT_NEAR(std::log2(e2 / e3), 5.0, 0.15) << "errors " << e2 << " " << e3;
}

double dopri5ToleranceError(double tol, OdeStats* stats_out = nullptr) {
  Eigen::VectorXd y(2);
  y << kX0, kV0;
  OdeOptions options;
  options.t1 = 5.0;
  options.step = 0.0;  // automatic initial step
  options.rtol = tol;
  options.atol = tol;
  RunContext ctx;
  const OdeStats stats = integrateDopri5(test::oscillatorRhs(kOmega, kZeta), y, options, ctx);
  if (stats_out) *stats_out = stats;
  return oscillatorError(y, options.t1);
}

TEST(OdeExplicit, Dopri5GlobalErrorIsProportionalToTolerance) {
  // Error-per-step control of the 4th-order estimate with the 5th-order solution propagated gives
  // a global error ∝ tol (h ∝ tol^(1/5), global error ∝ h^5). Slope over four decades within ±0.2.
  const double e_loose = dopri5ToleranceError(1e-6), e_tight = dopri5ToleranceError(1e-10);
  const double slope = std::log10(e_loose / e_tight) / 4.0;
  EXPECT_NEAR(slope, 1.0, 0.2) << "errors " << e_loose << " " << e_tight;
  // And the error is of the order of the tolerance (not 100× above it).
  EXPECT_LT(e_loose, 1e-4);
  EXPECT_LT(e_tight, 1e-8);
}

TEST(OdeExplicit, Dopri5ErrorEstimateBoundsTheTrueError) {
  // The accumulated local estimate (of the 4th-order companion) is an upper estimate of the error of the
  // propagated 5th-order solution on this damped (contractive) problem.
  OdeStats stats;
  const double error = dopri5ToleranceError(1e-7, &stats);
  EXPECT_GT(stats.error_estimate, error / std::hypot(kX0, kV0));
  EXPECT_LT(stats.error_estimate, 1e-3);  // and not vacuous
}

TEST(OdeExplicit, Dopri5DenseOutputIsAsAccurateAsTheSteps) {
  // Outputs every 0.01 s fall between steps (steps are ~0.1 s at tol 1e-9); the 4th-order continuous
  // extension must keep them at the step points' accuracy (a wrong coefficient gives O(h) = 1e-2 errors).
  Eigen::VectorXd y(2);
  y << kX0, kV0;
  OdeOptions options;
  options.t1 = 5.0;
  options.rtol = options.atol = 1e-9;
  options.output_interval = 0.01;
  double max_error = 0.0;
  long outputs = 0;
  RunContext ctx;
  const OdeStats stats = integrateDopri5(test::oscillatorRhs(kOmega, kZeta), y, options, ctx,
                                         [&](double t, const Eigen::VectorXd& state) {
                                           const OscillatorState exact = dampedOscillator(kOmega, kZeta, kX0, kV0, t);
                                           max_error = std::max(max_error, std::abs(state[0] - exact.position));
                                           ++outputs;
                                         });
  EXPECT_EQ(outputs, 501);  // t0, 499 interior times, t1
  EXPECT_LT(stats.steps, 200);  // so most outputs really are interpolated
  EXPECT_LT(max_error, 1e-7);   // 100 × tol: interpolation error of the same order as the step error
}

TEST(OdeExplicit, Rk4HermiteOutputIsFourthOrder) {
  // Outputs at t = 0.5 + k·0.3 never hit the step grid; their error must shrink 16× per halving.
  auto max_output_error = [](double h) {
    Eigen::VectorXd y(2);
    y << kX0, kV0;
    OdeOptions options;
    options.t1 = 5.0;
    options.step = h;
    options.output_interval = 0.0317;
    double max_error = 0.0;
    RunContext ctx;
    integrateRk4(test::oscillatorRhs(kOmega, kZeta), y, options, ctx, [&](double t, const Eigen::VectorXd& s) {
      max_error = std::max(max_error, std::abs(s[0] - dampedOscillator(kOmega, kZeta, kX0, kV0, t).position));
    });
    return max_error;
  };
  const double e1 = max_output_error(0.04), e2 = max_output_error(0.02);
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.3) << "errors " << e1 << " " << e2;
}

TEST(OdeExplicit, ObserverSeesStartEveryOutputTimeAndEnd) {
  std::vector<double> times;
  Eigen::VectorXd y(2);
  y << kX0, kV0;
  OdeOptions options;
  options.t1 = 1.0;
  options.step = 0.07;
  options.output_interval = 0.3;
  RunContext ctx;
  const auto record = [&](double t, const Eigen::VectorXd&) { times.push_back(t); };
  integrateRk4(test::oscillatorRhs(kOmega, kZeta), y, options, ctx, record);
  const std::vector<double> expected{0.0, 0.3, 0.6, 0.9, 1.0};
  ASSERT_EQ(times.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(times[i], expected[i], 1e-15);
  times.clear();
  y << kX0, kV0;
  integrateDopri5(test::oscillatorRhs(kOmega, kZeta), y, options, ctx, record);
  ASSERT_EQ(times.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(times[i], expected[i], 1e-15);
}

TEST(OdeExplicit, Rk4LastStepIsShortenedToEndAtT1) {
  // 1.0 / 0.3 is not an integer: four steps, the last of 0.1 s; the result is the exact-time solution.
  Eigen::VectorXd y(2);
  y << kX0, kV0;
  OdeOptions options;
  options.t1 = 1.0;
  options.step = 0.3;
  RunContext ctx;
  const OdeStats stats = integrateRk4(test::oscillatorRhs(kOmega, kZeta), y, options, ctx);
  EXPECT_EQ(stats.steps, 4);
  EXPECT_DOUBLE_EQ(stats.last_step, 0.3);
  EXPECT_EQ(stats.rhs_evaluations, 4 * 4 + 1);
  // Ending at 1.2 instead of 1.0 would be an error ~|x'|·0.2 ≈ 0.3; RK4's own error at ωh = 0.6 is
  // 1.8e-3 (order (ωh)^4/120 per step · growth), so 5e-3 separates the two.
  EXPECT_LT(oscillatorError(y, 1.0), 5e-3);
}

// Van der Pol, μ = 5, y(0) = (2, 0), over 10 s (about one relaxation cycle with two fast transitions).
Eigen::VectorXd vanDerPolRk4(double h) {
  Eigen::VectorXd y(2);
  y << 2.0, 0.0;
  OdeOptions options;
  options.t1 = 10.0;
  options.step = h;
  RunContext ctx;
  integrateRk4(test::vanDerPolRhs(5.0), y, options, ctx);
  return y;
}

TEST(OdeExplicit, VanDerPolDopri5MatchesIndependentRk4Reference) {
  // Reference: RK4 at h = 1e-4; its own error is bounded by Richardson's (y_h − y_2h)/15.
  const Eigen::VectorXd reference = vanDerPolRk4(1e-4);
  const double reference_error = (reference - vanDerPolRk4(2e-4)).cwiseAbs().maxCoeff() / 15.0;
  ASSERT_LT(reference_error, 1e-10);
  double previous = INFINITY;
  for (double tol : {1e-5, 1e-7, 1e-9, 1e-11}) {
    Eigen::VectorXd y(2);
    y << 2.0, 0.0;
    OdeOptions options;
    options.t1 = 10.0;
    options.rtol = options.atol = tol;
    RunContext ctx;
    const OdeStats stats = integrateDopri5(test::vanDerPolRhs(5.0), y, options, ctx);
    const double error = (y - reference).cwiseAbs().maxCoeff();
    // Global error within two decades of the tolerance (error growth through the fast transitions),
    // and decreasing with it.
    EXPECT_LT(error, 100.0 * tol + 10.0 * reference_error) << "tol " << tol;
    EXPECT_LT(error, previous) << "tol " << tol;
    EXPECT_GT(stats.rejected_steps, 0) << "the transitions should force some rejections";
    previous = error;
  }
}

}  // namespace
}  // namespace maris
