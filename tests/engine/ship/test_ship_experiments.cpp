// Theory against towing-tank measurements: the KCS model of the Tokyo 2015 workshop (Case 2.1, KRISO; the
// data set shipped as resources/data/ship/kcs_tokyo2015_case21_efd.csv, provenance in its README) and the
// position of the Series 60 hump. These are not accuracy tests of our numerics (those compare with closed
// forms elsewhere) but of the paper's claims (the Series 60 hump, the KCS curve), with tolerances from the physics the linear
// theory leaves out, never fitted to our output.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catalog.hpp"
#include "core/scene.hpp"
#include "ship/ship_study.hpp"

using namespace maris;
using namespace maris::ship;

namespace {

struct KcsPoint {
  double froude, c_total_measured;
  double michell = 0, corrected = 0, holtrop = 0;  // C_T of the three predictions
};

// The ship_kcs scenario (1+k = 1.165 as the paper, ν = 1.27e-6 m²/s as the tests, published hull-only S) on a
// 129 × 25 grid: its grid error (≈ 1 % of C_W at Fn 0.2, docs/ship.md) is far below the effects tested here.
std::vector<KcsPoint> kcsPredictions() {
  ShipParameters p;
  p.hull_source = "kcs";
  p.length = 7.2786;
  p.wetted_surface = 9.4379;
  p.temperature = 11.0;
  p.form_factor = 1.165;
  p.tangency_correction = true;
  p.wave_number_correction = true;
  p.stations = 129;
  p.waterlines = 25;
  p.measured_file = "builtin:kcs_tokyo2015_case21_efd.csv";
  RunContext ctx;
  const ShipModel m = buildShipModel(p, ctx);
  const MeasuredPoints efd = readMeasuredPoints(p.measured_file);
  std::vector<KcsPoint> out;
  GridKochin plain(m.grid);
  auto corrected = correctedKochin(m);
  for (std::size_t i = 0; i < efd.froude.size(); ++i) {
    KcsPoint k{efd.froude[i], efd.c_total[i]};
    const double U = k.froude * std::sqrt(p.gravity * p.length), rho = m.water.density;
    const double q = 0.5 * rho * U * U * m.wetted_surface;
    const double viscous =
        m.form_factor * ittc57FrictionCoefficient(U * m.particulars.length_wl / m.water.kinematic_viscosity);
    k.michell = viscous + michellWaveResistance(plain, U, p.gravity, rho, michellSettings(p, m, false)).resistance / q;
    k.corrected =
        viscous + michellWaveResistance(*corrected, U, p.gravity, rho, michellSettings(p, m, true)).resistance / q;
    k.holtrop =
        holtropMennen(m.holtrop_hull, U, rho, m.water.kinematic_viscosity, p.gravity, false, m.holtrop_edition).total /
        q;
    out.push_back(k);
  }
  return out;
}

// The tests were run free to sink and trim (sinkage 1.4 cm = 4 % of T at Fn 0.26); a fixed model measures
// about 4.5 % less C_T there (Wu 2025, fixed vs free CFD of this case, as quoted with the data's provenance).
constexpr double kFreeSinkageShare = 0.05;

}  // namespace

TEST(ShipExperiments, UncorrectedMichellOverpredictsTheKcsTowingTank) {
  // Paper R11: the original theory "frantically over predicts" the KCS. Above Fn 0.15 the uncorrected C_T
  // must exceed the measurement by more than the free-sinkage share (which would push it the other way).
  for (const KcsPoint& k : kcsPredictions()) {
    if (k.froude < 0.15) continue;
    EXPECT_GT(k.michell, k.c_total_measured * (1 + kFreeSinkageShare)) << "Fn " << k.froude;
  }
}

