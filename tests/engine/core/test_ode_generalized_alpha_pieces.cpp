// Generalized-α run in pieces (GeneralizedAlphaState) and passive coordinates (SecondOrderSystem::
// passive_coordinates): a run continued call by call with its state is the run of one call; a passive
// coordinate, however it converges, does not hold back the Newton iterations of the others.
#include <cmath>

#include <gtest/gtest.h>

#include "core/closed_forms.hpp"
#include "core/errors.hpp"
#include "core/ode.hpp"
#include "ode_test_problems.hpp"

namespace maris {
namespace {

// A slow mode x (ω ≈ 1 rad/s, cubic spring so that Newton iterates) tied to a stiff mode y (ω ≈ 1000 rad/s)
// that h = 10 ms leaves unresolved; ρ∞ = 0.8 damps it by 0.8 per step.
SecondOrderSystem slowAndStiff() {
  SecondOrderSystem s;
  s.size = 2;
  s.residual = [](double, const Eigen::VectorXd& q, const Eigen::VectorXd&, const Eigen::VectorXd& acc,
                  Eigen::VectorXd& r) {
    r[0] = acc[0] + q[0] + 0.5 * q[0] * q[0] * q[0] + 0.1 * (q[0] - q[1]);
    r[1] = acc[1] + 1e6 * (q[1] - q[0]);
  };
  return s;
}

struct PiecewiseRun {
  Eigen::VectorXd q, v;
  OdeStats stats;
};

// From x = 1, y = 0 (the stiff mode fully excited) to t = 1 s in `pieces` calls, with or without the state.
PiecewiseRun runInPieces(int pieces, bool carry_state) {
  PiecewiseRun run{Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d::Zero(), {}};
  GeneralizedAlphaState state;
  OdeOptions options;
  options.step = 0.01;
  options.rtol = 1e-12;
  options.atol = 1e-14;
  RunContext ctx;
  for (int k = 0; k < pieces; ++k) {
    options.t0 = static_cast<double>(k) / pieces;
    options.t1 = static_cast<double>(k + 1) / pieces;
    const OdeStats s = integrateGeneralizedAlpha(slowAndStiff(), run.q, run.v, options, {}, ctx, {},
                                                 carry_state ? &state : nullptr);
    run.stats.steps += s.steps;
    run.stats.rejected_steps += s.rejected_steps;
  }
  return run;
}

TEST(GeneralizedAlphaPieces, ContinuingWithTheStateIsTheRunOfOneCall) {
  const PiecewiseRun whole = runInPieces(1, true), carried = runInPieces(10, true), restarted = runInPieces(10, false);
  ASSERT_EQ(whole.stats.steps, 100);
  EXPECT_EQ(carried.stats.steps, 100);
  EXPECT_EQ(carried.stats.rejected_steps, 0);
  // Same discrete solution up to the Newton tolerance (the pieces refresh their iteration matrix at each start;
  // measured 8e-13 in q, 4e-12 in v).
  EXPECT_LT((carried.q - whole.q).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((carried.v - whole.v).cwiseAbs().maxCoeff(), 1e-8);
  // Restarting from the exact acceleration of each piece's first state re-injects the stiff mode's
  // acceleration (≈ 1e6 × its displacement): a different solution (measured 5.3e-4 away). The check above
  // means something.
  EXPECT_GT((restarted.q - whole.q).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(GeneralizedAlphaPieces, StateOfTheWrongSizeIsIgnoredAndFilled) {
  GeneralizedAlphaState state;
  state.acceleration = Eigen::VectorXd::Zero(5);  // not this system's: the initial acceleration is solved
  Eigen::VectorXd q = Eigen::Vector2d(1.0, 0.0), v = Eigen::Vector2d::Zero();
  OdeOptions options;
  options.t1 = 0.05;
  options.step = 0.01;
  RunContext ctx;
  integrateGeneralizedAlpha(slowAndStiff(), q, v, options, {}, ctx, {}, &state);
  ASSERT_EQ(state.acceleration.size(), 2);
  ASSERT_EQ(state.pseudo_acceleration.size(), 2);
  // The end acceleration satisfies the equation at the end state (Newton tolerance 1e-6 relative).
  Eigen::VectorXd r(2);
  slowAndStiff().residual(options.t1, q, v, state.acceleration, r);
  EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-6 * (1.0 + state.acceleration.cwiseAbs().maxCoeff()));
}

// An oscillator x with a passive record w whose residual jumps by ±1000 at every call (a record that never
// settles); the caller's iteration matrix is exact for x and the identity for w. Counted in the convergence
// test, w makes every step fail; as a passive coordinate it leaves x to converge, at the oscillator's accuracy.
TEST(GeneralizedAlphaPieces, PassiveCoordinateDoesNotHoldBackTheOthers) {
  constexpr double kOmega = 2.0, kZeta = 0.1;
  long calls = 0;
  const SecondOrderSystem oscillator = test::oscillatorSystem(kOmega, kZeta);  // writes r[0] from entry 0
  SecondOrderSystem s;
  s.size = 2;
  s.residual = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                   Eigen::VectorXd& r) {
    oscillator.residual(t, q, v, acc, r);
    r[1] = acc[1] - ((calls++ % 2) ? 1e3 : -1e3);
  };
  s.solve_iteration_matrix = [&](const IterationMatrixRequest& req, Eigen::VectorXd& rhs) {
    rhs[0] /= 1 + req.dv_dacc * 2 * kZeta * kOmega + req.dq_dacc * kOmega * kOmega;
    return true;
  };
  OdeOptions options;
  options.t1 = 2.0;
  options.step = 0.01;
  options.min_step = 1e-3;
  RunContext ctx;
  Eigen::VectorXd q = Eigen::Vector2d(1.0, 0.0), v = Eigen::Vector2d(0.5, 0.0);
  EXPECT_THROW(integrateGeneralizedAlpha(s, q, v, options, {}, ctx), SolverError);

  s.passive_coordinates = 1;
  q = Eigen::Vector2d(1.0, 0.0);
  v = Eigen::Vector2d(0.5, 0.0);
  const OdeStats stats = integrateGeneralizedAlpha(s, q, v, options, {}, ctx);
  EXPECT_EQ(stats.rejected_steps, 0);
  const OscillatorState exact = dampedOscillator(kOmega, kZeta, 1.0, 0.5, options.t1);
  // Second order at h = 0.01: phase error ≈ (ωh)²/12 · ωt · |x| = 1.5e-4 (measured 7.2e-5).
  EXPECT_LT(std::abs(q[0] - exact.position), 2e-4);
}

}  // namespace
}  // namespace maris
