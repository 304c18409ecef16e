// Time integration: the three integrators of core/ode.hpp on the riser, the automatic choice, and the
// top motion from a time table.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_integration.hpp"
#include "riser/riser_results.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "riser_test_support.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

using test::run;
using test::column;

// Largest difference of a history column between two runs at the times both sampled.
double maxDifferenceAtCommonTimes(const Results& a, const Results& b, const std::string& name) {
  const auto &ta = column(a, "time"), &tb = column(b, "time"), &va = column(a, name), &vb = column(b, name);
  double d = 0;
  std::size_t j = 0;
  for (std::size_t i = 0; i < ta.size(); ++i) {
    while (j < tb.size() && tb[j] < ta[i] - 1e-9) ++j;
    if (j < tb.size() && std::abs(tb[j] - ta[i]) < 1e-9) d = std::max(d, std::abs(va[i] - vb[j]));
  }
  return d;
}

// A 3D problem with current and elliptical top motion: 60 m tensioned riser, n = 8, 4 s.
RiserParameters movingRiser() {
  RiserParameters p;
  p.length = 60.0;
  p.segment_count = 8;
  p.bottom_z = -60.0;
  p.seabed_level = -60.0;
  p.top_tension = 1e6;
  p.end_time = 4.0;
  p.motion_period = 4.0;
  p.motion_ramp_time = 2.0;
  p.stress_times = {2.0};
  p.probes = {{30.0}};
  return p;
}

// RK4 at half its stability limit and DOPRI5 at rtol 1e-9 solve the same equations: the probe motion
// (≈ 0.5 m) agrees within 1e-6·L. DOPRI5 reports its error estimate and takes steps of its own choice.
TEST(RiserIntegrators, Rk4AndDopri5Agree) {
  RiserParameters p = movingRiser();
  p.integrator = "rk4";
  const Results rk4 = run(p);
  p.integrator = "dopri5";
  p.tolerance = 1e-9;
  const Results dopri = run(p);
  EXPECT_GT(*std::max_element(column(rk4, "probe_dx").begin(), column(rk4, "probe_dx").end()), 0.1);
  for (const char* c : {"probe_dx", "probe_dy", "probe_dz"})
    EXPECT_LT(maxDifferenceAtCommonTimes(rk4, dopri, c), 1e-6 * p.length) << c;
  EXPECT_GT(dopri.stats.error_estimate, 0.0);
  EXPECT_NE(dopri.stats.method.find("DOPRI5"), std::string::npos);
  EXPECT_NE(rk4.stats.steps, dopri.stats.steps);
}

// Generalized-α is second order in both formulations: against DOPRI5 (rtol 1e-10), halving h from T/80
// must cut the probe error by about 4 (measured 3.96 J, 3.97 A; 4.2 while A's velocities were projected;
// accept > 3), and at h = T/160 the error is below 3e-3 of the motion (measured 1.7e-3 J, 7.6e-4 A). J: the
// bottom constraint drift (Baumgarte at rate 1/h) falls at the same order. A: the joints' positions are
// projected after every step (velocities are left to Baumgarte), so the drift at output times between the
// projected steps, where q is a Hermite interpolant, is a local error: below 2e-7 L and falling at third
// order (measured 7.8e-6 m = 1.3e-7 L at T/80, 9.4e-7 m at T/160; 4.8e-4 m = 8e-6 L at T/80 with Baumgarte
// alone). Four frames: chunks (one Jacobian
// each) longer than the step. A uses the O(n) force-space Newton matrix, J the dense one.
TEST(RiserIntegrators, ImplicitConvergesAtSecondOrderInBothFormulations) {
  RiserParameters p = movingRiser();
  p.integrator = "dopri5";
  p.tolerance = 1e-10;
  const Results reference = run(p);
  const double motion = *std::max_element(column(reference, "probe_dx").begin(), column(reference, "probe_dx").end());
  p.integrator = "implicit";
  p.tolerance = 1e-8;
  p.frame_count = 4;
  for (const char* formulation : {"joint", "absolute"}) {
    p.formulation = formulation;
    double errors[2], drift[2];
    for (int k = 0; k < 2; ++k) {
      p.time_step = k == 0 ? 0.05 : 0.025;
      const Results implicit = run(p);
      errors[k] = maxDifferenceAtCommonTimes(reference, implicit, "probe_dx");
      drift[k] = implicit.findScalar("constraint_drift")->value;
    }
    EXPECT_GT(errors[0] / errors[1], 3.0) << formulation << ": " << errors[0] << " " << errors[1];
    EXPECT_LT(errors[1], 3e-3 * motion) << formulation;
    if (std::string(formulation) == "joint") {
      EXPECT_GT(drift[0] / drift[1], 3.0) << formulation << ": " << drift[0] << " " << drift[1];
    } else {
      EXPECT_LT(std::max(drift[0], drift[1]), 2e-7 * p.length) << drift[0] << " " << drift[1];
      EXPECT_GT(drift[0] / drift[1], 6.0) << drift[0] << " " << drift[1];
    }
  }
}

