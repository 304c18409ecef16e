// Statics where dynamic relaxation cannot settle: a riser whose buoyant part floats at the water line (refused, the
// fields named) and the relaxation's step limit (riser_statics, riser_relaxation).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_relaxation.hpp"
#include "riser/riser_scene.hpp"
#include "riser/riser_statics.hpp"
#include "riser_test_cases.hpp"
#include "sanitized_build.hpp"

namespace maris::riser {
namespace {

// The lazy-wave riser (800 m, top pinned 20 m below the surface) with its modules from the top to s = 550 m: a net
// lift of 1993 N/m over 550 m against 1001 N/m of submerged weight over the last 250 m.
RiserParameters floatingLazyWave(int n) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_lazy_wave.json");
  p.segment_count = n;
  p.buoyancy_modules.front().start = 0.0;
  return p;
}

// Why it is refused: with buoyancy wherever the pipe is (the still-water level raised out of reach) the O(n) Newton
// finds an equilibrium whose buoyant arch rises 80 m above z = 0. Any fully submerged equilibrium of the real model
// would be one of this model too (the loads agree below the surface), so there is none below the surface, and the
// riser floats: measured up to z = +80.3 m at n = 40; asserted above +50 m.
TEST(RiserRelaxationLimits, WithoutTheSurfaceTheBuoyantArchRisesAboveIt) {
  RiserParameters p = floatingLazyWave(40);
  p.water_level = 1e5;
  p.seabed_contact = false;
  p.seabed_level = -1e5;
  const RiserModel m = buildRiserModel(p);
  RunContext context;
  const StaticSolution s = solveStatics(m, context);
  EXPECT_TRUE(s.banded);
  EXPECT_LT(s.residual, 1e-11);
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  poseFromState(m, 0.0, restState(m, s.orientation, s.top), ws.pose);
  double highest = -1e9;
  for (int i = 0; i <= m.n; ++i) highest = std::max(highest, ws.pose.position[i].z());
  EXPECT_GT(highest, 50.0);
}

// With the surface, statics stops with FloatingRiserError within one pendulum period 2π√(L/g) = 56.74 s of damped
// motion (measured 35.5 s at n = 40 and 60, 42.6 s at n = 20; before, the relaxation ran 55 000–62 000 steps per
// period, tens of minutes), inside its step limit, naming the buoyant stretch and its net lift (ρ_w g π D²/4 of the
// 0.8 m modules minus their weight in air, from the model's segment to 1e-9).
TEST(RiserRelaxationLimits, FloatingRiserStopsWithinOnePeriod) {
  const std::vector<int> counts = ::maris::test::kSanitizedBuild ? std::vector<int>{20} : std::vector<int>{20, 40, 60};
  for (int n : counts) {
    const RiserModel m = buildRiserModel(floatingLazyWave(n));
    const double lift = m.segments[0].buoyancy_per_length - m.segments[0].weight_per_length;
    ASSERT_NEAR(lift, 1993.0, 1.0) << n;  // the scenario's "net lift about 2 kN/m"
    RunContext context;
    try {
      solveStatics(m, context);
      ADD_FAILURE() << "n = " << n << ": statics found an equilibrium of a floating riser";
    } catch (const FloatingRiserError& e) {
      EXPECT_GT(e.time(), 0.0) << n;
      EXPECT_LE(e.time(), 2 * std::numbers::pi * std::sqrt(800.0 / 9.81)) << n;
      EXPECT_LE(e.step(), relaxationStepLimit(m)) << n;
      EXPECT_GE(e.first(), 0.0) << n;
      EXPECT_LE(e.last(), 550.0) << n;  // the modules' end
      EXPECT_LE(e.first(), e.last()) << n;
      EXPECT_NEAR(e.lift(), lift, 1e-9 * lift) << n;
      EXPECT_NE(std::string(e.what()).find("floats"), std::string::npos) << e.what();
    }
  }
}

// The scene turns it into invalid input (exit code 2 in maris-cli) on the module row over the floating stretch.
TEST(RiserRelaxationLimits, SceneRefusesTheFloatingRiserNamingTheModules) {
  RiserParameters p = floatingLazyWave(20);
  RunContext context;
  try {
    solveRiser(p, context);
    ADD_FAILURE() << "the floating riser ran";
  } catch (const InputError& e) {
    ASSERT_EQ(e.errors().size(), 1u);
    EXPECT_EQ(e.errors()[0].path, "buoyancy_modules[0].start");
    EXPECT_EQ(e.errors()[0].value, "0");
    EXPECT_NE(e.errors()[0].message.find("still-water level z = 0 m"), std::string::npos) << e.errors()[0].message;
  }
}

// The step limit: 10⁶ segment-steps, at least 2000.
TEST(RiserRelaxationLimits, StepLimitScalesWithTheSegments) {
  EXPECT_EQ(relaxationStepLimit(buildRiserModel(floatingLazyWave(40))), 24390);
  EXPECT_EQ(relaxationStepLimit(buildRiserModel(floatingLazyWave(1000))), 2000);
}

// DampedRelaxation stops at its limit: the slack cable held at both ends (n = 50) takes 390–490 steps in its first
// period; limited to 100 it stops inside that period with the steps of the pieces it finished (≤ 100), says so,
// and a further call does nothing.
TEST(RiserRelaxationLimits, RelaxationStopsAtItsStepLimit) {
  RiserParameters p = test::implicitCableHeldAtBothEnds(50, 0.0);
  p.formulation = "joint";
  RiserModel m = buildRiserModel(p);
  m.motion_amplitude.setZero();
  DampedRelaxation relax(m);
  relax.limitSteps(100);
  Eigen::VectorXd y = restState(relax.model(), m.initial_orientation, m.initial_top);
  RunContext context;
  relax.advance(y, relax.period(), context);
  EXPECT_TRUE(relax.exhausted());
  EXPECT_LE(relax.steps(), 100);
  EXPECT_GT(relax.stalledTime(), 0.0);
  EXPECT_LT(relax.stalledTime(), relax.period());
  EXPECT_GT(relax.stalledStep(), 0.0);
  const long steps = relax.steps();
  relax.advance(y, relax.period(), context);
  EXPECT_EQ(relax.steps(), steps);
}

// Past its step limit before the floating test has seen half a period, statics stops with a SolverError that names
// the limit, the residual and the surface (n = 200: limit 4975 steps, reached after 0.47 periods). Release only:
// 10 s there, minutes under the sanitizers, which run the same code paths in the two tests above.
TEST(RiserRelaxationLimits, StaticsStopsAtTheStepLimitNamingWhatDidNotSettle) {
  if (::maris::test::kSanitizedBuild) GTEST_SKIP() << "Release only (see the comment)";
  const RiserModel m = buildRiserModel(floatingLazyWave(200));
  RunContext context;
  try {
    solveStatics(m, context);
    ADD_FAILURE() << "statics found an equilibrium of a floating riser";
  } catch (const FloatingRiserError& e) {
    ADD_FAILURE() << "the floating test fired first (it took half a period at n = 20–60): " << e.what();
  } catch (const SolverError& e) {
    EXPECT_EQ(e.step(), relaxationStepLimit(m));
    const std::string text = e.what();
    EXPECT_NE(text.find("did not settle within its limit of 4975 steps"), std::string::npos) << text;
    EXPECT_NE(text.find("largest in the moment about joint"), std::string::npos) << text;
    EXPECT_NE(text.find("held at the still-water level"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace maris::riser
