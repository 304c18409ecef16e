// Inputs of the viscous part and of the paper's wave-number correction, through the scene's model stage:
// Prohaska's form factor recovered from measured points, its bad-input messages, and the Wigley fore-shoulder
// ratio of eq 12.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "ship/ship_study.hpp"

using namespace maris;
using namespace maris::ship;

namespace {

// Writes measured points C_T = (1 + k) C_F(Re) + c Fn⁴ for the default Wigley model (L = 4 m, fresh water
// at 15 °C, Re on L_WL = L), the exact low-speed law that Prohaska's method assumes.
std::string writeProhaskaPoints(double form_factor, double slope, const std::vector<double>& froude) {
  const ShipParameters p;
  const WaterProperties w = waterProperties(WaterKind::Fresh, p.temperature);
  const std::string path = ::testing::TempDir() + "ship_prohaska_points.csv";
  std::ofstream out(path);
  out << "froude,c_total\n-,-\n";
  for (double fn : froude) {
    const double re = fn * std::sqrt(p.gravity * p.length) * p.length / w.kinematic_viscosity;
    char row[80];
    std::snprintf(row, sizeof row, "%.17g,%.17g\n", fn, form_factor * ittc57FrictionCoefficient(re) + slope * std::pow(fn, 4));
    out << row;
  }
  return path;
}

}  // namespace

TEST(ShipViscousInputs, ProhaskaRecoversTheFormFactorOfExactLowSpeedData) {
  // Points on the exact line C_T/C_F = (1+k) + c Fn⁴/C_F: the least-squares intercept is 1+k to round-off
  // (1e-9: the fit's condition number times 1e-16). Points above Fn 0.2 (default prohaska_froude_max) carry
  // a large wave resistance and must be left out, or the intercept moves.
  const std::string path = writeProhaskaPoints(1.12, 0.05, {0.10, 0.12, 0.14, 0.16, 0.18, 0.20});
  {
    std::ofstream(path, std::ios::app) << "0.35,0.02\n0.45,0.03\n";
  }
  ShipParameters p;
  p.form_factor_method = "prohaska";
  p.measured_file = path;
  p.stations = 65;
  p.waterlines = 13;
  RunContext ctx;
  const ShipModel m = buildShipModel(p, ctx);
  ASSERT_TRUE(m.prohaska.has_value());
  EXPECT_EQ(m.prohaska->points, 6);
  EXPECT_NEAR(m.form_factor, 1.12, 1e-9);
  EXPECT_NEAR(m.prohaska->slope, 0.05, 1e-7);
  EXPECT_LT(m.prohaska->rms_residual, 1e-9);
}

TEST(ShipViscousInputs, ProhaskaWithoutUsablePointsIsAnInputError) {
  ShipParameters p;
  p.form_factor_method = "prohaska";
  // No measured file: a cross-field error naming the method.
  const auto errors = checkShipParameters(p);
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors.front().path, "viscous.form_factor_method");
  // One usable point (the others are above prohaska_froude_max): an InputError naming the file and the range.
  p.measured_file = writeProhaskaPoints(1.1, 0.05, {0.15, 0.3, 0.4});
  p.stations = 65;
  p.waterlines = 13;
  RunContext ctx;
  try {
    buildShipModel(p, ctx);
    FAIL() << "a Prohaska fit through one point was accepted";
  } catch (const InputError& e) {
    const std::string all = describeErrors(e.errors());
    EXPECT_NE(all.find("measured.file"), std::string::npos) << all;
    EXPECT_NE(all.find("prohaska_froude_max"), std::string::npos) << all;
  }
}

TEST(ShipViscousInputs, WigleyForeShoulderRatioMatchesTheArcLength) {
  // The Wigley design waterline from the FP to midship (its fore shoulder) has s_FS/l_FS =
  // 1.006627, so k̂0/k0 = 1 + 3.7 × 0.006627 = 1.024521. The chord polyline on 257 stations underestimates
  // the arc by ~1e-7 relative; the independent arc length has 7 digits: 1e-6.
  ShipParameters p;
  p.wave_number_correction = true;
  RunContext ctx;
  const ShipModel m = buildShipModel(p, ctx);
  EXPECT_NEAR(m.fore_shoulder.distance, 0.5 * p.length, 1e-12);
  EXPECT_NEAR(m.fore_shoulder.arc_length / m.fore_shoulder.distance, 1.006627, 1e-6);
  EXPECT_NEAR(m.wave_number_factor, 1.024521, 4e-6);
}