// The 3D cable (free bottom, whirled top) in absolute coordinates: generalized-α stays second order with the
// joints' positions closed after every step. Richardson differences of the probe at L/2 between h = 40, 20,
// 10 ms over 10 s fall by about 4 (measured 4.16; with Newton at 1e-9 4.12, and 4.04, 3.98 on to 2.5 ms; accept
// > 3.8). Tolerance 1e-6, so that Newton follows the step's expected error (1e-3 of it: 1e-6, 6.3e-7, 1.6e-7): at
// the default 1e-3 (Newton at 1e-6 throughout) the differences stop at Newton's floor, 3.9e-5 m (ratios 3.6, 2.9,
// 1.7). Carrying the top's velocity mismatch down the chain at every step made it first order
// (bench error 4.6e-3 instead of 1.6e-4 at 20 ms, n = 20; here a ratio of 2.9).
TEST(RiserIntegrators, ImplicitStaysSecondOrderOnAFreeCableInAbsoluteCoordinates) {
  RiserParameters p = test::implicitCable(10, 0.04);
  p.frame_count = 4;
  p.tolerance = 1e-6;
  std::vector<Results> runs;
  for (double h : {0.04, 0.02, 0.01}) {
    p.time_step = h;
    runs.push_back(run(p));
  }
  const double coarse = maxDifferenceAtCommonTimes(runs[0], runs[1], "probe_dx");
  const double fine = maxDifferenceAtCommonTimes(runs[1], runs[2], "probe_dx");
  EXPECT_GT(coarse / fine, 3.8) << coarse << " " << fine;
  EXPECT_GT(fine, 0.0);
}

// The same cable without torsion at small steps: the error must keep falling at second order, not stop at a
// floor set by Newton's tolerance. In A Newton contracts slowly (a median 0.065 per iteration against J's 0.0036 at T/1600),
// and the iterates it accepts, each off by up to its tolerance, add up step after step. With Newton at 1e-6
// (the former rule, whatever the asked tolerance) the largest probe difference against J2 at T/3200 was 1.9e-4,
// 8.4e-5, 1.2e-4 of the motion at T/200, T/400, T/800 (n = 50); with Newton at 1e-3 of the step's expected error
// (the asked 1e-6 is below it: 6.3e-7, 1.6e-7, 3.9e-8) it is 1.8e-4, 4.5e-5, 1.0e-5 (ratios 4.1, 4.4; accept > 3.5;
// at 1e-3 of the tolerance, Newton at 1e-9, 1.9e-4, 4.6e-5, 1.1e-5). The reference's own error is about 1e-6 (3D cable,
// n = 400: J2 at T/3200 and J3 at T/6400 differ by 1.1e-6 of the motion).
TEST(RiserIntegrators, ImplicitAbsoluteErrorHasNoNewtonFloorAtSmallSteps) {
  MARIS_RELEASE_ONLY("RiserIntegrators.ImplicitConvergesAtSecondOrderInBothFormulations");
  RiserParameters p = test::implicitCable(50, 0.0);
  p.torsion = false;
  p.tolerance = 1e-6;
  p.probes = {{0.5 * p.length}};
  const double period = p.motion_period;
  auto probeDifference = [](const Results& a, const Results& b) {
    double d = 0;
    for (const char* c : {"probe_dx", "probe_dy", "probe_dz"}) d = std::max(d, maxDifferenceAtCommonTimes(a, b, c));
    return d;
  };
  RiserParameters joint = p;
  joint.formulation = "joint";
  joint.time_step = period / 3200;
  const Results reference = run(joint);
  double motion = 0;
  for (const char* c : {"probe_dx", "probe_dy", "probe_dz"})
    for (double x : column(reference, c)) motion = std::max(motion, std::abs(x));
  std::vector<double> error;
  for (double k : {200.0, 400.0, 800.0}) {
    p.time_step = period / k;
    error.push_back(probeDifference(run(p), reference) / motion);
  }
  EXPECT_GT(error[0] / error[1], 3.5) << error[0] << " " << error[1];
  EXPECT_GT(error[1] / error[2], 3.5) << error[1] << " " << error[2];
  EXPECT_LT(error[2], 2e-5);
}

