// The O(n) force-space Newton matrix of the implicit integrator (riser_newton), the unreduced balance
// equations it differentiates, and the constraint projection (absolute coordinates).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "riser/riser_implicit.hpp"
#include "riser/riser_newton.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {
double kDenseStep = 1e-4;

// 3D riser in current with internal flow (widest band), tensioner top, pinned bottom, n = 6, in absolute
// coordinates with torsion, at a moving state: rest shape with random velocities (constraints violated).
struct MovingModel {
  RiserParameters p;
  RiserModel m;
  Eigen::VectorXd y;
};

MovingModel movingAbsoluteModel(bool flow) {
  MovingModel c;
  c.p = test::inclinedTensionedRiser(6, "absolute", flow);
  c.m = buildRiserModel(c.p);
  c.y = restState(c.m, c.m.initial_orientation, c.m.initial_top);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int i = c.m.first_dynamic; i <= c.m.last_dynamic; ++i) {
    const Eigen::Index o = segmentStateOffset(c.m, i);
    for (int k = 7; k < 13; ++k) c.y[o + k] = u(rng);
  }
  return c;
}

// At the accelerations and reactions of evaluateRhs, the unreduced equations hold: segment rows
// x − W(EF − D'F + b) and constraint rows vanish to round-off (1e-9 of the acceleration scale) in both formulations.
TEST(RiserNewton, BalanceResidualVanishesAtTheReactionSolution) {
  for (const char* formulation : {"joint", "absolute"}) {
    MovingModel c = movingAbsoluteModel(true);
    c.p.formulation = formulation;
    c.m = buildRiserModel(c.p);
    c.y = restState(c.m, c.m.initial_orientation, c.m.initial_top);
    RiserWorkspace ws = makeWorkspace(c.m, 3.0);
    Eigen::VectorXd dy;
    evaluateRhs(c.m, ws, 1.3, c.y, dy);
    std::vector<Vec6> seg;
    std::vector<Vec3> rows;
    balanceResidual(c.m, ws, 1.3, ws.acceleration, ws.reaction, seg, rows);
    double scale = 1.0, largest = 0.0;
    for (int i = c.m.first_dynamic; i <= c.m.last_dynamic; ++i) {
      scale = std::max(scale, ws.acceleration[i].norm());
      largest = std::max(largest, seg[i].norm());
    }
    for (const Vec3& r : rows) largest = std::max(largest, r.norm());
    EXPECT_LT(largest, 1e-9 * scale) << formulation;
  }
}

// A chart reset at a moving state starts from θ = 0 exactly (not a round-off angle with an arbitrary axis),
// and mapping back gives the same state: positions and velocities to 1e-14 (round-off), rotations to 1e-15.
TEST(RiserNewton, ChartResetStartsAtZeroRotationAndMapsBack) {
  MovingModel c = movingAbsoluteModel(false);
  OrientationChart chart(c.m, 10.0);
  Eigen::VectorXd q, v, y;
  chart.reset(c.y, q, v);
  for (int k = 0; k <= c.m.last_dynamic - c.m.first_dynamic; ++k)
    for (int e = 0; e < 3; ++e) EXPECT_EQ(q[3 + 6 * k + 3 + e], 0.0) << "segment " << k;
  chart.toState(q, v, y);
  RiserWorkspace ws_expected = makeWorkspace(c.m, 0.0), ws_mapped = makeWorkspace(c.m, 0.0);
  const RiserPose &expected = ws_expected.pose, &mapped = ws_mapped.pose;
  poseFromState(c.m, 0.0, c.y, ws_expected.pose);
  poseFromState(c.m, 0.0, y, ws_mapped.pose);
  for (int i = c.m.first_dynamic; i <= c.m.last_dynamic; ++i) {
    EXPECT_LT((mapped.position[i] - expected.position[i]).norm(), 1e-14 * c.p.length) << i;
    EXPECT_LT((mapped.velocity[i] - expected.velocity[i]).norm(), 1e-14) << i;
    EXPECT_LT((mapped.omega[i] - expected.omega[i]).norm(), 1e-14) << i;
    EXPECT_LT((mapped.rotation[i] - expected.rotation[i]).norm(), 1e-15) << i;
  }
}

