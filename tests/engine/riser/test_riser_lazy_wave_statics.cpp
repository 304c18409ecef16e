// The lazy-wave riser's statics from the piecewise catenary start (riser_piecewise_catenary): the start against the
// closed-form grounded catenary where the weight is uniform, the O(n) Newton converged without dynamic relaxation
// over a range of n, and its shape against the one dynamic relaxation (an independent method) reaches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "riser/riser_piecewise_catenary.hpp"
#include "riser/riser_relaxation.hpp"
#include "riser/riser_statics.hpp"
#include "riser_test_cases.hpp"
#include "sanitized_build.hpp"

namespace maris::riser {
namespace {

RiserParameters lazyWave(int n) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_lazy_wave.json");
  p.segment_count = n;
  return p;
}

std::vector<double> nodeArcLengths(const RiserModel& m) {
  std::vector<double> s;
  for (const Segment& g : m.segments) s.push_back(g.arc_start);
  s.push_back(m.length);
  return s;
}

// Joint positions A_0 .. A_n of a joint state.
std::vector<Vec3> jointPositions(const RiserModel& m, const Eigen::VectorXd& y) {
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  poseFromState(m, 0.0, y, ws.pose);
  return {ws.pose.position.begin(), ws.pose.position.end()};
}

// Uniform submerged weight (the lazy-wave riser without its modules): the piecewise solution is the closed-form
// grounded catenary of seabedInitialPoints (s = √(h(h + 2a)), span L − s + a asinh(s/a)). Both are found by
// bisection to round-off; 1e-6 m on 800 m.
TEST(RiserLazyWaveStatics, UniformWeightGivesTheClosedFormGroundedCatenary) {
  RiserParameters p = lazyWave(40);
  p.buoyancy_modules.clear();
  const RiserModel m = buildRiserModel(p);
  ASSERT_FALSE(submergedWeightVaries(m.segments));
  const std::vector<double> s = nodeArcLengths(m);
  const auto line = piecewiseCatenary(m.segments, m.seabed.get(), m.initial_top, m.anchor, m.length, s);
  const auto closed = seabedInitialPoints(*m.seabed, m.initial_top, m.anchor, m.length, s);
  ASSERT_TRUE(line.has_value());
  ASSERT_EQ(line->points.size(), closed.size());
  for (std::size_t k = 0; k < closed.size(); ++k) EXPECT_LT((line->points[k] - closed[k]).norm(), 1e-6) << k;
  EXPECT_LT(line->touchdown, m.length);  // part of it lies on the bed
}

// With the modules: the start runs from the top to the anchor (1e-6 m), heavy–buoyant–heavy gives a sag bend and a
// hog bend above it before the touchdown, and the weight changes along the riser (the start is used).
TEST(RiserLazyWaveStatics, PiecewiseStartHasSagAndHogBendsAndEndsAtTheAnchor) {
  const RiserModel m = buildRiserModel(lazyWave(40));
  ASSERT_TRUE(submergedWeightVaries(m.segments));
  const std::vector<double> s = nodeArcLengths(m);
  const auto line = piecewiseCatenary(m.segments, m.seabed.get(), m.initial_top, m.anchor, m.length, s);
  ASSERT_TRUE(line.has_value());
  EXPECT_LT((line->points.front() - m.initial_top).norm(), 1e-9);
  EXPECT_LT((line->points.back() - m.anchor).norm(), 1e-6);
  // Heights at the nodes: a local minimum (sag bend) above the modules' start, a local maximum (hog bend) among them.
  int minima = 0, maxima = 0;
  for (std::size_t k = 1; k + 1 < s.size() && s[k] < line->touchdown; ++k) {
    const double z0 = line->points[k - 1].z(), z1 = line->points[k].z(), z2 = line->points[k + 1].z();
    if (z1 < z0 && z1 < z2) ++minima;
    if (z1 > z0 && z1 > z2) {
      ++maxima;
      EXPECT_GT(s[k], 400.0);
      EXPECT_LT(s[k], 550.0);
    }
  }
  EXPECT_EQ(minima, 1);
  EXPECT_EQ(maxima, 1);
}

// The O(n) Newton from the piecewise start: no dynamic relaxation, no dense fallback, no warning, at most 15
// iterations for every n from 20 to 60 and at 80 and 100 (measured 8–11; from the uniform catenary start it took
// 35–102 damped iterations and needed dynamic relaxation at n = 30, 38, 44, 50). Under the sanitizers those four
// n only (the same code paths at each n); the whole range is checked in the Release build.
TEST(RiserLazyWaveStatics, NewtonConvergesWithoutRelaxationOverARangeOfN) {
  std::vector<int> counts;
  for (int n = 20; n <= 60; n += 2) counts.push_back(n);
  counts.insert(counts.end(), {80, 100});
  if (::maris::test::kSanitizedBuild) counts = {30, 38, 44, 50};
  for (int n : counts) {
    const RiserModel m = buildRiserModel(lazyWave(n));
    RunContext context;
    const StaticSolution s = solveStatics(m, context);
    EXPECT_TRUE(s.banded) << "n = " << n;
    EXPECT_EQ(s.relaxation_steps, 0) << "n = " << n;
    EXPECT_TRUE(context.warnings().empty()) << "n = " << n << ": " << context.warnings().front();
    EXPECT_LE(s.iterations, 15) << "n = " << n;
    EXPECT_LT(s.residual, 1e-11) << "n = " << n;
  }
}

// Dynamic relaxation (riser_relaxation: damped motion, generalized-α) run for 20 pendulum periods reaches the
// Newton's shape: every joint within 1e-6 m (measured: the difference falls ×4 per period to 5e-10–9e-10 m after
// 15 periods and stays there, the relaxation's own integration tolerance; 0.2–0.4 m after the first period).
// Under the sanitizers n = 30 only, relaxed for 12 periods (the same code paths; 0.4 m / 4¹¹ ≈ 1e-7 m, inside
// the same 1e-6 m): n = 50 and the full 20 periods are checked in the Release build.
TEST(RiserLazyWaveStatics, NewtonShapeAgreesWithDynamicRelaxation) {
  constexpr bool kSanitized = ::maris::test::kSanitizedBuild;
  const std::vector<int> counts = kSanitized ? std::vector<int>{30} : std::vector<int>{30, 50};
  const double periods = kSanitized ? 12.0 : 20.0;
  for (int n : counts) {
    const RiserModel m = buildRiserModel(lazyWave(n));
    RunContext context;
    const StaticSolution s = solveStatics(m, context);
    RiserModel still = m;
    still.motion_amplitude.setZero();
    DampedRelaxation relax(still);
    Eigen::VectorXd y = restState(relax.model(), m.initial_orientation, m.initial_top);
    relax.advance(y, periods * relax.period(), context);
    const auto newton = jointPositions(m, restState(m, s.orientation, s.top));
    const auto relaxed = jointPositions(relax.model(), y);
    ASSERT_EQ(newton.size(), relaxed.size());
    double worst = 0.0;
    for (std::size_t k = 0; k < newton.size(); ++k) worst = std::max(worst, (newton[k] - relaxed[k]).norm());
    EXPECT_LT(worst, 1e-6) << "n = " << n;
  }
}

}  // namespace
}  // namespace maris::riser