TEST(ShipExperiments, TangencyCorrectionMovesKcsTowardsTheMeasurement) {
  // Paper R11: the corrected theory agrees far better. Ours (own integral boundary layer, not XFOIL) is
  // closer than the uncorrected theory at every speed where waves matter, by at least a third of the gap.
  for (const KcsPoint& k : kcsPredictions()) {
    if (k.froude < 0.15) continue;
    const double before = k.michell - k.c_total_measured, after = std::abs(k.corrected - k.c_total_measured);
    EXPECT_LT(after, before * 2.0 / 3.0) << "Fn " << k.froude;
  }
}

TEST(ShipExperiments, ViscousPartMatchesKcsAtLowSpeed) {
  // At Fn 0.108 waves are < 4 % of C_T, so C_T ≈ (1+k) C_F: the paper's 1+k = 1.165 (Prohaska on another
  // data set, Chen et al. 2016) with ITTC-57. Tolerance 8 %: these tests' own Prohaska intercept is 1.137
  // (2.4 % lower), the rudder adds 1.2 % of S with unknown drag, Re on L_WL vs Lpp moves C_F by 0.4 %.
  const KcsPoint k = kcsPredictions().front();
  ASSERT_NEAR(k.froude, 0.108, 1e-12);
  EXPECT_NEAR(k.corrected / k.c_total_measured, 1.0, 0.08);
  EXPECT_NEAR(k.holtrop / k.c_total_measured, 1.0, 0.08);
}

TEST(ShipExperiments, HoltropMennenMissesTheKcsGradientAboveFroudeZeroPointTwoFive) {
  // Paper R11: Holtrop–Mennen "misses its gradient from Fn 0.25 to 0.3". Measured dC_T between Fn 0.260
  // and 0.282 is 0.79e-3; the regression must give less than half of it (the sinkage share cannot explain
  // a factor of two: it is 5 % of C_T).
  const auto pts = kcsPredictions();
  const KcsPoint& a = pts[4];
  const KcsPoint& b = pts[5];
  ASSERT_NEAR(a.froude, 0.260, 1e-12);
  ASSERT_NEAR(b.froude, 0.282, 1e-12);
  EXPECT_LT(b.holtrop - a.holtrop, 0.5 * (b.c_total_measured - a.c_total_measured));
  // The corrected Michell curve does rise at least as steeply as the measurement there.
  EXPECT_GT(b.corrected - a.corrected, b.c_total_measured - a.c_total_measured);
}

TEST(ShipExperiments, WaveNumberCorrectionDelaysTheSeries60HumpTowardsFroudeZeroPointThree) {
  // Paper §4.2: measured hump near Fn 0.30, original theory 0.28. k̂0 = f·k0 maps C_W(Fn) of the
  // uncorrected theory to Fn·√f (the k0² prefactor stays, so C_W itself changes by 1/f), so the hump moves by
  // √f: here f = 1.048 (s_FS/l_FS = 1.0129), 0.286 → 0.292, inside ±0.01 of 0.30. One step 0.002.
  const BuiltinScenario* b = findBuiltin("ship_series60");
  ASSERT_NE(b, nullptr);
  Scenario s = b->scenario;
  for (const std::string o : {"speed.froude_min=0.26", "speed.froude_max=0.32", "speed.count=31",
                              "numerics.stations=129", "numerics.waterlines=25", "corrections.wave_number=true",
                              "corrections.tangency=false"})
    applyOverride(s, o);
  RunContext ctx;
  const Results r = runScenario(requireScene("ship"), s, ctx);
  const Table* t = r.findTable("resistance_curve");
  ASSERT_NE(t, nullptr);
  const auto& fn = t->find("froude")->values;
  auto hump = [&](const char* column) {
    const auto& v = t->find(column)->values;
    double at = 0;
    for (std::size_t k = 1; k + 1 < v.size(); ++k)
      if (v[k] > v[k - 1] && v[k] >= v[k + 1]) at = fn[k];
    return at;
  };
  const double f = r.findScalar("wave_number_factor")->value;
  EXPECT_NEAR(hump("c_wave_corrected"), hump("c_wave") * std::sqrt(f), 0.0021);
  EXPECT_NEAR(hump("c_total_corrected"), 0.30, 0.01);
}
