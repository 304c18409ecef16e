// Plausibility warnings of the tether scene: a robot above the surface, a leader faster than the follower's
// saturation, a shape with less chord slack than one control tick; each alone at its field. The built-in
// scenarios raise none.
#include "engine/plausibility_test_support.hpp"

namespace maris {
namespace {

using testing::expectOnlyWarning;
using testing::plausibilityOf;
using testing::warningAt;

TEST(TetherPlausibility, TheBuiltInScenariosRaiseNone) {
  testing::expectBuiltinsRaiseNone("tether");
}

TEST(TetherPlausibility, ALeaderAboveTheSurface) {
  expectOnlyWarning(plausibilityOf("tether_default", {"leader.z=0.3"}), "leader.z", "0.3 m above the water surface");
}

TEST(TetherPlausibility, AFollowerPlacedAboveTheSurface) {
  // d = 0.45 is ΔH = (2d − 1) ΔH_max = −0.05 m: the follower's attachment sits 0.05 m above the leader's, at
  // z = +0.03 m for a leader at −0.02 m (both attachments at body z = 0).
  EXPECT_TRUE(plausibilityOf("tether_default", {"leader.z=-0.06"}).empty());
  expectOnlyWarning(plausibilityOf("tether_default", {"leader.z=-0.02"}), "initial.d", "0.03 m above the water surface");
}

TEST(TetherPlausibility, ALeaderPathThatClimbsOutOfTheWater) {
  // From z = −0.4 m at 0.05 m/s for the 12 s run: z = +0.2 m at the end.
  const std::string leg =
      R"(leader.path=[{"duration": 20, "forward_speed": 0, "lateral_speed": 0, "vertical_speed": 0.05, "yaw_rate_deg": 0}])";
  expectOnlyWarning(plausibilityOf("tether_default", {leg}), "leader.path[0].vertical_speed", "z = 0.2 m");
}

TEST(TetherPlausibility, ALeaderFasterThanTheFollowerCanMove) {
  // The moving-leader example has legs at 0.1 m/s forward and 0.05 m/s sideways and up/down.
  const auto w = plausibilityOf("tether_sim3_moving_leader", {"control.max_linear_speed=0.08"});
  ASSERT_EQ(w.size(), 2u) << describeErrors(w);
  EXPECT_NE(warningAt(w, "parameters.leader.path[0].forward_speed"), nullptr) << describeErrors(w);
  EXPECT_NE(warningAt(w, "parameters.leader.path[3].forward_speed"), nullptr) << describeErrors(w);
}

TEST(TetherPlausibility, ANearlyTautTargetShape) {
  // Level tether, L = 1.5 m, H = a·H_max = 0.014 m: L − S ≈ 8H²/(3L) = 3.5e-4 m, below one tick of
  // 0.3 m/s / 30 Hz = 0.01 m; a = 0.2 (H = 0.14 m) leaves 0.035 m.
  EXPECT_TRUE(plausibilityOf("tether_default", {"target.a=0.2"}).empty());
  expectOnlyWarning(plausibilityOf("tether_default", {"target.a=0.02"}), "target.a", "nearly taut");
}

TEST(TetherPlausibility, ANearlyVerticalTargetShape) {
  // Level tether, L = 1.5 m: span S = 2 asinh(√(CH(CH+2)))/C with C = 8H/(L² − 4H²) (eqs 2 and 7). a = 1.0713
  // (H = 0.74991 m) gives S = 1.75 mm, below one tick of 0.3 m/s / 30 Hz = 0.01 m; a = 1.07 (H = 0.749 m) gives
  // S = 14.6 mm; a = 1 (H = 0.7 m) gives S = 0.35 m.
  EXPECT_TRUE(plausibilityOf("tether_default", {"target.a=1.07"}).empty());
  expectOnlyWarning(plausibilityOf("tether_default", {"target.a=1.0713"}), "target.a", "hangs nearly vertically");
}

}  // namespace
}  // namespace maris
