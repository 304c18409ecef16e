// Hemisphere coefficients: Hulme tables and limits, monotone interpolation, Haskind excitation, WAMIT import
// and the cross-check against the independent WAMIT run (tests/engine/wec/data/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "core/ocean_waves.hpp"
#include "wec/wec_hydro.hpp"
#include "wec/wec_model.hpp"
#include "wec/wec_wamit.hpp"
#include "source_tree.hpp"
#include "wec_test_models.hpp"

using namespace maris::wec;

namespace {
using wec_test::kRho, wec_test::kWamitG, wec_test::kSphere;
double volume(double a) { return 2.0 / 3.0 * std::numbers::pi * a * a * a; }
}  // namespace

// Hulme (1982) Table 1 rows, read back through the interpolant: nodes are reproduced to round-off.
TEST(WecHydro, HulmeHeaveNodesAreReproduced) {
  const double ka[] = {0.05, 0.4, 1.0, 2.0, 5.0, 10.0};
  const double mu[] = {0.8764, 0.6452, 0.4284, 0.3884, 0.4471, 0.4771};
  const double lambda[] = {0.1036, 0.3410, 0.2484, 0.1031, 0.0116, 0.0012};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(hulmeHeaveAddedMass(ka[i]), mu[i], 1e-12) << "ka = " << ka[i];
    EXPECT_NEAR(hulmeHeaveDamping(ka[i]), lambda[i], 1e-12) << "ka = " << ka[i];
  }
  EXPECT_NEAR(hulmeSurgeAddedMass(0.8), 0.6421, 1e-12);
  EXPECT_NEAR(hulmeSurgeDamping(1.0), 0.3535, 1e-12);
}

// Exact limits (rigid-lid and Dirichlet image problems, closed forms) to 1e-4.
TEST(WecHydro, AddedMassTendsToTheExactLimits) {
  EXPECT_NEAR(hulmeHeaveAddedMass(0.0), 0.8310, 1e-4);
  EXPECT_NEAR(hulmeHeaveAddedMass(1e6), 0.5, 1e-4);
  EXPECT_NEAR(hulmeSurgeAddedMass(0.0), 0.5, 1e-4);
  EXPECT_NEAR(hulmeSurgeAddedMass(1e7), 0.2732, 1e-4);
  EXPECT_NEAR(hulmeHeaveDamping(1e-9), 0.0, 1e-6);
  EXPECT_NEAR(hulmeHeaveDamping(1e4), 0.0, 1e-6);
  EXPECT_NEAR(hemisphereHeavePhase(0.0), 0.0, 1e-12);
  EXPECT_NEAR(hemisphereSurgePhase(0.0), std::numbers::pi / 2, 1e-12);
}

// Haskind–Newman in water of depth h (Newman 1976, axisymmetric body): |X3|² = 4ρgC_g B33/k and
// |X1|² = 8ρgC_g B11/k hold for WAMIT's own excitation and damping to 1 % (WAMIT's panel error),
// which also checks that the importer dimensionalises both files consistently. At T = 8 s (kh = 3.2) the
// deep-water form 2ρg³B/ω³ is already 1.6 % off, so the finite-depth form is the reference.
TEST(WecHydro, WamitImportSatisfiesHaskind) {
  const auto db = readWamit(kSphere, kRho, kWamitG, 1.0);
  int checked = 0;
  for (const auto& r : db->rows()) {
    const double period = 2.0 * std::numbers::pi / r.omega;
    if (period < 4.0 || period > 8.0) continue;
    const double k = maris::ocean::waveNumber(r.omega, 50.0, kWamitG), cg = maris::ocean::groupVelocity(r.omega, 50.0, kWamitG);
    EXPECT_NEAR(std::norm(r.hydro.heave.excitation) * k / (4 * kRho * kWamitG * cg * r.hydro.heave.damping), 1.0, 0.01)
        << "T = " << period;
    EXPECT_NEAR(std::norm(r.hydro.surge.excitation) * k / (8 * kRho * kWamitG * cg * r.hydro.surge.damping), 1.0, 0.01)
        << "T = " << period;
    ++checked;
  }
  EXPECT_EQ(checked, 9);
  EXPECT_NEAR(db->addedMassInfinityHeave() / (kRho * volume(5.0)), 0.5, 0.002);
}

