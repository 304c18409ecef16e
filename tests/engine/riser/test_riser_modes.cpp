// Natural frequencies of the linearised chain against closed forms (brief §5.2, §5.3, §5.5).
#include <gtest/gtest.h>

#include <cmath>

#include "riser/riser_modes.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using test::kPi;

// Distinct frequencies: in 3D every planar bending mode appears twice (two transverse planes).
std::vector<double> distinctFrequencies(const RiserParameters& p, int count) {
  const RiserModel m = buildRiserModel(p);
  RunContext context;
  const StaticSolution s = solveStatics(m, context);
  const RiserModes modes = computeModes(m, s, 4 * count);
  std::vector<double> out;
  for (double w : modes.frequencies)
    if (out.empty() || w > out.back() * (1 + 1e-6)) out.push_back(w);
  out.resize(std::min<std::size_t>(out.size(), count));
  return out;
}

// Pinned-pinned tensioned beam, eq (66): ω_k = (kπ/L)√(T/m* + (kπ/L)² EI/m*). L = 10 m, m* = 1 kg/m,
// EI = 1000 N·m², T = 100 N: 4.42838, 13.97616, 29.62837 rad/s. The SM errors are O(1/n²):
// +0.21 %, +0.33 %, +0.32 % at n = 10 (brief §5.3); tolerance 0.5 % at n = 10, and halving Δ
// must reduce each error about 4x (3 to 5).
TEST(RiserModes, TensionedPinnedBeamMatchesEquation66) {
  const double exact[3] = {4.42838, 13.97616, 29.62837};
  double previous[3] = {0, 0, 0};
  for (int n : {10, 20}) {
    RiserParameters p = test::calmInAir();
    p.length = 10.0;
    p.segment_count = n;
    p.outer_diameter = 0.1;
    p.inner_diameter = 0.0;
    p.added_mass_coefficient = 0.0;
    p.density = 1.0 / (kPi / 4 * 0.01);                   // m* = 1 kg/m
    p.youngs_modulus = 1000.0 / (kPi / 64 * 1e-4);        // EI = 1000 N·m²
    p.torsion = false;
    p.gravity = 0.0;
    p.top_condition = "tensioner";
    p.top_tension = 100.0;
    p.top_z = 0.0;
    p.bottom_condition = "pinned";
    p.bottom_z = -10.0;
    const std::vector<double> w = distinctFrequencies(p, 3);
    ASSERT_EQ(w.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const double error = (w[k] - exact[k]) / exact[k];
      EXPECT_LT(std::abs(error), n == 10 ? 5e-3 : 1.5e-3) << "mode " << k + 1 << " n = " << n;
      if (previous[k] != 0) {
        EXPECT_NEAR(previous[k] / error, 4.0, 1.0) << "mode " << k + 1;
      }
      previous[k] = error;
    }
  }
}

// Hanging chain (top pinned, bottom free, EI ≈ 0): ω_k = (j_0,k / 2)√(g/L), j_0,k = 2.404826,
// 5.520078, 8.653728. SM errors at n = 20: +0.007 %, +0.25 %, +1.03 % (brief §5.2): tolerance 1.5 %.
TEST(RiserModes, HangingChainMatchesBesselZeros) {
  RiserParameters p = test::calmInAir();
  p.length = 10.0;
  p.segment_count = 20;
  p.outer_diameter = 0.05;
  p.inner_diameter = 0.0;
  p.youngs_modulus = 1e-3;
  p.torsion = false;
  p.added_mass_coefficient = 0.0;  // added mass is applied along the whole length, even above water
  const std::vector<double> w = distinctFrequencies(p, 3);
  const double zeros[3] = {2.404826, 5.520078, 8.653728};
  ASSERT_EQ(w.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const double exact = zeros[k] / 2 * std::sqrt(p.gravity / p.length);
    EXPECT_NEAR(w[k], exact, (k == 0 ? 5e-4 : 1.5e-2) * exact) << "mode " << k + 1;
  }
}

// Cantilever: ω_k = (β_k L)² √(EI/(μ L⁴)), β_k L = 1.875104, 4.694091, 7.854757. SM errors at n = 20:
// +0.057 %, +0.20 %, +0.33 % (brief §5.5): tolerance 0.5 % (rotary inertia adds < 0.01 %).
TEST(RiserModes, CantileverMatchesEulerBernoulli) {
  RiserParameters p = test::tipLoadedCantilever(20, 0.0);
  p.point_loads.clear();
  p.added_mass_coefficient = 0.0;
  p.internal_fluid_density = 0.0;
  const std::vector<double> w = distinctFrequencies(p, 3);
  const double beta[3] = {1.875104, 4.694091, 7.854757};
  const double area = kPi / 4 * (0.01 - 0.0064);
  const double mu = p.density * area, ei = test::bendingStiffness(p);
  ASSERT_EQ(w.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const double exact = beta[k] * beta[k] * std::sqrt(ei / (mu * std::pow(10.0, 4)));
    EXPECT_NEAR(w[k], exact, 5e-3 * exact) << "mode " << k + 1;
  }
}

}  // namespace
}  // namespace maris::riser
