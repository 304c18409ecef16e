// The seismic scene through the catalog: built-in scenarios validate, bad input is a field error,
// the default scenario runs and reports the free-field checks.
#include <gtest/gtest.h>

#include "catalog.hpp"
#include "core/errors.hpp"

namespace maris {
namespace {

TEST(SeismicScene, BuiltinScenariosValidate) {
  const auto& scene = requireScene("seismic");
  int count = 0;
  for (const auto& b : builtinScenarios()) {
    if (b.scenario.scene != "seismic") continue;
    ++count;
    const auto errors = validateParameters(scene, b.scenario.parameters);
    EXPECT_TRUE(errors.empty()) << b.id << ": " << describeErrors(errors);
  }
  EXPECT_GE(count, 2);
  EXPECT_NE(findBuiltin("seismic_default"), nullptr);
}

TEST(SeismicScene, SvBeyondCriticalAngleIsAFieldError) {
  // Default seabed vs/vp = 2000/4546: critical angle 26.1° (the paper's value).
  auto s = findBuiltin("seismic_default")->scenario;
  s.parameters["incidence"]["wave_type"] = "SV";
  s.parameters["incidence"]["angle_deg"] = 30.0;
  const auto errors = validateParameters(requireScene("seismic"), s.parameters);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].path, "parameters.incidence.angle_deg");
  EXPECT_NE(errors[0].message.find("26.1"), std::string::npos) << errors[0].message;
}

TEST(SeismicScene, TooFineMeshIsAFieldError) {
  auto s = findBuiltin("seismic_default")->scenario;
  s.parameters["solver"]["cutoff_frequency"] = 40.0;
  const auto errors = validateParameters(requireScene("seismic"), s.parameters);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].path, "parameters.solver.cutoff_frequency");
}

}  // namespace
}  // namespace maris
