// Plausibility warnings of the FIV scene: speeds whose Re = UD/ν leaves the paper's 1.61e4–2.01e5 and
// submergences below the fitted h* = 1.11, each alone at its field; the paper's set-up raises none.
#include "engine/plausibility_test_support.hpp"

namespace maris {
namespace {

using testing::expectOnlyWarning;
using testing::plausibilityOf;

TEST(FivPlausibility, ThePapersSetUpRaisesNone) {
  testing::expectBuiltinsRaiseNone("fiv", {"fiv_galloping_hysteresis"});
}

TEST(FivPlausibility, ASpeedBeyondThePapersReynoldsNumbers) {
  // D = 0.09 m, ν = 1.118e-6 m²/s: U = 2.6 m/s is Re = 2.093e5 > 2.013e5.
  expectOnlyWarning(plausibilityOf("fiv_default", {"sweep.speed_max=2.6"}), "sweep.speed_max", "Re = UD/ν = 2.093e+05");
  expectOnlyWarning(plausibilityOf("fiv_default", {"sweep.speed_min=0.1"}), "sweep.speed_min", "Re = UD/ν = 8050");
}

TEST(FivPlausibility, ASubmergenceShallowerThanTheFit) {
  expectOnlyWarning(plausibilityOf("fiv_default", {"free_surface.submergence_ratios=[0.8, 2.22]"}),
                    "free_surface.submergence_ratios[0]", "h* = 1.11");
  expectOnlyWarning(plausibilityOf("fiv_default", {"detail.submergence_ratio=1.0"}), "detail.submergence_ratio",
                    "h* = 1.11");
}

TEST(FivPlausibility, ALightCylinder) {
  // ρD²L = 998.2 × 0.09² × 1 = 8.085 kg: m = 8 kg is m* = 0.9894, 8.2 kg is 1.014.
  EXPECT_TRUE(plausibilityOf("fiv_default", {"structure.mass=8.2"}).empty());
  expectOnlyWarning(plausibilityOf("fiv_default", {"structure.mass=8"}), "structure.mass", "m* = m/(ρD²L) = 0.9894");
}

TEST(FivPlausibility, TheGallopingHysteresisExampleSaysWhyItWarns) {
  // U = 4.4–9.4 m/s is Re = 3.5e5–7.6e5: the example checks harmonic balance on the model, not the paper's flow.
  const auto w = plausibilityOf("fiv_galloping_hysteresis", {});
  EXPECT_EQ(w.size(), 3u) << describeErrors(w);
  EXPECT_NE(findBuiltin("fiv_galloping_hysteresis")->scenario.description.find("warn"), std::string::npos);
}

}  // namespace
}  // namespace maris
