// How the integrators fail: divergence, non-finite right-hand sides, step-size collapse and too many
// steps become SolverError naming time and quantity; a cancel request becomes RunCancelled quickly.
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/ode.hpp"
#include "ode_test_problems.hpp"

namespace maris {
namespace {

// Stiff linear oscillator x'' + 100001 x' + 100000 x = 0: first-order eigenvalues −1 and −1e5.
constexpr double kStiffOmega = 316.22776601683796;             // √1e5 [rad/s]
constexpr double kStiffZeta = 100001.0 / (2.0 * kStiffOmega);  // [-]

TEST(OdeFailures, Rk4BeyondItsStabilityLimitReportsDivergenceAsSolverError) {
  // RK4's real stability interval is |hλ| ≤ 2.785, so h = 0.01 is 360× too large for λ = −1e5: the
  // fast mode grows by |R(−1000)| ≈ 4e10 per step and overflows within ~30 steps.
  Eigen::VectorXd y(2);
  y << 1.0, 0.0;
  OdeOptions options;
  options.t1 = 5.0;
  options.step = 0.01;
  options.state_name = test::positionVelocityName;
  RunContext ctx;
  try {
    integrateRk4(test::oscillatorRhs(kStiffOmega, kStiffZeta), y, options, ctx);
    FAIL() << "expected SolverError, final state " << y.transpose();
  } catch (const SolverError& e) {
    EXPECT_LT(e.time(), 1.0);
    EXPECT_GT(e.step(), 0);
    EXPECT_TRUE(e.quantity() == "position" || e.quantity() == "velocity") << e.what();
  }
}

// y' = (t > 0.5 ? NaN : 1) in the velocity component only.
OdeRhs nanAfterHalfSecond() {
  return [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt[0] = y[1];
    dydt[1] = t > 0.5 ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  };
}

TEST(OdeFailures, NonFiniteRightHandSideNamesTheComponent) {
  OdeOptions options;
  options.step = 0.01;
  options.state_name = test::positionVelocityName;
  RunContext ctx;
  for (int integrator = 0; integrator < 2; ++integrator) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(2);
    try {
      if (integrator == 0)
        integrateRk4(nanAfterHalfSecond(), y, options, ctx);
      else
        integrateDopri5(nanAfterHalfSecond(), y, options, ctx);
      FAIL() << "expected SolverError";
    } catch (const SolverError& e) {
      EXPECT_EQ(e.quantity(), "velocity") << e.what();
      EXPECT_NEAR(e.time(), 0.5, 0.02) << e.what();
      EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    }
  }
}

TEST(OdeFailures, Dopri5StepSizeCollapseAtABlowUpIsSolverError) {
  // y' = y², y(0) = 1 has the solution 1/(1 − t), which blows up at t = 1.
  Eigen::VectorXd y = Eigen::VectorXd::Ones(1);
  OdeOptions options;
  options.t1 = 2.0;
  options.state_name = [](Eigen::Index) { return std::string("blow-up variable"); };
  RunContext ctx;
  try {
    integrateDopri5([](double, const Eigen::VectorXd& s, Eigen::VectorXd& d) { d[0] = s[0] * s[0]; }, y, options,
                    ctx);
    FAIL() << "expected SolverError";
  } catch (const SolverError& e) {
    EXPECT_EQ(e.quantity(), "blow-up variable") << e.what();
    EXPECT_NEAR(e.time(), 1.0, 1e-3) << e.what();
  }
}

TEST(OdeFailures, TooManyStepsIsSolverError) {
  Eigen::VectorXd y(2);
  y << 1.0, 0.0;
  OdeOptions options;
  options.t1 = 10.0;
  options.max_steps = 100;
  options.rtol = options.atol = 1e-12;  // needs far more than 100 steps
  RunContext ctx;
  EXPECT_THROW(integrateDopri5(test::oscillatorRhs(2.0, 0.0), y, options, ctx), SolverError);
  options.step = 0.01;  // RK4: 1000 steps
  EXPECT_THROW(integrateRk4(test::oscillatorRhs(2.0, 0.0), y, options, ctx), SolverError);
}

// Runs `integrate` with a cancel flag set from another thread after 50 ms; returns the delay from
// setting the flag to RunCancelled reaching the caller [s], or +inf if it never came.
template <class Integrate>
double cancellationLatency(Integrate integrate) {
  std::atomic<bool> cancel{false};
  RunContext ctx({}, &cancel);
  std::chrono::steady_clock::time_point flagged;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    flagged = std::chrono::steady_clock::now();
    cancel.store(true);
  });
  double latency = INFINITY;
  try {
    integrate(ctx);
  } catch (const RunCancelled&) {
    latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - flagged).count();
  }
  canceller.join();
  return latency;
}

TEST(OdeFailures, CancellationStopsEveryIntegratorWithin100ms) {
  // Each run would take far longer than 50 ms (1e9 steps); the requirement is 100 ms after the request.
  OdeOptions options;
  options.t1 = 1e9;
  options.step = 1.0;
  options.max_steps = std::numeric_limits<long>::max();
  const double rk4 = cancellationLatency([&](RunContext& ctx) {
    Eigen::VectorXd y(2);
    y << 1.0, 0.0;
    integrateRk4(test::oscillatorRhs(1e-3, 0.0), y, options, ctx);
  });
  EXPECT_LT(rk4, 0.1);
  const double dopri5 = cancellationLatency([&](RunContext& ctx) {
    Eigen::VectorXd y(2);
    y << 1.0, 0.0;
    OdeOptions adaptive = options;
    adaptive.max_step = 1.0;
    integrateDopri5(test::oscillatorRhs(1e-3, 0.0), y, adaptive, ctx);
  });
  EXPECT_LT(dopri5, 0.1);
  const double alpha = cancellationLatency([&](RunContext& ctx) {
    Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
    integrateGeneralizedAlpha(test::oscillatorSystem(1e-3, 0.0), q, v, options, {}, ctx);
  });
  EXPECT_LT(alpha, 0.1);
}

TEST(OdeFailures, InconsistentOptionsAreRejected) {
  Eigen::VectorXd y = Eigen::VectorXd::Ones(2);
  RunContext ctx;
  OdeOptions backwards;
  backwards.t0 = 1.0;
  backwards.t1 = 0.0;
  EXPECT_THROW(integrateRk4(test::oscillatorRhs(1.0, 0.0), y, backwards, ctx), std::invalid_argument);
  OdeOptions no_step;
  no_step.step = 0.0;
  EXPECT_THROW(integrateRk4(test::oscillatorRhs(1.0, 0.0), y, no_step, ctx), std::invalid_argument);
  GeneralizedAlphaOptions bad_rho;
  bad_rho.rho_inf = 1.5;
  Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
  EXPECT_THROW(integrateGeneralizedAlpha(test::oscillatorSystem(1.0, 0.0), q, v, OdeOptions{}, bad_rho, ctx),
               std::invalid_argument);
}

}  // namespace
}  // namespace maris
