// Internal flow of constant speed (paper eqs 43-52): centrifugal u² κ and Coriolis 2u ṫ forces.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "riser/riser_loads.hpp"
#include "riser/riser_scene.hpp"
#include "riser/riser_statics.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

// A pipe with flow speed u and only the flow loads switched on (no gravity, drag, current).
RiserParameters flowingPipe(int n, double u) {
  RiserParameters p = test::calmInAir();
  p.length = 20.0;
  p.segment_count = n;
  p.outer_diameter = 0.3;
  p.inner_diameter = 0.25;
  p.gravity = 0.0;
  p.internal_fluid_density = 1000.0;
  p.internal_flow_speed = u;
  return p;
}

// Pose with segment tangents t_i and zero velocities; joints follow r_{i+1} = r_i + l_i t_i from the origin.
RiserPose poseFromTangents(const RiserModel& m, const std::vector<Vec3>& tangents) {
  RiserPose pose;
  pose.resize(m.n + 1);
  Vec3 r = Vec3::Zero();
  for (int i = 0; i <= m.n; ++i) {
    pose.rotation[i] = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), tangents[i]).toRotationMatrix();
    pose.position[i] = r;
    r += m.segments[i].length * tangents[i];
  }
  pose.end_position = r;
  return pose;
}

SegmentLoads flowLoads(const RiserModel& m, const RiserPose& pose) {
  SegmentLoads loads;
  loads.resize(m.n + 1);
  addInternalFlow(m, pose, loads);
  return loads;
}

// Straight and at rest: κ = 0 and ṫ = 0, so the flow exerts nothing (eq 46). Round-off only.
TEST(RiserInternalFlow, StraightPipeAtRestFeelsNoFlowForce) {
  const RiserModel m = buildRiserModel(flowingPipe(10, 8.0));
  const Vec3 t = Vec3(1, 2, -3).normalized();
  const RiserPose pose = poseFromTangents(m, std::vector<Vec3>(m.n + 1, t));
  const SegmentLoads loads = flowLoads(m, pose);
  const double scale = m.segments[1].fluid_mass_per_length * 64.0;  // m_f u² [N/m]
  for (int i = 0; i <= m.n; ++i) EXPECT_LT(loads.force[i].norm(), 1e-12 * scale) << "segment " << i;
}

// Chords of a circle of radius R: the quadratic fit (eqs 47-49) through three equal chords gives
// |k| = sin φ/Δ with φ = 2 asin(Δ/2R) (exact for this shape), so the force on an interior segment is
// m_f l u² sin φ/Δ pointing away from the centre (the centrifugal force ρ_f A u² κ per length);
// continuum value m_f l u²/R, from which it differs by (Δ/R)²/8.
TEST(RiserInternalFlow, CurvedPipeFeelsCentrifugalForceOutward) {
  const double u = 6.0, radius = 40.0;
  const RiserModel m = buildRiserModel(flowingPipe(16, u));
  const double delta = m.element_length;
  std::vector<Vec3> tangents;
  double angle = 0.0;
  for (int i = 0; i <= m.n; ++i) {
    const double phi_i = 2 * std::asin(m.segments[i].length / (2 * radius));
    const double mid = angle + phi_i / 2;
    tangents.emplace_back(std::cos(mid), 0.0, std::sin(mid));  // circle in the xz-plane, centre (0, 0, R)
    angle += phi_i;
  }
  const RiserPose pose = poseFromTangents(m, tangents);
  const SegmentLoads loads = flowLoads(m, pose);
  const Vec3 centre(0, 0, radius);
  const double phi = 2 * std::asin(delta / (2 * radius));
  for (int i = 2; i <= m.n - 2; ++i) {
    const Segment& s = m.segments[i];
    const Vec3 mid = pose.position[i] + 0.5 * s.length * pose.tangent(i);
    const Vec3 outward = (mid - centre).normalized();
    const double per_unit = s.fluid_mass_per_length * s.length * u * u;
    EXPECT_NEAR(loads.force[i].dot(outward), per_unit * std::sin(phi) / delta, 1e-10 * per_unit / radius) << i;
    EXPECT_NEAR(loads.force[i].dot(outward), per_unit / radius, 0.13 * std::pow(delta / radius, 2) * per_unit / radius);
    EXPECT_LT((loads.force[i] - loads.force[i].dot(outward) * outward).norm(), 1e-10 * per_unit / radius) << i;
  }
  // End segments use one-sided stencils (eq 49 at s_L, s_R): O(Δ²) as well, larger constant.
  for (int i : {0, 1, m.n - 1, m.n}) {
    const Segment& s = m.segments[i];
    const double expected = s.fluid_mass_per_length * s.length * u * u / radius;
    EXPECT_NEAR(loads.force[i].norm(), expected, 1.0 * std::pow(delta / radius, 2) * expected) << i;
  }
}

