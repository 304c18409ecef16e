// Static equilibria of the segment chain against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "riser/riser_results.hpp"
#include "riser/riser_statics.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

struct StaticShape {
  RiserModel model;
  StaticSolution solution;
  RiserPose pose;
  RiserProfile profile;
};

StaticShape solveShape(const RiserParameters& p) {
  StaticShape s{buildRiserModel(p), {}, {}, {}};
  RunContext context;
  s.solution = solveStatics(s.model, context);
  const Eigen::VectorXd y = restState(s.model, s.solution.orientation, s.solution.top);
  RiserWorkspace ws = makeWorkspace(s.model, 0.0);
  s.profile = evaluateProfile(s.model, ws, 0.0, y);
  s.pose = ws.pose;
  return s;
}

// Point at arc length s of a static shape.
Vec3 pointAt(const StaticShape& s, double arc) {
  const auto [i, xi] = s.model.locate(arc);
  return s.pose.position[i] + xi * s.pose.tangent(i);
}

// Small tip load: the SM cantilever deflects exactly PL³/(3EI)·(1 - 1/(4n²)) (linear theory; closed form of the rigid-segment chain with C = EI/Δ).
// Tolerance 1e-6 relative: geometric nonlinearity at PL²/EI = 1e-4 is O((δ/L)²) ≈ 1e-9, Newton's residual 1e-11.
class CantileverTipLoad : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(CantileverTipLoad, MatchesDiscreteEulerBernoulli) {
  const auto [n, torsion] = GetParam();
  const double length = 10.0;
  RiserParameters p = test::tipLoadedCantilever(n, 1.0, length);
  p.torsion = torsion;
  const double ei = test::bendingStiffness(p);
  p.point_loads[0].force_z = -1e-4 * ei / (length * length);
  const double load = -p.point_loads[0].force_z;
  const StaticShape s = solveShape(p);
  const double expected = load * std::pow(length, 3) / (3 * ei) * (1 - 1.0 / (4.0 * n * n));
  EXPECT_NEAR(-s.pose.end_position.z(), expected, 1e-6 * expected);
}

INSTANTIATE_TEST_SUITE_P(SegmentCounts, CantileverTipLoad,
                         ::testing::Values(std::make_tuple(2, true), std::make_tuple(5, true),
                                           std::make_tuple(20, false), std::make_tuple(40, true)));

// Large deflection under a dead vertical tip load (elastica). Reference: tip deflection / L and
// horizontal shortening / L at PL²/EI = 1, 2, 5 (K. E. Bisshopp, D. C. Drucker, "Large deflection of cantilever beams", Quarterly of Applied
// Mathematics 3, 1945; values computed independently and consistent with their tables).
// Tolerance 2e-3 relative at n = 40 (discretisation O(1/n²)); halving n must raise the error ~4x.
struct ElasticaRow {
  double load_parameter, deflection, shortening;
};
class Elastica : public ::testing::TestWithParam<ElasticaRow> {};

TEST_P(Elastica, MatchesBisshoppDruckerAndConvergesQuadratically) {
  const ElasticaRow row = GetParam();
  double errors[2];
  int k = 0;
  for (int n : {20, 40}) {
    RiserParameters p = test::tipLoadedCantilever(n, 1.0, 10.0);
    p.point_loads[0].force_z = -row.load_parameter * test::bendingStiffness(p) / 100.0;
    const StaticShape s = solveShape(p);
    const double deflection = -s.pose.end_position.z() / 10.0, shortening = 1.0 - s.pose.end_position.x() / 10.0;
    EXPECT_NEAR(shortening, row.shortening, 5e-3 * row.shortening + 2e-3 * row.deflection) << "n = " << n;
    errors[k++] = std::abs(deflection - row.deflection);
    if (n == 40) {
      EXPECT_NEAR(deflection, row.deflection, 2e-3 * row.deflection);
    }
  }
  EXPECT_GT(errors[0] / errors[1], 3.0) << "expected O(1/n²): errors " << errors[0] << ", " << errors[1];
}