// The banded solve equals the inverse of the dense iteration matrix S = ∂r/∂acc + γ'∂r/∂v + β'∂r/∂q of the
// chart residual, formed here independently by central differences of every column (the core's default path
// uses forward ones). Steps β' = β h²·1.1, γ' = γ h·1.1 of h = 20 ms. For random right sides b (work rows
// zero, whose identity block is a documented approximation), ‖S x − b‖ ≤ 1e-6 ‖b‖: the differences are
// accurate to ~1e-8 of S's scale; a wrong sign or a missing coupling gives O(1).
TEST(RiserNewton, BandedForceSpaceSolveInvertsTheDenseIterationMatrix) {
  if (const char* e = std::getenv("DENSE_STEP")) kDenseStep = std::atof(e);
  for (bool flow : {false, true}) {
    MovingModel c = movingAbsoluteModel(flow);
    OrientationChart chart(c.m, 10.0);
    Eigen::VectorXd q, v, r0, rp, rm;
    chart.reset(c.y, q, v);
    const Eigen::Index n = chart.size();
    Eigen::VectorXd acc = Eigen::VectorXd::Zero(n);
    chart.residual(0.7, q, v, acc, r0);
    acc = -r0;  // the accelerations of (q, v)
    const double h = 0.02, dq = 0.3025 * h * h * 1.1, dv = 0.6111 * h * 1.1;
    Eigen::MatrixXd s(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const double e = kDenseStep * (1 + std::abs(acc[j]));
      Eigen::VectorXd qp = q, vp = v, ap = acc, qm = q, vm = v, am = acc;
      qp[j] += dq * e, vp[j] += dv * e, ap[j] += e;
      qm[j] -= dq * e, vm[j] -= dv * e, am[j] -= e;
      chart.residual(0.7, qp, vp, ap, rp);
      chart.residual(0.7, qm, vm, am, rm);
      s.col(j) = (rp - rm) / (2 * e);
    }
    ForceSpaceNewtonMatrix newton(c.m, chart);
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    const Eigen::Index work = n - kWorkIntegrals;
    for (int trial = 0; trial < 3; ++trial) {
      Eigen::VectorXd b(n);
      for (Eigen::Index k = 0; k < n; ++k) b[k] = k < work ? g(rng) : 0.0;
      Eigen::VectorXd x = b;
      const IterationMatrixRequest request{0.7, q, v, acc, dv, dq, trial == 0};
      ASSERT_TRUE(newton.solve(request, x));
      const Eigen::VectorXd defect = (s * x - b).head(work);
      EXPECT_LT(defect.norm(), 1e-6 * b.norm()) << "flow " << flow << " trial " << trial << ": " << defect.norm() / b.norm();
      if (std::getenv("SHOW")) std::printf("defect %g\n", defect.norm() / b.norm());
      EXPECT_GT((x - b).norm(), 1e-2 * b.norm()) << "S must differ from I for the test to mean anything";
    }
    EXPECT_EQ(newton.refreshes(), 1);
    EXPECT_EQ(newton.bandwidth(), flow ? 23 : 14);
  }
}

// Projection: a state with violated joints (random velocities, positions moved by up to 5 cm). |Φ| ≤ 1e-9 m;
// the velocities are left as they were (their mismatch to Baumgarte: projectConstraints says why). Pinned
// bottom: after two sweeps (the bottom's mismatch spread over turns of all segments converges quadratically
// from 5e-2 m). Free bottom: closed by translation alone, orientations untouched.
TEST(RiserNewton, ProjectionRestoresTheConstraints) {
  for (const bool pinned : {true, false}) {
    MovingModel c = movingAbsoluteModel(false);
    if (!pinned) c.m.bottom = BottomCondition::Free;
    ASSERT_EQ(bottomHeld(c.m), pinned);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    for (int i = c.m.first_dynamic; i <= c.m.last_dynamic; ++i)
      for (int k = 0; k < 3; ++k) c.y[segmentStateOffset(c.m, i) + k] += u(rng);
    const Eigen::VectorXd start = c.y;
    RiserWorkspace ws = makeWorkspace(c.m, 0.0);
    poseFromState(c.m, 0.4, c.y, ws.pose);
    const ConstraintViolation before = constraintViolation(c.m, ws.pose, 0.4);
    EXPECT_GT(before.largest, 1e-2);
    const double after = projectConstraints(c.m, ws, 0.4, c.y, 2);
    EXPECT_LT(after, 1e-9) << pinned;
    const ConstraintViolation phi = constraintViolation(c.m, ws.pose, 0.4);
    EXPECT_GT(phi.velocity[1].norm(), 1e-2) << "the velocities' mismatch must be there for the test to mean anything";
    for (int i = c.m.first_dynamic; i <= c.m.last_dynamic; ++i) {
      const Eigen::Index o = segmentStateOffset(c.m, i);
      EXPECT_EQ(c.y.segment<6>(o + 7), start.segment<6>(o + 7)) << "velocities " << i;
      if (!pinned) {
        EXPECT_EQ(c.y.segment<4>(o + 3), start.segment<4>(o + 3)) << "orientation " << i;
      }
    }
  }
}

// n = 1000 ("runs at all"): a 1000 m riser in absolute coordinates with torsion, implicit steps of
// 50 ms (the explicit torsion limit is ~0.2 ms) over 0.5 s at tolerance 1e-6, no current (the straight shape is the
// static one, skipping the dense statics), top starting its elliptical motion: its 10 steps, none rejected, finite
// results and joints held together (|Φ| < 1e-6 m, projected after every step). The whole case 5 at n = 1000 (36 s,
// 720 steps, none rejected, ≈ 7 s) is a bench row, too long for a test under the sanitizers.
TEST(RiserNewton, ThousandSegmentsRunImplicitly) {
  MARIS_RELEASE_ONLY("RiserNewton.BandedForceSpaceSolveInvertsTheDenseIterationMatrix");
  RiserParameters p;
  p.length = 1000.0;
  p.segment_count = 1000;
  p.bottom_z = -1000.0;
  p.seabed_level = -1000.0;
  p.formulation = "absolute";
  p.solve_statics = false;
  p.integrator = "implicit";
  p.time_step = 0.05;
  p.tolerance = 1e-6;
  p.end_time = 0.5;
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.frame_count = 1;
  p.stress_times.clear();
  RunContext context;
  const Results r = solveRiser(p, context);
  EXPECT_EQ(r.stats.steps, 10);
  EXPECT_EQ(r.stats.rejected_steps, 0);
  EXPECT_LT(r.findScalar("constraint_drift")->value, 1e-6);
  EXPECT_TRUE(std::isfinite(r.findScalar("max_tension")->value));
}

}  // namespace
}  // namespace maris::riser
