// Length scales that make the hull degenerate are input errors naming the field (they gave NaN
// Holtrop–Mennen results with exit 0).
#include <gtest/gtest.h>

#include <filesystem>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "source_tree.hpp"

namespace maris {
namespace {

std::string runError(const std::vector<std::string>& assignments) {
  Scenario s = findBuiltin("ship_default")->scenario;
  for (const auto& a : assignments) applyOverride(s, a);
  RunContext ctx;
  try {
    runScenario(requireScene("ship"), s, ctx);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ShipInputLimits, AnOffsetsTableAtTheWrongLengthIsNamed) {
  // kcs_model_offsets.csv spans 7.58 m (Lpp 7.2786 m); offsets_length_pp left at 1 m scaled it 7.3 times.
  const std::string file = maris::test::sourceDir() + "/resources/data/ship/kcs_model_offsets.csv";
  const std::string m = runError({"hull.source=offsets_file", "hull.offsets_file=" + file, "hull.offsets_length_pp=1.0"});
  EXPECT_NE(m.find("parameters.hull.offsets_length_pp = 1.0: but the stations of"), std::string::npos) << m;
  EXPECT_NE(m.find("span 7.58335 m"), std::string::npos) << m;
}

TEST(ShipInputLimits, ADenormalBeamIsADegenerateHull) {
  const std::string m = runError({"hull.source=wigley", "hull.beam=5e-324"});
  EXPECT_NE(m.find("parameters.hull.beam = 5e-324: must be at least hull.length / 1000"), std::string::npos) << m;
}

}  // namespace
}  // namespace maris
