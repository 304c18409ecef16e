// Frequency-domain model: power bounds, passive optimum, mirror symmetry, long-wave limit, natural frequency.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wec/wec_frequency.hpp"
#include "wec_test_models.hpp"

using namespace maris::wec;

// Capture width ≤ 3λ/(2π) (surge–heave point absorber, Newman 1976) and P̄ ≤ |X_θ|²/(8B_θ) (optimal reactive
// control) for every ω and several PTO dampings. Holds exactly because X comes from Haskind.
TEST(WecFrequency, CaptureWidthNeverExceedsPointAbsorberBound) {
  const WecModel m = wec_test::model(wec_test::defaults());
  for (double b : {1e5, 1e6, 3.52e6, 1e7, 1e8})
    for (double w = 0.1; w <= 5.0; w += 0.01) {
      const FrequencyResponse r = solveFrequency(m, m.floats[0], w, b);
      EXPECT_LE(r.capture_width, r.capture_width_bound * (1.0 + 1e-12)) << "omega " << w << " B " << b;
      EXPECT_LE(r.power, r.power_bound * (1.0 + 1e-12)) << "omega " << w << " B " << b;
    }
}

// B_opt = √(B_θ² + (ωJ − K_θ/ω)²) maximises ½Bω²|Θ|²: a golden-section search on log B agrees to 1e-6.
TEST(WecFrequency, OptimalPtoDampingMaximisesMeanPower) {
  const WecModel m = wec_test::model(wec_test::defaults());
  for (double w : {0.5, 1.0, 1.5, 2.5}) {
    const double b_opt = solveFrequency(m, m.floats[0], w).optimal_damping;
    auto power = [&](double log_b) { return solveFrequency(m, m.floats[0], w, std::exp(log_b)).power; };
    double lo = std::log(b_opt) - 3.0, hi = std::log(b_opt) + 3.0;
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-9; ++i) {
      const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
      (power(a) > power(b) ? hi : lo) = power(a) > power(b) ? b : a;
    }
    EXPECT_NEAR(std::exp(0.5 * (lo + hi)) / b_opt, 1.0, 1e-6) << "omega " << w;
  }
}

// Mirroring the geometry (x → −x, θ0 → π − θ0) together with the wave direction leaves |Θ| and |F_h| unchanged
//, to round-off.
TEST(WecFrequency, MirroredLayoutGivesIdenticalResponse) {
  auto p = wec_test::defaults();
  p.floats[0].hinge_x = 7.0;
  const WecModel a = wec_test::model(p);
  p.floats[0].hinge_x = -7.0;
  p.floats[0].arm_angle_deg = -180.0 - p.floats[0].arm_angle_deg;
  p.wave_direction = "-x";
  const WecModel b = wec_test::model(p);
  for (double w = 0.3; w <= 3.0; w += 0.1) {
    const FrequencyResponse ra = solveFrequency(a, a.floats[0], w), rb = solveFrequency(b, b.floats[0], w);
    EXPECT_NEAR(std::abs(rb.pitch) / std::abs(ra.pitch), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(rb.hinge_fx) / std::abs(ra.hinge_fx), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(rb.hinge_fz) / std::abs(ra.hinge_fz), 1.0, 1e-9);
    EXPECT_NEAR(rb.power / ra.power, 1.0, 1e-9);
  }
}

// Long waves tilt the arm quasi-statically: the float follows the surface, |Θ|/a → 1/r_x0 (heave excitation
// → ρgA_w, here through Haskind and the interpolated λ33 slope at ka → 0: 1 % tolerance).
TEST(WecFrequency, LongWaveRaoTendsToStaticTilt) {
  const WecModel m = wec_test::model(wec_test::defaults());
  const auto& f = m.floats[0];
  const double rx = f.arm_length * std::cos(f.theta0);
  EXPECT_NEAR(std::abs(solveFrequency(m, f, 0.05).pitch) * rx, 1.0, 0.01);
}

// The natural frequency is the root of K_θ = ω²J(ω) and the response peaks near it when the PTO is off.
TEST(WecFrequency, NaturalFrequencyIsTheUndampedRoot) {
  auto p = wec_test::defaults();
  p.floats[0].pto_damping = 0.0;
  const WecModel m = wec_test::model(p);
  const double wn = naturalFrequency(m, m.floats[0]);
  const FrequencyResponse r = solveFrequency(m, m.floats[0], wn);
  EXPECT_NEAR(r.stiffness, wn * wn * r.inertia, 1e-9 * r.stiffness);
  double best = 0.0, w_best = 0.0;
  for (double w = 0.5; w <= 3.0; w += 0.001) {
    const double a = std::abs(solveFrequency(m, m.floats[0], w).pitch);
    if (a > best) best = a, w_best = w;
  }
  // Radiation damping (ζ ≈ 0.07) and the frequency dependence of X shift the peak by a few per cent at most.
  EXPECT_NEAR(w_best / wn, 1.0, 0.05);
}
