// Levenberg–Marquardt (core/least_squares.hpp) on problems whose minimum is known in closed form.
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/least_squares.hpp"

namespace maris {
namespace {

// Rosenbrock's function as least squares: r = (10 (x₂ − x₁²), 1 − x₁); minimum 0 at (1, 1).
LeastSquaresProblem rosenbrock(bool analytic_jacobian) {
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    r = Eigen::Vector2d(10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0]);
    return true;
  };
  if (analytic_jacobian)
    p.jacobian = [](const Eigen::VectorXd& x, const Eigen::VectorXd&, Eigen::MatrixXd& j) {
      j.resize(2, 2);
      j << -20.0 * x[0], 10.0, -1.0, 0.0;
      return true;
    };
  return p;
}

TEST(LeastSquares, RosenbrockFromTheClassicalStart) {
  // Start (−1.2, 1) (Rosenbrock 1960). The residual is zero at the minimum, so LM converges
  // quadratically: 1e-10 on x is round-off plus the last step, far above machine precision.
  for (const bool analytic : {true, false})
    for (const auto damping : {LeastSquaresDamping::Marquardt, LeastSquaresDamping::Levenberg}) {
      LeastSquaresOptions o;
      o.damping = damping;
      const LeastSquaresReport rep = levenbergMarquardt(rosenbrock(analytic), Eigen::Vector2d(-1.2, 1.0), o);
      EXPECT_TRUE(rep.converged) << describe(rep.stop);
      EXPECT_NEAR(rep.x[0], 1.0, 1e-10);
      EXPECT_NEAR(rep.x[1], 1.0, 1e-10);
      EXPECT_LT(rep.cost, 1e-20);
      EXPECT_NEAR(rep.initial_cost, 4.4 * 4.4 + 2.2 * 2.2, 1e-12);  // r(x0) = (−4.4, 2.2)
      EXPECT_LE(rep.iterations, 100);
    }
}

TEST(LeastSquares, StraightLineFitMatchesTheNormalEquations) {
  // Linear model c₀ + c₁ t through non-collinear data: the optimum is the normal-equations solution
  // (closed form), and its cost is the residual sum of squares there. 1e-9 relative: round-off of a
  // well-conditioned 2 × 2 system plus the forward-difference Jacobian, exact for a linear model.
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0, 4.0}, y{1.1, 2.9, 5.2, 6.8, 9.1};
  LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& c, Eigen::VectorXd& r) {
    r.resize(5);
    for (int i = 0; i < 5; ++i) r[i] = c[0] + c[1] * t[i] - y[i];
    return true;
  };
  Eigen::MatrixXd a(5, 2);
  Eigen::VectorXd b(5);
  for (int i = 0; i < 5; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = t[i];
    b[i] = y[i];
  }
  const Eigen::Vector2d exact = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  const double exact_cost = (a * exact - b).squaredNorm();
  const LeastSquaresReport rep = levenbergMarquardt(p, Eigen::Vector2d(0.0, 0.0), {});
  EXPECT_TRUE(rep.converged) << describe(rep.stop);
  EXPECT_NEAR(rep.x[0], exact[0], 1e-9 * std::abs(exact[0]));
  EXPECT_NEAR(rep.x[1], exact[1], 1e-9 * std::abs(exact[1]));
  EXPECT_NEAR(rep.cost, exact_cost, 1e-9 * exact_cost);
}

TEST(LeastSquares, ExponentialDecayRecoversItsParameters) {
  // Data y = 2 e^{−0.5 t} sampled exactly: the optimum (2, −0.5) has cost 0. Start far off (1, 0).
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& c, Eigen::VectorXd& r) {
    r.resize(20);
    for (int i = 0; i < 20; ++i) {
      const double t = 0.25 * i;
      r[i] = c[0] * std::exp(c[1] * t) - 2.0 * std::exp(-0.5 * t);
    }
    return true;
  };
  const LeastSquaresReport rep = levenbergMarquardt(p, Eigen::Vector2d(1.0, 0.0), {});
  EXPECT_TRUE(rep.converged) << describe(rep.stop);
  EXPECT_NEAR(rep.x[0], 2.0, 1e-8);
  EXPECT_NEAR(rep.x[1], -0.5, 1e-8);
}

TEST(LeastSquares, TrialPointKeepsABoundAndTheOptimumSitsOnIt) {
  // min (x − 3)² subject to x ≤ 1 (by clamping the trial point): the constrained optimum is x = 1,
  // cost 4. Without descent beyond the bound the solver stops with NoDescent or a converged step.
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    r = Eigen::VectorXd::Constant(1, x[0] - 3.0);
    return true;
  };
  p.trial_point = [](const Eigen::VectorXd& x, const Eigen::VectorXd& d) {
    return Eigen::VectorXd((x + d).cwiseMin(1.0));
  };
  const LeastSquaresReport rep = levenbergMarquardt(p, Eigen::VectorXd::Constant(1, -2.0), {});
  EXPECT_DOUBLE_EQ(rep.x[0], 1.0);
  EXPECT_DOUBLE_EQ(rep.cost, 4.0);
  EXPECT_EQ(rep.initial_cost, 25.0);
}

TEST(LeastSquares, ReportsAnUndefinedStartAndRejectsUndefinedTrials) {
  LeastSquaresProblem p;
  // r = √x − 2 is defined for x ≥ 0 only; minimum at x = 4.
  p.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    if (x[0] < 0.0) return false;
    r = Eigen::VectorXd::Constant(1, std::sqrt(x[0]) - 2.0);
    return true;
  };
  const LeastSquaresReport bad = levenbergMarquardt(p, Eigen::VectorXd::Constant(1, -1.0), {});
  EXPECT_EQ(bad.stop, LeastSquaresStop::InvalidStart);
  EXPECT_FALSE(bad.converged);
  EXPECT_EQ(bad.iterations, 0);
  // From x = 0.01 the first Gauss–Newton step would be far negative only for tiny μ; every accepted
  // point must be admissible and the fit reaches x = 4 (tolerance: the 1e-7 forward-difference step).
  const LeastSquaresReport good = levenbergMarquardt(p, Eigen::VectorXd::Constant(1, 0.01), {});
  EXPECT_TRUE(good.converged) << describe(good.stop);
  EXPECT_NEAR(good.x[0], 4.0, 1e-6);
}

TEST(LeastSquares, StopsAtTheIterationLimit) {
  LeastSquaresOptions o;
  o.max_iterations = 2;
  const LeastSquaresReport rep = levenbergMarquardt(rosenbrock(true), Eigen::Vector2d(-1.2, 1.0), o);
  EXPECT_EQ(rep.stop, LeastSquaresStop::IterationLimit);
  EXPECT_FALSE(rep.converged);
  EXPECT_EQ(rep.iterations, 2);
  EXPECT_LT(rep.cost, rep.initial_cost);  // every accepted step descends
}

}  // namespace
}  // namespace maris
