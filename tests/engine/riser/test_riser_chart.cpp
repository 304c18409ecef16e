// The charts of the implicit integrator (riser_implicit): the maps of a segment's chart coordinates to its
// orientation and body angular velocity, and the chart's handling of a state when it is reset.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "riser/riser_chart_maps.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

Mat3 chartTurn(ChartKind kind, const Vec3& theta) { return chartMaps(kind, theta).turn; }
Mat3 chartRateMap(ChartKind kind, const Vec3& theta) { return chartMaps(kind, theta).rate_map; }

Vec3 bodyRateByDifferences(ChartKind kind, const Vec3& theta, const Vec3& rate) {
  const double h = 1e-6;  // central differences: truncation 1e-12, round-off 1e-10
  const Mat3 derivative = (chartTurn(kind, theta + h * rate) - chartTurn(kind, theta - h * rate)) / (2 * h);
  const Mat3 body = chartTurn(kind, theta).transpose() * derivative;  // [ω_body]×
  return {body(2, 1), body(0, 2), body(1, 0)};
}

// Both rate maps give the body angular velocity of E(θ + ε θ̇): checked by central differences of the turn
// (the rotation vector's is the right Jacobian of SO(3), J_r(θ)).
TEST(RiserChart, RateMapsGiveTheBodyAngularVelocity) {
  const Vec3 theta(0.7, -1.1, 0.4), rate(0.3, 0.5, -0.2);
  for (ChartKind kind : {ChartKind::RotationVector, ChartKind::SwingTwist}) {
    EXPECT_LT((bodyRateByDifferences(kind, theta, rate) - chartRateMap(kind, theta) * rate).norm(), 1e-9);
    EXPECT_LT((chartRateMap(kind, Vec3(1e-5, 0, 0)) - Mat3::Identity()).norm(), 2e-5);  // first order in θ
    EXPECT_EQ(chartRateMap(kind, Vec3::Zero()), Mat3::Identity());
  }
}

// The rate term Ṁ θ̇ (closed form) against central differences of M along θ̇ (step 1e-5: truncation ~1e-10,
// round-off ~1e-11), at random θ of sizes up to 3 rad, 0.2 and 0.05 rad (both sides of the series branch below
// 0.1 rad) and 5e-3 rad.
TEST(RiserChart, RateTermIsTheDerivativeOfTheRateMap) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double sizes[] = {3.0, 0.2, 0.05, 5e-3};
  for (ChartKind kind : {ChartKind::RotationVector, ChartKind::SwingTwist})
    for (int k = 0; k < 200; ++k) {
      const double size = sizes[k % 4];
      const Vec3 theta = size * Vec3(u(rng), u(rng), u(rng)) / std::sqrt(3.0), rate(u(rng), u(rng), u(rng));
      const double h = 1e-5;
      const Vec3 differences = (chartRateMap(kind, theta + h * rate) - chartRateMap(kind, theta - h * rate)) * rate / (2 * h);
      EXPECT_LT((chartMaps(kind, theta, rate).rate_term - differences).norm(), 1e-8 * (1 + differences.norm())) << k;
    }
}

// The point of the swing–twist chart: the segment's axis E e_x does not depend on the spin θ_x (the rotation
// vector's does, by O(|θ_s| θ_x)), and a spin rate alone is a body spin about e_x.
TEST(RiserChart, SwingTwistAxisIgnoresTheSpin) {
  const Vec3 theta(0.2, -0.8, 0.5), spun(1.4, -0.8, 0.5);
  auto axisShift = [&](ChartKind kind) { return (chartTurn(kind, theta).col(0) - chartTurn(kind, spun).col(0)).norm(); };
  EXPECT_LT(axisShift(ChartKind::SwingTwist), 1e-15);
  EXPECT_GT(axisShift(ChartKind::RotationVector), 0.1);
  const Vec3 spin_rate = chartRateMap(ChartKind::SwingTwist, theta) * Vec3::UnitX();
  EXPECT_LT((spin_rate - Vec3::UnitX()).norm(), 1e-15);
}

