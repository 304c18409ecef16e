// Axial flexibility (model.axial_flexibility): a top held at a fixed height above the riser's length, the stretch
// taken by a spring k = EA/L at the top. Static tension against the closed form of an elastic bar; the dynamic top
// tension of the peer riser (top swinging 2 m in a 1 m/s current) against an independent lumped-mass model with
// an axial spring per element, written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "riser/riser_model.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

RiserParameters fixedHeight() { return test::builtinParameters("scenarios/riser/riser_peer_fixed_height.json"); }

double axialRigidity(const RiserParameters& p) {
  return p.youngs_modulus * pi / 4 * (p.outer_diameter * p.outer_diameter - p.inner_diameter * p.inner_diameter);
}

// Tension at the top and the bottom of the static shape (table profile_static).
std::pair<double, double> staticEndTensions(const RiserParameters& p) {
  RunContext context;
  const Results r = solveRiser(p, context);
  const Table* t = r.findTable("profile_static");
  const auto& tension = t->find("tension")->values;
  return {tension.front(), tension.back()};
}

TEST(RiserAxialSpring, FixedHeightTopIsRefusedWithoutAndAcceptedWithAxialFlexibility) {
  RiserParameters p = fixedHeight();
  EXPECT_TRUE(checkRiserParameters(p).empty());
  p.axial_flexibility = false;
  const auto errors = checkRiserParameters(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("model.axial_flexibility"), std::string::npos) << errors[0].message;
  p.axial_flexibility = true;
  p.top_condition = "tensioner";
  EXPECT_FALSE(checkRiserParameters(p).empty());
}

// A straight vertical riser held 3 mm above its length, still water, no motion. Without weight the tension is
// uniform, T = EA·δ/L (6.33e9 N · 3e-5 = 190 kN); with the submerged weight W of riser and contents the stretch is
// set by the mean tension, so T_top = EA·δ/L + W/2 and T_bottom = EA·δ/L − W/2 (an elastic bar under its own
// weight, linear in s). The chain is straight at rest, so these hold up to the statics' convergence (1e-7 relative).
TEST(RiserAxialSpring, StaticTensionIsEaTimesStretchOverLength) {
  RiserParameters p = fixedHeight();
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.motion_amplitude_x = 0.0;
  p.end_time = 0.0;
  p.segment_count = 20;
  const double stretch = 0.003, ea_strain = axialRigidity(p) * stretch / p.length;
  p.water_level = 10.0;  // all of it under water (the top stands 3 mm above z = 0)
  const double a_out = pi / 4 * 0.5 * 0.5, a_inn = pi / 4 * 0.46 * 0.46;
  const double weight =
      (p.density * (a_out - a_inn) + p.internal_fluid_density * a_inn - p.water_density * a_out) * p.gravity * p.length;
  const auto [top, bottom] = staticEndTensions(p);
  EXPECT_NEAR(top, ea_strain + weight / 2, 1e-7 * ea_strain);
  EXPECT_NEAR(bottom, ea_strain - weight / 2, 1e-7 * ea_strain);
  EXPECT_NEAR(0.5 * (top + bottom), ea_strain, 1e-7 * ea_strain);
  p.gravity = 0.0;
  const auto [top0, bottom0] = staticEndTensions(p);
  EXPECT_NEAR(top0, ea_strain, 1e-7 * ea_strain);
  EXPECT_NEAR(bottom0, ea_strain, 1e-7 * ea_strain);
}

// Independent reference: a lumped-mass model in the xz plane (the discretisation of MoorDyn: M. Hall, A. Goupee,
// Ocean Engineering 104 (2015) 590–603), N elements of length l = L/N between nodes 0 (top, prescribed) and N
// (anchor). Per element an axial spring, tension EA(|d|/l − 1), so the stretch is spread along the riser instead
// of lumped at the top; bending springs EI/l on the angle between neighbouring elements; normal drag
// ½ρ C_dn D l |v_n| v_n at the element's mid-point velocity relative to the current, half to each node; submerged
// weight; node mass (pipe + contents) l plus the normal added mass C_a ρ A_out l across the node's tangent
// (C_at = 0). Explicit RK4. Only the prescribed top motion (x(t) with its ramp) is taken from the riser model.
class LumpedMassRiser {
 public:
  LumpedMassRiser(const RiserParameters& p, const RiserModel& m, int elements) : m_(m), n_(elements) {
    const double a_out = pi / 4 * p.outer_diameter * p.outer_diameter;
    const double a_inn = pi / 4 * p.inner_diameter * p.inner_diameter;
    l_ = p.length / n_;
    ea_ = p.youngs_modulus * (a_out - a_inn);
    ei_ = p.youngs_modulus * pi / 64 * (std::pow(p.outer_diameter, 4) - std::pow(p.inner_diameter, 4));
    mass_ = (p.density * (a_out - a_inn) + p.internal_fluid_density * a_inn) * l_;
    added_ = p.added_mass_coefficient * p.water_density * a_out * l_;
    weight_ = (mass_ / l_ - p.water_density * a_out) * p.gravity * l_;
    drag_ = 0.5 * p.water_density * p.normal_drag_coefficient * p.outer_diameter * l_;
    current_ = p.current_speed_surface;
    height_ = p.top_z;
    anchor_ = Eigen::Vector2d(p.bottom_x, p.bottom_z);
    r_.resize(n_ + 1);
    v_.assign(n_ + 1, Eigen::Vector2d::Zero());
    for (int j = 0; j <= n_; ++j) r_[j] = Eigen::Vector2d(p.top_x, height_) + (anchor_ - Eigen::Vector2d(p.top_x, height_)) * j / n_;
  }

