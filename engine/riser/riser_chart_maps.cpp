#include "riser/riser_chart_maps.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace maris::riser {
namespace {

// The coefficients of exp([θ]×) = I + s0 K + c1 K² and J_r(θ) = I − c1 K + c2 K² (K = [θ]×, a = |θ|), and of
// their derivatives along a: d1 = c1'(a)/a, d2 = c2'(a)/a. By their series below 0.1 rad, where the closed forms
// cancel (d2 loses ~1e-6 relative at 1e-2 rad, 9e-11 at 0.1); the series are within 6e-15 relative there
// (checked against 50-digit arithmetic).
struct RodriguesCoefficients {
  double s0, c1, c2, d1, d2;
};

RodriguesCoefficients rodrigues(double a) {
  const double x = a * a;
  if (a < 0.1) {
    return {1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72))),
            0.5 - x / 24 * (1 - x / 30 * (1 - x / 56)),
            1.0 / 6 - x / 120 * (1 - x / 42 * (1 - x / 72)),
            -1.0 / 12 + x / 180 - x * x / 6720 + x * x * x / 453600,
            -1.0 / 60 + x / 1260 - x * x / 60480 + x * x * x / 4989600};
  }
  const double s = std::sin(a), c = std::cos(a), a3 = x * a;
  return {s / a, (1 - c) / x, (a - s) / a3, (s / x - 2 * (1 - c) / a3) / a,
          ((1 - c) / a3 - 3 * (a - s) / (a3 * a)) / a};
}

// The rotation-vector maps. J̇_r θ̇ = −d1 (θ·θ̇)(θ × θ̇) + d2 (θ·θ̇) θ × (θ × θ̇) + c2 θ̇ × (θ × θ̇): the derivative of
// J_r = I − c1 K + c2 K² along θ̇, where the K̇ = [θ̇]× terms acting on θ̇ itself vanish.
ChartMaps rotationVectorMaps(const Vec3& theta, const Vec3& rate) {
  const RodriguesCoefficients r = rodrigues(theta.norm());
  const Mat3 k = skew(theta), k2 = k * k;
  const Vec3 cross = theta.cross(rate);
  const double along = theta.dot(rate);
  return {Mat3::Identity() + r.s0 * k + r.c1 * k2, Mat3::Identity() - r.c1 * k + r.c2 * k2,
          -r.d1 * along * cross + r.d2 * along * theta.cross(cross) + r.c2 * rate.cross(cross)};
}

}  // namespace

ChartMaps chartMaps(ChartKind kind, const Vec3& theta, const Vec3& rate) {
  if (kind == ChartKind::RotationVector) return rotationVectorMaps(theta, rate);
  // E = E_s T, T = exp(θ_x[e_x]×). ω = Tᵀ J_s θ̇_s + θ̇_x e_x; its rate at fixed θ̈:
  // d(Tᵀ)/dt = −θ̇_x [e_x]× Tᵀ, so Ṁ θ̇ = −θ̇_x e_x × (Tᵀ J_s θ̇_s) + Tᵀ J̇_s θ̇_s.
  const Vec3 swing(0, theta.y(), theta.z()), swing_rate(0, rate.y(), rate.z());
  const ChartMaps s = rotationVectorMaps(swing, swing_rate);
  const double c = std::cos(theta.x()), sn = std::sin(theta.x());
  Mat3 spin;
  spin << 1, 0, 0, 0, c, -sn, 0, sn, c;
  ChartMaps m;
  m.turn = s.turn * spin;
  m.rate_map = spin.transpose() * s.rate_map;
  m.rate_map.col(0) = Vec3::UnitX();
  m.rate_term = -rate.x() * Vec3::UnitX().cross(spin.transpose() * (s.rate_map * swing_rate)) +
                spin.transpose() * s.rate_term;
  return m;
}

Vec3 chartCoordinates(ChartKind kind, const Mat3& turn) {
  if (turn == Mat3::Identity()) return Vec3::Zero();
  if (kind == ChartKind::RotationVector) {
    const Eigen::AngleAxisd a(turn);
    return a.angle() * a.axis();
  }
  // The swing turns e_x to the axis t about e_x × t; atan2 keeps the angle accurate near 0 and π.
  const Vec3 axis = turn.col(0), normal = Vec3::UnitX().cross(axis);
  const double sine = normal.norm();
  // An axis turned exactly to −e_x: any half turn about an axis normal to e_x will do (e_y here).
  const Vec3 half_turn(0, axis.x() < 0 ? std::numbers::pi : 0.0, 0);
  const Vec3 swing = sine > 0 ? Vec3(std::atan2(sine, axis.x()) * normal / sine) : half_turn;
  const Mat3 spin = chartMaps(ChartKind::RotationVector, swing).turn.transpose() * turn;
  return {std::atan2(spin(2, 1), spin(1, 1)), swing.y(), swing.z()};
}

}  // namespace maris::riser
