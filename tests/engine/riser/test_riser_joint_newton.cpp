// The O(n) joint-coordinate Newton matrix of the implicit integrator (riser_joint_newton): it inverts the dense
// iteration matrix of the joint chart residual closely enough, gives the same trajectories as the core's dense
// path with comparable Newton iterations, and its cost per refresh does not grow with n.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "core/ode.hpp"
#include "core/angles.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_joint_newton.hpp"
#include "riser/riser_statics.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

// 3D riser in a 1 m/s current at 0.6 rad (default section, tensioner top, pinned bottom 5 m off), joint
// coordinates, at a moving state: rest shape with random angular velocities (bottom constraint violated).
struct JointCase {
  RiserParameters p;
  RiserModel m;
  Eigen::VectorXd y;
};

JointCase movingJointModel(int n, bool torsion, bool flow) {
  JointCase c;
  c.p = test::inclinedTensionedRiser(n, "joint", flow);
  c.p.torsion = torsion;
  c.p.current_direction_deg = degreesFromRadians(0.6);
  c.m = buildRiserModel(c.p);
  c.y = restState(c.m, c.m.initial_orientation, c.m.initial_top);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int i = c.m.first_dynamic; i <= c.m.last_dynamic; ++i)
    for (int k = 4; k < 7; ++k) c.y[segmentStateOffset(c.m, i) + k] = u(rng);
  normaliseState(c.m, c.y);
  return c;
}

// S_J = ∂r/∂acc + γ'∂r/∂v + β'∂r/∂q of the joint chart residual by central differences of every column
// (independent of the twin construction).
Eigen::MatrixXd denseIterationMatrix(OrientationChart& chart, double t, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& v, const Eigen::VectorXd& acc, double dq, double dv) {
  const Eigen::Index n = chart.size();
  Eigen::MatrixXd s(n, n);
  Eigen::VectorXd rp, rm;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double e = 1e-4 * (1 + std::abs(acc[j]));
    Eigen::VectorXd qp = q, vp = v, ap = acc, qm = q, vm = v, am = acc;
    qp[j] += dq * e, vp[j] += dv * e, ap[j] += e;
    qm[j] -= dq * e, vm[j] -= dv * e, am[j] -= e;
    chart.residual(t, qp, vp, ap, rp);
    chart.residual(t, qm, vm, am, rm);
    s.col(j) = (rp - rm) / (2 * e);
  }
  return s;
}