  // Damped motion with the top at rest until the shape settles in the current (mass-proportional damping c).
  void settle(double duration, double h, double c) {
    for (double t = 0; t < duration; t += h) step(0.0, h, c);
    for (auto& v : v_) v.setZero();
  }

  // Top force z on the riser [N] at time t (after step): the top element's pull and the top node's half-element weight.
  double topForceZ(double t) {
    std::vector<Eigen::Vector2d> f;
    forces(t, r_, v_, f, 0.0);
    return -f[0].y() + 0.5 * weight_;
  }

  void step(double t, double h, double damping) {
    // RK4 on the interior nodes 1..n−1.
    const auto r0 = r_, v0 = v_;
    std::vector<Eigen::Vector2d> k1r, k1v, k2r, k2v, k3r, k3v, k4r, k4v, rr = r0, vv = v0;
    derivative(t, r0, v0, k1r, k1v, damping);
    advance(r0, v0, k1r, k1v, 0.5 * h, rr, vv);
    derivative(t + 0.5 * h, rr, vv, k2r, k2v, damping);
    advance(r0, v0, k2r, k2v, 0.5 * h, rr, vv);
    derivative(t + 0.5 * h, rr, vv, k3r, k3v, damping);
    advance(r0, v0, k3r, k3v, h, rr, vv);
    derivative(t + h, rr, vv, k4r, k4v, damping);
    for (int j = 1; j < n_; ++j) {
      r_[j] = r0[j] + h / 6 * (k1r[j] + 2 * k2r[j] + 2 * k3r[j] + k4r[j]);
      v_[j] = v0[j] + h / 6 * (k1v[j] + 2 * k2v[j] + 2 * k3v[j] + k4v[j]);
    }
    setEnds(t + h, r_, v_);
  }

 private:
  void setEnds(double t, std::vector<Eigen::Vector2d>& r, std::vector<Eigen::Vector2d>& v) const {
    const TopKinematics top = m_.topAt(t);
    r[0] = Eigen::Vector2d(top.position.x(), height_);
    v[0] = Eigen::Vector2d(top.velocity.x(), 0.0);
    r[n_] = anchor_;
    v[n_].setZero();
  }

  void advance(const std::vector<Eigen::Vector2d>& r0, const std::vector<Eigen::Vector2d>& v0,
               const std::vector<Eigen::Vector2d>& dr, const std::vector<Eigen::Vector2d>& dv, double h,
               std::vector<Eigen::Vector2d>& r, std::vector<Eigen::Vector2d>& v) const {
    for (int j = 1; j < n_; ++j) {
      r[j] = r0[j] + h * dr[j];
      v[j] = v0[j] + h * dv[j];
    }
  }

  void forces(double t, std::vector<Eigen::Vector2d> r, std::vector<Eigen::Vector2d> v, std::vector<Eigen::Vector2d>& f,
              double damping) const {
    setEnds(t, r, v);
    f.assign(n_ + 1, Eigen::Vector2d::Zero());
    std::vector<Eigen::Vector2d> g(n_);  // ∂θ_e/∂r_{e+1}
    std::vector<double> theta(n_);
    for (int e = 0; e < n_; ++e) {
      const Eigen::Vector2d d = r[e + 1] - r[e];
      const double len = d.norm();
      const Eigen::Vector2d u = d / len;
      const double tension = ea_ * (len / l_ - 1);
      f[e] += tension * u;
      f[e + 1] -= tension * u;
      theta[e] = std::atan2(d.y(), d.x());
      g[e] = Eigen::Vector2d(-d.y(), d.x()) / (len * len);
      Eigen::Vector2d rel = 0.5 * (v[e] + v[e + 1]) - Eigen::Vector2d(current_, 0.0);
      const Eigen::Vector2d normal = rel - rel.dot(u) * u;
      const Eigen::Vector2d drag = -drag_ * normal.norm() * normal;
      f[e] += 0.5 * drag;
      f[e + 1] += 0.5 * drag;
    }
    for (int j = 1; j < n_; ++j) {
      const double moment = ei_ / l_ * std::remainder(theta[j] - theta[j - 1], 2 * pi);
      f[j + 1] -= moment * g[j];
      f[j] += moment * (g[j] + g[j - 1]);
      f[j - 1] -= moment * g[j - 1];
      f[j].y() -= weight_;
      f[j] -= damping * mass_ * v[j];
    }
  }