// Hulme (deep water) against the WAMIT BEM run for ka in [0.3, 1.3] where kh ≥ 3: 1.5 % of the
// mode's peak coefficient (the table's 4 digits plus WAMIT's discretisation).
TEST(WecHydro, HulmeAgreesWithWamitInDeepWater) {
  const auto db = readWamit(kSphere, kRho, kWamitG, 1.0);
  const double a = 5.0, rho_v = kRho * volume(a);
  const HemisphereHydro hulme(a, kRho, kWamitG);
  int checked = 0;
  for (const auto& r : db->rows()) {
    const double ka = r.omega * r.omega * a / kWamitG;
    if (ka < 0.3 || ka > 1.3) continue;
    const FloatHydro h = hulme.at(r.omega);
    EXPECT_NEAR(h.heave.added_mass / rho_v, r.hydro.heave.added_mass / rho_v, 0.015 * 0.88) << "ka " << ka;
    EXPECT_NEAR(h.surge.added_mass / rho_v, r.hydro.surge.added_mass / rho_v, 0.015 * 0.67) << "ka " << ka;
    EXPECT_NEAR(h.heave.damping / (rho_v * r.omega), r.hydro.heave.damping / (rho_v * r.omega), 0.015 * 0.34)
        << "ka " << ka;
    EXPECT_NEAR(h.surge.damping / (rho_v * r.omega), r.hydro.surge.damping / (rho_v * r.omega), 0.015 * 0.41)
        << "ka " << ka;
    // Haskind magnitude from Hulme's damping against WAMIT's diffraction solution: 1.5 % of the peak.
    EXPECT_NEAR(std::abs(h.heave.excitation), std::abs(r.hydro.heave.excitation),
                0.015 * std::abs(r.hydro.heave.excitation) + 0.005 * kRho * kWamitG * std::numbers::pi * a * a);
    // Phases: the table is WAMIT's (integer degrees) so this checks units and interpolation, to 2°.
    EXPECT_NEAR(std::arg(h.heave.excitation / r.hydro.heave.excitation), 0.0, 2.0 * std::numbers::pi / 180);
    EXPECT_NEAR(std::arg(h.surge.excitation / r.hydro.surge.excitation), 0.0, 2.0 * std::numbers::pi / 180);
    ++checked;
  }
  EXPECT_GE(checked, 8);
}

// The e^{−iωt} ↔ e^{+iωt} conversion is a conjugation and round-trips exactly.
TEST(WecHydro, PhaseConventionRoundTripIsExact) {
  const Complex x(3.0, -4.0);
  EXPECT_EQ(fromEMinusIwt(toEMinusIwt(x)), x);
  // A force leading the wave by 25° has phase +25° in e^{+iωt} and −25° in e^{−iωt}.
  const Complex lead = std::polar(1.0, 25.0 * std::numbers::pi / 180);
  EXPECT_NEAR(std::arg(toEMinusIwt(lead)), -25.0 * std::numbers::pi / 180, 1e-15);
  // The physical signal Re{X e^{iωt}} equals Re{conj(X) e^{−iωt}} at every instant.
  for (double t : {0.0, 0.3, 1.7}) EXPECT_NEAR((lead * std::polar(1.0, 2.0 * t)).real(),
                                               (toEMinusIwt(lead) * std::polar(1.0, -2.0 * t)).real(), 1e-15);
}

TEST(WecHydro, MissingWamitFileNamesTheFile) {
  try {
    readWamit("/nonexistent/body", kRho, kWamitG, 1.0);
    FAIL() << "expected InputError";
  } catch (const maris::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/body.1"), std::string::npos) << e.what();
  }
}
