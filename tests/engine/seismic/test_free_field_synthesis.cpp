// Time-domain free field by complex-frequency Fourier synthesis (free_field_synthesis.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "seismic/free_field_synthesis.hpp"
#include "seismic/seismic_inputs.hpp"
#include "free_field_test_setup.hpp"

namespace maris::seismic {
namespace {

using testing::kSeabed, testing::kWater;
constexpr double kDt = 0.001;        // [s]
constexpr double kPulseStart = 1.0;  // [s] the incident pulse leaves zero at the origin here
constexpr double kPulseLength = 0.2; // [s] the paper's pulse

std::vector<double> pulseSamples(int n) {
  std::vector<double> u(n);
  for (int k = 0; k < n; ++k) u[k] = bsplinePulse(k * kDt - kPulseStart, kPulseLength);
  return u;
}

double peakAbs(const std::vector<double>& v, int from, int to) {
  double m = 0.0;
  for (int k = std::max(from, 0); k < std::min<int>(to, v.size()); ++k) m = std::max(m, std::abs(v[k]));
  return m;
}

TEST(FreeFieldSynthesis, HalfSpaceSurfaceMotionIsTwiceTheIncident) {
  // No water, vertical P: u_y(surface) = 2·u0(t) exactly; the synthesis errors are the pulse's
  // aliasing above 500 Hz and the 1e-6 wrap-around, both far below 1e-5 of the peak.
  const FreeField ff(kSeabed, WaterLayer{1025.0, 1450.0, 0.0}, WaveType::P, 0.0);
  const auto u0 = pulseSamples(3000);
  const FreeFieldSynthesis syn(ff, u0, 0.0, kDt);
  const auto h = syn.solid(0.0);
  for (int k = 0; k < 3000; ++k) ASSERT_NEAR(h.uy[k], 2.0 * u0[k], 1e-5) << "t = " << k * kDt;
}

TEST(FreeFieldSynthesis, NothingMovesBeforeTheFirstArrival) {
  // Causality of the time convention: with a conjugated transfer function the lossless water layer's
  // reverberation would leak before the pulse. At depth 600 m the wave arrives 600/4500 s early,
  // at the water surface 600/1450 s late. Tolerance 1e-5 of the peak (wrap-around damping is 1e-6).
  const FreeField ff(kSeabed, kWater, WaveType::P, 0.0);
  const FreeFieldSynthesis syn(ff, pulseSamples(8000), 0.0, kDt);
  const auto bottom = syn.solid(-600.0);
  const auto seabed = syn.solid(0.0);
  const auto surface = syn.water(kWater.depth);
  const int k_bottom = static_cast<int>((kPulseStart - 600.0 / 4500.0) / kDt) - 2;
  const int k_seabed = static_cast<int>(kPulseStart / kDt) - 2;
  const int k_surface = static_cast<int>((kPulseStart + 600.0 / 1450.0) / kDt) - 2;
  const double peak = peakAbs(surface.uy, 0, 8000);
  EXPECT_GT(peak, 1.0);
  EXPECT_LT(peakAbs(bottom.uy, 0, k_bottom), 1e-5 * peak);
  EXPECT_LT(peakAbs(seabed.uy, 0, k_seabed), 1e-5 * peak);
  EXPECT_LT(peakAbs(surface.uy, 0, k_surface), 1e-5 * peak);
}

TEST(FreeFieldSynthesis, SeabedFirstArrivalIsOnePlusReflectionCoefficient) {
  // Before the first echo returns from the water surface (2h/c_f = 0.83 s) the seabed moves as
  // (1 + R)·u0 with R = (Zs − Zf)/(Zs + Zf): peak 1.78201 (§5.3). Tolerance 1e-4: sampling of the
  // pulse's C² kinks at 1 ms.
  const FreeField ff(kSeabed, kWater, WaveType::P, 0.0);
  const FreeFieldSynthesis syn(ff, pulseSamples(8000), 0.0, kDt);
  const auto seabed = syn.solid(0.0);
  const int k0 = static_cast<int>(kPulseStart / kDt), k1 = k0 + static_cast<int>(0.8 / kDt);
  EXPECT_NEAR(peakAbs(seabed.uy, k0, k1), 1.78201, 1e-4);
}

TEST(FreeFieldSynthesis, VelocityIsTheDerivativeOfDisplacement) {
  // Spectral derivative vs a central difference of the displacement history: O(dt²) ≈ 1e-3 of the peak.
  const FreeField ff(kSeabed, kWater, WaveType::P, 30.0 * std::numbers::pi / 180.0);
  const FreeFieldSynthesis syn(ff, pulseSamples(4000), 0.0, kDt);
  const auto h = syn.solid(-100.0);
  const double vpeak = peakAbs(h.vx, 0, 4000);
  for (int k = 1; k < 3999; ++k) ASSERT_NEAR(h.vx[k], (h.ux[k + 1] - h.ux[k - 1]) / (2 * kDt), 1e-3 * vpeak);
}

TEST(FreeFieldSynthesis, DelayedSamplingIsExactForQuadratics) {
  // Catmull–Rom reproduces quadratics exactly between samples (round-off).
  std::vector<double> q(50);
  for (int k = 0; k < 50; ++k) q[k] = 3.0 + 2.0 * k * 0.1 - 0.5 * (k * 0.1) * (k * 0.1);
  for (double t : {1.234, 2.0501, 4.77}) EXPECT_NEAR(sampleDelayed(q, 0.0, 0.1, t), 3.0 + 2.0 * t - 0.5 * t * t, 1e-12);
  EXPECT_EQ(sampleDelayed(q, 0.0, 0.1, -5.0), 0.0);
}

}  // namespace
}  // namespace maris::seismic
