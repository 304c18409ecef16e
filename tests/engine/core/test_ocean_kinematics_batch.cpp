// The batched (vectorised) wave kinematics against the direct formula, WaveField::kinematics, which the
// closed-form tests of test_ocean_waves.cpp check against Dean & Dalrymple's cosh/sinh forms; and its sine,
// cosine and exponential kernels against the standard library's.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/ocean_kinematics_batch.hpp"
#include "core/wave_spectrum.hpp"
#include "ocean_test_constants.hpp"

namespace maris::ocean {
namespace {

using test::kG;

TEST(OceanKinematicsBatch, KernelsAgreeWithTheLibraryToAFewUlps) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-1e5, 1e5), small(-4.0, 4.0), argument(-708.0, 708.0);
  double worst_trig = 0.0, worst_exp = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = i % 2 ? angle(rng) : small(rng);
    double s, c;
    fastSinCos(x, s, c);
    worst_trig = std::max({worst_trig, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
    const double e = argument(rng);
    worst_exp = std::max(worst_exp, std::abs(fastExp(e) - std::exp(e)) / std::exp(e));
  }
  // Values ≤ 1 in magnitude: 4e-16 absolute is two units in the last place at 1; exp relative 4e-16.
  EXPECT_LT(worst_trig, 4e-16);
  EXPECT_LT(worst_exp, 4e-16);
  double s, c;
  fastSinCos(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
  EXPECT_EQ(fastExp(0.0), 1.0);
}

// The phases of a harmonic synthesis (the vessel motion): cos and sin of φ − ω t against the library's of the same
// argument. The argument's own rounding (of ω t and of the difference, which a fused multiply-add may merge: each
// ≤ 1.2e-16 of its size, so ≤ 2.3e-16 (|ω t| + |ψ|)) and two units in the last place of the kernels; beyond 6e6 rad
// the library's values themselves.
TEST(OceanKinematicsBatch, HarmonicPhasesAgreeWithTheLibrary) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> phase_of(-7.0, 7.0), omega_of(0.2, 3.0);
  std::vector<double> phase(203), omega(203), c(203), s(203);
  for (std::size_t j = 0; j < phase.size(); ++j) phase[j] = phase_of(rng), omega[j] = omega_of(rng);
  for (const double t : {0.0, 17.3, 10800.0, 1e5}) {
    harmonicPhases(phase.size(), phase.data(), omega.data(), t, c.data(), s.data());
    for (std::size_t j = 0; j < phase.size(); ++j) {
      const double psi = phase[j] - omega[j] * t;
      const double bound = 4e-16 + 2.3e-16 * (std::abs(omega[j] * t) + std::abs(psi));
      EXPECT_NEAR(c[j], std::cos(psi), bound) << t << " " << j;
      EXPECT_NEAR(s[j], std::sin(psi), bound) << t << " " << j;
    }
  }
  const double t = 1e7;  // ω t beyond the reduction's range
  harmonicPhases(phase.size(), phase.data(), omega.data(), t, c.data(), s.data());
  for (std::size_t j = 0; j < phase.size(); ++j) {
    EXPECT_EQ(c[j], std::cos(phase[j] - omega[j] * t)) << j;
    EXPECT_EQ(s[j], std::sin(phase[j] - omega[j] * t)) << j;
  }
}

// Largest |batch − direct| over the points, per quantity relative to that quantity's scale at the point: the sum of
// the components' magnitudes a ω^p (|cosh| or |sinh| ratio) at the stretched height, so that a point deep down,
// where the kinematics are small, is held to its own size and not to the surface's.
struct Scales {
  double eta, u, w, du, dw;
};

Scales scalesAt(const WaveField& field, double z_stretched) {
  const double h = field.depth();
  Scales s{0, 0, 0, 0, 0};
  for (std::size_t j = 0; j < field.size(); ++j) {
    const WaveComponent& c = field.components()[j];
    const double k = waveNumber(c.omega, h, kG);
    const double z = std::isinf(h) ? z_stretched : std::max(z_stretched, -h);
    // Beyond k h = 300 the ratios equal e^{k z} to 1e-260 (and cosh, sinh would overflow past k h = 710).
    const bool deep = std::isinf(h) || k * h > 300.0;
    const double ch = deep ? std::exp(k * z) : std::cosh(k * (z + h)) / std::sinh(k * h);
    const double sh = deep ? std::exp(k * z) : std::abs(std::sinh(k * (z + h))) / std::sinh(k * h);
    s.eta += c.amplitude;
    s.u += c.amplitude * c.omega * ch;
    s.w += c.amplitude * c.omega * sh;
    s.du += c.amplitude * c.omega * c.omega * ch;
    s.dw += c.amplitude * c.omega * c.omega * sh;
  }
  s.w = std::max(s.w, s.u * 1e-3);  // at the sea bed sinh → 0: hold w to a thousandth of u's scale there
  s.dw = std::max(s.dw, s.du * 1e-3);
  return s;
}

double stretchedHeight(const WaveField& field, double z, double eta) {
  const double h = field.depth();
  switch (field.stretching()) {
    case Stretching::Wheeler: return std::isinf(h) ? z - eta : h * (z - eta) / (h + eta);
    case Stretching::Vertical: return std::min(z, 0.0);
    case Stretching::None: return z;
  }
  return z;
}

// Crest and trough of the field along its direction at time t (on a 0.05 m grid over ±150 m), and points at the
// surface just below each, at depths, at the sea bed and above the crest (dry).
std::vector<Eigen::Vector3d> testPoints(const WaveField& field, double direction, double t) {
  const double cb = std::cos(direction), sb = std::sin(direction);
  double crest_s = 0, trough_s = 0, crest = -1e9, trough = 1e9;
  for (double s = -150.0; s <= 150.0; s += 0.05) {
    const double eta = field.elevation(s * cb, s * sb, t);
    if (eta > crest) crest = eta, crest_s = s;
    if (eta < trough) trough = eta, trough_s = s;
  }
  const double bottom = std::isinf(field.depth()) ? -300.0 : -field.depth();
  std::vector<Eigen::Vector3d> points;
  for (const auto& [s, eta] : {std::pair{crest_s, crest}, std::pair{trough_s, trough}, std::pair{37.0, 0.0}}) {
    const double top = s == 37.0 ? field.elevation(s * cb, s * sb, t) : eta;
    for (double z : {top - 1e-6, top - 0.5, 0.0, -1.0, -10.0, -50.0, 0.999 * bottom, bottom, top + 0.3})
      points.emplace_back(s * cb + 3.0 * sb, s * sb - 3.0 * cb, z);  // 3 m off the line: y matters
  }
  return points;
}

// The direction of every field below.
constexpr double kDirection = 0.5;

// Returns the number of points whose phases the batch rotated from an anchor's.
long expectBatchEqualsDirectAt(const WaveField& field, const std::vector<Eigen::Vector3d>& points, double t,
                               double ramp, double ramp_rate, double tolerance) {
  const WaveKinematicsBatch batch(field, kDirection, kG);
  WaveKinematicsBatch::Scratch scratch;
  std::vector<FluidKinematics> fast(points.size());
  batch.evaluate(points.data(), points.size(), t, ramp, ramp_rate, scratch, fast.data());
  int wet = 0, dry = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const FluidKinematics direct = field.kinematics(points[i], t, ramp, ramp_rate);
    const Scales s = scalesAt(field, stretchedHeight(field, points[i].z(), direct.elevation));
    const double r = std::max(ramp, 1e-300), rate_u = std::abs(ramp_rate) * s.u / r, rate_w = std::abs(ramp_rate) * s.w / r;
    EXPECT_EQ(fast[i].wet, direct.wet) << "point " << i;
    if (fast[i].wet != direct.wet) continue;
    (direct.wet ? wet : dry)++;
    EXPECT_LE(std::abs(fast[i].elevation - direct.elevation), tolerance * ramp * s.eta) << "point " << i;
    const Eigen::Vector3d dv = fast[i].velocity - direct.velocity, da = fast[i].acceleration - direct.acceleration;
    EXPECT_LE(dv.head<2>().norm(), tolerance * ramp * s.u) << "point " << i << " z " << points[i].z();
    EXPECT_LE(std::abs(dv.z()), tolerance * ramp * s.w) << "point " << i << " z " << points[i].z();
    EXPECT_LE(da.head<2>().norm(), tolerance * (ramp * s.du + rate_u * r)) << "point " << i;
    EXPECT_LE(std::abs(da.z()), tolerance * (ramp * s.dw + rate_w * r)) << "point " << i;
  }
  EXPECT_GE(wet, 1);
  return scratch.rotated_points;
}

