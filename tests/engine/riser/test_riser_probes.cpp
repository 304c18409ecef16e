// Probe points (output.probes): each records the history of its own point on the riser; bad arc
// lengths are field errors; scenarios written with the former output.probe_position still load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/scene.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_model.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

const Column& historyColumn(const Results& r, const std::string& name) {
  const Column* c = r.findTable("history")->find(name);
  if (!c) throw std::runtime_error("no history column " + name);
  return *c;
}

using test::hasErrorAt;

// Position at arc length s by linear interpolation between the stored nodes of one frame (the
// segments are rigid and straight, so this is exact). `first` is the frame's first row in node_positions.
Vec3 interpolateNodes(const Table& nodes, std::size_t first, int node_count, double s) {
  const auto& arc = nodes.find("arc_length")->values;
  const auto &x = nodes.find("x")->values, &y = nodes.find("y")->values, &z = nodes.find("z")->values;
  for (int k = 0; k + 1 < node_count; ++k) {
    const std::size_t a = first + k, b = a + 1;
    if (s > arc[b] && k + 2 < node_count) continue;
    const double w = (s - arc[a]) / (arc[b] - arc[a]);
    return Vec3(x[a], y[a], z[a]) + w * Vec3(x[b] - x[a], y[b] - y[a], z[b] - z[a]);
  }
  return Vec3::Zero();
}

// Three probes on a short run of the default riser in current with elliptical top motion: one between nodes, one
// at the top (s = 0) and one at the bottom (s = L). References: the node positions of the stored frames
// interpolated at s (independent of the probe code), the top_x/y and end_x/y columns. Tolerance 1e-9 L:
// round-off of positions of order 100 m.
TEST(RiserProbes, EachProbeRecordsTheHistoryOfItsOwnPoint) {
  RiserParameters p = test::shortMovingTopRun();
  p.frame_count = 5;
  const double s_between = 0.37 * p.length;  // inside segment 3 (Δ = 12.5 m, segments start at 6.25 + 12.5 k)
  p.probes = {{s_between}, {0.0}, {p.length}};
  RunContext context;
  const Results r = solveRiser(p, context);
  const double tol = 1e-9 * p.length;

  // Probe 1 against the stored frames, relative to the first frame (t = 0 is the first sample).
  const Table& nodes = *r.findTable("node_positions");
  const auto& frame_time = nodes.find("time")->values;
  const int node_count = p.segment_count + 2;
  const auto& time = historyColumn(r, "time").values;
  const Vec3 start = interpolateNodes(nodes, 0, node_count, s_between);
  int frames_checked = 0;
  for (std::size_t first = 0; first < frame_time.size(); first += node_count) {
    const auto row = std::find(time.begin(), time.end(), frame_time[first]) - time.begin();
    ASSERT_LT(static_cast<std::size_t>(row), time.size()) << "frame at t = " << frame_time[first] << " not a sample";
    const Vec3 expected = interpolateNodes(nodes, first, node_count, s_between) - start;
    EXPECT_NEAR(historyColumn(r, "probe_dx").values[row], expected.x(), tol) << "t = " << time[row];
    EXPECT_NEAR(historyColumn(r, "probe_dy").values[row], expected.y(), tol) << "t = " << time[row];
    EXPECT_NEAR(historyColumn(r, "probe_dz").values[row], expected.z(), tol) << "t = " << time[row];
    ++frames_checked;
  }
  EXPECT_GE(frames_checked, 4);

  // Probe 2 sits on the top end, probe 3 on the bottom end: their histories are those of the ends.
  const auto &top_x = historyColumn(r, "top_x").values, &top_y = historyColumn(r, "top_y").values;
  const auto& top_z = historyColumn(r, "top_z").values;
  const auto &end_x = historyColumn(r, "end_x").values, &end_y = historyColumn(r, "end_y").values;
  double top_motion = 0.0, probe1_motion = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    EXPECT_NEAR(historyColumn(r, "probe2_dx").values[i], top_x[i] - top_x[0], tol) << "t = " << time[i];
    EXPECT_NEAR(historyColumn(r, "probe2_dy").values[i], top_y[i] - top_y[0], tol) << "t = " << time[i];
    EXPECT_NEAR(historyColumn(r, "probe3_dx").values[i], end_x[i] - end_x[0], tol) << "t = " << time[i];
    EXPECT_NEAR(historyColumn(r, "probe3_dy").values[i], end_y[i] - end_y[0], tol) << "t = " << time[i];
    top_motion = std::max(top_motion, Vec3(top_x[i] - top_x[0], top_y[i] - top_y[0], top_z[i] - top_z[0]).norm());
    probe1_motion = std::max(probe1_motion, std::abs(historyColumn(r, "probe_dx").values[i]));
  }
  // The checks must compare something that moves.
  EXPECT_GT(top_motion, 0.1);
  EXPECT_GT(probe1_motion, 1e-3);

  // Every probe has a displacement plot, a summary scalar and a row of the probes table.
  for (const char* plot : {"probe_displacement", "probe2_displacement", "probe3_displacement"})
    EXPECT_TRUE(std::any_of(r.plots.begin(), r.plots.end(), [&](const PlotSpec& s) { return s.name == plot; })) << plot;
  ASSERT_NE(r.findScalar("probe2_max_displacement"), nullptr);
  EXPECT_NEAR(r.findScalar("probe2_max_displacement")->value, top_motion, tol);
  ASSERT_NE(r.findTable("probes"), nullptr);
  EXPECT_EQ(r.findTable("probes")->rows(), 3u);
}

