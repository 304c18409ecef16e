// The "fiv" scene end to end: the built-in scenario's curves, the paper's Reynolds numbers, the
// energy balance on every converged cycle, hard cases, input errors, post-processing and calibration.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "fiv/fiv_calibration.hpp"
#include "fiv/fiv_theory.hpp"

namespace maris::fiv {
namespace {

// A built-in scenario with overrides "path=json".
Scenario builtin(const std::string& id, const std::vector<std::string>& overrides = {}) {
  Scenario s = findBuiltin(id)->scenario;
  for (const auto& o : overrides) applyOverride(s, o);
  return s;
}

Results run(const Scenario& s) {
  RunContext ctx;
  return runScenario(requireScene("fiv"), s, ctx);
}

bool anyWarningContains(const Results& r, const std::string& text) {
  for (const auto& w : r.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

TEST(FivScene, DefaultSweepReportsEveryCurveFiniteWithTheEnergyBalanceOnConvergedCycles) {
  // 24 speeds 0.2–2.5 m/s (every 0.1 m/s). Paper eq 8 = eq 13 on a periodic cycle: ⟨Fẏ⟩ = ⟨cẏ²⟩ within
  // 1 % where the cycle converged (RK4 work error at 40 steps per period is ~1e-4).
  const Results r = run(builtin("fiv_default", {"sweep.speed_count=24"}));
  const Table* sweep = r.findTable("sweep");
  ASSERT_NE(sweep, nullptr);
  for (const auto& c : sweep->columns)
    for (double v : c.values) ASSERT_TRUE(std::isfinite(v)) << c.name;
  for (const char* plot : {"amplitude_ratio", "frequency_ratio", "power", "efficiency", "detail_spectrum"}) {
    bool found = false;
    for (const auto& p : r.plots) found = found || p.name == plot;
    EXPECT_TRUE(found) << plot;
  }
  EXPECT_NE(r.findTable("paper_amplitude"), nullptr);
  // The animated view: one frame per requested step, the cylinder box first, the surface at z = 0
  // (the detail point is at h* = 5.56, so the box centre sits 0.5 m below it, ± the amplitude).
  ASSERT_EQ(r.view.frames.size(), 48u);
  const Shape3D& box = r.view.frames.front().shapes.front();
  EXPECT_EQ(box.kind, Shape3D::Kind::Box);
  EXPECT_NEAR(box.points[0].z(), -5.56 * 0.09, r.findScalar("detail_amplitude")->value + 1e-9);
  ASSERT_TRUE(r.view.water_level_z.has_value());
  EXPECT_EQ(*r.view.water_level_z, 0.0);
  int checked = 0;
  for (const char* label : {"h1.11", "h5.56", "hinf"}) {
    const auto& p = sweep->find(std::string("P_up_") + label)->values;
    const auto& pf = sweep->find(std::string("PF_up_") + label)->values;
    const auto& res = sweep->find(std::string("residual_up_") + label)->values;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (res[i] > 1e-3 || p[i] < 1e-3) continue;
      EXPECT_NEAR(pf[i] / p[i], 1.0, 0.01) << label << " row " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
  // Above 2 m/s the published wake coupling makes the responses quasi-periodic: they are found stationary
  // (response 2) and averaged, and none is left drifting (response 3), so the run gives no such warning.
  int stationary = 0;
  for (const auto& c : sweep->columns) {
    if (c.name.rfind("response_", 0) != 0) continue;
    for (double v : c.values) {
      EXPECT_NE(v, 3.0) << c.name;
      stationary += v == 2.0;
    }
  }
  EXPECT_GT(stationary, 0);
  EXPECT_FALSE(anyWarningContains(r, "drifting")) << r.warnings.size();
}

// Partial results (for live plots): the sweep table grows row by row while the first h* climbs,
// every partial table is rectangular, and each partial row equals the finished run's row (the
// same continuation computed once: bit for bit).
TEST(FivScene, SweepPublishesGrowingPartialResultsWhoseRowsMatchTheFinishedRun) {
  const Scenario s = builtin("fiv_default", {"sweep.speed_count=12"});
  std::vector<std::shared_ptr<const Results>> partials;
  RunContext ctx;
  ctx.setPartialSink([&](std::shared_ptr<const Results> r) { partials.push_back(std::move(r)); }, 0.0);
  const Results final_results = runScenario(requireScene("fiv"), s, ctx);
  const Table* final_sweep = final_results.findTable("sweep");
  ASSERT_NE(final_sweep, nullptr);
  ASSERT_GE(partials.size(), 3u);
  std::size_t previous_rows = 0, grew = 0;
  for (const auto& partial : partials) {
    const Table* sweep = partial->findTable("sweep");
    ASSERT_NE(sweep, nullptr);
    for (const auto& c : sweep->columns) ASSERT_EQ(c.values.size(), sweep->rows()) << c.name;
    EXPECT_GE(sweep->rows(), previous_rows);
    grew += sweep->rows() > previous_rows ? 1 : 0;
    previous_rows = sweep->rows();
    for (const auto& c : sweep->columns) {
      const Column* whole = final_sweep->find(c.name);
      ASSERT_NE(whole, nullptr) << c.name;
      for (std::size_t i = 0; i < c.values.size(); ++i) ASSERT_EQ(c.values[i], whole->values[i]) << c.name << " row " << i;
    }
    EXPECT_FALSE(partial->plots.empty());
  }
  EXPECT_EQ(partials.front()->findTable("sweep")->rows(), 1u);  // published after the first point
  EXPECT_GE(grew, 3u);
  EXPECT_EQ(previous_rows, final_sweep->rows());
}

TEST(FivScene, ReynoldsNumbersReproduceThePapersPairsWithinOnePercent) {
  // Re = UD/ν with D = 0.09 m and ν = 1.118e-6 m²/s (both inferred from the paper's (U, Re) pairs and h/h*); paper pairs (U [m/s], Re) from its text.
  const Results r = run(builtin("fiv_default", {"sweep.speed_count=24", "free_surface.submergence_ratios=[]",
                                                "sweep.sweep_down=false"}));
  const Table* t = r.findTable("sweep");
  const auto& u = t->find("U")->values;
  const auto& re = t->find("Re")->values;
  const std::pair<double, double> pairs[] = {{0.2, 1.61e4}, {0.4, 3.22e4}, {0.5, 4.025e4}, {1.2, 9.66e4},
                                             {2.0, 1.61e5},  {2.2, 1.78e5}, {2.5, 2.02e5}};
  for (const auto& [speed, paper_re] : pairs) {
    std::size_t i = 0;
    while (i < u.size() && std::abs(u[i] - speed) > 1e-9) ++i;
    ASSERT_LT(i, u.size()) << speed;
    EXPECT_NEAR(re[i] / paper_re, 1.0, 0.01) << "U = " << speed;
  }
}

TEST(FivScene, CylinderCloseToTheSurfaceIsFlaggedWhenItsAmplitudeExceedsTheClearance) {
  // h* = 1.11: clearance h − D/2 = 0.055 m; galloping amplitudes of 0.1 m and more must be flagged.
  const Results r = run(builtin("fiv_default", {"sweep.speed_count=8", "free_surface.include_deep=false",
                                                "free_surface.submergence_ratios=[1.11]", "model.forcing=\"galloping\""}));
  EXPECT_TRUE(anyWarningContains(r, "break the surface"));
  const auto& flags = r.findTable("sweep")->find("clearance_exceeded_up_h1.11")->values;
  EXPECT_EQ(flags.back(), 1.0);
  EXPECT_EQ(flags.front(), 0.0);  // 0.2 m/s is below the galloping onset: at rest
}

TEST(FivScene, HardCasesZeroDampingLowMassRatioAndZeroSpeedStayFinite) {
  // ξ = 0: no converted power, galloping saturates at the polynomial's root r∞ (finite amplitude).
  const Results undamped = run(builtin("fiv_default", {"sweep.speed_count=4", "structure.damping_input=\"coefficient\"",
                                                       "structure.damping_coefficient=0", "sweep.sweep_down=false"}));
  EXPECT_TRUE(anyWarningContains(undamped, "zero structural damping"));
  for (double p : undamped.findTable("sweep")->find("P_up_hinf")->values) EXPECT_EQ(p, 0.0);
  // m* = 0.06: far outside the model's range, must still run and warn.
  const Results light = run(builtin("fiv_default", {"sweep.speed_count=4", "structure.mass=0.5"}));
  EXPECT_TRUE(anyWarningContains(light, "mass ratio"));
  for (const auto& c : light.findTable("sweep")->columns)
    for (double v : c.values) EXPECT_TRUE(std::isfinite(v)) << c.name;
  // U = 0: no fluid force, the seed decays: A = 0 exactly, no power.
  const Results still = run(builtin("fiv_default", {"sweep.speed_count=1", "sweep.speed_min=0", "detail.speed=0"}));
  for (double a : still.findTable("sweep")->find("A_star_up_hinf")->values) EXPECT_EQ(a, 0.0);
  EXPECT_EQ(still.findScalar("detail_amplitude")->value, 0.0);
}

TEST(FivScene, BadInputNamesTheFieldAndTheAllowedValues) {
  Scenario s = builtin("fiv_default", {"sweep.speed_min=2", "sweep.speed_max=1", "calibration.enabled=true",
                                       "calibration.free_coefficients=\"galloping.a9\""});
  const auto errors = validateParameters(requireScene("fiv"), s.parameters);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].path, "parameters.sweep.speed_max");
  EXPECT_EQ(errors[1].path, "parameters.calibration.free_coefficients");
  EXPECT_NE(errors[1].message.find("galloping.force_scale"), std::string::npos) << "lists the allowed names";
  Scenario post = builtin("fiv_default", {"analysis.mode=\"post_process\"", "analysis.series_file=\"/nonexistent.csv\""});
  const auto post_errors = validateParameters(requireScene("fiv"), post.parameters);
  ASSERT_EQ(post_errors.size(), 1u);
  EXPECT_EQ(post_errors[0].path, "parameters.analysis.series_file");
}

TEST(FivScene, CancellationStopsTheSweep) {
  std::atomic<bool> cancel{true};
  RunContext ctx({}, &cancel);
  EXPECT_THROW(runScenario(requireScene("fiv"), builtin("fiv_default"), ctx), RunCancelled);
}

TEST(FivScene, PostProcessorReadsAnImportedRecord) {
  // y = A sin(2πft), lift with a 7f shedding component: A, f1, n = 7 (eq 22), P = ½cω²A² (eq 13),
  // η from eqs 14–15. 400 samples per period: amplitudes and powers exact to round-off.
  const double a = 0.2, f = 0.5, dt = 1.0 / (400.0 * f), pi = std::numbers::pi;
  const auto file = std::filesystem::temp_directory_path() / "maris_fiv_series_test.csv";
  {
    std::ofstream out(file);
    out.precision(12);
    out << "# synthetic record\ntime,y,ydot,lift\ns,m,m/s,N\n";
    for (int i = 0; i < 400 * 16; ++i) {
      const double t = i * dt;
      out << t << "," << a * std::sin(2 * pi * f * t) << "," << a * 2 * pi * f * std::cos(2 * pi * f * t) << ","
          << 30.0 * std::cos(2 * pi * f * t) + 10.0 * std::sin(2 * pi * 7 * f * t) << "\n";
    }
  }
  const Results r = run(builtin("fiv_default", {"analysis.mode=\"post_process\"",
                                                "analysis.series_file=\"" + file.string() + "\"",
                                                "analysis.series_flow_speed=2.0"}));
  std::filesystem::remove(file);
  EXPECT_NEAR(r.findScalar("amplitude")->value, a, 1e-9);  // samples hit the peaks; 12 digits written
  EXPECT_NEAR(r.findScalar("f1")->value, f, 1e-9);
  EXPECT_EQ(r.findScalar("lift_alternations")->value, 7.0);
  const FivModel model = buildFivModel(FivParameters{});
  const double p = sinusoidDamperPower(model.damping, 2 * pi * f, a);
  EXPECT_NEAR(r.findScalar("power")->value / p, 1.0, 1e-5);
  // ⟨lift·ẏ⟩: only the in-phase cos part does work: ½·30·(2πf a).
  EXPECT_NEAR(r.findScalar("power_fluid")->value, 0.5 * 30.0 * 2 * pi * f * a, 1e-4);
  const double fluid = sweptFluidPower(model.density, 2.0, model.length, model.side, a);
  EXPECT_NEAR(r.findScalar("efficiency")->value / betzEfficiency(p, fluid), 1.0, 1e-5);
}

TEST(FivScene, CalibrationRecoversAKnownForceScale) {
  // Reference points made by the model itself with force_scale = 1.3 (galloping only, deep): the fit
  // from 1.0 must return 1.3 within 1 % (limit cycles converged to 1e-4: the data carry ~1e-4 noise).
  FivParameters truth;
  truth.forcing = "galloping";
  truth.force_scale = 1.3;
  truth.convergence_tolerance = 1e-4;
  std::vector<ReferencePoint> points;
  for (double u : {0.8, 1.4, 2.0}) {
    ReferencePoint p;
    p.speed = u;
    p.submergence_ratio = kDeep;
    p.amplitude = 1.0;  // placeholder, replaced by the model's amplitude below
    points.push_back(p);
  }
  RunContext ctx;
  for (const auto& r : calibrationResiduals(truth, points, ctx)) {
    for (auto& p : points)
      if (p.speed == r.speed) p.amplitude = r.model, p.amplitude_sigma = 0.01 * r.model;
  }
  FivParameters start = truth;
  start.force_scale = 1.0;
  start.free_coefficients = "galloping.force_scale";
  const CalibrationResult fit = calibrate(start, points, ctx);
  EXPECT_NEAR(fit.fitted[0], 1.3, 0.013);
  EXPECT_LT(fit.cost, 0.01 * fit.cost_initial);
}

}  // namespace
}  // namespace maris::fiv
