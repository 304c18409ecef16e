// Models shared by the wec tests, built from the scene's own parameter defaults (one source of truth).
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include <unistd.h>

#include "catalog.hpp"
#include "source_tree.hpp"
#include "wec/wec_model.hpp"
#include "wec/wec_parameters.hpp"

namespace wec_test {

inline constexpr double kDeg = std::numbers::pi / 180.0;
inline constexpr double kRho = 1025.0;     // [kg/m³] sea water
inline constexpr double kWamitG = 9.80665; // [m/s²] gravity of the WAMIT run of the sphere
// The WAMIT files of a floating sphere (tests/engine/wec/data).
inline const std::string kSphere = maris::test::sourceDir() + "/tests/engine/wec/data/sphere";

inline const maris::SceneDefinition& scene() { return maris::requireScene("wec"); }

// A scratch folder per test process (CTest runs every test case in a process of its own).
inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("maris_wec_test_" + std::to_string(::getpid())) / name;
  std::filesystem::create_directories(dir);
  return dir;
}

// A number as a field of a hydrodynamic data file: a space, then all 17 significant digits.
inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, " %.17g", v);
  return buf;
}

// The default single float (L = 10 m, θ0 = −30°, a = 3 m, B_PTO = 3.52e6 N·m·s) with radiation kernels of
// 40 s sampled at `dt`.
inline maris::wec::WecModel model(const maris::wec::WecParameters& p, double dt = 0.05) {
  maris::wec::WecModel m = maris::wec::buildWecModel(p);
  maris::wec::buildRadiation(m, p.kernel_duration, dt);
  return m;
}
inline maris::wec::WecParameters defaults() { return maris::wec::WecParameters{}; }
// The default float's model, built once per test program (kernels and fits cost ~0.1 s).
inline const maris::wec::WecModel& defaultModel() {
  static const maris::wec::WecModel m = model(defaults());
  return m;
}

// A sea whose frequencies are all multiples of one Δω, so that it repeats with the period 2π/Δω: over one whole
// period the variance of a linear response is exactly Σ ½|H(ω_j)|² a_j² whatever the phases (the cross terms of
// distinct multiples of Δω integrate to zero), which lets a test hold the time domain to 1 % in a record of a few
// minutes. The scene's seas (ocean::irregularSea) have no common period. `count` components ω_j = (j0 + j) Δω over
// [0.3, 3.5]·ω_p, Δω = 3.2 ω_p / count, a_j = √(2 S(ω_j) Δω); phases those of the scene's sea for p (any would do).
inline maris::wec::IncidentWaves commensurateSea(const maris::wec::WecParameters& p, int count) {
  const double wp = 2.0 * std::numbers::pi / p.peak_period, d_omega = 3.2 * wp / count;
  const double first = std::round(0.3 * wp / d_omega);
  maris::wec::WecParameters same = p;
  same.component_count = count;
  const auto phases = maris::wec::makeIrregularWave(same, 1.0).field.components();
  std::vector<double> omega;
  for (int j = 0; j < count; ++j) omega.push_back((first + j) * d_omega);
  const auto s = maris::wec::spectrumDensity(p.spectrum, p.significant_height, p.peak_period, p.peak_enhancement, omega);
  std::vector<maris::ocean::WaveComponent> components;
  for (std::size_t j = 0; j < omega.size(); ++j)
    components.push_back({omega[j], std::sqrt(2.0 * s[j] * d_omega), phases[j].phase});
  maris::wec::IncidentWaves sea;
  sea.field = maris::ocean::WaveField(std::move(components), 0.0, maris::ocean::kDeepWater, p.gravity,
                                      maris::ocean::Stretching::None);
  sea.ramp_duration = p.ramp_duration;
  return sea;
}

// The repeat period 2π/Δω of a commensurateSea [s].
inline double repeatPeriod(const maris::wec::IncidentWaves& sea) {
  const auto& c = sea.field.components();
  return 2.0 * std::numbers::pi / (c[1].omega - c[0].omega);
}

}  // namespace wec_test