// A probe's stresses are those of the profile at its arc length, interpolated linearly between the two joints around
// it (joint k at (k − ½)Δ): at a joint, that joint's value; a quarter of the way to the next, ¾ and ¼ of theirs (for
// σ_b, of its components σ_xy and σ_xz);
// above the first joint, the first joint's. Reference: the stress profile table at the same time (all joints),
// tolerance 1e-9 of the largest stress (round-off). The nearest joint's value, up to Δ/2 away, made σ_b(L/2) of case
// 5 converge at first order in n (riser_stress_convergence.hpp).
TEST(RiserProbes, StressesAreInterpolatedBetweenTheJointsAroundTheProbe) {
  RiserParameters p = test::shortMovingTopRun();  // n = 8, L = 100 m: joints at 6.25 + 12.5 (k − 1) m
  p.stress_times = {2.0};
  const double joint3 = 31.25, quarter = joint3 + 0.25 * 12.5, above_first = 2.0;
  p.probes = {{joint3}, {quarter}, {above_first}};
  RunContext context;
  const Results r = solveRiser(p, context);
  const Table& profile = *r.findTable("profile_t2");
  const auto& arc = profile.find("arc_length")->values;
  const auto& row = historyColumn(r, "time").values;
  const auto at = std::find(row.begin(), row.end(), 2.0) - row.begin();
  ASSERT_LT(static_cast<std::size_t>(at), row.size()) << "no history sample at the stress time";
  const std::size_t k3 = std::find(arc.begin(), arc.end(), joint3) - arc.begin();
  ASSERT_LT(k3 + 1, arc.size()) << "joint 3 not at " << joint3 << " m";
  // σ_t interpolated directly; σ_b = |(σ_xy, σ_xz)| of the interpolated components (|M| has a kink at M = 0).
  const auto &xy = profile.find("stress_xy")->values, &xz = profile.find("stress_xz")->values;
  const double bending_quarter = std::hypot(0.75 * xy[k3] + 0.25 * xy[k3 + 1], 0.75 * xz[k3] + 0.25 * xz[k3 + 1]);
  for (const char* quantity : {"bending_stress", "torsional_stress"}) {
    const auto& along = profile.find(quantity)->values;
    double scale = 0;
    for (double v : along) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0) << quantity;
    const double tol = 1e-9 * scale;
    const bool bending = std::string(quantity) == "bending_stress";
    const double quarter_value = bending ? bending_quarter : 0.75 * along[k3] + 0.25 * along[k3 + 1];
    EXPECT_NEAR(historyColumn(r, std::string("probe_") + quantity).values[at], along[k3], tol) << quantity;
    EXPECT_NEAR(historyColumn(r, std::string("probe2_") + quantity).values[at], quarter_value, tol) << quantity;
    EXPECT_NEAR(historyColumn(r, std::string("probe3_") + quantity).values[at], along[1], tol) << quantity;
    // The interpolation must differ from the nearest joint's value for the check to mean something.
    EXPECT_GT(std::abs(along[k3 + 1] - along[k3]), 1e-3 * scale) << quantity;
  }
  const Table& probes = *r.findTable("probes");
  EXPECT_EQ(probes.find("joint_above")->values, (std::vector<double>{3, 3, 1}));
  EXPECT_EQ(probes.find("weight_below")->values, (std::vector<double>{0, 0.25, 0}));
}

TEST(RiserProbes, ProbeBeyondTheRiserOrNoProbeIsAFieldError) {
  const SceneDefinition scene = makeRiserScene();
  RiserParameters p;
  p.probes = {{10.0}, {p.length + 1.0}};
  auto errors = validateParameters(scene, riserBinder().write(p));
  EXPECT_TRUE(hasErrorAt(errors, "parameters.output.probes[1].arc_length")) << describeErrors(errors);
  EXPECT_NE(describeErrors(errors).find("[0, 100]"), std::string::npos) << describeErrors(errors);

  p.probes = {{-1.0}};
  errors = validateParameters(scene, riserBinder().write(p));
  EXPECT_TRUE(hasErrorAt(errors, "parameters.output.probes[0].arc_length")) << describeErrors(errors);

  p.probes.clear();
  errors = validateParameters(scene, riserBinder().write(p));
  EXPECT_TRUE(hasErrorAt(errors, "parameters.output.probes")) << describeErrors(errors);
}

// Scenario files written before output.probes had one number output.probe_position: it becomes a
// one-row table, with a note, and validates as before (out of range still named).
TEST(RiserProbes, FormerProbePositionKeyStillLoads) {
  const SceneDefinition scene = makeRiserScene();
  Json old = riserBinder().write(RiserParameters{});
  old["output"].erase("probes");
  old["output"]["probe_position"] = 30.0;
  EXPECT_TRUE(validateParameters(scene, old).empty()) << describeErrors(validateParameters(scene, old));

  Json upgraded = old;
  const auto notes = upgradeParameters(scene, upgraded);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes.front().find("output.probe_position"), std::string::npos) << notes.front();
  EXPECT_FALSE(upgraded["output"].contains("probe_position"));
  const RiserParameters p = riserBinder().read(upgraded);
  ASSERT_EQ(p.probes.size(), 1u);
  EXPECT_EQ(p.probes.front().arc_length, 30.0);
  EXPECT_TRUE(upgradeParameters(scene, upgraded).empty()) << "a second upgrade has nothing to do";

  old["output"]["probe_position"] = 130.0;
  EXPECT_TRUE(hasErrorAt(validateParameters(scene, old), "parameters.output.probes[0].arc_length"));
}

}  // namespace
}  // namespace maris::riser
