// Partial results of a riser run (for live plots in the GUI): what is published while the run goes
// must be a faithful prefix of what the run finally returns.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "riser/riser_scene.hpp"
#include "core/angles.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

// A swinging pendulum chain: short, coarse and quick, but with a history of many rows.
RiserParameters swingingChain() {
  RiserParameters p = test::calmInAir();
  p.length = 10.0;
  p.segment_count = 4;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.08;
  p.initial_inclination_deg = degreesFromRadians(0.5);
  p.solve_statics = false;
  p.end_time = 2.0;
  p.frame_count = 5;
  return p;
}

TEST(RiserLive, PartialHistoriesArePrefixesOfTheFinalHistory) {
  std::vector<std::shared_ptr<const Results>> partials;
  RunContext context;
  // A tiny interval: the context throttles, so how many arrive depends on the machine, but the first
  // one always passes (nothing was published before) once the history has two rows.
  context.setPartialSink([&](std::shared_ptr<const Results> r) { partials.push_back(std::move(r)); }, 1e-3);
  const Results final_results = solveRiser(swingingChain(), context);
  ASSERT_FALSE(partials.empty());

  const Table* history = final_results.findTable("history");
  ASSERT_NE(history, nullptr);
  std::size_t previous_rows = 0;
  for (const auto& partial : partials) {
    const Table* h = partial->findTable("history");
    ASSERT_NE(h, nullptr);
    // Same columns (names and units) as the final table, fewer or equal rows, growing from one to the next.
    ASSERT_EQ(h->columns.size(), history->columns.size());
    EXPECT_GE(h->rows(), 2u);
    EXPECT_LE(h->rows(), history->rows());
    EXPECT_GE(h->rows(), previous_rows);
    previous_rows = h->rows();
    for (std::size_t c = 0; c < h->columns.size(); ++c) {
      EXPECT_EQ(h->columns[c].name, history->columns[c].name);
      EXPECT_EQ(h->columns[c].unit, history->columns[c].unit);
      // Exactly the same numbers: the partial is a copy of the recorder's rows, not a recomputation.
      for (std::size_t i = 0; i < h->rows(); ++i) ASSERT_EQ(h->columns[c].values[i], history->columns[c].values[i]);
    }
    // The live plots have the final plots' names, so the GUI keeps the same tabs.
    for (const auto& plot : partial->plots) {
      const bool in_final = std::any_of(final_results.plots.begin(), final_results.plots.end(),
                                        [&](const PlotSpec& f) { return f.name == plot.name; });
      EXPECT_TRUE(in_final) << plot.name;
      EXPECT_EQ(plot.table, "history");
    }
    EXPECT_FALSE(partial->plots.empty());
    // At most the latest shape for the 3D view.
    EXPECT_LE(partial->view.frames.size(), 1u);
  }
}

TEST(RiserLive, PublishingLeavesTheTrajectoryUnchanged) {
  // The same run without and with a partial sink.
  RunContext plain;
  const Results a = solveRiser(swingingChain(), plain);
  RunContext live;
  int count = 0;
  live.setPartialSink([&](std::shared_ptr<const Results>) { ++count; }, 1e-3);
  const Results b = solveRiser(swingingChain(), live);
  EXPECT_GE(count, 1);
  const auto& za = a.findTable("history")->find("end_z")->values;
  const auto& zb = b.findTable("history")->find("end_z")->values;
  ASSERT_EQ(za.size(), zb.size());
  // Publishing only copies: the trajectory is bit-identical with and without a sink.
  for (std::size_t i = 0; i < za.size(); ++i) ASSERT_EQ(za[i], zb[i]);
}

}  // namespace
}  // namespace maris::riser