void expectBatchEqualsDirect(const WaveField& field, double t, double ramp, double ramp_rate, double tolerance) {
  const std::vector<Eigen::Vector3d> points = testPoints(field, kDirection, t);
  expectBatchEqualsDirectAt(field, points, t, ramp, ramp_rate, tolerance);
  int wet = 0, dry = 0;
  for (const Eigen::Vector3d& p : points) (field.kinematics(p, t, ramp, ramp_rate).wet ? wet : dry)++;
  EXPECT_GE(wet, 17);  // crest, trough and the middle point: surface (wet when unramped), depths, sea bed
  EXPECT_GE(dry, 3);   // above each surface
}

WaveField jonswapSea(double depth, Stretching stretching) {
  return irregularSea(jonswap(6.0, 10.0, 3.3), 200, Discretisation::RandomFrequency, 1, kDirection, depth, kG,
                     stretching);
}

// 1e-13 of each quantity's scale: the sums run in another order (SIMD lanes) and the kernels are within 2 ulps.
TEST(OceanKinematicsBatch, EqualsTheDirectFormulaWithWheelerStretchingAtSurfaceDepthCrestAndTrough) {
  for (double depth : {100.0, 30.0, kDeepWater}) {
    SCOPED_TRACE(depth);
    expectBatchEqualsDirect(jonswapSea(depth, Stretching::Wheeler), 37.3, 1.0, 0.0, 1e-13);
    expectBatchEqualsDirect(jonswapSea(depth, Stretching::Wheeler), 7.1, 0.37, 0.05, 1e-13);  // within the ramp
  }
  // A regular wave: crest and trough exactly on the grid of the search above.
  expectBatchEqualsDirect(airyWave(8.0, 9.0, kDirection, 0.2, 60.0, kG, Stretching::Wheeler), 3.0, 1.0, 0.0, 1e-13);
}

