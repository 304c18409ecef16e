// Incident time functions: the B-spline pulse, the Ricker wavelet, recorded accelerograms.
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "core/spectrum.hpp"
#include "core/errors.hpp"
#include "seismic/seismic_inputs.hpp"

namespace maris::seismic {
namespace {

TEST(SeismicInputs, BsplinePulseHasUnitPeakAndCompactSupport) {
  // 16[τ³ − 4(τ−¼)³ + …] peaks at τ = ½ with value 1, vanishes outside [0, T] (exact cubic algebra).
  EXPECT_NEAR(bsplinePulse(0.1, 0.2), 1.0, 1e-14);
  EXPECT_EQ(bsplinePulse(-0.01, 0.2), 0.0);
  EXPECT_NEAR(bsplinePulse(0.25, 0.2), 0.0, 1e-12);
  // Symmetric about T/2.
  EXPECT_NEAR(bsplinePulse(0.03, 0.2), bsplinePulse(0.17, 0.2), 1e-14);
}

TEST(SeismicInputs, BsplinePulseSpectrumHasItsFirstZeroAtFourOverT) {
  // |U(f)|/|U(0)| = [sin(πfT/4)/(πfT/4)]⁴ (Fourier transform of the cubic B-spline): 0.657 at 5 Hz, 0 at 20 Hz for T = 0.2 s.
  // Rectangle-rule quadrature at 0.1 ms: error ~1e-6.
  const double T = 0.2, dt = 1e-4;
  auto amplitude = [&](double f) {
    std::complex<double> s = 0.0;
    for (int k = 0; k * dt <= T; ++k) s += bsplinePulse(k * dt, T) * std::polar(1.0, 2 * std::numbers::pi * f * k * dt);
    return std::abs(s) * dt;
  };
  const double u0 = amplitude(0.0);
  const double x = std::numbers::pi * 5.0 * T / 4.0;
  EXPECT_NEAR(amplitude(5.0) / u0, std::pow(std::sin(x) / x, 4), 1e-5);
  EXPECT_NEAR(amplitude(20.0) / u0, 0.0, 1e-5);
}

TEST(SeismicInputs, RickerPeaksAtItsCentre) {
  EXPECT_DOUBLE_EQ(rickerWavelet(1.0, 2.0, 1.0), 1.0);
  // Zero crossings at τ = ±1/(√2·π·f).
  EXPECT_NEAR(rickerWavelet(1.0 + 1.0 / (std::sqrt(2.0) * std::numbers::pi * 2.0), 2.0, 1.0), 0.0, 1e-14);
}

TEST(SeismicInputs, AccelerogramIsBaselineCorrectedAndScaled) {
  // A 1.5 Hz burst with a constant 0.02 m/s² offset (a typical baseline error): raw, it would end with
  // 0.2 m/s of velocity and drift; corrected, the record ends nearly at rest and peaks exactly at the target.
  const auto file = std::filesystem::temp_directory_path() / "maris_seismic_record.csv";
  {
    std::ofstream out(file);
    out << "time_s,acc_m_s2\n# synthetic record\n";
    for (int k = 0; k <= 1000; ++k) {
      const double t = 0.01 * k;
      const double burst = t > 2.0 && t < 6.0 ? std::sin(2 * std::numbers::pi * 1.5 * t) * std::sin(std::numbers::pi * (t - 2.0) / 4.0) : 0.0;
      out << t << "," << burst + 0.02 << "\n";
    }
  }
  const Accelerogram rec = loadAccelerogram(file.string(), 0.005, 3.0, "input.accelerogram_file");
  std::filesystem::remove(file);
  EXPECT_NEAR(rec.final_velocity_before, 0.2, 0.01);
  double peak = 0.0, v_peak = 0.0;
  for (double a : rec.acceleration) peak = std::max(peak, std::abs(a));
  for (double v : rec.velocity) v_peak = std::max(v_peak, std::abs(v));
  EXPECT_NEAR(peak, 3.0, 1e-12);
  // The quadratic-cubic displacement baseline leaves a small residual end velocity (< 5 % of the peak).
  EXPECT_LT(std::abs(rec.velocity.back()), 0.05 * v_peak);
}

TEST(SeismicInputs, UnreadableAccelerogramNamesTheField) {
  try {
    loadAccelerogram("/nonexistent/record.csv", 0.01, 1.0, "input.accelerogram_file");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.errors().at(0).path, "input.accelerogram_file");
  }
}

TEST(SeismicInputs, BuiltinSyntheticRecordLoadsWithItsDesignedContent) {
  // resources/data/seismic/synthetic_kanai_tajimi.csv: 25 s at 0.01 s, Kanai–Tajimi filter at 2.5 Hz
  // with ζ 0.6 (its generator's parameters). After correction: the target peak exactly, and the
  // acceleration's Fourier amplitude, smoothed over ±0.5 Hz, largest within 1–5 Hz (the broad filter
  // peak; below it the baseline correction removes content, above it the filter rolls off as f⁻²).
  const Accelerogram rec = loadAccelerogram("builtin:synthetic_kanai_tajimi.csv", 0.01, 2.0, "input.accelerogram_file");
  ASSERT_EQ(rec.acceleration.size(), 2501u);
  double peak = 0.0;
  for (double a : rec.acceleration) peak = std::max(peak, std::abs(a));
  EXPECT_NEAR(peak, 2.0, 1e-12);
  const std::size_t n = 4096;
  std::vector<std::complex<double>> z(n, 0.0);
  for (std::size_t k = 0; k < rec.acceleration.size(); ++k) z[k] = rec.acceleration[k];
  z = fft(std::move(z));
  const double df = 1.0 / (n * 0.01);
  const int half_window = static_cast<int>(0.5 / df);
  double best = 0.0, f_best = 0.0;
  for (int k = half_window; k < static_cast<int>(15.0 / df); ++k) {
    double sum = 0.0;
    for (int j = k - half_window; j <= k + half_window; ++j) sum += std::abs(z[j]);
    if (sum > best) best = sum, f_best = k * df;
  }
  EXPECT_GT(f_best, 1.0);
  EXPECT_LT(f_best, 5.0);
  try {
    loadAccelerogram("builtin:no_such_record.csv", 0.01, 1.0, "input.accelerogram_file");
    FAIL() << "an unknown built-in record was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.errors().at(0).path, "input.accelerogram_file");
  }
}

}  // namespace
}  // namespace maris::seismic
