// Plausibility warnings of the seismic scene: input spectra beyond the mesh's cut-off (the band edge checked
// against the closed-form spectra) and runs too short for the wave to pass the model, each alone at its field.
#include <cmath>
#include <numbers>

#include "engine/plausibility_test_support.hpp"
#include "seismic/seismic_plausibility.hpp"

namespace maris {
namespace {

using testing::expectOnlyWarning;
using testing::plausibilityOf;

TEST(SeismicPlausibility, TheBuiltInModelsRaiseNone) {
  testing::expectBuiltinsRaiseNone("seismic");
}

TEST(SeismicPlausibility, TheBandEdgeIsWhereTheSpectrumFallsToOnePercent) {
  // Ricker: (f/f_p)² e^{1 − (f/f_p)²} = 0.01 beyond f_p; B-spline pulse: sinc⁴(fT/4) = 0.01 below its first zero.
  seismic::SeismicParameters p;
  p.input_kind = "ricker";
  p.ricker_peak_frequency = 1.5;
  const double x = seismic::inputBandEdge(p) / 1.5;
  EXPECT_GT(x, 1.0);
  EXPECT_NEAR(x * x * std::exp(1 - x * x), 0.01, 1e-9);
  p.input_kind = "pulse";
  p.pulse_duration = 0.2;
  const double y = seismic::inputBandEdge(p) * 0.2 / 4;
  EXPECT_GT(y, 0.0);
  EXPECT_LT(y, 1.0);
  EXPECT_NEAR(std::pow(std::sin(std::numbers::pi * y) / (std::numbers::pi * y), 4), 0.01, 1e-9);
}

TEST(SeismicPlausibility, AnInputAboveTheMeshCutOff) {
  // Ricker band edge 2.76 f_p: 1.8 Hz → 4.97 Hz (inside f_cut = 5 Hz), 1.9 Hz → 5.25 Hz.
  EXPECT_TRUE(plausibilityOf("seismic_default", {"input.ricker_peak_frequency=1.8"}).empty());
  expectOnlyWarning(plausibilityOf("seismic_default", {"input.ricker_peak_frequency=1.9"}),
                    "input.ricker_peak_frequency", "beyond solver.cutoff_frequency = 5 Hz");
  // B-spline band edge 2.96/T: a 0.1 s pulse reaches 29.6 Hz against the box's 20 Hz.
  expectOnlyWarning(plausibilityOf("seismic_verification_box", {"input.pulse_duration=0.1"}), "input.pulse_duration",
                    "beyond solver.cutoff_frequency = 20 Hz");
}

TEST(SeismicPlausibility, ARunTooShortForTheWaveToPassTheReef) {
  // Default: arrival 0.40 s + Ricker 3/1.5 Hz = 2 s + P travel up the reef 0.23 s = 2.63 s.
  EXPECT_TRUE(plausibilityOf("seismic_default", {"solver.duration=2.7"}).empty());
  expectOnlyWarning(plausibilityOf("seismic_default", {"solver.duration=2.5"}), "solver.duration", "the response is cut off");
}

}  // namespace
}  // namespace maris
