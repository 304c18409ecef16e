// Plausibility warnings of the WEC: each check fires alone, at its field, just beyond its range (closed forms:
// ka = ω²a/g; deep-water λ = 2πg/ω²; the hemisphere's draft is its radius), and the default raises none.
#include <cmath>
#include <numbers>

#include "engine/plausibility_test_support.hpp"

namespace maris {
namespace {

using testing::expectOnlyWarning;
using testing::plausibilityOf;

TEST(WecPlausibility, TheBuiltInFloatsRaiseNone) {
  testing::expectBuiltinsRaiseNone("wec");
}

TEST(WecPlausibility, AFloatDeeperThanTheWaterReachesTheSeaBed) {
  // a = 3 m in 2.5 m of water; H = 1 m stays below 0.78 d = 1.95 m, so only the float is named.
  expectOnlyWarning(plausibilityOf("wec_default", {"water.depth=2.5", "waves.height=1"}), "floats[0].radius",
                    "reaches the sea bed");
}

TEST(WecPlausibility, AFrequencyBeyondHulmesTables) {
  // ka = 10 at ω = √(10 g/a) = 5.718 rad/s for a = 3 m: 5.7 is inside, 5.75 beyond.
  EXPECT_TRUE(plausibilityOf("wec_default", {"frequency.omega_max=5.7"}).empty());
  expectOnlyWarning(plausibilityOf("wec_default", {"frequency.omega_max=5.75"}), "frequency.omega_max",
                    "end of Hulme's tables");
  expectOnlyWarning(plausibilityOf("wec_default", {"frequency.omega_max=5.7", "frequency.check_frequencies=[1, 5.75]"}),
                    "frequency.check_frequencies[1]", "end of Hulme's tables");
}

TEST(WecPlausibility, ARegularWaveSteeperThanOneSeventh) {
  // ω = 2 rad/s in 20 m is deep water (kh = 8.2): λ = 2πg/ω² = 15.41 m; H = 2.3 m is 0.149 > 1/7, 2.1 m is 0.136.
  const double lambda = 2 * std::numbers::pi * 9.81 / 4.0;
  EXPECT_TRUE(plausibilityOf("wec_default", {"waves.frequency=2", "waves.height=2.1"}).empty());
  const auto w = plausibilityOf("wec_default", {"waves.frequency=2", "waves.height=2.3"});
  char expected[64];
  std::snprintf(expected, sizeof expected, "H/λ = %.4g", 2.3 / lambda);
  expectOnlyWarning(w, "waves.height", expected);
}

TEST(WecPlausibility, AnAmplitudeBeyondTheFloatsDraft) {
  // H/2 = 3.05 m > a = 3 m at ω = 1 rad/s (λ = 59.8 m in 20 m, H/λ = 0.10: not too steep).
  EXPECT_TRUE(plausibilityOf("wec_default", {"waves.height=5.9"}).empty());
  expectOnlyWarning(plausibilityOf("wec_default", {"waves.height=6.1"}), "waves.height", "exceeds the draft");
}

TEST(WecPlausibility, AWaveInShallowWater) {
  // ω = 0.2 rad/s in 20 m: ω²h/g = 0.00815 = kh tanh kh gives kh = 0.290 < π/10 = 0.314.
  expectOnlyWarning(plausibilityOf("wec_default", {"waves.frequency=0.2"}), "waves.frequency", "shallow water");
}

TEST(WecPlausibility, ASteepIrregularSea) {
  // T_p = 6 s in 20 m: λ_p = 55.0 m (finite depth); H_s = 4 m is H_s/λ_p = 0.072 > 1/15.
  expectOnlyWarning(plausibilityOf("wec_irregular", {"waves.significant_height=4"}), "waves.significant_height",
                    "1/15");
}

}  // namespace
}  // namespace maris
