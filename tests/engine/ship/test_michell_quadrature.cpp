// Quadrature building blocks of Michell's integral: exactness on polynomials at tiny and huge frequencies
// and the Wigley Kochin function against independent reference values.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "ship/hull_form.hpp"
#include "ship/michell_quadrature.hpp"
#include "ship/michell_resistance.hpp"

using namespace maris::ship;

TEST(MichellQuadrature, FilonIsExactForQuadraticsAtAnyFrequency) {
  // Reference: ∫_0^1 x² e^{iωx} dx = e^{iω}(1/(iω) + 2/ω² − 2/(iω³)) + 2/(iω³)  (two integrations by parts).
  for (double w : {1e-4, 0.05, 1.0, 100.0, 1e4}) {
    const std::complex<double> i(0, 1);
    const std::complex<double> exact =
        std::abs(w) < 1e-3 ? std::complex<double>(1.0 / 3.0 - w * w / 10.0, w / 4.0 - w * w * w / 36.0)
                           : std::exp(i * w) * (1.0 / (i * w) + 2.0 / (w * w) - 2.0 / (i * w * w * w)) + 2.0 / (i * w * w * w);
    for (int n : {3, 5, 41}) {
      Eigen::VectorXd f(n);
      const double h = 1.0 / (n - 1);
      for (int k = 0; k < n; ++k) f[k] = (k * h) * (k * h);
      const auto got = filonIntegral(f, 0.0, h, w);
      // Round-off only: Filon–Simpson interpolates x² exactly; the scale is max(|exact|, 1e-3).
      const double scale = std::max(std::abs(exact), 1e-3);
      EXPECT_NEAR(got.real(), exact.real(), 1e-10 * scale) << "omega " << w << " n " << n;
      EXPECT_NEAR(got.imag(), exact.imag(), 1e-10 * scale) << "omega " << w << " n " << n;
    }
  }
}

TEST(MichellQuadrature, FilonSeriesJoinsClosedFormAtSwitch) {
  // The coefficients are continuous across the θ = 0.2 switch (series vs closed form): the series is exact
  // to 1e-16 there, the closed forms lose ε·(1/θ³)·θ ≈ 1e-13 to cancellation, so 5e-13 is round-off.
  const auto a = filonCoefficients(0.2 - 1e-12), b = filonCoefficients(0.2 + 1e-12);
  EXPECT_NEAR(a.alpha, b.alpha, 5e-13);
  EXPECT_NEAR(a.beta, b.beta, 5e-13);
  EXPECT_NEAR(a.gamma, b.gamma, 5e-13);
}

TEST(MichellQuadrature, ExpTrapezoidIsExactForLinearProfiles) {
  // ∫_{−T}^0 (1 + z/T) e^{bz} dz = 1/b − (1 − e^{−bT})/(b² T) = T Σ_n (−bT)^n/(n+2)! (series for bT < 0.1).
  const double T = 2.0;
  for (double bT : {1e-8, 1e-3, 1.0, 50.0, 1e4}) {
    const double b = bT / T;
    double exact = 0;
    if (bT < 0.1) {
      double term = 0.5;  // (−bT)^n/(n+2)!
      for (int k = 0; k < 12; ++k) {
        exact += T * term;
        term *= -bT / (k + 3);
      }
    } else {
      exact = 1.0 / b - (1.0 - std::exp(-bT)) / (b * b * T);
    }
    for (int n : {3, 11}) {
      Eigen::VectorXd w(n);
      const double dz = T / (n - 1);
      expTrapezoidWeights(b, dz, w);
      double sum = 0;
      for (int j = 0; j < n; ++j) sum += w[j] * (1.0 - j * dz / T);
      EXPECT_NEAR(sum, exact, 1e-12 * exact) << "bT " << bT << " n " << n;
    }
  }
}

TEST(MichellQuadrature, ExpTrapezoidConvergesAtSecondOrderForQuadratics) {
  // ∫_{−T}^0 (1 − z²/T²) e^{bz} dz (closed form: wigleyDepthFactor, checked against its series below).
  const double T = 1.0, b = 3.0;
  const double exact = 1.0 / b - 2.0 / (b * b * b * T * T) + std::exp(-b * T) * (2.0 / (b * b * T) + 2.0 / (b * b * b * T * T));
  EXPECT_NEAR(wigleyDepthFactor(T, b), exact, 1e-14);
  double previous = 0;
  for (int n : {11, 21, 41}) {
    Eigen::VectorXd w(n);
    const double dz = T / (n - 1);
    expTrapezoidWeights(b, dz, w);
    double sum = 0;
    for (int j = 0; j < n; ++j) sum += w[j] * (1.0 - (j * dz) * (j * dz));
    const double error = std::abs(sum - exact);
    if (previous > 0) {
      // Halving dz divides the error by 4 (second order), within 10 %.
      EXPECT_NEAR(previous / error, 4.0, 0.4) << "n " << n;
    }
    previous = error;
  }
}

TEST(MichellQuadrature, WigleyKochinMatchesIndependentReferenceValues) {
  // |P+iQ|² for L = 1, B = 0.1, T = 0.0625, computed by an independent long-double implementation of the theory (outside this repository)
  // and checked there by brute-force 2-D Gauss–Legendre to 13 digits. k0 = 1/Fn² for L = 1. Analytic path: 1e-10; offsets path on 251×51... here 257×51: 2e-3.
  struct Row {
    double fn, lambda, value;
  };
  const Row rows[] = {{0.20, 1.0, 1.588466334738e-07}, {0.35, 1.0, 4.433355134357e-07}, {0.35, 1.3, 6.906600745412e-07},
                      {0.35, 3.0, 3.891769772407e-08}, {1.0, 3.0, 7.281103590811e-06}, {1.0, 10.0, 3.260839240643e-08}};
  GridKochin grid(sampleHull(makeParametricHull(1.0, 0.1, 0.0625), 257, 51), false);
  for (const auto& r : rows) {
    const double k0 = 1.0 / (r.fn * r.fn);
    EXPECT_NEAR(wigleyKochinSquared(1.0, 0.1, 0.0625, k0, r.lambda), r.value, 1e-10 * r.value) << r.fn << " " << r.lambda;
    double fine = 0, coarse = 0;
    grid.evaluate(k0, r.lambda, fine, coarse);
    EXPECT_NEAR(fine, r.value, 2e-3 * r.value) << r.fn << " " << r.lambda;
  }
}