TEST(OceanKinematicsBatch, EqualsTheDirectFormulaWithVerticalAndNoStretching) {
  expectBatchEqualsDirect(jonswapSea(100.0, Stretching::Vertical), 37.3, 1.0, 0.0, 1e-13);
  expectBatchEqualsDirect(jonswapSea(100.0, Stretching::None), 37.3, 1.0, 0.0, 1e-13);
}

// Phase rotation (ocean_kinematics_batch.hpp): the Gauss points of a riser, 3 per 1 m segment from 1 m above the
// still water to the sea bed, on a line that drifts 12 m sideways and 9 m along the waves (so anchors are renewed
// every 0.1/k_max of s and the rotations span up to that), against the direct formula within the batch's
// 1e-13 of each quantity's scale; most points rotate.
TEST(OceanKinematicsBatch, RotatedPhasesAlongAnInclinedLineEqualTheDirectFormula) {
  for (double depth : {100.0, 30.0, kDeepWater}) {
    SCOPED_TRACE(depth);
    const WaveField field = jonswapSea(depth, Stretching::Wheeler);
    const double length = std::isinf(depth) ? 101.0 : depth + 1.0;
    const double along_x = std::cos(kDirection), along_y = std::sin(kDirection);
    std::vector<Eigen::Vector3d> points;
    for (double segment = 0.0; segment < length; segment += 1.0)
      for (double xi : {0.1127016653792583, 0.5, 0.8872983346207417}) {
        const double f = (segment + xi) / length;
        const double s = 4.0 + 9.0 * f * f, side = 12.0 * f;
        points.emplace_back(s * along_x - side * along_y, s * along_y + side * along_x, 1.0 - (segment + xi));
      }
    const long rotated = expectBatchEqualsDirectAt(field, points, 37.3, 1.0, 0.0, 1e-13);
    EXPECT_GE(rotated, static_cast<long>(points.size()) * 3 / 4);
    EXPECT_LT(rotated, static_cast<long>(points.size()));  // some anchors renewed along the way
  }
}