// A straight pipe turning rigidly with angular velocity Ω: ṫ = Ω × t, κ = 0, so each segment gets the
// Coriolis force −2 m_f l u Ω × t (eq 46) at its centre; its power is F · v_centre.
TEST(RiserInternalFlow, RotatingPipeFeelsCoriolisForce) {
  const double u = -3.0;  // upward flow
  const RiserModel m = buildRiserModel(flowingPipe(6, u));
  const Vec3 t = Vec3(0, 0, -1), omega(0.2, -0.1, 0.05);
  RiserPose pose = poseFromTangents(m, std::vector<Vec3>(m.n + 1, t));
  for (int i = 0; i <= m.n; ++i) {
    pose.omega[i] = omega;
    pose.velocity[i] = omega.cross(pose.position[i]);
  }
  const SegmentLoads loads = flowLoads(m, pose);
  double power = 0.0;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& s = m.segments[i];
    const Vec3 expected = -2 * s.fluid_mass_per_length * s.length * u * omega.cross(t);
    EXPECT_LT((loads.force[i] - expected).norm(), 1e-12 * expected.norm()) << i;
    const Vec3 arm = 0.5 * s.length * t;
    EXPECT_LT((loads.moment[i] - arm.cross(expected)).norm(), 1e-12 * expected.norm() * s.length) << i;
    power += expected.dot(omega.cross(pose.position[i] + arm));
  }
  EXPECT_NEAR(loads.power_flow, power, 1e-12 * std::abs(power) + 1e-12);
}

// Taut string (tensioner T, EI ≈ 0, no gravity) in a uniform current with internal flow: the u² term
// lowers the effective tension to T − ρ_f A_inn u² (Païdoussis), so the mid-span deflection grows by
// T/(T − ρ_f A_inn u²) over the same string without flow (≈ 1.23 here). Both runs share the
// discretisation and slope² errors (≈ 1e-3), so the ratio is compared at 3e-3.
TEST(RiserInternalFlow, FlowLowersTheEffectiveTensionOfATautString) {
  auto midSpanDeflection = [](double u) {
    RiserParameters p = test::calmInAir();
    p.length = 100.0;
    p.segment_count = 40;
    p.outer_diameter = 0.1;
    p.inner_diameter = 0.08;
    p.youngs_modulus = 1e3;
    p.torsion = false;
    p.gravity = 0.0;
    p.water_level = 10.0;
    p.normal_drag_coefficient = 1.0;
    p.current_speed_surface = p.current_speed_seabed = 1.0;
    p.internal_fluid_density = 1000.0;
    p.internal_flow_speed = u;
    p.top_condition = "tensioner";
    p.top_tension = 1e5;
    p.bottom_condition = "pinned";
    p.bottom_z = -100.0;
    const RiserModel m = buildRiserModel(p);
    RunContext context;
    const StaticSolution s = solveStatics(m, context);
    Vec3 r = s.top;
    for (int i = 0; i <= m.n / 2; ++i) r += m.segments[i].length * s.orientation[i].toRotationMatrix().col(0);
    return std::pair{r.x(), 1000.0 * pi / 4 * 0.08 * 0.08 * u * u};
  };
  const auto [still, zero] = midSpanDeflection(0.0);
  const auto [flowing, reduction] = midSpanDeflection(60.0);
  const double expected_ratio = 1e5 / (1e5 - reduction);
  EXPECT_GT(expected_ratio, 1.2);
  EXPECT_NEAR(flowing / still, expected_ratio, 3e-3 * expected_ratio) << still << " " << flowing << " " << zero;
}

// Moving top, current and flow: E(t) − E(0) = W_drag + W_damping + W_top + W_flow along the run (the flow
// power is evaluated at the segment centres, where eq 46 applies its force). Integration error of RK4
// only: 1e-7 of the energy scale.
TEST(RiserInternalFlow, EnergyBalanceIncludesTheWorkOfTheFlow) {
  RiserParameters p;
  p.segment_count = 10;
  p.internal_flow_speed = -5.0;
  p.end_time = 3.0;
  p.motion_period = 3.0;
  p.motion_ramp_time = 1.0;
  p.integrator = "rk4";
  p.stress_times.clear();
  RunContext context;
  const Results r = solveRiser(p, context);
  EXPECT_LT(r.findScalar("energy_balance_error")->value, 1e-7);
  const auto& flow = r.findTable("history")->find("work_flow")->values;
  EXPECT_GT(std::abs(flow.back()), 0.0) << "the flow must do work on the moving riser";
}

}  // namespace
}  // namespace maris::riser