INSTANTIATE_TEST_SUITE_P(LoadParameters, Elastica,
                         ::testing::Values(ElasticaRow{1.0, 0.30172, 0.05643}, ElasticaRow{2.0, 0.49346, 0.16064},
                                           ElasticaRow{5.0, 0.71379, 0.38763}));

// Uniformly loaded cantilever (own weight): tip deflection qL⁴/(8EI); the error must fall as 1/n².
TEST(RiserStatics, CantileverUnderOwnWeightConvergesAtSecondOrder) {
  double previous_error = 0.0;
  for (int n : {10, 20, 40}) {
    RiserParameters p = test::tipLoadedCantilever(n, 0.0);
    p.point_loads.clear();
    p.gravity = 9.81;
    p.density = 10.0;  // light: q L⁴/(8 EI) ≈ 1e-4 L keeps the response linear
    p.internal_fluid_density = 0.0;
    const StaticShape s = solveShape(p);
    const double q = p.density * pi / 4 * (0.1 * 0.1 - 0.08 * 0.08) * p.gravity;
    const double expected = q * std::pow(10.0, 4) / (8 * test::bendingStiffness(p));
    const double error = std::abs(-s.pose.end_position.z() - expected) / expected;
    EXPECT_LT(error, 2.0 / (n * n)) << "n = " << n;
    if (previous_error > 0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.4) << "n = " << n;
    }
    previous_error = error;
  }
}

// Inextensible catenary, supports 80 m apart at equal height, S = 100 m, w = 100 N/m:
// a = 33.8202 m, sag 26.5438 m, H = 3382.02 N, support tension 6036.39 N (from the closed form).
// Tolerance 1e-3 relative at n = 50 (chain of straight links: O(1/n²)).
TEST(RiserStatics, HangingChainMatchesCatenary) {
  RiserParameters p = test::calmInAir();
  p.length = 100.0;
  p.segment_count = 50;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.0;
  p.youngs_modulus = 1.0;  // EI ≈ 5e-6 N·m²: a chain
  p.torsion = false;
  p.density = 100.0 / (9.81 * pi / 4 * 0.01);
  p.bottom_condition = "pinned";
  p.bottom_x = 80.0;
  p.bottom_z = 0.0;
  const StaticShape s = solveShape(p);
  EXPECT_NEAR(-pointAt(s, 50.0).z(), 26.5438, 1e-3 * 26.5438);
  EXPECT_NEAR(s.profile.tension.front(), 6036.39, 1e-3 * 6036.39);
  EXPECT_NEAR(s.profile.tension.back(), 6036.39, 1e-3 * 6036.39);
  // Vertical balance: the two supports carry the whole weight w S (to Newton's tolerance).
  EXPECT_NEAR(-s.solution.end_reaction.z(), 100.0 * 100.0 / 2, 1e-6 * 5000);
}

// Static twist of a hanging rod under an end torque: φ = T L/(G J) exactly (n springs GJ/Δ in series).
TEST(RiserStatics, EndTorqueTwistsByTLOverGJ) {
  RiserParameters p = test::calmInAir();
  p.length = 12.0;
  p.segment_count = 6;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.08;
  p.gravity = 0.0;
  p.top_condition = "clamped";
  const double gj = p.shear_modulus * pi / 32 * (std::pow(0.1, 4) - std::pow(0.08, 4));
  const double torque = 0.3 * gj / p.length;  // 0.3 rad of twist
  PointLoadRow l;
  l.node = p.segment_count + 1;
  l.moment_z = torque;
  p.point_loads = {l};
  const StaticShape s = solveShape(p);
  const Mat3 relative = s.pose.rotation[0].transpose() * s.pose.rotation[p.segment_count];
  // The tangent points down (-z), so a torque about +z twists by -TL/GJ about the tangent.
  EXPECT_NEAR(zyxAngles(relative).x(), -torque * p.length / gj, 1e-9);
  EXPECT_NEAR(s.pose.end_position.z(), -p.length, 1e-9);
}

