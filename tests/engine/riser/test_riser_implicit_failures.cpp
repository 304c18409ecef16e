// Implicit integrator near its limits: a Newton iterate that leaves the rotation-vector chart must make the
// integrator halve its step (not end the run), and a failure that remains must name time, step and quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {

// Probe displacement at the last history sample.
double finalProbeX(const Results& r) {
  return r.findTable("history")->find("probe_dx")->values.back();
}

// An iterate with |θ| ≥ 5 rad for one segment: the residual is NaN (the core then halves the step) and
// chartOverflow names that segment and the time. Below the limit the residual is finite.
TEST(RiserImplicitFailures, ResidualBeyondTheChartIsNonFiniteAndNamed) {
  RiserParameters p;
  p.segment_count = 6;
  p.solve_statics = false;
  const RiserModel m = buildRiserModel(p);
  OrientationChart chart(m, 10.0);
  Eigen::VectorXd y = restState(m, m.initial_orientation, m.initial_top), q, v, r;
  chart.reset(y, q, v);
  const Eigen::VectorXd acc = Eigen::VectorXd::Zero(chart.size());
  EXPECT_TRUE(std::isnan(chart.chartOverflow().t));
  const Eigen::Index theta_x = 3 + 2 * chart.perSegment() + (chart.perSegment() == 6 ? 3 : 0);  // 3rd dynamic segment
  q[theta_x] = 1.0;
  chart.residual(0.5, q, v, acc, r);
  EXPECT_TRUE(r.allFinite());
  EXPECT_TRUE(std::isnan(chart.chartOverflow().t));
  q[theta_x] = 6.0;
  chart.residual(0.75, q, v, acc, r);
  EXPECT_TRUE(r.array().isNaN().all());
  EXPECT_EQ(chart.chartOverflow().t, 0.75);
  EXPECT_EQ(chart.chartOverflow().quantity, "segment " + std::to_string(m.first_dynamic + 2) + " rotation vector");
}

// Case 5 in absolute coordinates without torsion (A2) at h = T/5 = 2 s: Newton fails on some steps (at T/25
// it ran off the chart near t = 4.9 s and the run ended with "rotated 6.9 rad within one chunk" before the
// held bottom's mismatch was spread over all rotations; T/10 failed until the swing–twist chart without
// torsion, so the test now takes T/5). With the step halved it finishes, with rejected steps to show the
// halving (measured 5 of 17), and its probe motion at t = 8 s is as close to h = T/200 as generalized-α at
// 5 steps per period can be: its period error ≈ (ωh)²/12 = 13 % gives a phase error ≈ 0.66 rad over the
// 0.8 period, so up to ~0.6 of the amplitude, more with ρ∞'s damping (measured 0.62; J2 at T/5, never
// halved, 0.76; 0.31 while Newton, giving up on its first matrix, halved 25 of 88 steps and so refined the
// run; at T/10, without halvings, 0.18 against the estimate 0.17). Asserted: within 0.9 of the amplitude (a
// step that diverged, or a halving that lost the state, leaving the riser near rest, would not be). Under the
// sanitizers the reference takes T/50 (period error (ωh)²/12 ≈ 1.3e-3, far inside that bound).
TEST(RiserImplicitFailures, StepTooLongForNewtonIsHalvedNotFatal) {
  RiserParameters p = test::paperCaseFive();
  p.formulation = "absolute";
  p.torsion = false;
  p.integrator = "implicit";
  p.end_time = 8.0;
  p.frame_count = 2;
  p.stress_times.clear();
  p.time_step = p.motion_period / 5;
  RunContext context;
  Results coarse;
  ASSERT_NO_THROW(coarse = solveRiser(p, context));
  EXPECT_GT(coarse.stats.rejected_steps, 0);
  p.time_step = p.motion_period / (::maris::test::kSanitizedBuild ? 50 : 200);
  const Results fine = solveRiser(p, context);
  const auto& motion = fine.findTable("history")->find("probe_dx")->values;
  double amplitude = 0;
  for (double d : motion) amplitude = std::max(amplitude, std::abs(d));
  ASSERT_GT(amplitude, 0.1);
  EXPECT_LT(std::abs(finalProbeX(coarse) - finalProbeX(fine)), 0.9 * amplitude);
}