// The twin solve x of S_J x = b leaves a defect ‖S_J x − b‖ ≤ 3e-3 ‖b‖ for random b (work rows zero), with
// random angular velocities |ω| ≤ 0.05 rad/s, both at a chart state on its reference (θ_J = 0, as at a refresh
// right after a chunk start) and moved off it by one random rotation vector of 0.03 rad for every segment (a
// nearly rigid turn, J_r ≠ I). The neglected terms (riser_joint_newton.hpp) are of relative size ω h ≈ 2.5e-3
// at h = 50 ms (the case-5 step) and β'|α||θ_J|; the dense difference error is ~1e-8 (measured defect with
// ω = 0, θ_J = 0: 2e-6–2e-5). A wrong sign, a missing coupling or a wrong chart map gives O(1), and the defect
// must be far below that of S = I (≈ 1–240 here; torsion makes S stiff).
TEST(RiserJointNewton, TwinSolveInvertsTheDenseJointIterationMatrix) {
  for (double offset : {0.0, 0.03})
    for (bool torsion : {true, false})
      for (bool flow : {false, true}) {
        JointCase c = movingJointModel(8, torsion, flow);
        OrientationChart chart(c.m, 20.0);
        Eigen::VectorXd q, v, r0;
        chart.reset(c.y, q, v);
        const Eigen::Index n = chart.size(), work = n - kWorkIntegrals;
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const Vec3 turn = offset * Vec3(u(rng), u(rng), u(rng)).normalized();
        for (Eigen::Index k = 3; k < work; k += 3) q.segment<3>(k) += turn;
        Eigen::VectorXd acc = Eigen::VectorXd::Zero(n);
        chart.residual(0.7, q, v, acc, r0);
        acc = -r0;
        const double h = 0.05, dq = 0.3025 * h * h * 1.1, dv = 0.6111 * h * 1.1;
        const Eigen::MatrixXd s = denseIterationMatrix(chart, 0.7, q, v, acc, dq, dv);
        JointNewtonMatrix newton(c.m, chart, 20.0);
        std::normal_distribution<double> g;
        for (int trial = 0; trial < 3; ++trial) {
          Eigen::VectorXd b(n);
          for (Eigen::Index k = 0; k < n; ++k) b[k] = k < work ? g(rng) : 0.0;
          Eigen::VectorXd x = b;
          const IterationMatrixRequest request{0.7, q, v, acc, dv, dq, trial == 0};
          ASSERT_TRUE(newton.solve(request, x));
          const double defect = (s * x - b).head(work).norm() / b.norm();
          const double identity_defect = (s * b - b).head(work).norm() / b.norm();
          if (std::getenv("SHOW"))
            std::printf("offset %g torsion %d flow %d: defect %.2e (S = I: %.2e)\n", offset, torsion, flow, defect,
                        identity_defect);
          EXPECT_LT(defect, 3e-3) << "offset " << offset << " torsion " << torsion << " flow " << flow;
          EXPECT_LT(defect, 1e-2 * identity_defect) << "offset " << offset << " torsion " << torsion << " flow " << flow;
        }
        EXPECT_EQ(newton.refreshes(), 1);
      }
}

// Cost check: balance evaluations per refresh are the same for n = 12 and n = 48 (2 + 2b + 1 of the twin with
// its band b = 14 without flow), while a dense matrix would need N = 3(n + 1) + 7 residuals each.
TEST(RiserJointNewton, EvaluationsPerRefreshDoNotGrowWithN) {
  long per_refresh[2] = {0, 0};
  int idx = 0;
  for (int n : {12, 48}) {
    JointCase c = movingJointModel(n, true, false);
    OrientationChart chart(c.m, 20.0);
    Eigen::VectorXd q, v, r0;
    chart.reset(c.y, q, v);
    Eigen::VectorXd acc = Eigen::VectorXd::Zero(chart.size());
    JointNewtonMatrix newton(c.m, chart, 20.0);
    for (int k = 0; k < 3; ++k) {
      Eigen::VectorXd b = Eigen::VectorXd::Ones(chart.size());
      ASSERT_TRUE(newton.solve({0.1 * k, q, v, acc, 0.03, 1e-3, true}, b));
    }
    ASSERT_EQ(newton.refreshes(), 3);
    per_refresh[idx++] = newton.balanceEvaluations() / newton.refreshes();
  }
  EXPECT_EQ(per_refresh[0], per_refresh[1]);
  EXPECT_EQ(per_refresh[0], 2 + 2 * 14 + 1);
}