// Taut string (tensioner T, EI ≈ 0, no gravity) in a uniform current: mid-span deflection qL²/(8T)
// with q = ½ ρ D C_dn v² (small-deflection string). Tolerance 0.5 %: slope² ≈ 7e-4 nonlinear terms + O(1/n²).
TEST(RiserStatics, TautStringInCurrentSagsAsParabola) {
  RiserParameters p = test::calmInAir();
  p.length = 100.0;
  p.segment_count = 40;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.08;
  p.youngs_modulus = 1e3;
  p.torsion = false;
  p.gravity = 0.0;
  p.water_level = 10.0;
  p.seabed_level = -100.0;
  p.normal_drag_coefficient = 1.0;
  p.current_speed_surface = p.current_speed_seabed = 1.0;
  p.top_condition = "tensioner";
  p.top_tension = 1e5;
  p.bottom_condition = "pinned";
  p.bottom_z = -100.0;
  const StaticShape s = solveShape(p);
  const double q = 0.5 * p.water_density * 0.1 * 1.0;
  const double expected = q * 100.0 * 100.0 / (8 * p.top_tension);
  EXPECT_NEAR(pointAt(s, 50.0).x(), expected, 5e-3 * expected);
}

}  // namespace
}  // namespace maris::riser

namespace maris::riser {
namespace {

// Reactions and stresses of a horizontal cantilever under a small tip load P: the bending moment at joint
// k (s_k = (k − ½)Δ) is P (L − s_k) by statics of the part below, so σ_b = P (L − s_k)/w_B with
// w_B = π(D_out⁴ − D_inn⁴)/(32 D_out); it bends in the vertical plane, so σ_b = |σ_xz| or |σ_xy| and the
// other is zero. Tolerance 1e-6 relative: M̄ is the moment conjugate to relative Euler angles, equal to
// the physical moment up to O(angle²) = 1e-8 at PL²/EI = 1e-4.
TEST(RiserStatics, CantileverStressesFollowTheBendingMomentOfTheTipLoad) {
  const int n = 10;
  RiserParameters p = test::tipLoadedCantilever(n, 0.0);
  const double ei = test::bendingStiffness(p), tip = 1e-4 * ei / (p.length * p.length);
  p = test::tipLoadedCantilever(n, tip);
  const StaticShape s = solveShape(p);
  const double wb = pi * (std::pow(0.1, 4) - std::pow(0.08, 4)) / (32 * 0.1);
  for (int k = 1; k <= n; ++k) {
    const double expected = tip * (p.length - s.profile.arc_length[k]) / wb;
    EXPECT_NEAR(s.profile.bending_stress[k], expected, 1e-6 * expected) << "joint " << k;
    const double in_plane = std::max(std::abs(s.profile.stress_xy[k]), std::abs(s.profile.stress_xz[k]));
    const double out_of_plane = std::min(std::abs(s.profile.stress_xy[k]), std::abs(s.profile.stress_xz[k]));
    EXPECT_NEAR(in_plane, expected, 1e-6 * expected);
    EXPECT_LT(out_of_plane, 1e-9 * expected);
  }
}

// A chain hanging straight down from a pin (free bottom, in air): the tension at joint k carries the weight
// of everything below, w (L − s_k), and the top reaction is the whole weight wL upward (joint reactions of
// eq 53 from the block-tridiagonal solve at rest). Round-off tolerance 1e-9 relative.
TEST(RiserStatics, HangingChainTensionIsTheWeightBelow) {
  RiserParameters p = test::calmInAir();
  p.length = 50.0;
  p.segment_count = 12;
  p.outer_diameter = 0.05;
  p.inner_diameter = 0.0;
  p.torsion = false;
  const StaticShape s = solveShape(p);
  const double w = s.model.segments[1].weight_per_length;
  for (int k = 1; k <= p.segment_count; ++k) {
    const double expected = w * (p.length - s.profile.arc_length[k]);
    EXPECT_NEAR(s.profile.tension[k], expected, 1e-9 * w * p.length) << "joint " << k;
  }
  EXPECT_NEAR(s.profile.tension[0], w * p.length, 1e-9 * w * p.length);
  EXPECT_NEAR(s.profile.tension[p.segment_count + 1], 0.0, 1e-9 * w * p.length);
}

}  // namespace
}  // namespace maris::riser
