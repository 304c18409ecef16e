// Live results of the ship scene: the resistance sweep publishes the rows finished so far while it runs, each
// row equal bit for bit to the finished run's, without changing the finished run; cancelling mid-sweep stops it.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "core/scene.hpp"
#include "engine/results_identity.hpp"

using namespace maris;

namespace {

// KCS: three Michell-type curves (plain, corrected with the tangency correction), measured points and the
// full-scale columns, so a partial row has every kind of column. Coarse so that the test takes about a second.
Scenario coarseKcs(int speeds) {
  const BuiltinScenario* b = findBuiltin("ship_kcs");
  EXPECT_NE(b, nullptr);
  Scenario s = b->scenario;
  applyOverride(s, "speed.count=" + std::to_string(speeds));
  applyOverride(s, "speed.froude_min=0.15");
  applyOverride(s, "numerics.stations=65");
  applyOverride(s, "numerics.waterlines=13");
  applyOverride(s, "numerics.threads=2");
  return s;
}

using Partials = std::vector<std::shared_ptr<const Results>>;

Results runKcs(const Scenario& s, Partials* partials) {
  RunContext ctx;
  if (partials) ctx.setPartialSink([partials](std::shared_ptr<const Results> r) { partials->push_back(r); }, 0.0);
  return runScenario(requireScene("ship"), s, ctx);
}

}  // namespace

TEST(ShipLive, SweepPublishesGrowingPartialResultsWhoseRowsMatchTheFinishedRun) {
  const Scenario s = coarseKcs(12);
  Partials partials;
  const Results finished = runKcs(s, &partials);
  const Table& all = *finished.findTable("resistance_curve");
  ASSERT_EQ(all.rows(), 12u);
  const auto& froude = all.find("froude")->values;

  // At interval 0 every wake-up of the sweep's coordinator publishes: several partials for 12 rows.
  ASSERT_GE(partials.size(), 2u);
  std::size_t previous_rows = 0;
  for (const auto& partial : partials) {
    const Table* t = partial->findTable("resistance_curve");
    ASSERT_NE(t, nullptr);
    // Same plots (so the GUI keeps its tabs), same columns, rows never fewer than before.
    ASSERT_EQ(partial->plots.size(), finished.plots.size());
    for (std::size_t k = 0; k < finished.plots.size(); ++k) EXPECT_EQ(partial->plots[k].name, finished.plots[k].name);
    ASSERT_EQ(t->columns.size(), all.columns.size());
    EXPECT_GE(t->rows(), std::max<std::size_t>(previous_rows, 1));
    previous_rows = t->rows();
    EXPECT_NE(partial->findTable("measured"), nullptr);
    EXPECT_FALSE(partial->view.empty());  // the hull
    // Every row is the finished run's row at the same Froude number, bit for bit, in Froude-number order.
    const auto& fn = t->find("froude")->values;
    EXPECT_TRUE(std::is_sorted(fn.begin(), fn.end()));
    for (std::size_t i = 0; i < t->rows(); ++i) {
      const auto at = std::find(froude.begin(), froude.end(), fn[i]);
      ASSERT_NE(at, froude.end()) << "partial row at Fn " << fn[i] << " is not a row of the finished run";
      const auto row = static_cast<std::size_t>(at - froude.begin());
      for (std::size_t c = 0; c < all.columns.size(); ++c) {
        EXPECT_EQ(t->columns[c].name, all.columns[c].name);
        EXPECT_EQ(t->columns[c].values[i], all.columns[c].values[row]) << all.columns[c].name << " at Fn " << fn[i];
      }
    }
  }
  // The sweep grew between partials, and the first one came before the sweep ended.
  EXPECT_LT(partials.front()->findTable("resistance_curve")->rows(), all.rows());

  // A listener does not change the finished run.
  test::expectIdenticalResults(finished, runKcs(s, nullptr));
}

TEST(ShipLive, CancellationAtTheFirstPartialStopsTheSweep) {
  // The cancel flag is raised by the first partial result; the run must throw RunCancelled, with no more rows
  // finished than were already running on the two worker threads (each polls every 1500 Kochin evaluations).
  const Scenario s = coarseKcs(60);
  std::atomic<bool> cancel{false};
  double furthest = 0;  // largest sweep fraction reported
  RunContext ctx(
      [&](double fraction, const std::string& stage) {
        if (stage.find("Michell") != std::string::npos) furthest = std::max(furthest, fraction);
      },
      &cancel);
  ctx.setProgressInterval(0.0);
  std::size_t rows_at_cancel = 0;
  ctx.setPartialSink(
      [&](std::shared_ptr<const Results> r) {
        if (!cancel) rows_at_cancel = r->findTable("resistance_curve")->rows();
        cancel = true;
      },
      0.0);
  EXPECT_THROW(runScenario(requireScene("ship"), s, ctx), RunCancelled);
  ASSERT_TRUE(cancel.load());
  EXPECT_GE(rows_at_cancel, 1u);
  EXPECT_LE(furthest * 60, static_cast<double>(rows_at_cancel + 2) + 1e-9);
}