// After three hours ω t ≈ 4e4 rad: the direct formula's own argument carries ≈ 7e-12 rad of rounding (one unit in
// the last place of 4e4), so the two agree to that, not to 1e-13.
TEST(OceanKinematicsBatch, EqualsTheDirectFormulaAfterThreeHours) {
  expectBatchEqualsDirect(jonswapSea(100.0, Stretching::Wheeler), 10800.0, 1.0, 0.0, 2e-11);
}

// Truncation ε: against the direct formula (all components) every wet point's velocity is within ε Σ|a ω| and its
// acceleration within ε Σ|a ω²| (times the ramp, plus the ramp-rate term's ε share), the bound stated in
// ocean_kinematics_batch.hpp, with 1e-13 of the scale for the rounding; and components are in fact dropped (the
// deep points differ from the untruncated batch), else the bound would be checked on nothing.
TEST(OceanKinematicsBatch, TruncationStaysWithinItsStatedBound) {
  for (const double depth : {100.0, kDeepWater}) {
    SCOPED_TRACE(depth);
    const WaveField field = jonswapSea(depth, Stretching::Wheeler);
    double velocity_scale = 0.0, acceleration_scale = 0.0;
    for (const WaveComponent& c : field.components()) {
      velocity_scale += c.amplitude * c.omega;
      acceleration_scale += c.amplitude * c.omega * c.omega;
    }
    const double epsilon = 1e-4, ramp = 0.8, ramp_rate = 0.05;
    const WaveKinematicsBatch truncated(field, kDirection, kG, epsilon), exact(field, kDirection, kG);
    WaveKinematicsBatch::Scratch scratch_truncated, scratch_exact;
    std::vector<Eigen::Vector3d> points;
    for (double z = 0.0; z >= -100.0; z -= 2.5) points.emplace_back(3.0, -2.0, z);
    std::vector<FluidKinematics> fast(points.size()), all(points.size());
    const double t = 41.7;
    truncated.evaluate(points.data(), points.size(), t, ramp, ramp_rate, scratch_truncated, fast.data());
    exact.evaluate(points.data(), points.size(), t, ramp, ramp_rate, scratch_exact, all.data());
    const double velocity_bound = (epsilon + 1e-13) * ramp * velocity_scale;
    const double acceleration_bound = (epsilon + 1e-13) * (ramp * acceleration_scale + ramp_rate * velocity_scale);
    int dropped = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const FluidKinematics direct = field.kinematics(points[i], t, ramp, ramp_rate);
      ASSERT_EQ(fast[i].wet, direct.wet);
      EXPECT_EQ(fast[i].elevation, all[i].elevation) << "η takes every component";
      EXPECT_LE((fast[i].velocity - direct.velocity).cwiseAbs().maxCoeff(), velocity_bound) << points[i].z();
      EXPECT_LE((fast[i].acceleration - direct.acceleration).cwiseAbs().maxCoeff(), acceleration_bound) << points[i].z();
      dropped += fast[i].velocity != all[i].velocity;
    }
    EXPECT_GE(dropped, 20);  // of 41 points: the deeper ones lose their short waves
  }
}

