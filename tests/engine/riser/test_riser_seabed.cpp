// Sea-bed contact and buoyancy modules against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/scene.hpp"
#include "riser/riser_buoyancy.hpp"
#include "riser/riser_results.hpp"
#include "riser/riser_scene.hpp"
#include "riser/riser_statics.hpp"
#include "riser_test_cases.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

// A chain (EI ≈ 0, w = 100 N/m in air, D = 0.1 m) pinned at the origin and at an anchor on a flat bed 50 m below
// the top, 120 m away horizontally; 150 m long, so part of it rests on the bed.
RiserParameters chainOnTheBed(int n, double stiffness) {
  RiserParameters p = test::calmInAir();
  p.length = 150.0;
  p.segment_count = n;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.0;
  p.youngs_modulus = 1.0;  // EI ≈ 5e-6 N·m²: a chain
  p.torsion = false;
  p.density = 100.0 / (9.81 * pi / 4 * 0.01);
  p.seabed_level = -50.0;
  p.seabed_contact = true;
  p.seabed_normal_stiffness = stiffness;
  p.bottom_condition = "pinned";
  p.bottom_x = 120.0;
  p.bottom_z = -50.0 + 0.05;  // the axis of the pipe resting on the bed
  return p;
}

// The cable catenary with a grounded length on a rigid frictionless bed. With a = H/w, the suspended length s and
// its horizontal projection x_s follow from the catenary z(x) = a(cosh(x/a) − 1) through the touchdown point, where
// it is tangent to the bed: s = a sinh(x_s/a), z = a(cosh(x_s/a) − 1), so s² = (z + a)² − a² = z(z + 2a) and
// x_s = a asinh(s/a). The rest, L − s, lies straight on the bed to the anchor: X = L − s + a asinh(s/a) fixes a
// (monotone in a; bisection). Top tension T = w(a + z) = H + w z; touchdown at arc length s from the top.
struct GroundedCatenary {
  double a, suspended, horizontal, top_tension;
};
GroundedCatenary groundedCatenary(double length, double span, double height, double w) {
  auto s = [&](double a) { return std::sqrt(height * (height + 2 * a)); };
  double lo = 1e-6, hi = 0.5 * (length * length / height - height);
  for (int it = 0; it < 200; ++it) {
    const double a = 0.5 * (lo + hi);
    (length - s(a) + a * std::asinh(s(a) / a) < span ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  return {a, s(a), w * a, w * (a + height)};
}

struct Static {
  RiserModel model;
  StaticSolution solution;
  RiserProfile profile;
  SeabedContactState contact;
};
Static solveStatic(const RiserParameters& p) {
  Static s{buildRiserModel(p), {}, {}, {}};
  RunContext context;
  s.solution = solveStatics(s.model, context);
  const Eigen::VectorXd y = restState(s.model, s.solution.orientation, s.solution.top);
  RiserWorkspace ws = makeWorkspace(s.model, 0.0);
  s.profile = evaluateProfile(s.model, ws, 0.0, y);
  s.contact = seabedContact(s.model, ws.pose);
  return s;
}

// Static touchdown and top tension of the chain on a stiff bed (k = 1e7 N/m², penetration w/k = 1e-5 m) against the
// closed form above with the height measured to the resting axis. n = 100 (Δ = 1.5 m): the chain of straight links
// is O(1/n²) off in tension (1.1e-5 for the free catenary at n = 100); the touchdown point is ill-conditioned (the
// chain meets the bed tangentially, so a vertical error ε moves it by √(2aε)): asserted within one link, Δ.
// Measured: T 6686.14 N against 6685.25 (1.3e-4), touchdown 65.25 m against 64.68; at n = 200 and 400: T 1.2e-5 and
// 1.3e-5, touchdown 64.87 and 64.69 m.
TEST(RiserSeabed, CatenaryOnARigidBedMatchesTheGroundedClosedForm) {
  const RiserParameters p = chainOnTheBed(100, 1e7);
  const Static s = solveStatic(p);
  const double height = 0.0 - (p.bottom_z - 100.0 / p.seabed_normal_stiffness);
  const GroundedCatenary c = groundedCatenary(p.length, p.bottom_x, height, 100.0);
  EXPECT_NEAR(s.profile.tension.front(), c.top_tension, 2e-4 * c.top_tension);
  EXPECT_NEAR(s.contact.touchdown, c.suspended, p.length / p.segment_count);
  // The grounded part carries H along the bed to the anchor (frictionless in statics).
  EXPECT_NEAR(s.profile.tension.back(), c.horizontal, 2e-4 * c.top_tension);
  // The bed carries the weight of the grounded length: w (L − s).
  EXPECT_NEAR(s.contact.normal_force, 100.0 * (p.length - c.suspended), 100.0 * p.length / p.segment_count);
}

// Stiffer bed → closed form: the top-tension error falls with k until the discretisation floor (n = 100). Measured
// against the rigid bed's closed form: 1.9e-3, 3.8e-4, 1.9e-4 at k = 1e3, 1e4, 1e5 N/m² (floor 1.3e-4 at 1e7).
TEST(RiserSeabed, StifferBedApproachesTheRigidClosedForm) {
  double previous = 1e300;
  for (double k : {1e3, 1e4, 1e5}) {
    const RiserParameters p = chainOnTheBed(100, k);
    const Static s = solveStatic(p);
    const GroundedCatenary c = groundedCatenary(p.length, p.bottom_x, -p.bottom_z, 100.0);  // rigid bed
    const double error = std::abs(s.profile.tension.front() - c.top_tension) / c.top_tension;
    EXPECT_LT(error, previous) << "k = " << k;
    previous = error;
  }
  EXPECT_LT(previous, 2e-4);
}

// A free 10 m steel rod (D 0.05 m) on a bed at z = −10 m (k = 1e6 N/m², c = 2e3 N·s/m², μ_a = 0.5, μ_l = 0.8,
// tanh over 1 cm/s), run for 2 s by RK4 from rest without statics; the caller places it on the bed.
RiserParameters rodOnTheBed() {
  RiserParameters p = test::chainInAir(10);
  p.youngs_modulus = 2.07e11;
  p.top_condition = "free";
  p.bottom_condition = "free";
  p.seabed_contact = true;
  p.seabed_level = -10.0;
  p.seabed_normal_stiffness = 1e6;
  p.seabed_normal_damping = 2e3;
  p.seabed_axial_friction = 0.5;
  p.seabed_lateral_friction = 0.8;
  p.solve_statics = false;
  p.modes = false;
  p.end_time = 2.0;
  p.integrator = "rk4";
  p.frame_count = 4;
  p.probes = {{5.0}};
  return p;
}

// A 10 m rod lying on a flat bed, pulled along its axis by F at its end (dynamics, smoothed Coulomb, tanh,
// v_s = 1 cm/s). Below μ w L it creeps at the speed where the friction balances F, v = v_s atanh(F/(μ w L));
// above, it slides with a = (F − μ w L)/m. 2 s of motion; tolerances cover the start-up (v_s/a ≈ 4 ms). Measured:
// creep 10.973 mm against 10.986 mm, slide 4.919 m against 4.905 m.
TEST(RiserSeabed, RodOnTheBedSlidesWhenThePullExceedsTheFriction) {
  auto pulled = [](double ratio) {
    RiserParameters p = rodOnTheBed();
    p.initial_inclination_deg = 90.0;  // lying along +x
    const double w = p.density * pi / 4 * 0.05 * 0.05 * p.gravity;
    p.top_z = -10.0 + 0.025 - w / p.seabed_normal_stiffness;  // resting
    PointLoadRow pull;
    pull.node = 0;
    pull.force_x = -ratio * 0.5 * w * p.length;
    p.point_loads = {pull};
    RunContext context;
    const Results r = solveRiser(p, context);
    return r.findScalar("probe_max_displacement")->value;
  };
  // Creep: 0.5 of the friction.
  const double creep = pulled(0.5);
  EXPECT_NEAR(creep, 0.01 * std::atanh(0.5) * 2.0, 0.05 * 0.01 * std::atanh(0.5) * 2.0);
  // Slide: 1.5 of it, a = 0.5 μ g.
  const double slide = pulled(1.5);
  EXPECT_NEAR(slide, 0.5 * (0.5 * 0.5 * 9.81) * 4.0, 0.02 * 0.5 * (0.5 * 0.5 * 9.81) * 4.0);
}

// A rod lying down a bed sloped at 10° (rising towards +x), μ_a = 0.5 > tan 10°: the smoothed Coulomb law holds it
// only by creeping at the speed where μ w cos α tanh(v/v_s) = w sin α, v = v_s atanh(tan α/μ) = 3.685 mm/s
// (v_s = 1 cm/s); 2 s after starting at rest it has moved 7.37 mm down the slope (5 %: the start-up).
TEST(RiserSeabed, RodOnASlopedBedCreepsAtTheSpeedWhereFrictionHoldsItsWeight) {
  RiserParameters p = rodOnTheBed();
  p.seabed_slope_deg = 10.0;
  p.seabed_slope_direction_deg = 0.0;
  const double alpha = 10.0 * pi / 180, w = p.density * pi / 4 * 0.05 * 0.05 * p.gravity;
  p.initial_inclination_deg = 80.0;  // down the slope, towards −x
  p.initial_azimuth_deg = 180.0;
  const RiserModel bare = buildRiserModel(p);
  const double height = bare.seabed->heightAt(10.0, 0.0);
  EXPECT_NEAR(height, -10.0 + 10.0 * std::tan(alpha), 1e-12);
  const Vec3 top = Vec3(10.0, 0.0, height) + (0.025 - w * std::cos(alpha) / p.seabed_normal_stiffness) * bare.seabed->normal;
  p.top_x = top.x();
  p.top_z = top.z();
  RunContext context;
  const Results r = solveRiser(p, context);
  const double expected = 0.01 * std::atanh(std::tan(alpha) / 0.5) * 2.0;
  EXPECT_NEAR(r.findScalar("probe_max_displacement")->value, expected, 0.05 * expected);
}

// Hard case: slack touchdown and lift-off. The grounded chain above in water (submerged 21 N/m, drag 1.2), top
// heaving ±5 m at 8 s: the top falls faster than the chain sinks, so the chain goes slack, lands on the bed and is
// lifted off again. Automatic RK4 step (1693 steps): the run completes, the touchdown travels (57.7 … 106.3 m;
// 57.7 … 106.25 at h = 10 ms, 106.27 at 5 ms), part of the chain stays on the bed, and the energy balance (contact
// spring in the energy, its damper and the friction in the damping work) closes: 5.4e-5 (6.6e-5 at h = 10 ms,
// 3.4e-6 at 5 ms).
TEST(RiserSeabed, HeavingTopLiftsOffAndLandsTheTouchdownStably) {
  RiserParameters p = chainOnTheBed(40, 1e5);
  p.seabed_normal_damping = 1e3;
  p.seabed_axial_friction = 0.3;
  p.seabed_lateral_friction = 0.3;
  p.seabed_friction_velocity = 0.05;
  p.motion_amplitude_z = 5.0;
  p.motion_period = 8.0;
  p.motion_ramp_time = 4.0;
  p.end_time = 16.0;
  p.integrator = "rk4";
  p.water_level = 0.0;  // in water, with drag: it falls at ≈ 0.6 m/s, the top at up to 3.9 m/s (slack)
  p.normal_drag_coefficient = 1.2;
  p.modes = false;
  p.frame_count = 4;
  p.probes = {{100.0}};
  RunContext context;
  const Results r = solveRiser(p, context);
  const double lowest = r.findScalar("touchdown_arc_length_min")->value;
  const double highest = r.findScalar("touchdown_arc_length_max")->value;
  EXPECT_GT(highest - lowest, 30.0) << "the touchdown point should travel with the heave";
  EXPECT_LT(highest, p.length) << "the chain never leaves the bed entirely";
  EXPECT_LT(r.findScalar("energy_balance_error")->value, 5e-4);
  ASSERT_NE(r.findTable("history"), nullptr);
  EXPECT_NE(r.findTable("history")->find("touchdown_arc_length"), nullptr);
}

// Bad seabed and buoyancy sections name the field.
TEST(RiserSeabed, BadSectionsNameTheField) {
  const SceneDefinition scene = makeRiserScene();
  auto errorsOf = [&](const RiserParameters& p, const std::function<void(Json&)>& change) {
    Json j = riserBinder().write(p);
    change(j);
    return describeErrors(validateParameters(scene, j));
  };
  RiserParameters p = chainOnTheBed(20, 1e5);
  EXPECT_NE(errorsOf(p, [](Json& j) { j["seabed"]["normal_stiffness"] = -1.0; }).find("seabed.normal_stiffness"),
            std::string::npos);
  EXPECT_NE(errorsOf(p, [](Json& j) { j["seabed"]["friction_velocity"] = 0.0; }).find("seabed.friction_velocity"),
            std::string::npos);
  EXPECT_NE(errorsOf(p, [](Json& j) { j["seabed"]["slope_deg"] = 80.0; }).find("seabed.slope_deg"), std::string::npos);
  const std::string buried = errorsOf(p, [](Json& j) { j["bottom"]["z"] = -60.0; });
  EXPECT_NE(buried.find("bottom.z"), std::string::npos) << buried;
  EXPECT_NE(buried.find("below the sea bed"), std::string::npos) << buried;
  p.buoyancy_modules = {{10.0, 30.0, 0.5, 20.0, 1.0, 1.0}, {25.0, 40.0, 0.5, 20.0, 1.0, 1.0}};
  const std::string overlap = errorsOf(p, [](Json&) {});
  EXPECT_NE(overlap.find("buoyancy_modules[1].start"), std::string::npos) << overlap;
  p.buoyancy_modules = {{10.0, 200.0, 0.5, 20.0, 1.0, 1.0}};
  EXPECT_NE(errorsOf(p, [](Json&) {}).find("buoyancy_modules[0].end"), std::string::npos);
  p.buoyancy_modules = {{10.0, 20.0, 0.05, 20.0, 1.0, 1.0}};
  EXPECT_NE(errorsOf(p, [](Json&) {}).find("buoyancy_modules[0].outer_diameter"), std::string::npos);
  p.buoyancy_modules = {{10.0, 20.0, 0.5, -3.0, 1.0, 1.0}};
  EXPECT_NE(errorsOf(p, [](Json&) {}).find("buoyancy_modules[0].mass_per_length"), std::string::npos);
}

// Buoyancy modules whose ends fall between joints: the model's total buoyancy and weight are the bare pipe's plus
// the modules' exactly (length-weighted shares), and a vertical riser hanging in water from its top carries the
// net weight of all of it (statics, 1e-9).
TEST(RiserSeabed, BuoyancyModulesAddTheirBuoyancyAndMassWhereverTheyEnd) {
  RiserParameters p = test::calmInAir();
  p.water_level = 0.0;
  p.seabed_level = -200.0;
  p.length = 100.0;
  p.segment_count = 17;  // joints at (k − ½)·5.88 m: no module end on a joint
  p.buoyancy_modules = {{12.3, 41.7, 0.8, 150.0, 1.2, 1.0}, {60.0, 71.1, 0.7, 80.0, 1.0, 1.0}};
  const RiserModel m = buildRiserModel(p);
  const double g = p.gravity, a_out = pi / 4 * 0.25, a_inn = pi / 4 * 0.45 * 0.45;
  const double bare_weight = (p.density * (a_out - a_inn) + p.internal_fluid_density * a_inn) * g * p.length;
  double weight = 0, buoyancy = 0;
  for (const Segment& s : m.segments) {
    weight += s.weight_per_length * s.length;
    buoyancy += s.buoyancy_per_length * s.length;
  }
  const double module_mass = 150.0 * 29.4 + 80.0 * 11.1;
  const double module_area_length = pi / 4 * (0.64 * 29.4 + 0.49 * 11.1), bare_area_length = a_out * (100 - 40.5);
  EXPECT_NEAR(weight, bare_weight + module_mass * g, 1e-9 * weight);
  EXPECT_NEAR(buoyancy, p.water_density * g * (bare_area_length + module_area_length), 1e-9 * buoyancy);
  p.top_z = 0.0;
  const Static s = solveStatic(p);
  EXPECT_NEAR(s.profile.tension.front(), weight - buoyancy, 1e-9 * weight);
}

}  // namespace
}  // namespace maris::riser