// Below the step's expected error a tighter tolerance must not tighten Newton: it only costs residuals (case 5 at
// 50 ms and the scenario's 1e-6 took 3284 residuals in A2 with Newton at 1e-9, against 1441 at 1e-6, with the same
// error). At T/50 the expected probe error is 25 (1/50)² = 1e-2 of the motion, so Newton runs at 1e-6 for both
// tolerances (1e-3 of 1e-2, capped), and the runs must be the same to the last bit. With Newton at 1e-3 of the
// tolerance alone (1e-9 and 1e-7) they differed.
TEST(RiserIntegrators, ToleranceBelowTheStepsExpectedErrorDoesNotTightenNewton) {
  RiserParameters p = test::implicitCable(20, 0.0);
  p.time_step = p.motion_period / 50;
  p.probes = {{0.5 * p.length}};
  p.tolerance = 1e-6;
  const Results tight = run(p);
  p.tolerance = 1e-4;
  const Results loose = run(p);
  EXPECT_EQ(tight.findScalar("rhs_evaluations")->value, loose.findScalar("rhs_evaluations")->value);
  EXPECT_EQ(maxDifferenceAtCommonTimes(tight, loose, "probe_dx"), 0.0);
  EXPECT_EQ(column(tight, "probe_dx").size(), column(loose, "probe_dx").size());
}

// Stiff torsion: a short-element pipe whose torsional frequency 2√(GJ/ι)/Δ needs explicit steps of
// ~50 µs. RK4 at the implicit's step (5 ms, ~100x its limit) must stop with a SolverError naming time,
// segment and quantity; the implicit integrator runs at that step and stays within 1 % of the motion of an
// RK4 reference at its stable step.
TEST(RiserIntegrators, ImplicitStepsFarBeyondTheExplicitLimit) {
  RiserParameters p = test::calmInAir();
  p.length = 10.0;
  p.segment_count = 20;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.08;
  p.initial_inclination_deg = 90.0;
  p.solve_statics = false;
  p.top_condition = "clamped";
  p.end_time = 0.5;
  p.stress_times.clear();
  p.integrator = "rk4";
  const Results reference = run(p);
  const double omega = highestFrequencyEstimate(buildRiserModel(p));
  EXPECT_GT(omega * 5e-3, 50.0) << "the case must be stiff for the test to mean anything";
  p.time_step = 5e-3;
  try {
    run(p);
    ADD_FAILURE() << "RK4 far beyond its stability limit must fail";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("segment"), std::string::npos) << e.what();
    EXPECT_GT(e.time(), 0.0);
  }
  p.integrator = "implicit";
  p.tolerance = 1e-8;
  const Results implicit = run(p);
  const auto& z = column(reference, "end_z");
  const double sag = -*std::min_element(z.begin(), z.end());
  EXPECT_GT(sag, 0.01);
  EXPECT_LT(maxDifferenceAtCommonTimes(reference, implicit, "end_z"), 1e-2 * sag);
}

// auto: RK4 for the default riser (explicit steps within the budget), implicit when they are not.
TEST(RiserIntegrators, AutoPicksRk4UnlessTheExplicitStepCountExplodes) {
  RiserParameters p;
  EXPECT_EQ(planIntegration(buildRiserModel(p), p).method, Integrator::Rk4);
  p.segment_count = 400;  // torsion: ω_max ∝ 1/Δ, bending ∝ 1/Δ²
  p.end_time = 600.0;
  const IntegrationPlan plan = planIntegration(buildRiserModel(p), p);
  EXPECT_EQ(plan.method, Integrator::Implicit) << plan.reason;
}

// Clamped cubic spline through x(t) = A(1 − cos ωt) sampled every h over one period (end slopes 0 as the
// spline assumes): errors within the Hall–Meyer bounds 5/384 h⁴, 1/24 h³, 3/8 h² times max|x''''| = Aω⁴.
// Before and after the table the first and last rows hold.
TEST(RiserTopMotion, TableSplineIsFourthOrderAccurate) {
  const double a = 2.0, period = 8.0, w = 2 * pi / period, h = period / 32;
  std::vector<TopMotionRow> rows;
  for (int k = 0; k <= 32; ++k) rows.push_back({k * h, a * (1 - std::cos(w * k * h)), 0.0, 0.0});
  const TopMotionSpline s = buildTopMotionSpline(rows, false);
  const double d4 = a * std::pow(w, 4);
  double e0 = 0, e1 = 0, e2 = 0;
  for (int k = 1; k < 1000; ++k) {  // inside the table: at its ends the acceleration jumps to the held rest
    const double t = period * k / 1000.0;
    const TopKinematics kin = s.at(t);
    e0 = std::max(e0, std::abs(kin.position.x() - a * (1 - std::cos(w * t))));
    e1 = std::max(e1, std::abs(kin.velocity.x() - a * w * std::sin(w * t)));
    e2 = std::max(e2, std::abs(kin.acceleration.x() - a * w * w * std::cos(w * t)));
  }
  EXPECT_LT(e0, 5.0 / 384 * std::pow(h, 4) * d4);
  EXPECT_LT(e1, 1.0 / 24 * std::pow(h, 3) * d4);
  EXPECT_LT(e2, 3.0 / 8 * h * h * d4);
  EXPECT_GT(e0, 0.0);
  EXPECT_EQ(s.at(-1.0).position.x(), 0.0);
  EXPECT_NEAR(s.at(period + 5).position.x(), rows.back().x, 1e-15);
  EXPECT_EQ(s.at(period + 5).velocity.norm(), 0.0);
}