// Case 5 at n = 400 in 0.5 s chunks (frames), h = 50 ms: no rejected step in either formulation. Before the
// integrator's accelerations were carried over the chunks' chart resets (GeneralizedAlphaState) and the work
// integrals left out of Newton's convergence test (passive coordinates), absolute coordinates halved their
// steps at the start (t ≈ 0.1 s) and after chunk starts (t ≈ 3.5 s): 406 of 1837 steps over the 36 s, 111 of
// 496 in this 6 s run (joint coordinates: 8 of 145 with the work integrals counted in, before their rows were
// completed per step).
TEST(RiserImplicitFailures, FineChainInShortChunksTakesNoRejectedSteps) {
  MARIS_RELEASE_ONLY("RiserImplicitFailures.FreeCableInAbsoluteCoordinatesTakesCoarseStepsWithoutRejection");
  for (const char* formulation : {"absolute", "joint"}) {
    RiserParameters p = test::paperCaseFive();
    p.formulation = formulation;
    p.segment_count = 400;
    p.integrator = "implicit";
    p.time_step = 0.05;
    p.end_time = 6.0;
    p.frame_count = 12;
    p.stress_times.clear();
    RunContext context;
    const Results r = solveRiser(p, context);
    EXPECT_EQ(r.stats.steps, 120) << formulation;
    EXPECT_EQ(r.stats.rejected_steps, 0) << formulation;
  }
}

// The 3D cable (free bottom) at n = 200 with steps of T/25 over its 2 s smooth start: no rejected step in
// absolute coordinates. While the projection after each step closed the joints mass-weighted, it did so by
// turning the 15 cm segments (a rotation is the cheaper move in the mass metric), kinking the chain; the
// bending springs then failed Newton again and again (here 464 steps, 118 rejected; bench, 10 s: 1043 steps
// instead of 63 at n = 200). Closing the joints by translation takes the 13 steps.
TEST(RiserImplicitFailures, FreeCableInAbsoluteCoordinatesTakesCoarseStepsWithoutRejection) {
  RiserParameters p = test::implicitCable(200, 0.16);
  ASSERT_EQ(p.bottom_condition, "free");
  p.end_time = 2.0;
  RunContext context;
  const Results r = solveRiser(p, context);
  EXPECT_EQ(r.stats.steps, 13);
  EXPECT_EQ(r.stats.rejected_steps, 0);
  EXPECT_LT(r.findScalar("constraint_drift")->value, 1e-5 * p.length);
}

// A slack cable held at both ends (the 3D cable pinned to an anchor 26.9 m away, n = 100) at T/25 over 10 s:
// its bottom's mismatch, spread over small turns of all segments, lets A3 take the nominal 63 steps (measured
// 63, none rejected). At T/25 A's Newton is on its edge here: while a step whose second iterate diverged was
// given up at once, it took 85 steps, 11 rejected, in equal steps of 10/63 s (A2 118, 21); Newton now forms
// its matrix once more at that iterate (core/ode_newton.cpp), and A2 also takes 63, none. The mass-weighted
// projection of every joint took 441, 107 rejected; J3 63, none.
TEST(RiserImplicitFailures, SlackCableHeldAtBothEndsKeepsItsSteps) {
  MARIS_RELEASE_ONLY("RiserImplicitFailures.SlackCableHeldAtBothEndsBetweenFramesKeepsItsSteps (the same cable, "
                     "integrator and step, in 40 output chunks)");
  const RiserParameters p = test::implicitCableHeldAtBothEnds(100, 0.16);
  RunContext context;
  const Results r = solveRiser(p, context);
  EXPECT_LE(r.stats.steps, 66);
  EXPECT_LE(r.stats.rejected_steps, 1);
}

// The same with the scenario's 40 frames (0.25 s output intervals, each an integration chunk) at h = 0.16 s:
// while each interval was closed by a 0.09 s step, A3 took 247 steps with 92 rejected (J3 82, 1), and A2 263
// with 100: Newton diverged on the first full step after the short one, at the top segments' positions. Cut
// into two equal steps of 0.125 s: A3, A2 and J3 80 steps, none rejected (nominal 80; A3 81, 1 and A2 93, 7
// before Newton formed its matrix again at a diverging second iterate, which alone leaves 178, 51 with the
// short steps).
// Under the sanitizers the first 2.5 s in the same 0.25 s chunks (the same code paths, a quarter of the steps:
// nominal 20, accepted ≤ 21, rejected ≤ 2); the whole run is checked in the Release build.
TEST(RiserImplicitFailures, SlackCableHeldAtBothEndsBetweenFramesKeepsItsSteps) {
  constexpr bool kSanitized = ::maris::test::kSanitizedBuild;
  RiserParameters p = test::implicitCableHeldAtBothEnds(100, 0.16);
  p.frame_count = kSanitized ? 10 : 40;
  if (kSanitized) p.end_time = 2.5;
  p.modes = false;  // the steps only: the natural frequencies do not enter the time history
  RunContext context;
  const Results r = solveRiser(p, context);
  EXPECT_LE(r.stats.steps, kSanitized ? 21 : 84);
  EXPECT_LE(r.stats.rejected_steps, 2);
}

}  // namespace
}  // namespace maris::riser
