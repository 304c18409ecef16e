// makeScene/runScenario: validation happens before the solver, cross-field checks get full paths,
// warnings and wall time are recorded, cancellation and solver failures surface as typed errors.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "core/scene.hpp"

namespace maris {
namespace {

struct PipeParameters {
  double outer_diameter = 0.5;  // [m]
  double inner_diameter = 0.4;  // [m]
  double duration = 1.0;        // [s] how long the demo solver "runs"
};

SceneDefinition pipeScene(std::atomic<int>* solver_calls) {
  SchemaBinder<PipeParameters> b;
  b.real("pipe.outer_diameter", &PipeParameters::outer_diameter, "m", Range::positive(10), "Outer diameter");
  b.real("pipe.inner_diameter", &PipeParameters::inner_diameter, "m", Range::nonNegative(10), "Inner diameter");
  b.real("run.duration", &PipeParameters::duration, "s", Range::nonNegative(100), "Busy time");
  auto check = [](const PipeParameters& p) {
    std::vector<FieldError> errors;
    if (p.inner_diameter >= p.outer_diameter)
      errors.push_back({"pipe.inner_diameter", std::to_string(p.inner_diameter), "must be < pipe.outer_diameter"});
    return errors;
  };
  auto solve = [solver_calls](const PipeParameters& p, RunContext& ctx) {
    ++*solver_calls;
    ctx.warn("demo warning");
    const double wall_start = ctx.elapsedSeconds();
    while (ctx.elapsedSeconds() - wall_start < p.duration) {
      ctx.throwIfCancelled();
      ctx.progress((ctx.elapsedSeconds() - wall_start) / p.duration, "busy");
    }
    if (p.duration == 0.0) throw SolverError("pipe wall stress", 0.25, 12, "became non-finite");
    Results r;
    r.addScalar("area", 0.25 * M_PI * (p.outer_diameter * p.outer_diameter - p.inner_diameter * p.inner_diameter),
                "m^2", "Wall cross-section");
    return r;
  };
  return makeScene<PipeParameters>("pipe", "Pipe", "Test scene", b, check, solve);
}

Scenario pipeScenario(const SceneDefinition& scene) {
  Scenario s = defaultScenario(scene);
  s.parameters["run"]["duration"] = 0.01;
  return s;
}

TEST(Scene, CrossFieldErrorsCarryTheFullPathAndTheSolverIsNotCalled) {
  std::atomic<int> calls{0};
  const auto scene = pipeScene(&calls);
  Scenario s = pipeScenario(scene);
  s.parameters["pipe"]["inner_diameter"] = 0.6;
  RunContext ctx;
  try {
    runScenario(scene, s, ctx);
    FAIL();
  } catch (const InputError& e) {
    ASSERT_EQ(e.errors().size(), 1u);
    EXPECT_EQ(e.errors()[0].path, "parameters.pipe.inner_diameter");
  }
  EXPECT_EQ(calls.load(), 0);
}

TEST(Scene, RunRecordsWarningsAndWallTime) {
  std::atomic<int> calls{0};
  const auto scene = pipeScene(&calls);
  RunContext ctx;
  const Results r = runScenario(scene, pipeScenario(scene), ctx);
  EXPECT_NEAR(r.findScalar("area")->value, 0.25 * M_PI * (0.25 - 0.16), 1e-15);
  EXPECT_GE(r.stats.wall_time_s, 0.01);
  ASSERT_EQ(r.warnings.size(), 1u);
}

TEST(Scene, CancellationFromAnotherThreadStopsWithin100ms) {
  std::atomic<int> calls{0};
  const auto scene = pipeScene(&calls);
  Scenario s = pipeScenario(scene);
  s.parameters["run"]["duration"] = 30.0;
  std::atomic<bool> cancel{false};
  RunContext ctx({}, &cancel);
  std::chrono::steady_clock::time_point requested;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    requested = std::chrono::steady_clock::now();
    cancel = true;
  });
  EXPECT_THROW(runScenario(scene, s, ctx), RunCancelled);
  const double latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - requested).count();
  canceller.join();
  EXPECT_LT(latency, 0.1);
}

TEST(Scene, SolverErrorNamesTimeStepAndQuantity) {
  std::atomic<int> calls{0};
  const auto scene = pipeScene(&calls);
  Scenario s = pipeScenario(scene);
  s.parameters["run"]["duration"] = 0.0;
  RunContext ctx;
  try {
    runScenario(scene, s, ctx);
    FAIL();
  } catch (const SolverError& e) {
    EXPECT_EQ(std::string(e.what()), "solver failed at t = 0.25 s (step 12): pipe wall stress became non-finite");
  }
}

TEST(Scene, ProgressIsThrottledButReportsBothEnds) {
  int calls = 0;
  double last = -1;
  RunContext ctx([&](double f, const std::string&) { ++calls; last = f; }, nullptr);
  ctx.setProgressInterval(10.0);
  ctx.progress(0.0);
  for (int i = 1; i < 1000; ++i) ctx.progress(i / 1000.0);
  ctx.progress(1.0);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(last, 1.0);
}

TEST(Scene, NonFiniteStateIsReportedByName) {
  Eigen::VectorXd y(3);
  y << 1.0, std::nan(""), 2.0;
  try {
    throwIfNotFinite(y, 1.5, 7, [](Eigen::Index i) { return "node " + std::to_string(i) + " x"; });
    FAIL();
  } catch (const SolverError& e) {
    EXPECT_EQ(e.quantity(), "node 1 x");
    EXPECT_EQ(e.step(), 7);
  }
}

}  // namespace
}  // namespace maris
