// Linear wave kinematics against the closed forms (Dean & Dalrymple 1991, ch. 4), dispersion against an
// independent long-double bisection, stretching's mapping of crest and trough, and the synthesised sea's
// variance, reproducibility and non-repetition.
#include <cmath>
#include <cstring>
#include <numbers>

#include <gtest/gtest.h>

#include "core/ocean_waves.hpp"
#include "ocean_test_constants.hpp"

namespace maris::ocean {
namespace {

using test::kG;
using std::numbers::pi;

// Independent root of ω² = g k tanh(kh): bisection in long double on [0, ω²/g + ω/√(gh)].
long double bisectionWaveNumber(double omega, double depth) {
  const long double w2 = static_cast<long double>(omega) * omega / kG;
  long double lo = 0.0L, hi = w2 + omega / std::sqrt(kG * depth);
  for (int i = 0; i < 200; ++i) {
    const long double mid = 0.5L * (lo + hi);
    (mid * std::tanh(mid * depth) < w2 ? lo : hi) = mid;
  }
  return 0.5L * (lo + hi);
}

// Group velocity against dω/dk of the dispersion relation ω(k) = √(g k tanh kh) by a central difference
// (an independent route: truncation ~(δk)² ω''' ≈ 1e-10 relative at δk = 1e-5 k), and its two limits:
// g/(2ω) in deep water (exactly) and √(g h) for kh → 0.
TEST(OceanWaves, GroupVelocityIsTheSlopeOfTheDispersionRelation) {
  auto omega_of = [](double k, double h) { return std::sqrt(kG * k * std::tanh(k * h)); };
  for (double h : {5.0, 50.0, 500.0})
    for (double omega : {0.2, 0.6, 1.5}) {
      const double k = waveNumber(omega, h, kG), dk = 1e-5 * k;
      const double slope = (omega_of(k + dk, h) - omega_of(k - dk, h)) / (2.0 * dk);
      EXPECT_NEAR(groupVelocity(omega, h, kG), slope, 1e-8 * slope) << "h = " << h << ", omega = " << omega;
    }
  EXPECT_EQ(groupVelocity(0.8, kDeepWater, kG), 0.5 * kG / 0.8);
  EXPECT_NEAR(groupVelocity(0.01, 1.0, kG), std::sqrt(kG * 1.0), 1e-5 * std::sqrt(kG));
}

TEST(OceanWaves, DispersionMatchesBisectionTo1e12FromShallowToDeep) {
  for (double depth : {1.0, 10.0, 100.0, 1000.0}) {
    for (double period : {2.0, 5.0, 10.0, 20.0, 60.0}) {
      const double omega = 2.0 * pi / period;
      const double k = waveNumber(omega, depth, kG);
      const long double reference = bisectionWaveNumber(omega, depth);
      EXPECT_LT(std::abs(k - reference) / reference, 1e-12) << "h = " << depth << ", T = " << period;
      EXPECT_LT(std::abs(kG * k * std::tanh(k * depth) - omega * omega) / (omega * omega), 1e-13);
    }
  }
  // Deep water: k = ω²/g exactly; kh = 50 finite depth agrees with it to 1e-15 (tanh 50 = 1 − 7e-44).
  const double omega = 2.0 * pi / 8.0;
  EXPECT_EQ(waveNumber(omega, kDeepWater, kG), omega * omega / kG);
  const double k_deep = omega * omega / kG;
  EXPECT_NEAR(waveNumber(omega, 50.0 / k_deep, kG), k_deep, 1e-15 * k_deep);
  // Shallow water: k → ω/√(gh) as kh → 0 (kh = 0.01 here: tanh x ≈ x − x³/3, relative 1.7e-5).
  const double h = std::pow(0.01 * std::sqrt(kG) / omega, 2);
  const double k_shallow = omega / std::sqrt(kG * h);
  EXPECT_NEAR(waveNumber(omega, h, kG), k_shallow, 2e-5 * k_shallow);
  EXPECT_THROW(waveNumber(0.0, 10.0, kG), std::invalid_argument);
  EXPECT_THROW(waveNumber(1.0, -1.0, kG), std::invalid_argument);
}

// The closed forms written directly with cosh and sinh (no shared code with the library's stable form).
struct AiryReference {
  double a, omega, k, h, beta, phase;
  FluidKinematics at(double x, double y, double z, double t) const {
    const double psi = k * (x * std::cos(beta) + y * std::sin(beta)) - omega * t + phase;
    const bool deep = std::isinf(h);
    const double c = deep ? std::exp(k * z) : std::cosh(k * (z + h)) / std::sinh(k * h);
    const double s = deep ? std::exp(k * z) : std::sinh(k * (z + h)) / std::sinh(k * h);
    FluidKinematics f;
    const double u = a * omega * c * std::cos(psi), du = a * omega * omega * c * std::sin(psi);
    f.velocity = {u * std::cos(beta), u * std::sin(beta), a * omega * s * std::sin(psi)};
    f.acceleration = {du * std::cos(beta), du * std::sin(beta), -a * omega * omega * s * std::cos(psi)};
    f.elevation = a * std::cos(psi);
    return f;
  }
};

TEST(OceanWaves, AiryKinematicsMatchClosedFormsInDeepAndFiniteDepth) {
  const double height = 6.0, period = 10.0, beta = 30.0 * pi / 180.0, phase = 0.4;
  for (double depth : {kDeepWater, 200.0, 30.0}) {
    const WaveField wave = airyWave(height, period, beta, phase, depth, kG, Stretching::None);
    const double omega = 2.0 * pi / period;
    const AiryReference ref{0.5 * height, omega, waveNumber(omega, depth, kG), depth, beta, phase};
    const double scale = ref.a * omega;  // velocity amplitude at the surface in deep water
    const double bottom = std::isinf(depth) ? -150.0 : -depth;
    for (double z : {0.0, -5.0, 0.5 * bottom, bottom}) {
      for (double t : {0.0, 1.3, 4.7, 8.2}) {
        const double x = 12.0, y = -7.0;
        const FluidKinematics expected = ref.at(x, y, z, t);
        if (z > expected.elevation) continue;  // dry under a trough
        const FluidKinematics got = wave.kinematics(Eigen::Vector3d(x, y, z), t);
        ASSERT_TRUE(got.wet);
        EXPECT_NEAR(got.elevation, expected.elevation, 1e-13 * ref.a);
        EXPECT_LT((got.velocity - expected.velocity).norm(), 1e-12 * scale) << "h = " << depth << ", z = " << z;
        EXPECT_LT((got.acceleration - expected.acceleration).norm(), 1e-12 * scale * omega);
      }
    }
    if (!std::isinf(depth)) {  // no flow through the seabed
      EXPECT_NEAR(wave.kinematics(Eigen::Vector3d(0, 0, -depth), 2.0).velocity.z(), 0.0, 1e-14 * scale);
    }
  }
  // Deep-water surface speed is πH/T; a point above the crest is dry.
  const WaveField deep = airyWave(height, period, 0.0, 0.0, kDeepWater, kG, Stretching::None);
  EXPECT_NEAR(deep.kinematics(Eigen::Vector3d::Zero(), 0.0).velocity.x(), pi * height / period, 1e-14);
  EXPECT_FALSE(deep.kinematics(Eigen::Vector3d(0, 0, 3.01), 0.0).wet);
  EXPECT_EQ(deep.kinematics(Eigen::Vector3d(0, 0, 3.01), 0.0).velocity, Eigen::Vector3d::Zero());
}

TEST(OceanWaves, WheelerStretchingMapsTheSurfaceToZeroAndTheSeabedToItself) {
  const double height = 8.0, period = 12.0;
  for (double depth : {kDeepWater, 40.0}) {
    const WaveField linear = airyWave(height, period, 0.0, 0.0, depth, kG, Stretching::None);
    const WaveField wheeler = airyWave(height, period, 0.0, 0.0, depth, kG, Stretching::Wheeler);
    const WaveField vertical = airyWave(height, period, 0.0, 0.0, depth, kG, Stretching::Vertical);
    const double omega = 2.0 * pi / period;
    const AiryReference ref{0.5 * height, omega, waveNumber(omega, depth, kG), depth, 0.0, 0.0};
    // t = 0: crest (η = +4 m) at x = 0; t = T/2: trough (η = −4 m); and two times in between.
    for (double t : {0.0, 0.5 * period, 0.2 * period, 0.7 * period}) {
      const double eta = linear.elevation(0, 0, t);
      const FluidKinematics surface = wheeler.kinematics(Eigen::Vector3d(0, 0, eta), t);
      const FluidKinematics still = ref.at(0, 0, 0.0, t);  // the linear values at z = 0 (dry under a trough)
      EXPECT_LT((surface.velocity - still.velocity).norm(), 1e-13) << "t = " << t;
      EXPECT_LT((surface.acceleration - still.acceleration).norm(), 1e-13);
      if (!std::isinf(depth)) {
        const Eigen::Vector3d bed(0, 0, -depth);
        EXPECT_LT((wheeler.kinematics(bed, t).velocity - linear.kinematics(bed, t).velocity).norm(), 1e-14);
      } else {  // deep water: a point 10 m under the surface sees the linear field 10 m under z = 0
        const FluidKinematics under = wheeler.kinematics(Eigen::Vector3d(0, 0, eta - 10.0), t);
        EXPECT_LT((under.velocity - linear.kinematics(Eigen::Vector3d(0, 0, -10.0), t).velocity).norm(), 1e-13);
      }
      // Vertical stretching: above z = 0 (under a crest) the z = 0 values; below, the linear ones.
      if (eta > 0) {
        const FluidKinematics held = vertical.kinematics(Eigen::Vector3d(0, 0, 0.5 * eta), t);
        EXPECT_LT((held.velocity - still.velocity).norm(), 1e-14);
      }
      const Eigen::Vector3d deep_point(0, 0, -6.0);
      EXPECT_LT((vertical.kinematics(deep_point, t).velocity - linear.kinematics(deep_point, t).velocity).norm(), 1e-14);
    }
  }
}

TEST(OceanWaves, SameSeedGivesTheBitwiseSameSeaAndAnotherSeedAnother) {
  const WaveSpectrum spectrum = jonswap(4.0, 10.0, 3.3);
  for (auto method : {Discretisation::EqualEnergy, Discretisation::RandomFrequency}) {
    const WaveField a = irregularSea(spectrum, 200, method, 42, 0.3, 300.0, kG, Stretching::Wheeler);
    const WaveField b = irregularSea(spectrum, 200, method, 42, 0.3, 300.0, kG, Stretching::Wheeler);
    const WaveField c = irregularSea(spectrum, 200, method, 43, 0.3, 300.0, kG, Stretching::Wheeler);
    ASSERT_EQ(a.size(), 200u);
    EXPECT_EQ(std::memcmp(a.components().data(), b.components().data(), 200 * sizeof(WaveComponent)), 0);
    const double eta_a = a.elevation(3.0, 1.0, 1234.5), eta_b = b.elevation(3.0, 1.0, 1234.5);
    EXPECT_EQ(std::memcmp(&eta_a, &eta_b, sizeof(double)), 0);
    EXPECT_NE(a.components()[0].phase, c.components()[0].phase);
  }
}

// Sample variance of η over `duration` at x = y = 0, sampled every dt.
double sampleVariance(const WaveField& sea, double duration, double dt) {
  const int n = static_cast<int>(duration / dt);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double eta = sea.elevation(0.0, 0.0, i * dt);
    sum += eta;
    sum2 += eta * eta;
  }
  const double mean = sum / n;
  return sum2 / n - mean * mean;
}

TEST(OceanWaves, SynthesisedSeaHasItsSignificantHeightWithinTheStatisticalTolerance) {
  // The sample variance of a Gaussian sea over T has, for T ≫ the correlation time, standard deviation
  // σ(m̂0) = √(2π ∫ S² dω / T) (Bendat & Piersol, Random Data, 2010, §8.2.2 with R(τ) = ∫ S cos ωτ dω);
  // Hs = 4√m0 then has relative standard deviation σ(m̂0)/(2 m0). Each seed must lie within 4σ.
  const double hs = 4.0, tp = 10.0, duration = 3.0 * 3600.0, dt = 0.5;
  const WaveSpectrum spectrum = jonswap(hs, tp, 3.3);
  double s2 = 0.0;  // ∫ S² dω by the trapezoid rule on a fine grid
  const double lo = spectrum.bandLow(), hi = spectrum.bandHigh(), h = (hi - lo) / 20000.0;
  for (int i = 0; i <= 20000; ++i) s2 += (i == 0 || i == 20000 ? 0.5 : 1.0) * h * std::pow(spectrum.density(lo + i * h), 2);
  const double m0 = hs * hs / 16.0;
  const double relative_sigma_hs = std::sqrt(2.0 * pi * s2 / duration) / (2.0 * m0);
  EXPECT_GT(relative_sigma_hs, 0.005);  // ≈ 1.9 % for this sea: the tolerance below is 4σ ≈ 7.6 %
  EXPECT_LT(relative_sigma_hs, 0.03);
  for (auto method : {Discretisation::EqualEnergy, Discretisation::RandomFrequency}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const WaveField sea = irregularSea(spectrum, 200, method, seed, 0.0, kDeepWater, kG, Stretching::Wheeler);
      // The components carry the band's variance: all but the tails outside [0.5, 6]·ω_p (< 1e-3 of m0).
      EXPECT_NEAR(sea.variance(), m0, 1e-3 * m0);
      const double hs_sample = 4.0 * std::sqrt(sampleVariance(sea, duration, dt));
      EXPECT_NEAR(hs_sample / hs, 1.0, 4.0 * relative_sigma_hs) << "seed " << seed;
    }
  }
}

