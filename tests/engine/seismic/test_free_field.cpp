// Free field of a half-space under a water layer (engine/seismic/free_field.hpp) against closed forms
// and reference values computed by an independent implementation (a separate pure-Python script, outside
// this repository; for the no-water case checked against K. Aki, P. G. Richards, Quantitative Seismology,
// 2nd ed., 2002, eq 5.32).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "seismic/free_field.hpp"
#include "free_field_test_setup.hpp"

namespace maris::seismic {
namespace {

using testing::kDeg, testing::kSeabed, testing::kWater, testing::kNoWater, testing::omegaOf;

// Aki & Richards (2002) eq 5.32, free-surface reflection of an incident P wave: displacement ratios.
struct FreeSurfaceCoefficients {
  double pp, ps;
};
FreeSurfaceCoefficients akiRichardsFreeSurface(double alpha, double beta, double incidence) {
  const double p = std::sin(incidence) / alpha;
  const double ci = std::cos(incidence), cj = std::sqrt(1.0 - beta * beta * p * p);
  const double a = 1.0 / (beta * beta) - 2.0 * p * p;
  const double b = 4.0 * p * p * (ci / alpha) * (cj / beta);
  return {(-a * a + b) / (a * a + b), 4.0 * (alpha / beta) * p * (ci / alpha) * a / (a * a + b)};
}

TEST(FreeField, NoWaterSurfaceAmplitudesMatchReferenceTable) {
  // §5.3 table (6 digits, so 1e-6 absolute covers its rounding).
  const double angles[] = {0, 15, 30, 45, 60, 75};
  const double ux[] = {0, 0.408444, 0.753656, 0.968349, 0.973440, 0.671979};
  const double uy[] = {2, 1.940779, 1.769153, 1.499140, 1.138311, 0.661329};
  const double rpp[] = {1, 0.966172, 0.879415, 0.780888, 0.730232, 0.792294};
  const double rps[] = {0, 0.401848, 0.707661, 0.848042, 0.788645, 0.511036};
  for (int i = 0; i < 6; ++i) {
    const FreeField ff(kSeabed, kNoWater, WaveType::P, angles[i] * kDeg);
    const auto a = ff.solve(omegaOf(1.0));
    const auto s = ff.solidAt(a, omegaOf(1.0), 0.0, 0.0);
    EXPECT_NEAR(std::abs(s.ux), ux[i], 1e-6) << angles[i];
    EXPECT_NEAR(std::abs(s.uy), uy[i], 1e-6) << angles[i];
    EXPECT_NEAR(std::abs(a.reflected_p / a.incident), rpp[i], 1e-6) << angles[i];
    // Displacement ratio of the reflected SV: |b|/vs over |a|/vp.
    EXPECT_NEAR(std::abs(a.reflected_s / kSeabed.vs) / std::abs(a.incident / kSeabed.vp), rps[i], 1e-6) << angles[i];
  }
}

TEST(FreeField, NoWaterReflectionMatchesAkiRichards) {
  // Same closed form in double precision: agreement to round-off (1e-12).
  for (double deg : {5.0, 20.0, 37.0, 52.0, 88.0}) {
    const FreeField ff(kSeabed, kNoWater, WaveType::P, deg * kDeg);
    const auto a = ff.solve(omegaOf(3.0));
    const auto ref = akiRichardsFreeSurface(kSeabed.vp, kSeabed.vs, deg * kDeg);
    EXPECT_NEAR(std::abs(a.reflected_p / a.incident), std::abs(ref.pp), 1e-12) << deg;
    EXPECT_NEAR(std::abs(a.reflected_s / kSeabed.vs) / std::abs(a.incident / kSeabed.vp), std::abs(ref.ps), 1e-12)
        << deg;
  }
}

TEST(FreeField, NoWaterSvSurfaceAmplitudesMatchReferenceTable) {
  const double angles[] = {0, 5, 10, 15, 20, 23};
  const double ux[] = {2, 1.998772, 1.999119, 2.018293, 2.123365, 2.409898};
  const double uy[] = {0, 0.138113, 0.266237, 0.367918, 0.393277, 0.232094};
  for (int i = 0; i < 6; ++i) {
    const FreeField ff(kSeabed, kNoWater, WaveType::SV, angles[i] * kDeg);
    const auto s = ff.solidAt(ff.solve(omegaOf(2.0)), omegaOf(2.0), 0.0, 0.0);
    EXPECT_NEAR(std::abs(s.ux), ux[i], 1e-6) << angles[i];
    EXPECT_NEAR(std::abs(s.uy), uy[i], 1e-6) << angles[i];
  }
}

TEST(FreeField, EnergyIsConservedWithWater) {
  // The water layer over a pressure-release surface carries no net flux: the reflected P and SV
  // energy flux equals the incident one; only round-off (1e-12) remains.
  const double freqs[] = {0.1, 0.5, 1, 2, 5, 10, 20};
  for (double f : freqs) {
    for (double deg = 0; deg <= 75; deg += 15) {
      const FreeField ff(kSeabed, kWater, WaveType::P, deg * kDeg);
      EXPECT_LT(std::abs(ff.energyResidual(ff.solve(omegaOf(f)))), 1e-12) << "P " << deg << " f " << f;
    }
    for (double deg = 0; deg <= 20; deg += 5) {
      const FreeField ff(kSeabed, kWater, WaveType::SV, deg * kDeg);
      EXPECT_LT(std::abs(ff.energyResidual(ff.solve(omegaOf(f)))), 1e-12) << "SV " << deg << " f " << f;
    }
  }
}

TEST(FreeField, VanishingWaterLayerEqualsNoWater) {
  // h = 1e-6 m: the layer's impedance ρ_f ω tan(ωh/c)/η → 0; difference O(ωh/c) ≈ 1e-8, checked at 1e-6.
  const WaterLayer thin{1025.0, 1450.0, 1e-6};
  for (auto [type, deg] : {std::pair{WaveType::P, 30.0}, std::pair{WaveType::SV, 15.0}, std::pair{WaveType::P, 70.0}}) {
    for (double f : {0.5, 3.0, 15.0}) {
      const FreeField wet(kSeabed, thin, type, deg * kDeg), dry(kSeabed, kNoWater, type, deg * kDeg);
      const auto sw = wet.solidAt(wet.solve(omegaOf(f)), omegaOf(f), 0.0, 0.0);
      const auto sd = dry.solidAt(dry.solve(omegaOf(f)), omegaOf(f), 0.0, 0.0);
      EXPECT_LT(std::abs(sw.ux - sd.ux), 1e-6);
      EXPECT_LT(std::abs(sw.uy - sd.uy), 1e-6);
    }
  }
}

TEST(FreeField, VerticalPMatchesWaterColumnImpedanceClosedForm) {
  // 1D impedance solution (§5.3): |u_B| = 2Zs/√(Zs² + Zf² tan²kh), |u_A| = 2Zs/√(Zs² cos²kh + Zf² sin²kh).
  const double zs = kSeabed.density * kSeabed.vp, zf = kWater.density * kWater.sound_speed;
  const FreeField ff(kSeabed, kWater, WaveType::P, 0.0);
  for (double f : {0.3, 0.5, 1.0, 1.208333, 2.7, 9.1}) {
    const double kh = 2.0 * std::numbers::pi * f * kWater.depth / kWater.sound_speed;
    const auto a = ff.solve(omegaOf(f));
    const double ub = std::abs(ff.solidAt(a, omegaOf(f), 0.0, 0.0).uy);
    const double ua = std::abs(ff.waterAt(a, omegaOf(f), 0.0, kWater.depth).uy);
    EXPECT_NEAR(ub, 2.0 * zs / std::hypot(zs, zf * std::tan(kh)), 1e-9 * ub) << f;
    EXPECT_NEAR(ua, 2.0 * zs / std::hypot(zs * std::cos(kh), zf * std::sin(kh)), 1e-9 * ua) << f;
  }
  // At the quarter-wave resonance c_f/(4h) = 0.604167 Hz the seabed stands still and the surface
  // reaches 2Zs/Zf = 16.349874 (§5.3, 8 digits; 1e-5 covers the rounding).
  const double f1 = kWater.sound_speed / (4.0 * kWater.depth);
  const auto a = ff.solve(omegaOf(f1));
  EXPECT_LT(std::abs(ff.solidAt(a, omegaOf(f1), 0.0, 0.0).uy), 1e-5);
  EXPECT_NEAR(std::abs(ff.waterAt(a, omegaOf(f1), 0.0, kWater.depth).uy), 16.349874, 1e-5);
}

TEST(FreeField, VerticalSvLeavesTheWaterAtRest) {
  // Vertical SV has no normal motion at the seabed, so the inviscid water is not driven: p ≡ 0 and the
  // seabed moves as a free surface, |u_x| = 2 (round-off 1e-12).
  const FreeField ff(kSeabed, kWater, WaveType::SV, 0.0);
  for (double f : {0.2, 1.0, 7.0}) {
    const auto a = ff.solve(omegaOf(f));
    const auto b = ff.solidAt(a, omegaOf(f), 0.0, 0.0);
    EXPECT_NEAR(std::abs(b.ux), 2.0, 1e-12);
    const double p_scale = kWater.density * kWater.sound_speed * 2.0 * std::numbers::pi * f;  // ρc·ω per unit u
    EXPECT_LT(std::abs(ff.waterAt(a, omegaOf(f), 0.0, 0.5 * kWater.depth).pressure), 1e-12 * p_scale);
  }
}

TEST(FreeField, WaterSurfaceHasNoHorizontalMotion) {
  // p = 0 at y = h makes the horizontal gradient of φ vanish there: u_x = 0 (round-off).
  for (auto [type, deg] : {std::pair{WaveType::P, 45.0}, std::pair{WaveType::SV, 20.0}, std::pair{WaveType::P, 75.0}}) {
    const FreeField ff(kSeabed, kWater, type, deg * kDeg);
    const auto a = ff.solve(omegaOf(1.3));
    EXPECT_LT(std::abs(ff.waterAt(a, omegaOf(1.3), 0.0, kWater.depth).ux), 1e-12);
  }
}

TEST(FreeField, ObliqueSvWithWaterMatchesReferenceValues) {
  // §5.3, f = 1 Hz, 5 digits: B (|u_x|, |u_y|) and A |u_y| for SV 10° and 20°.
  struct Row {
    double deg, bx, by, ay;
  };
  for (const Row r : {Row{10, 1.99895, 0.26546, 0.31475}, Row{20, 2.12215, 0.39224, 0.48985}}) {
    const FreeField ff(kSeabed, kWater, WaveType::SV, r.deg * kDeg);
    const auto a = ff.solve(omegaOf(1.0));
    const auto b = ff.solidAt(a, omegaOf(1.0), 0.0, 0.0);
    EXPECT_NEAR(std::abs(b.ux), r.bx, 1e-5);
    EXPECT_NEAR(std::abs(b.uy), r.by, 1e-5);
    EXPECT_NEAR(std::abs(ff.waterAt(a, omegaOf(1.0), 0.0, kWater.depth).uy), r.ay, 1e-5);
  }
}

TEST(FreeField, SvCriticalAngleIsReported) {
  // asin(1800/4500) = 23.5782° (§3.2); beyond it the field is computed (test_free_field_evanescent.cpp).
  EXPECT_NEAR(FreeField::criticalAngleSv(kSeabed) / kDeg, 23.5782, 1e-4);
  EXPECT_FALSE(FreeField(kSeabed, kWater, WaveType::SV, 23.5 * kDeg).reflectedPEvanescent());
  EXPECT_TRUE(FreeField(kSeabed, kWater, WaveType::SV, 23.6 * kDeg).reflectedPEvanescent());
  EXPECT_THROW(FreeField(kSeabed, kWater, WaveType::SV, 90.0 * kDeg), InputError);
}

TEST(FreeField, ObliquePWaterResonanceStopsTheSeabedVertically) {
  // The water layer's reactive impedance on the seabed, ρ_f ω tan(ωhη_f)/η_f, is infinite at
  // ωhη_f = π/2, i.e. f₁ = c_f/(4h cosθ_f) with sinθ_f = c_f sinθ/v_p: there the seabed cannot move
  // vertically (round-off, 1e-9), while just off resonance it does (> 0.05).
  for (double deg : {30.0, 45.0, 70.0}) {
    const FreeField ff(kSeabed, kWater, WaveType::P, deg * kDeg);
    const double sin_f = kWater.sound_speed * std::sin(deg * kDeg) / kSeabed.vp;
    const double f1 = kWater.sound_speed / (4.0 * kWater.depth * std::sqrt(1.0 - sin_f * sin_f));
    EXPECT_LT(std::abs(ff.solidAt(ff.solve(omegaOf(f1)), omegaOf(f1), 0.0, 0.0).uy), 1e-9) << deg;
    EXPECT_GT(std::abs(ff.solidAt(ff.solve(omegaOf(0.9 * f1)), omegaOf(0.9 * f1), 0.0, 0.0).uy), 0.05) << deg;
  }
}

}  // namespace
}  // namespace maris::seismic