// chartCoordinates inverts chartTurn: random θ with swings up to 0.95π and spins up to ±π, the identity (exactly
// 0), and a pure spin; turns agree to 1e-13 (round-off of atan2 near π).
TEST(RiserChart, CoordinatesInvertTheTurn) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (ChartKind kind : {ChartKind::RotationVector, ChartKind::SwingTwist}) {
    EXPECT_EQ(chartCoordinates(kind, Mat3::Identity()), Vec3::Zero());
    for (int k = 0; k < 200; ++k) {
      Vec3 theta(0.95 * pi * u(rng), u(rng), u(rng));
      if (kind == ChartKind::SwingTwist) {
        const Vec3 swing(0, theta.y(), theta.z());
        theta.tail<2>() *= 0.95 * pi * std::abs(u(rng)) / swing.norm();
      } else {
        theta *= 0.95 * pi * std::abs(u(rng)) / theta.norm();
      }
      const Mat3 turn = chartTurn(kind, theta);
      EXPECT_LT((chartTurn(kind, chartCoordinates(kind, turn)) - turn).norm(), 1e-13) << k;
      EXPECT_LT((chartCoordinates(kind, turn) - theta).norm(), 1e-12) << k;
    }
    const Vec3 spin(0.6, 0, 0);
    EXPECT_LT((chartCoordinates(kind, chartTurn(kind, spin)) - spin).norm(), 1e-15);
    // The axis turned exactly to −e_x (a half turn about e_z, then a spin): some θ of the same turn.
    Mat3 flipped;
    flipped << -1, 0, 0, 0, -std::cos(0.4), std::sin(0.4), 0, std::sin(0.4), std::cos(0.4);
    EXPECT_LT((chartTurn(kind, chartCoordinates(kind, flipped)) - flipped).norm(), 1e-13);
  }
}

// Carrying the integrator's accelerations over a chart reset (rebaseAccelerations): on a moving riser (n = 6,
// random rotations of 0.2 rad off the reference, random rates), the exact chart accelerations at (q, v) must,
// once rebased, be the exact accelerations in the chart reset at that state. Both charts, both formulations.
// The rate terms Ṁ θ̇ are central differences (error ~1e-8 relative); asserted within 1e-6 of the
// accelerations. Without the new chart's own rate term the swing–twist chart is off by O(|θ̇|²).
TEST(RiserChart, RebasedAccelerationsAreTheSameMotion) {
  for (const char* formulation : {"joint", "absolute"})
    for (bool torsion : {true, false}) {
      RiserParameters p = test::inclinedTensionedRiser(6, formulation, false);
      p.torsion = torsion;
      const RiserModel m = buildRiserModel(p);
      OrientationChart chart(m, 10.0);
      ASSERT_EQ(chart.kind(), torsion ? ChartKind::RotationVector : ChartKind::SwingTwist);
      Eigen::VectorXd q, v, y, acc, r;
      chart.reset(restState(m, m.initial_orientation, m.initial_top), q, v);
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      const int off = chart.perSegment() - 3;
      for (int k = 0; k <= m.last_dynamic - m.first_dynamic; ++k)
        for (int e = 0; e < 3; ++e) {
          q[3 + k * chart.perSegment() + off + e] = 0.2 * u(rng);
          v[3 + k * chart.perSegment() + off + e] = 0.5 * u(rng);
        }
      chart.toState(q, v, y);
      // Velocities the model keeps (without torsion no spin rate): map the state there and back.
      chart.fromState(y, q, v);
      chart.residual(0.0, q, v, Eigen::VectorXd::Zero(chart.size()), r);
      acc = -r;  // exact: r = acc − a(q, v)
      chart.rebaseAccelerations(q, v, acc);
      chart.toState(q, v, y);
      Eigen::VectorXd q_new, v_new;
      chart.reset(y, q_new, v_new);
      chart.residual(0.0, q_new, v_new, acc, r);
      const Eigen::Index rot_end = chart.size() - kWorkIntegrals;
      EXPECT_LT(r.head(rot_end).lpNorm<Eigen::Infinity>(), 1e-6 * acc.head(rot_end).lpNorm<Eigen::Infinity>())
          << formulation << " torsion " << torsion;
    }
}

}  // namespace
}  // namespace maris::riser
