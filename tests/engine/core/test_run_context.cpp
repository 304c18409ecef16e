// RunContext: progress throttling and clamping, thread-safe warnings, the partial-results sink, and
// that the shared integrators report progress monotonically up to 1.
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/ode.hpp"
#include "core/results.hpp"
#include "core/run_context.hpp"
#include "ode_test_problems.hpp"

namespace maris {
namespace {

TEST(RunContext, ProgressCallsNeverExceedOnePerIntervalPlusTheEnds) {
  // Calling progress() in a tight loop for 0.2 s with a 20 ms interval: at most 0.2/0.02 + 1 timed
  // reports, plus the two edge reports (0 and 1) which always pass. At least the two edges.
  int calls = 0;
  RunContext ctx([&](double, const std::string&) { ++calls; }, nullptr);
  ctx.setProgressInterval(0.02);
  ctx.progress(0.0);
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  for (long i = 0; elapsed < 0.2; ++i) {
    ctx.progress(0.5);
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  ctx.progress(1.0);
  EXPECT_GE(calls, 2);
  EXPECT_LE(calls, static_cast<int>(elapsed / 0.02) + 1 + 2);
}

TEST(RunContext, ProgressIsClampedAndCarriesTheStage) {
  std::vector<std::pair<double, std::string>> seen;
  RunContext ctx([&](double f, const std::string& stage) { seen.emplace_back(f, stage); }, nullptr);
  ctx.progress(-0.5, "statics");
  ctx.progress(1.5, "time integration");
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].first, 0.0);
  EXPECT_EQ(seen[0].second, "statics");
  EXPECT_EQ(seen[1].first, 1.0);
  EXPECT_EQ(seen[1].second, "time integration");
}

TEST(RunContext, WarningsFromSeveralThreadsAreAllKept) {
  RunContext ctx;
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&ctx, t] {
      for (int i = 0; i < 500; ++i) ctx.warn("thread " + std::to_string(t) + " note " + std::to_string(i));
    });
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(ctx.warnings().size(), 2000u);
}

TEST(RunContext, WithoutACancelFlagNothingIsCancelled) {
  RunContext ctx;
  EXPECT_FALSE(ctx.cancelRequested());
  EXPECT_NO_THROW(ctx.throwIfCancelled());
}

TEST(RunContext, PartialResultsAreThrottledByTheirInterval) {
  RunContext ctx;
  EXPECT_FALSE(ctx.wantsPartialResults());  // no sink: solvers must not build partial results
  int delivered = 0;
  ctx.setPartialSink([&](std::shared_ptr<const Results>) { ++delivered; }, 10.0);
  EXPECT_TRUE(ctx.wantsPartialResults());
  ctx.publishPartial(std::make_shared<Results>());
  EXPECT_EQ(delivered, 1);
  EXPECT_FALSE(ctx.wantsPartialResults());  // 10 s have not passed
}

TEST(RunContext, IntegratorsReportMonotoneProgressEndingAtOne) {
  for (int integrator = 0; integrator < 3; ++integrator) {
    std::vector<double> fractions;
    RunContext ctx([&](double f, const std::string& stage) {
      fractions.push_back(f);
      EXPECT_EQ(stage, "time integration");
    }, nullptr);
    ctx.setProgressInterval(0.0);  // every report passes
    OdeOptions options;
    options.t1 = 10.0;
    options.step = 0.01;
    if (integrator == 2) {
      Eigen::VectorXd q = Eigen::VectorXd::Ones(1), v = Eigen::VectorXd::Zero(1);
      integrateGeneralizedAlpha(test::oscillatorSystem(1.0, 0.0), q, v, options, {}, ctx);
    } else {
      Eigen::VectorXd y(2);
      y << 1.0, 0.0;
      if (integrator == 0)
        integrateRk4(test::oscillatorRhs(1.0, 0.0), y, options, ctx);
      else
        integrateDopri5(test::oscillatorRhs(1.0, 0.0), y, options, ctx);
    }
    ASSERT_GE(fractions.size(), 2u) << "integrator " << integrator;
    for (std::size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1]);
    EXPECT_EQ(fractions.back(), 1.0) << "integrator " << integrator;
  }
}

}  // namespace
}  // namespace maris