// Trajectories: generalized-α on the joint chart of the 3D moving-top case (n = 8, 3 s, h = 20 ms) with the
// core's dense finite-difference matrix and with the twin matrix agree to 1e-6 m at the probe points (Newton
// tolerance 1e-8: both converge to the same step solution; a wrong matrix that still converged would give the
// same answer, so the Newton counts are checked too: the twin path may need at most 1.5x the dense path's
// residual evaluations per step, excluding the dense path's matrix columns).
TEST(RiserJointNewton, TwinMatrixGivesTheDenseTrajectoryWithComparableNewtonIterations) {
  RiserParameters p = test::shortMovingTopRun();
  p.formulation = "joint";
  p.solve_statics = false;
  const RiserModel m = buildRiserModel(p);
  const Eigen::VectorXd y0 = restState(m, m.initial_orientation, m.initial_top);
  struct Outcome {
    Eigen::VectorXd y;
    OdeStats stats;
    long newton_residuals = 0;  // residuals of the Newton iterations (not those forming a dense matrix)
  };
  auto integrate = [&](bool twin) {
    OrientationChart chart(m, 50.0);
    JointNewtonMatrix newton(m, chart, 50.0);
    SecondOrderSystem system;
    system.size = chart.size();
    system.residual = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                          Eigen::VectorXd& r) { chart.residual(t, q, v, a, r); };
    if (twin)
      system.solve_iteration_matrix = [&](const IterationMatrixRequest& request, Eigen::VectorXd& rhs) {
        return newton.solve(request, rhs);
      };
    OdeOptions options;
    options.t0 = 0.0;
    options.t1 = p.end_time;
    options.step = 0.02;
    options.rtol = options.atol = 1e-8;
    Eigen::VectorXd q, v, y = y0;
    chart.reset(y, q, v);
    RunContext ctx;
    Outcome out;
    out.stats = integrateGeneralizedAlpha(system, q, v, options, GeneralizedAlphaOptions{}, ctx);
    chart.toState(q, v, out.y);
    // The dense path forms its matrix from one residual per coordinate (counted in rhs_evaluations).
    out.newton_residuals = out.stats.rhs_evaluations - (twin ? 0 : system.size * out.stats.jacobian_evaluations);
    return out;
  };
  const Outcome dense = integrate(false), twin = integrate(true);
  RiserWorkspace wd = makeWorkspace(m, 0.0), wt = makeWorkspace(m, 0.0);
  poseFromState(m, p.end_time, dense.y, wd.pose);
  poseFromState(m, p.end_time, twin.y, wt.pose);
  double largest = 0.0;
  for (int k = 0; k <= m.n + 1; ++k) largest = std::max(largest, (wd.pose.node(k) - wt.pose.node(k)).norm());
  EXPECT_LT(largest, 1e-6);
  EXPECT_EQ(dense.stats.steps, twin.stats.steps);
  EXPECT_EQ(twin.stats.rejected_steps, 0);
  EXPECT_LE(twin.newton_residuals, 1.5 * dense.newton_residuals);
  if (std::getenv("SHOW"))
    std::printf("dense: %ld steps, %ld Newton residuals, %ld refreshes; twin: %ld Newton residuals, %ld refreshes; "
                "largest node difference %.2e m\n",
                dense.stats.steps, dense.newton_residuals, dense.stats.jacobian_evaluations, twin.newton_residuals,
                twin.stats.jacobian_evaluations, largest);
}

}  // namespace
}  // namespace maris::riser

namespace maris::riser {
namespace {

// Statics in O(n): the paper's case-5 riser (500 m, tensioner, pinned bottom, 1 m/s current, torsion)
// at n = 60 and n = 240 is solved by the banded pseudo-time Newton without the dense fallback, to the dense
// path's tolerance, with iteration counts that do not grow with n by more than a few (a dense-cost method
// would show in the run time only; this checks the path and its convergence, which can fail).
TEST(RiserJointNewton, StaticsUsesTheBandedNewtonWithoutDenseFallback) {
  int iterations[2] = {0, 0};
  int idx = 0;
  for (int n : {60, 240}) {
    RiserParameters p;
    p.length = 500.0;
    p.segment_count = n;
    p.outer_diameter = 0.5;
    p.inner_diameter = 0.45;
    p.seabed_level = -500.0;
    p.bottom_z = -500.0;
    p.top_tension = 2.5e6;
    p.current_direction_deg = 90.0;
    const RiserModel m = buildRiserModel(p);
    RunContext context;
    const StaticSolution s = solveStatics(m, context);
    EXPECT_TRUE(s.banded) << "n = " << n;
    EXPECT_LT(s.residual, 1e-11) << "n = " << n;
    iterations[idx++] = s.iterations;
  }
  EXPECT_LE(iterations[1], iterations[0] + 15);
}

}  // namespace
}  // namespace maris::riser