// In 1000 m of water the short components (k h > 300) drop the mirror term e^{−k(z'+2h)} (≤ e^{−300} of their
// value) and take e^{k z'}, the long ones the ratio form: both against the direct formula within 1e-13 of the scale.
TEST(OceanKinematicsBatch, EqualsTheDirectFormulaWhereTheShortWavesDropTheMirrorTerm) {
  const WaveField field = jonswapSea(1000.0, Stretching::Wheeler);
  int long_waves = 0, short_waves = 0;
  for (const WaveComponent& c : field.components()) (waveNumber(c.omega, 1000.0, kG) * 1000.0 > 300.0 ? short_waves : long_waves)++;
  EXPECT_GE(long_waves, 20);
  EXPECT_GE(short_waves, 20);
  expectBatchEqualsDirect(field, 37.3, 1.0, 0.0, 1e-13);
}

// Without stretching a point above the still water keeps z' = z: a wave of k = 100 /m in 2.9 m of water (k h = 290,
// below the 300 of the mirror term) with a 5.1 m crest, at z = 3.5 m (k (z'+h) = 640: the ratio form, 2^±923) and
// z = 5 m (k (z'+h) = 790, beyond the ratio form's range: e^{k z'} = e^{500}, the mirror term e^{−1080} dropped). Against the direct formula within
// 1e-13 of the velocity's and acceleration's size (the sums of one component: their magnitudes a ω C, a ω² C).
TEST(OceanKinematicsBatch, PointsFarAboveTheStillWaterWithoutStretchingEqualTheDirectFormula) {
  const double depth = 2.9, k = 100.0, omega = std::sqrt(kG * k * std::tanh(k * depth));
  const WaveField field =
      airyWave(10.2, 2.0 * std::numbers::pi / omega, kDirection, 0.0, depth, kG, Stretching::None);
  const WaveKinematicsBatch batch(field, kDirection, kG);
  WaveKinematicsBatch::Scratch scratch;
  const double s = 1e-3;  // ψ = 0.1: velocity and acceleration have both components
  for (const double z : {3.5, 5.0}) {
    SCOPED_TRACE(z);
    const Eigen::Vector3d p(s * std::cos(kDirection), s * std::sin(kDirection), z);
    FluidKinematics fast;
    batch.evaluate(&p, 1, 0.0, 1.0, 0.0, scratch, &fast);
    const FluidKinematics direct = field.kinematics(p, 0.0);
    ASSERT_TRUE(direct.wet);
    ASSERT_TRUE(fast.wet);
    // cosh k(z+h)/sinh kh without its overflow at k (z+h) > 710
    const double c = (std::exp(k * z) + std::exp(-k * (z + 2.0 * depth))) / -std::expm1(-2.0 * k * depth);
    const double v = 5.1 * omega * c, a = v * omega;
    ASSERT_TRUE(std::isfinite(v * omega));
    EXPECT_LE((fast.velocity - direct.velocity).cwiseAbs().maxCoeff(), 1e-13 * v);
    EXPECT_LE((fast.acceleration - direct.acceleration).cwiseAbs().maxCoeff(), 1e-13 * a);
  }
}

// Points far along the waves (|k s| > 1e5) take the direct formula: the same values exactly.
TEST(OceanKinematicsBatch, FarPointsFallBackToTheDirectFormula) {
  const WaveField field = jonswapSea(100.0, Stretching::Wheeler);
  const WaveKinematicsBatch batch(field, kDirection, kG);
  WaveKinematicsBatch::Scratch scratch;
  const Eigen::Vector3d far(1e6 * std::cos(kDirection), 1e6 * std::sin(kDirection), -5.0);
  FluidKinematics fast;
  batch.evaluate(&far, 1, 20.0, 1.0, 0.0, scratch, &fast);
  const FluidKinematics direct = field.kinematics(far, 20.0);
  EXPECT_EQ(fast.velocity, direct.velocity);
  EXPECT_EQ(fast.acceleration, direct.acceleration);
  EXPECT_EQ(fast.elevation, direct.elevation);
}

}  // namespace
}  // namespace maris::ocean
