// The start of a run: a top that would jump from rest to full speed is refused with the field and the speed
// named; a start at rest without a ramp gives the same motion and top force in joint and absolute coordinates
// from the first frame. And the modes switch: off leaves the time history bit for bit and drops the modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "engine/results_identity.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

using test::column;
using test::errorsOf;

// Harmonic top motion with top.motion_ramp_time = 0 starting at speed A ω |cos φ| ≠ 0: an input error naming
// top.motion_ramp_time and the speed (2 m · 2π/10 s = 1.25664 m/s); at φ = ±90° (start at rest) it is accepted,
// as are a ramp, a table (clamped spline: zero velocity at its first row) and a tensioner's ignored z amplitude.
TEST(RiserStart, TopJumpingFromRestToFullSpeedIsRefused) {
  RiserParameters p;
  p.motion_ramp_time = 0.0;
  p.motion_period = 10.0;
  p.motion_amplitude_x = 2.0;
  p.motion_amplitude_y = 0.0;
  p.motion_phase_x_deg = 0.0;
  const std::vector<FieldError> errors = errorsOf(p);
  ASSERT_EQ(errors.size(), 1u) << describeErrors(errors);
  EXPECT_EQ(errors[0].path, "parameters.top.motion_ramp_time");
  EXPECT_NE(errors[0].message.find("1.25664 m/s"), std::string::npos) << errors[0].message;
  EXPECT_NEAR(initialTopSpeed(p), 2.0 * 2 * pi / 10.0, 1e-15);

  p.motion_phase_x_deg = -90.0;
  EXPECT_TRUE(errorsOf(p).empty()) << describeErrors(errorsOf(p));
  p.motion_phase_x_deg = 0.0;
  p.motion_ramp_time = 1e-3;
  EXPECT_TRUE(errorsOf(p).empty()) << describeErrors(errorsOf(p));
  p.motion_ramp_time = 0.0;
  p.top_motion = "table";
  p.top_motion_table = {{0.0, 0.0, 0.0, 0.0}, {5.0, 1.0, 0.0, 0.0}, {10.0, 0.0, 0.0, 0.0}};
  EXPECT_TRUE(errorsOf(p).empty()) << describeErrors(errorsOf(p));
  p.top_motion = "harmonic";
  p.motion_amplitude_x = 0.0;
  p.motion_amplitude_z = 1.0;  // the tensioner's vertical motion is free: no prescribed speed
  EXPECT_TRUE(errorsOf(p).empty()) << describeErrors(errorsOf(p));
}

// Largest |a − b| over a column sampled at the same times in both runs.
double largestDifference(const Results& a, const Results& b, const std::string& name) {
  const auto &va = column(a, "history", name), &vb = column(b, "history", name);
  EXPECT_EQ(va.size(), vb.size()) << name;
  double d = 0.0;
  for (std::size_t k = 0; k < std::min(va.size(), vb.size()); ++k) d = std::max(d, std::abs(va[k] - vb[k]));
  return d;
}

double largestMagnitude(const Results& r, const std::string& name) {
  double m = 0.0;
  for (double v : column(r, "history", name)) m = std::max(m, std::abs(v));
  return m;
}

// A ramp-free start at rest (top at A(1 − cos ωt) in x, 2 m, period 4 s, on a 60 m tensioned riser, n = 8, in
// current): joint and absolute coordinates agree from the first frame (t = 0) on, in the probe motion at L/2 and
// in the top force. DOPRI5 at rtol 1e-9; the tolerance is 100 times the sum of the two runs' error estimates
// (sums of relative local errors) times the quantity's scale, since A also carries its Baumgarte drift.
TEST(RiserStart, JointAndAbsoluteAgreeFromTheFirstFrameWithoutRamp) {
  RiserParameters p;
  p.length = 60.0;
  p.segment_count = 8;
  p.bottom_z = -60.0;
  p.seabed_level = -60.0;
  p.top_tension = 1e6;
  p.end_time = 4.0;
  p.motion_period = 4.0;
  p.motion_ramp_time = 0.0;
  p.motion_amplitude_y = 0.0;
  p.motion_phase_x_deg = -90.0;
  p.stress_times.clear();
  p.probes = {{30.0}};
  p.integrator = "dopri5";
  p.tolerance = 1e-9;
  p.modes = false;
  ASSERT_TRUE(errorsOf(p).empty()) << describeErrors(errorsOf(p));
  RunContext cj, ca;
  const Results joint = solveRiser(p, cj);
  p.formulation = "absolute";
  const Results absolute = solveRiser(p, ca);
  const double estimate = joint.stats.error_estimate + absolute.stats.error_estimate;
  ASSERT_GT(estimate, 0.0);
  ASSERT_EQ(column(joint, "history", "time").front(), 0.0);
  for (const char* c : {"probe_dx", "probe_dy", "probe_dz"}) {
    const double scale = std::max(largestMagnitude(joint, "probe_dx"), largestMagnitude(joint, "probe_dy"));
    EXPECT_LT(largestDifference(joint, absolute, c), 100 * estimate * scale) << c << ", estimate " << estimate;
  }
  for (const char* c : {"top_force_x", "top_force_y", "top_force_z"}) {
    const double scale = std::max(largestMagnitude(joint, "top_force_x"), largestMagnitude(joint, "top_force_z"));
    EXPECT_LT(largestDifference(joint, absolute, c), 100 * estimate * scale) << c << ", estimate " << estimate;
    // The first frame itself: both states are at rest with the same top acceleration.
    EXPECT_LT(std::abs(column(joint, "history", c).front() - column(absolute, "history", c).front()),
              100 * estimate * scale) << c << " at t = 0";
  }
}

// output.modes = false: no modes, mode shapes or frequency scalars, the method line says so, and the time
// history is bit for bit the run with the modes (the modes are computed from the static state only).
TEST(RiserModesSwitch, OffDropsTheModesAndLeavesTheHistoryUnchanged) {
  RiserParameters p = test::shortMovingTopRun();
  p.modes = true;
  RunContext c_on, c_off;
  const Results on = solveRiser(p, c_on);
  p.modes = false;
  const Results off = solveRiser(p, c_off);
  ASSERT_NE(on.findTable("modes"), nullptr);
  ASSERT_NE(on.findTable("mode_shapes"), nullptr);
  EXPECT_NE(on.findScalar("first_natural_frequency"), nullptr);
  EXPECT_EQ(off.findTable("modes"), nullptr);
  EXPECT_EQ(off.findTable("mode_shapes"), nullptr);
  EXPECT_EQ(off.findScalar("first_natural_frequency"), nullptr);
  for (const auto& plot : off.plots) EXPECT_EQ(plot.table.find("mode"), std::string::npos) << plot.name;
  EXPECT_NE(off.stats.method.find("output.modes = false"), std::string::npos) << off.stats.method;
  EXPECT_EQ(on.stats.method.find("output.modes"), std::string::npos) << on.stats.method;
  const Table *h_on = on.findTable("history"), *h_off = off.findTable("history");
  ASSERT_NE(h_on, nullptr);
  ASSERT_NE(h_off, nullptr);
  ASSERT_EQ(h_on->columns.size(), h_off->columns.size());
  for (std::size_t c = 0; c < h_on->columns.size(); ++c)
    maris::test::expectSameValues(h_on->columns[c].values, h_off->columns[c].values, "history." + h_on->columns[c].name);
  EXPECT_EQ(on.stats.steps, off.stats.steps);
}

}  // namespace
}  // namespace maris::riser
