// Plausibility warnings of the ship: a hull too full for thin-ship theory (L/B < 8) and low speeds on an
// offsets table with a coarse grid, each alone at its field; the Wigley default raises none.
#include "engine/plausibility_test_support.hpp"

namespace maris {
namespace {

using testing::expectOnlyWarning;
using testing::plausibilityOf;
using testing::warningAt;

TEST(ShipPlausibility, TheWigleyDefaultRaisesNone) {
  testing::expectBuiltinsRaiseNone("ship", {"ship_series60", "ship_kcs"});
}

TEST(ShipPlausibility, AFullFormulaHullIsBeyondThinShipTheory) {
  // L = 4 m: B = 0.49 m is L/B = 8.16, B = 0.51 m is L/B = 7.84.
  EXPECT_TRUE(plausibilityOf("ship_default", {"hull.beam=0.49"}).empty());
  expectOnlyWarning(plausibilityOf("ship_default", {"hull.beam=0.51"}), "hull.beam", "L/B = 7.843");
}

TEST(ShipPlausibility, TheKcsTableIsFullerThanThinShipTheoryAndItsExampleSaysSo) {
  // KCS: Lpp 230 m, B 32.2 m, L/B = 7.14 (the model is geometrically similar).
  const auto w = plausibilityOf("ship_kcs", {});
  expectOnlyWarning(w, "hull.source", "L/B = 7.1");
  EXPECT_NE(findBuiltin("ship_kcs")->scenario.description.find("warn"), std::string::npos);
}

TEST(ShipPlausibility, LowSpeedsOnATableNeedAFineGrid) {
  const auto base = plausibilityOf("ship_series60", {});
  const auto low = plausibilityOf("ship_series60", {"speed.froude_min=0.06"});
  EXPECT_EQ(low.size(), base.size() + 1) << describeErrors(low);
  EXPECT_NE(warningAt(low, "parameters.speed.froude_min"), nullptr) << describeErrors(low);
  const auto fine = plausibilityOf("ship_series60", {"speed.froude_min=0.06", "numerics.stations=513",
                                                     "numerics.waterlines=101"});
  EXPECT_EQ(warningAt(fine, "parameters.speed.froude_min"), nullptr) << describeErrors(fine);
}

}  // namespace
}  // namespace maris
