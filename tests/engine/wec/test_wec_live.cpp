// Live results of the wec scene: while it runs it publishes partial Results (frequency sweep rows, time-domain
// RAO points, time histories so far) in the layout of the finished run, and listening to them changes nothing.
// Coarse versions of the built-in scenarios (short runs, few frequencies) keep the sink at interval 0 cheap.
#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <memory>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "engine/results_identity.hpp"
#include "wec_test_models.hpp"

using namespace maris;

namespace {

using wec_test::scene;

// A built-in scenario made coarse: 20 s of simulated time, 24 frequencies, few check points and frames.
Scenario coarse(const std::string& id) {
  const BuiltinScenario* b = findBuiltin(id);
  EXPECT_NE(b, nullptr) << id;
  Scenario s = b ? b->scenario : Scenario{};
  s.parameters["time"]["duration"] = 20.0;
  s.parameters["time"]["animation_frames"] = 4;
  s.parameters["frequency"]["count"] = 24;
  if (!s.parameters["frequency"]["check_frequencies"].empty())
    s.parameters["frequency"]["check_frequencies"] = Json::array({0.8, 1.2, 1.6});
  return s;
}

// Checks each partial as it arrives against the finished run without a listener.
struct PartialChecker {
  const Results& finished;
  int count = 0;
  std::map<std::string, std::size_t> rows;      // table → rows in the latest partial that had it
  std::map<std::string, int> growth;            // table → partials in which it had more rows than before

  void check(const Results& partial) {
    ++count;
    // Same plots (names, tables, columns) as the finished run, so a GUI keeps its tabs.
    ASSERT_EQ(partial.plots.size(), finished.plots.size());
    for (std::size_t i = 0; i < partial.plots.size(); ++i) {
      EXPECT_EQ(partial.plots[i].name, finished.plots[i].name);
      EXPECT_EQ(partial.plots[i].table, finished.plots[i].table);
      EXPECT_EQ(partial.plots[i].y, finished.plots[i].y);
    }
    // A table, once published, stays.
    for (const auto& [name, n] : rows) ASSERT_NE(partial.findTable(name), nullptr) << name << " disappeared";
    for (const auto& t : partial.tables) {
      const Table* whole = finished.findTable(t.name);
      ASSERT_NE(whole, nullptr) << t.name;
      // Same columns as the final table, each with the same number of rows, never fewer than before.
      ASSERT_EQ(t.columns.size(), whole->columns.size()) << t.name;
      const std::size_t n = t.rows();
      EXPECT_GE(n, rows.count(t.name) ? rows[t.name] : 0u) << t.name << " shrank";
      if (n > (rows.count(t.name) ? rows[t.name] : 0u)) ++growth[t.name];
      rows[t.name] = n;
      ASSERT_LE(n, whole->rows()) << t.name;
      for (std::size_t c = 0; c < t.columns.size(); ++c) {
        const Column& col = t.columns[c];
        ASSERT_EQ(col.name, whole->columns[c].name) << t.name;
        ASSERT_EQ(col.unit, whole->columns[c].unit) << t.name;
        ASSERT_EQ(col.values.size(), n) << t.name << "." << col.name;
        for (std::size_t i = 0; i < n; ++i)
          ASSERT_EQ(col.values[i], whole->columns[c].values[i]) << t.name << "." << col.name << " row " << i;
      }
    }
  }
};

// Runs `s` without a listener, then with a sink at interval 0 that checks every partial.
PartialChecker runBoth(const Scenario& s, Results& finished) {
  RunContext quiet;
  finished = runScenario(scene(), s, quiet);
  PartialChecker checker{finished, 0, {}, {}};
  RunContext live;
  live.setPartialSink([&](std::shared_ptr<const Results> r) { checker.check(*r); }, 0.0);
  const Results with_sink = runScenario(scene(), s, live);
  test::expectIdenticalResults(with_sink, finished);
  return checker;
}

}  // namespace

// Regular waves, classical and augmented runs: the sweep, the time-domain RAO points and the histories (rows the
// augmented run has reached) grow; every partial row equals the finished run's row.
TEST(WecLive, DefaultPublishesGrowingPartialsWhoseRowsMatchTheFinishedRun) {
  Results finished;
  const PartialChecker c = runBoth(coarse("wec_default"), finished);
  EXPECT_GE(c.growth.at("frequency_response"), 20);  // one partial per frequency but the last (24)
  EXPECT_EQ(c.growth.at("rao_time_domain"), 3);  // after points 1 and 2, then whole in the history partials
  EXPECT_GE(c.growth.at("time_history"), 100);  // 400 steps, output every step
  EXPECT_EQ(c.rows.at("time_history"), finished.findTable("time_history")->rows() - 1);  // up to the last step
}

// Irregular sea, classical run only: the history grows with the main run.
TEST(WecLive, IrregularSeaPublishesTheGrowingTimeHistory) {
  Results finished;
  const PartialChecker c = runBoth(coarse("wec_irregular"), finished);
  EXPECT_GE(c.growth.at("time_history"), 100);
  EXPECT_EQ(c.rows.count("response_spectra"), 0u);  // computed after the run: only in the finished results
}

// Two interacting floats: both floats' columns appear in every partial (the sweep visits float 1 and 2 per
// frequency).
TEST(WecLive, TwoFloatPartialsCarryBothFloats) {
  Results finished;
  const PartialChecker c = runBoth(coarse("wec_two_floats"), finished);
  EXPECT_GE(c.growth.at("frequency_response"), 20);
  EXPECT_GE(c.growth.at("time_history"), 100);
}

// Without a sink nothing is built; with a throttled sink only a few partials arrive (the context's interval).
TEST(WecLive, ThrottledSinkReceivesFewPartials) {
  int count = 0;
  RunContext ctx;
  ctx.setPartialSink([&](std::shared_ptr<const Results>) { ++count; }, 3600.0);
  runScenario(scene(), coarse("wec_default"), ctx);
  EXPECT_EQ(count, 1);  // the first opportunity only: the hour-long interval has not passed again
}

// A cancel request made while partials stream (during the frequency sweep, and during the time histories)
// stops the run with RunCancelled: no partial follows in the sweep (checked after every frequency), and at
// most 64 more recorded steps in the time domain (the integrators check every 64 steps).
TEST(WecLive, CancellationWhileStreamingThrowsPromptly) {
  for (const std::string stage : {"frequency_response", "time_history"}) {
    std::atomic<bool> cancel{false};
    RunContext ctx([](double, const std::string&) {}, &cancel);
    std::size_t rows_at_cancel = 0, rows_after = 0;
    int after = 0;
    ctx.setPartialSink(
        [&](std::shared_ptr<const Results> r) {
          const Table* t = r->findTable(stage);
          if (cancel.load()) {
            ++after;
            rows_after = t ? t->rows() : 0;
          } else if (t) {
            rows_at_cancel = t->rows();
            cancel = true;
          }
        },
        0.0);
    EXPECT_THROW(runScenario(scene(), coarse("wec_irregular"), ctx), RunCancelled) << stage;
    EXPECT_TRUE(cancel.load()) << stage;
    if (stage == "frequency_response") {
      EXPECT_EQ(after, 0);
    }
    EXPECT_LE(rows_after, rows_at_cancel + 64) << stage;
  }
}
