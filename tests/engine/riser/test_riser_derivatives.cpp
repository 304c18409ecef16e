// Identities of the equations of motion at one instant: momentum balance (velocity terms and reaction
// solve), constraint accelerations (Jacobian blocks of eq 53), kinetic energy (mass matrix), drag loads.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "riser/riser_dynamics.hpp"
#include "core/angles.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

// A free-free chain in zero gravity: no external loads at all, only the internal springs and reactions.
// Added mass C_a = 1 across the axes and `tangential` along them.
RiserModel freeChain(const std::string& formulation, double tangential = 1.0) {
  RiserParameters p = test::calmInAir();
  p.formulation = formulation;
  p.tangential_added_mass_coefficient = tangential;
  p.length = 6.0;
  p.segment_count = 5;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.06;
  p.youngs_modulus = 2e9;
  p.shear_modulus = 1e9;
  p.gravity = 0.0;
  p.top_condition = "free";
  p.bottom_condition = "free";
  return buildRiserModel(p);  // (validation would refuse a load-free chain: nothing to compute)
}

// A bent chain with arbitrary angular velocities and top velocity; absolute coordinates get the
// consistent segment velocities v_{i+1} = v_i + ω_i × d_i, so Φ = 0 and Φ̇ = 0.
Eigen::VectorXd movingBentState(const RiserModel& m) {
  std::vector<Eigen::Quaterniond> q;
  std::vector<Vec3> omega;
  for (int i = 0; i <= m.n; ++i) {
    q.emplace_back(Eigen::AngleAxisd(0.3 * i, Vec3(0.2, 1.0, 0.1 * i).normalized()));
    omega.emplace_back(0.4 - 0.1 * i, 0.3 * std::sin(i), -0.2 + 0.15 * i);
  }
  const Vec3 top(0.5, -0.2, 1.0), top_velocity(0.3, -0.7, 0.2);
  Eigen::VectorXd y = restState(m, q, top);
  y.segment<3>(3) = top_velocity;
  Vec3 v = top_velocity;
  for (int i = 0; i <= m.n; ++i) {
    const Eigen::Index o = segmentStateOffset(m, i);
    const Vec3 d = m.segments[i].length * q[i].toRotationMatrix().col(0);
    if (m.formulation == Formulation::Joint) {
      y.segment<3>(o + 4) = omega[i];
    } else {
      y.segment<3>(o + 7) = v;
      y.segment<3>(o + 10) = omega[i];
    }
    v += omega[i].cross(d);
  }
  return y;
}

class Identities : public ::testing::TestWithParam<std::string> {};

// Without external loads the linear momentum Σ m a_c and the angular momentum about the origin
// Σ (r_c × m a_c + I_c α + ω × I_c ω) do not change: checks the velocity terms m ω×(ω×c), ω×Iω and
// the block-tridiagonal reaction solve. Tolerance 1e-10 of the scale Σ m|a_c| (round-off). Isotropic added mass
// (C_at = C_a): with C_at ≠ C_a the conserved quantity is the impulse of Kirchhoff's equations, not Σ m v_c
// (AnisotropicAddedMassConservesEnergy checks those terms through the energy balance).
TEST_P(Identities, MomentumIsConservedWithoutExternalLoads) {
  const RiserModel m = freeChain(GetParam());
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  const Eigen::VectorXd y = movingBentState(m);
  Eigen::VectorXd dy(y.size());
  evaluateRhs(m, ws, 0.0, y, dy);
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double scale = 0.0;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& s = m.segments[i];
    const Mat3& r = ws.pose.rotation[i];
    const Vec3 c = 0.5 * s.length * r.col(0), w = ws.pose.omega[i];
    const Vec3 a = ws.acceleration[i].head<3>(), alpha = ws.acceleration[i].tail<3>();
    const Vec3 a_centre = a + alpha.cross(c) + w.cross(w.cross(c));
    // Inertia about the centre: I_A minus the parallel-axis term m(|c|² I − c cᵀ) (local frame).
    const Vec3 c_local(0.5 * s.length, 0, 0);
    const Mat3 inertia_local = s.mass_local.bottomRightCorner<3, 3>() -
                               s.mass * (c_local.squaredNorm() * Mat3::Identity() - c_local * c_local.transpose());
    const Mat3 inertia = r * inertia_local * r.transpose();
    force += s.mass * a_centre;
    torque += (ws.pose.position[i] + c).cross(s.mass * a_centre) + inertia * alpha + w.cross(inertia * w);
    scale += s.mass * a_centre.norm() * (1.0 + (ws.pose.position[i] + c).norm());
  }
  ASSERT_GT(scale, 1.0) << "the springs must accelerate the chain";
  EXPECT_LT(force.norm(), 1e-10 * scale);
  EXPECT_LT(torque.norm(), 1e-10 * scale);
}

