// Partial results of the seismic scene (live plots): what is published while the FE time stepping
// runs must be a growing, faithful prefix of what the run finally returns, and publishing must not
// change the run. Coarse meshes keep each run well under a second in Release.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/run_context.hpp"
#include "engine/results_identity.hpp"

namespace maris {
namespace {

// The verification box at a coarse mesh (f_cut 6 Hz instead of 20: cells of ~24 m), one FE job.
Json coarseBox() {
  Json prm = findBuiltin("seismic_verification_box")->scenario.parameters;
  prm["solver"]["cutoff_frequency"] = 6.0;
  prm["solver"]["duration"] = 2.0;
  prm["output"]["snapshot_count"] = 4;
  return prm;
}

// The default reef at a coarse mesh (f_cut 1.5 Hz): main, coarse-companion and dry jobs on threads.
Json coarseReef() {
  Json prm = findBuiltin("seismic_default")->scenario.parameters;
  prm["input"]["ricker_peak_frequency"] = 0.3;
  prm["solver"]["cutoff_frequency"] = 1.5;
  prm["solver"]["duration"] = 4.0;
  prm["output"]["snapshot_count"] = 4;
  prm["modes"]["count"] = 0;
  return prm;
}

struct LiveRun {
  Results final_results;
  std::vector<std::shared_ptr<const Results>> partials;
};

LiveRun runWithSink(const Json& prm) {
  LiveRun run;
  RunContext ctx;
  // Interval 0: a partial whenever the solve thread's 10 ms poll finds the last one taken.
  ctx.setPartialSink([&](std::shared_ptr<const Results> r) { run.partials.push_back(std::move(r)); }, 0.0);
  run.final_results = requireScene("seismic").run(prm, ctx);
  return run;
}

// Every table of `partial` that holds a time history: its columns are the final table's (names,
// units, order), its rows the final rows bit for bit, and it has no more rows than the final one.
void expectPrefixOfFinal(const Table& partial, const Table& whole) {
  ASSERT_EQ(partial.columns.size(), whole.columns.size()) << partial.name;
  EXPECT_LE(partial.rows(), whole.rows()) << partial.name;
  for (std::size_t c = 0; c < partial.columns.size(); ++c) {
    const Column& p = partial.columns[c];
    const Column& w = whole.columns[c];
    EXPECT_EQ(p.name, w.name);
    EXPECT_EQ(p.unit, w.unit);
    ASSERT_EQ(p.values.size(), partial.rows()) << partial.name << " " << p.name;
    // Exactly equal: the partial copies the recorded samples, built by the final run's own code.
    for (std::size_t i = 0; i < p.values.size(); ++i)
      ASSERT_EQ(p.values[i], w.values[i]) << partial.name << " " << p.name << " row " << i;
  }
}

// Checks the growing-prefix property over all partials of a run for the named time-history tables.
void expectGrowingPrefixes(const LiveRun& run, const std::vector<std::string>& histories) {
  const Results& whole = run.final_results;
  std::vector<std::size_t> previous(histories.size(), 0);
  for (const auto& partial : run.partials) {
    for (std::size_t h = 0; h < histories.size(); ++h) {
      const Table* t = partial->findTable(histories[h]);
      ASSERT_NE(t, nullptr) << histories[h];
      EXPECT_GE(t->rows(), previous[h]) << histories[h] << ": rows decreased";
      previous[h] = t->rows();
      expectPrefixOfFinal(*t, *whole.findTable(histories[h]));
    }
    // Same structure as the final results: every table and plot of the partial is in the final one.
    for (const auto& t : partial->tables) EXPECT_NE(whole.findTable(t.name), nullptr) << t.name;
    for (const auto& plot : partial->plots) {
      const bool in_final = std::any_of(whole.plots.begin(), whole.plots.end(),
                                        [&](const PlotSpec& f) { return f.name == plot.name && f.y == plot.y; });
      EXPECT_TRUE(in_final) << plot.name;
    }
    // The 3D view: the wave field at the latest step (the final run's frame grid), unless the main
    // case had finished, when the partial carries its frames.
    const Table* stations = partial->findTable("station_histories");
    if (partial->view.frames.size() == 1) {
      EXPECT_EQ(partial->view.frames.front().time, stations->columns.front().values.back());
      ASSERT_FALSE(whole.view.frames.empty());
      EXPECT_EQ(partial->view.frames.front().shapes.front().points.size(),
                whole.view.frames.front().shapes.front().points.size());
    } else {
      EXPECT_EQ(partial->view.frames.size(), whole.view.frames.size());
      EXPECT_EQ(stations->rows(), whole.findTable("station_histories")->rows());
    }
  }
}

TEST(SeismicLive, BoxPublishesGrowingHistoriesWhoseRowsMatchTheFinishedRun) {
  const LiveRun run = runWithSink(coarseBox());
  // ~700 steps over a few hundred ms: the 10 ms poll gets several partials through.
  ASSERT_GE(run.partials.size(), 2u);
  expectGrowingPrefixes(run, {"station_histories", "verification"});
  // Published while stepping: the first partial is short of the end.
  EXPECT_LT(run.partials.front()->findTable("station_histories")->rows(),
            run.final_results.findTable("station_histories")->rows());
  // The free-field part (complete before the FE run) is in every partial as in the final results.
  expectPrefixOfFinal(*run.partials.front()->findTable("free_field_histories"),
                      *run.final_results.findTable("free_field_histories"));

  RunContext plain;
  test::expectIdenticalResults(requireScene("seismic").run(coarseBox(), plain), run.final_results);
}

TEST(SeismicLive, ReefWithThreadedJobsPublishesPrefixesAndLeavesTheRunUnchanged) {
  const LiveRun run = runWithSink(coarseReef());
  ASSERT_GE(run.partials.size(), 1u);
  expectGrowingPrefixes(run, {"station_histories"});
  // Whole-record post-processing is not in the partials.
  for (const auto& partial : run.partials) {
    EXPECT_EQ(partial->findTable("spectral_ratio"), nullptr);
    EXPECT_EQ(partial->findTable("amplification"), nullptr);
  }
  RunContext plain;
  test::expectIdenticalResults(requireScene("seismic").run(coarseReef(), plain), run.final_results);
}

TEST(SeismicLive, LiveFrameIsTheWaveFieldAtItsStep) {
  // 0.6 s of the coarse box (~180 steps) with 200 frames asked for: the final run keeps a frame at
  // every step, so each partial's frame has a final twin at the same time, whose drawn |u| it must equal.
  Json prm = coarseBox();
  prm["solver"]["duration"] = 0.6;
  prm["output"]["snapshot_count"] = 200;
  const LiveRun run = runWithSink(prm);
  int matched = 0;
  for (const auto& partial : run.partials) {
    if (partial->view.frames.size() != 1) continue;
    const Frame3D& live = partial->view.frames.front();
    for (const Frame3D& f : run.final_results.view.frames) {
      if (f.time != live.time) continue;
      ++matched;
      const Shape3D& a = live.shapes.front();
      const Shape3D& b = f.shapes.front();
      ASSERT_EQ(a.grid_u, b.grid_u);
      ASSERT_EQ(a.grid_v, b.grid_v);
      EXPECT_TRUE(a.points == b.points);
      EXPECT_TRUE(a.scalars == b.scalars) << "frame at t = " << f.time;
    }
  }
  EXPECT_GE(matched, 1);
}

TEST(SeismicLive, CancelRequestedFromThePartialSinkStopsTheTimeStepping) {
  // A longer box run (12 s simulated: ~3700 steps) cancelled by the sink at its first partial. The
  // workers check the flag every step, so the progress reported after the request stays near where
  // it was (FE stepping spans 0.05–0.95; ignoring the flag would carry it to 0.95). No wall-time
  // bound: the test machine is shared.
  Json prm = coarseBox();
  prm["solver"]["duration"] = 12.0;
  std::atomic<bool> cancel{false};
  double progress_after_cancel = 0.0;
  RunContext ctx(
      [&](double f, const std::string&) {
        if (cancel) progress_after_cancel = std::max(progress_after_cancel, f);
      },
      &cancel);
  int partials = 0, after_cancel = 0;
  double reached = 0.0;
  ctx.setPartialSink(
      [&](std::shared_ptr<const Results> r) {
        ++partials;
        if (cancel) ++after_cancel;
        reached = r->findScalar("time_reached")->value;
        cancel = true;
      },
      0.0);
  EXPECT_THROW(requireScene("seismic").run(prm, ctx), RunCancelled);
  EXPECT_EQ(partials, 1);
  EXPECT_EQ(after_cancel, 0);  // nothing is published once cancellation is requested
  EXPECT_LT(reached, 1.0);     // the first partial comes early in the 12 s
  EXPECT_LT(progress_after_cancel, 0.1);
}

}  // namespace
}  // namespace maris