  void derivative(double t, const std::vector<Eigen::Vector2d>& r, const std::vector<Eigen::Vector2d>& v,
                  std::vector<Eigen::Vector2d>& dr, std::vector<Eigen::Vector2d>& dv, double damping) const {
    std::vector<Eigen::Vector2d> f;
    forces(t, r, v, f, damping);
    dr.assign(n_ + 1, Eigen::Vector2d::Zero());
    dv.assign(n_ + 1, Eigen::Vector2d::Zero());
    for (int j = 1; j < n_; ++j) {
      const Eigen::Vector2d q = ((r[j] - r[j - 1]).normalized() + (r[j + 1] - r[j]).normalized()).normalized();
      const Eigen::Matrix2d mass = mass_ * Eigen::Matrix2d::Identity() + added_ * (Eigen::Matrix2d::Identity() - q * q.transpose());
      dr[j] = v[j];
      dv[j] = mass.lu().solve(f[j]);
    }
  }

  const RiserModel& m_;
  int n_;
  double l_, ea_, ei_, mass_, added_, weight_, drag_, current_, height_;
  Eigen::Vector2d anchor_;
  std::vector<Eigen::Vector2d> r_, v_;
};

struct Swing {
  double low = 1e300, high = -1e300;
};

// The peer riser with its top 100.003 m above the anchor swinging x = 2 sin(2πt/10) (10 s ramp) in a 1 m/s
// current: the top force over the last 16 s (1.6 periods, after the ramp) swings between ≈ 0.3 and 1.5 MN.
TEST(RiserAxialSpring, DynamicTopTensionSwingMatchesALumpedMassModelWithAxialSprings) {
  RiserParameters p = fixedHeight();
  p.segment_count = 40;
  p.integrator = "implicit";
  p.time_step = 0.025;  // T/400: expected probe error 43 (h/T)² = 2.7e-4 of the motion
  p.frame_count = 36;
  p.stress_times.clear();
  // Under the sanitizers the segment method's dynamic path with the axial spring runs for 2 s; the comparison
  // with the lumped-mass model (190 000 RK4 steps of test code) is checked in the Release build.
  if (::maris::test::kSanitizedBuild) p.end_time = 2.0;
  RunContext context;
  const Results r = solveRiser(p, context);
  const Table* history = r.findTable("history");
  const auto& time = history->find("time")->values;
  const auto& force = history->find("top_force_z")->values;
  if (::maris::test::kSanitizedBuild) {
    for (double f : force) EXPECT_TRUE(std::isfinite(f));
    return;
  }
  Swing maris;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= 20.0) maris.low = std::min(maris.low, force[k]), maris.high = std::max(maris.high, force[k]);

  const RiserModel model = buildRiserModel(p);
  LumpedMassRiser lumped(p, model, 40);
  const double h = 4e-4;  // RK4 below its axial stability limit 2.8 l / (2 c) = 8.9e-4 s at l = 2.5 m
  lumped.settle(40.0, h, 1.5);
  Swing reference;
  for (long k = 0; k * h < p.end_time - 0.5 * h; ++k) {
    lumped.step(k * h, h, 0.0);
    const double t = (k + 1) * h;
    if (t >= 20.0) {
      const double f = lumped.topForceZ(t);
      reference.low = std::min(reference.low, f), reference.high = std::max(reference.high, f);
    }
  }
  const double swing = reference.high - reference.low;
  std::printf("top force z over 20-36 s: segment method %.4g ... %.4g N, lumped mass %.4g ... %.4g N\n", maris.low,
              maris.high, reference.low, reference.high);
  EXPECT_GT(swing, 5e5);
  EXPECT_NEAR(maris.high - maris.low, swing, 0.03 * swing);
  EXPECT_NEAR(maris.high, reference.high, 0.03 * swing);
  EXPECT_NEAR(maris.low, reference.low, 0.03 * swing);
}

}  // namespace
}  // namespace maris::riser