// The accelerations keep the joints together: d/dt Φ̇ = 0 for Φ̇_j = v_{j-1} + ω_{j-1} × d_{j-1} − v_j
// (absolute coordinates: the Jacobian blocks D_{i,i}, D_{i,i+1} of eq 53 in the reaction system; joint
// coordinates: Φ̇ = 0 by construction, checked as well). Central difference along dy with step 1e-5:
// truncation ~1e-10·|ȧ|, round-off ~1e-11 |v|/step; tolerance 1e-6 of the acceleration scale.
TEST_P(Identities, AccelerationsKeepTheJointsTogether) {
  const RiserModel m = freeChain(GetParam());
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  const Eigen::VectorXd y = movingBentState(m);
  Eigen::VectorXd dy(y.size());
  evaluateRhs(m, ws, 0.0, y, dy);
  double scale = 0;
  for (int i = 0; i <= m.n; ++i) scale = std::max(scale, ws.acceleration[i].norm());
  auto constraintRates = [&](const Eigen::VectorXd& state) {
    RiserPose pose;
    pose.resize(m.n + 1);
    poseFromState(m, 0.0, state, pose);
    std::vector<Vec3> rates;
    for (int j = 1; j <= m.n; ++j) {
      const Vec3 d = m.segments[j - 1].length * pose.tangent(j - 1);
      rates.push_back(pose.velocity[j - 1] + pose.omega[j - 1].cross(d) - pose.velocity[j]);
    }
    return rates;
  };
  const double h = 1e-5;
  const auto plus = constraintRates(y + h * dy), minus = constraintRates(y - h * dy), now = constraintRates(y);
  for (int j = 0; j < m.n; ++j) {
    EXPECT_LT(now[j].norm(), 1e-12 * (1 + scale)) << "joint " << j + 1;
    EXPECT_LT(((plus[j] - minus[j]) / (2 * h)).norm(), 1e-6 * scale) << "joint " << j + 1;
  }
}

// Kinetic energy ½ vᵀ M v of the Newton–Euler blocks equals the integral along each segment of
// ½ (μ_t u_t² + μ |u − u_t t|²), u = v + ω × ξt, u_t = u·t (tangential added mass C_at = 0.4, normal C_a = 1),
// plus the cross-section's ½ ι (ω_x'² + (ω_y'² + ω_z'²)/2) per length (thin pipe),
// by a 2000-point midpoint rule (error ≈ 1e-7 relative for this quadratic integrand; tolerance 1e-6).
TEST_P(Identities, KineticEnergyMatchesTheIntegralAlongTheSegments) {
  const RiserModel m = freeChain(GetParam(), 0.4);
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  const Eigen::VectorXd y = movingBentState(m);
  poseFromState(m, 0.0, y, ws.pose);
  double integral = 0.0;
  const int points = 2000;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& s = m.segments[i];
    const Vec3 t = ws.pose.tangent(i), w = ws.pose.omega[i];
    const double mu = s.mass / s.length, mu_t = s.axial_mass / s.length, iota = s.mass_local(3, 3) / s.length;
    ASSERT_LT(mu_t, mu);
    for (int k = 0; k < points; ++k) {
      const double xi = (k + 0.5) * s.length / points;
      const Vec3 u = ws.pose.velocity[i] + w.cross(xi * t);
      const double along = u.dot(t);
      integral += 0.5 * (mu_t * along * along + mu * (u - along * t).squaredNorm()) * s.length / points;
    }
    const Vec3 wl = ws.pose.rotation[i].transpose() * w;
    integral += 0.5 * iota * s.length * (wl.x() * wl.x() + 0.5 * (wl.y() * wl.y() + wl.z() * wl.z()));
  }
  const double energy = kineticEnergy(m, ws.pose);
  ASSERT_GT(energy, 0.0);
  EXPECT_NEAR(energy, integral, 1e-6 * energy);
}