// The same riser driven by the harmonic motion A(sin(ωt + φ) − sin φ) with φ = −π/2 (= A(1 − cos ωt)) and
// by tables of it every T/20 and T/40. The riser feels the top acceleration, whose spline error is
// O(h²) (≤ 3/8 h² Aω⁴): the probe difference must fall by about 4 when the table is halved (accept > 3)
// and stay below 5e-4 A at T/40 (measured 2.8e-4 A); the top position itself within 1e-5 A (h⁴ term).
TEST(RiserTopMotion, TableReproducesTheHarmonicRunAtSecondOrder) {
  RiserParameters p = movingRiser();
  p.integrator = "rk4";
  p.motion_ramp_time = 0.0;
  p.motion_phase_x_deg = p.motion_phase_y_deg = -90.0;
  p.motion_amplitude_y = 0.0;
  const Results harmonic = run(p);
  p.top_motion = "table";
  const double w = 2 * pi / p.motion_period, a = p.motion_amplitude_x;
  double probe[2];
  for (int k = 0; k < 2; ++k) {
    const int rows = k == 0 ? 20 : 40;
    p.top_motion_table.clear();
    for (int j = 0; j <= rows; ++j) {
      const double t = p.motion_period * j / rows;
      p.top_motion_table.push_back({t, a * (1 - std::cos(w * t)), 0.0, 0.0});
    }
    const Results table = run(p);
    probe[k] = maxDifferenceAtCommonTimes(harmonic, table, "probe_dx");
    if (k == 1) {
      EXPECT_LT(maxDifferenceAtCommonTimes(harmonic, table, "top_x"), 1e-5 * a);
    }
  }
  EXPECT_GT(probe[0] / probe[1], 3.0) << probe[0] << " " << probe[1];
  EXPECT_LT(probe[1], 5e-4 * a);
}

// A run that ends without a failed step but whose own measures say it is inaccurate must say so (the user sees
// only plots otherwise). Thresholds of accuracyWarnings: energy balance above 5 %, error estimate above 0.1.
TEST(RiserAccuracyWarnings, NameTheMeasureThatIsOff) {
  Results good;
  good.addScalar("energy_balance_error", 1e-13, "-", "");
  good.addScalar("integrator_error_estimate", 6e-4, "-", "");
  EXPECT_TRUE(accuracyWarnings(good).empty());
  // The DOPRI5 run at rtol 1e-3 on the 3D cable (A3, n = 100, 68 s): balance 0.999, estimate 171.
  Results bad;
  bad.addScalar("energy_balance_error", 0.999, "-", "");
  bad.addScalar("integrator_error_estimate", 171.0, "-", "");
  const std::vector<std::string> w = accuracyWarnings(bad);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("energy_balance_error"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("0.999"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("integrator_error_estimate"), std::string::npos) << w[1];
  EXPECT_NE(w[1].find("171"), std::string::npos) << w[1];
  Results broken;  // a NaN is not "within the bound"
  broken.addScalar("energy_balance_error", std::nan(""), "-", "");
  EXPECT_EQ(accuracyWarnings(broken).size(), 1u);
}

// End to end: generalized-α at T/5 on the 3D cable expects a probe error of C (h/T)² = 25/25 = 1 of the motion
// (docs/riser.md): the scene warns; at T/50 (0.01) it does not.
TEST(RiserAccuracyWarnings, CoarseImplicitStepIsReported) {
  auto warnings = [](double step) {
    RiserParameters p = test::implicitCable(10, step);
    p.end_time = 4.0;
    RunContext context;
    solveRiser(p, context);
    return context.warnings();
  };
  const std::vector<std::string> coarse = warnings(4.0 / 5);
  ASSERT_FALSE(coarse.empty());
  EXPECT_NE(coarse.back().find("integrator_error_estimate"), std::string::npos) << coarse.back();
  for (const std::string& w : warnings(4.0 / 50)) EXPECT_EQ(w.find("integrator_error_estimate"), std::string::npos) << w;
}

}  // namespace
}  // namespace maris::riser