TEST(OceanWaves, IrregularSeaDoesNotRepeatAtTheBinPeriod) {
  // With equally spaced frequencies Δω the record would repeat after 2π/Δω (here 5.5 ω_p/200 → 364 s).
  // Random-in-bin and equal-energy frequencies do not: η(t) and η(t + 2π/Δω) are nearly uncorrelated.
  const WaveSpectrum spectrum = piersonMoskowitz(3.0, 9.0);
  const double d_omega = (spectrum.bandHigh() - spectrum.bandLow()) / 200.0, repeat = 2.0 * pi / d_omega;
  for (auto method : {Discretisation::EqualEnergy, Discretisation::RandomFrequency}) {
    const WaveField sea = irregularSea(spectrum, 200, method, 9, 0.0, kDeepWater, kG, Stretching::Wheeler);
    EXPECT_GT(smallestSpacing(sea), 0.0);
    double sxy = 0.0, sxx = 0.0, syy = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const double t = 1000.0 + 0.7 * i;
      const double x = sea.elevation(0, 0, t), y = sea.elevation(0, 0, t + repeat);
      sxy += x * y, sxx += x * x, syy += y * y;
    }
    EXPECT_LT(std::abs(sxy / std::sqrt(sxx * syy)), 0.3);
  }
}

// The start ramp: 0 up to t = 0, ½ at T_r/2, 1 from T_r on, T_r = 0 switches on at t = 0 (closed form), and its
// rate is the derivative of the ramp (central difference, 1e-8 relative to the peak rate π/(2T_r)).
TEST(OceanWaves, StartRampAndItsRate) {
  const double tr = 20.0;
  EXPECT_EQ(startRamp(-1.0, tr), 0.0);
  EXPECT_EQ(startRamp(0.0, tr), 0.0);
  EXPECT_NEAR(startRamp(10.0, tr), 0.5, 1e-15);
  EXPECT_EQ(startRamp(tr, tr), 1.0);
  EXPECT_EQ(startRamp(0.0, 0.0), 1.0);
  EXPECT_EQ(startRampRate(-1.0, tr), 0.0);
  EXPECT_EQ(startRampRate(tr + 1.0, tr), 0.0);
  for (double t : {1.0, 7.3, 10.0, 19.0}) {
    const double h = 1e-4;
    EXPECT_NEAR(startRampRate(t, tr), (startRamp(t + h, tr) - startRamp(t - h, tr)) / (2.0 * h),
                1e-8 * pi / (2.0 * tr)) << t;
  }
}

}  // namespace
}  // namespace maris::ocean