INSTANTIATE_TEST_SUITE_P(Formulations, Identities, ::testing::Values("joint", "absolute"));

// Morison drag (eq 34) reduced to a segment's origin: force and moment equal the integrals of the force
// density along the segment (3-point Gauss vs a 4000-point midpoint rule; the relative normal velocity
// does not vanish on the segment, so the integrand is smooth: tolerance 1e-6 relative), and the drag
// power Σ f·v at the Gauss points equals F·v_A + M·ω exactly (rigid body; round-off 1e-12).
TEST(RiserLoads, DragEqualsTheIntegralOfTheMorisonForceDensity) {
  RiserParameters p = test::calmInAir();
  p.water_level = 100.0;
  p.normal_drag_coefficient = 1.1;
  p.tangential_drag_coefficient = 0.2;
  p.current_speed_surface = p.current_speed_seabed = 1.5;
  p.current_direction_deg = degreesFromRadians(0.4);
  p.segment_count = 20;  // 5 m segments: the Gauss error (∝ l⁶) is ~1e-5 at 25 m, far below at 5 m
  const RiserModel m = buildRiserModel(p);
  RiserPose pose;
  pose.resize(m.n + 1);
  const int i = 2;
  pose.rotation[i] = Mat3(Eigen::AngleAxisd(1.0, Vec3(0.3, 1.0, -0.2).normalized()));
  pose.position[i] = Vec3(1.0, 2.0, -30.0);
  pose.velocity[i] = Vec3(-0.4, 0.3, 0.2);
  pose.omega[i] = Vec3(0.02, -0.03, 0.01);
  SegmentLoads loads;
  loads.resize(m.n + 1);
  addDrag(m, pose, 1.0, loads);
  const Segment& s = m.segments[i];
  const Mat3& r = pose.rotation[i];
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  const int points = 4000;
  for (int k = 0; k < points; ++k) {
    const double xi = (k + 0.5) * s.length / points;
    const Vec3 arm = xi * r.col(0);
    const Vec3 local = r.transpose() * (pose.velocity[i] + pose.omega[i].cross(arm) - m.currentAt(pose.position[i].z() + arm.z()));
    const double vn = std::hypot(local.y(), local.z());
    ASSERT_GT(vn, 0.1);
    const Vec3 density = r * Vec3(-s.tangential_drag * std::abs(local.x()) * local.x(), -s.normal_drag * vn * local.y(),
                                  -s.normal_drag * vn * local.z());
    force += density * s.length / points;
    moment += arm.cross(density) * s.length / points;
  }
  EXPECT_LT((loads.force[i] - force).norm(), 1e-6 * force.norm());
  EXPECT_LT((loads.moment[i] - moment).norm(), 1e-6 * moment.norm());
  const double power = loads.force[i].dot(pose.velocity[i]) + loads.moment[i].dot(pose.omega[i]);
  EXPECT_NEAR(loads.power_drag, power, 1e-12 * loads.force[i].norm() * pose.velocity[i].norm());
}

}  // namespace
}  // namespace maris::riser
