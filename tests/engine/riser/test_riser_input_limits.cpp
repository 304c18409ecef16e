// A time step far below the run's length is an input error naming solver.time_step and the limit
// (the fuzz campaign's "1 steps", end_z = −2.8e8 m at 1e-20 s from an overflowed step count).
#include <gtest/gtest.h>

#include "catalog.hpp"
#include "core/checked_count.hpp"
#include "core/errors.hpp"

namespace maris {
namespace {

std::string runError(const std::string& assignment) {
  Scenario s = findBuiltin("riser_default")->scenario;
  applyOverride(s, assignment);
  RunContext ctx;
  try {
    runScenario(requireScene("riser"), s, ctx);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RiserInputLimits, TinyTimeStepsAreRefusedNotOverflowed) {
  for (const char* step : {"1e-20", "1e-12"}) {
    const std::string m = runError(std::string("solver.time_step=") + step);
    EXPECT_NE(m.find("parameters.solver.time_step: gives"), std::string::npos) << step << ": " << m;
    EXPECT_NE(m.find("the limit is 2e+10"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace maris
