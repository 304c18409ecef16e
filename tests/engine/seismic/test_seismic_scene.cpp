// The seismic scene through the catalog: built-in scenarios validate, bad input is a field error,
// the default scenario runs and reports the free-field checks.
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/run_context.hpp"

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

TEST(SeismicScene, SvBeyondCriticalAngleIsAcceptedAndFlagged) {
  // Default seabed vs/vp = 2000/4546: critical angle 26.1° (the paper's value). Beyond it the
  // evanescent branch is computed: validation passes, the run flags it and reports a small precursor.
  auto s = findBuiltin("seismic_verification_box")->scenario;
  auto& prm = s.parameters;
  prm["incidence"]["wave_type"] = "SV";
  prm["incidence"]["angle_deg"] = 30.0;
  prm["input"]["kind"] = "ricker";
  prm["input"]["ricker_peak_frequency"] = 1.0;
  prm["solver"]["cutoff_frequency"] = 3.0;
  prm["solver"]["duration"] = 2.0;
  prm["output"]["snapshot_count"] = 0;
  const auto& scene = requireScene("seismic");
  ASSERT_TRUE(validateParameters(scene, prm).empty());
  RunContext ctx;
  const Results r = scene.run(prm, ctx);
  ASSERT_NE(r.findScalar("reflected_p_evanescent"), nullptr);
  EXPECT_EQ(r.findScalar("reflected_p_evanescent")->value, 1.0);
  bool warned = false;
  for (const auto& w : ctx.warnings()) warned = warned || w.find("evanescent") != std::string::npos;
  EXPECT_TRUE(warned);
  // A Ricker wavelet's Hilbert transform decays as t⁻³: 1 s of lead leaves < 1 % at the start.
  EXPECT_LT(r.findScalar("free_field_precursor_at_start")->value, 0.01);
}

// A duration that ends before the incident wave reaches the seabed origin leaves no reference motion (every peak
// ratio 0/0): the run ends with an input error naming solver.duration, never with NaN results.
TEST(SeismicScene, DurationEndingBeforeTheWaveArrivesIsAnInputError) {
  for (const char* id : {"seismic_default", "seismic_synthetic_record"}) {
    auto s = findBuiltin(id)->scenario;
    s.parameters["solver"]["duration"] = 0.1;
    s.parameters["output"]["snapshot_count"] = 0;
    const auto& scene = requireScene("seismic");
    ASSERT_TRUE(validateParameters(scene, s.parameters).empty()) << id;
    RunContext ctx;
    try {
      scene.run(s.parameters, ctx);
      ADD_FAILURE() << id << ": no error";
    } catch (const InputError& e) {
      ASSERT_FALSE(e.errors().empty());
      EXPECT_NE(e.errors()[0].path.find("solver.duration"), std::string::npos) << id << ": " << e.what();
    }
  }
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

namespace maris {
namespace {

TEST(SeismicScene, SweepAndTransferTablesAreFilled) {
  // Regression: columns were filled through references that a later Table::add invalidated, leaving
  // the angle-sweep and free-field transfer tables empty. A small, coarse reef sweep (f_cut 0.8 Hz).
  auto s = findBuiltin("seismic_default")->scenario;
  auto& prm = s.parameters;
  prm["model"]["compare_without_water"] = false;
  prm["incidence"]["sweep_angles_deg"] = nlohmann::json::array({15.0});
  prm["input"]["ricker_peak_frequency"] = 0.3;
  prm["solver"]["cutoff_frequency"] = 0.8;
  prm["solver"]["duration"] = 3.0;
  prm["output"]["snapshot_count"] = 0;
  prm["modes"]["count"] = 2;
  const auto& scene = requireScene("seismic");
  ASSERT_TRUE(validateParameters(scene, prm).empty());
  RunContext ctx;
  const Results r = scene.run(prm, ctx);
  auto rows = [&](const std::string& name) {
    for (const auto& t : r.tables)
      if (t.name == name) return t.rows();
    return std::size_t{0};
  };
  EXPECT_EQ(rows("angle_sweep"), 2u);
  EXPECT_EQ(rows("free_field_transfer"), 400u);
  EXPECT_EQ(rows("modes"), 2u);
  EXPECT_GT(r.stats.error_estimate, 0.0);  // the coarse-companion estimate is present
}

}  // namespace
}  // namespace maris

namespace maris {
namespace {

TEST(SeismicScene, CancellationStopsTheRunDuringTheTimeStepping) {
  // A cancel request 100 ms into the default scenario (seconds of FE work on three threads) must end
  // the run with RunCancelled before the stage after the FE runs (modal analysis) starts: the
  // workers check the flag every step. No wall-time bound (the test machine is shared).
  const auto& scene = requireScene("seismic");
  const auto prm = findBuiltin("seismic_default")->scenario.parameters;
  std::atomic<bool> cancel{false};
  std::atomic<bool> reached_modes{false};
  RunContext ctx(
      [&](double, const std::string& stage) {
        if (stage.rfind("modal", 0) == 0) reached_modes = true;
      },
      &cancel);
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    cancel = true;
  });
  EXPECT_THROW(scene.run(prm, ctx), RunCancelled);
  stopper.join();
  EXPECT_FALSE(reached_modes);
}

}  // namespace
}  // namespace maris
