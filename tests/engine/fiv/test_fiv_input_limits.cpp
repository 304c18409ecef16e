// Reference data with a NaN cell is an input error naming the line (it silently gave a null cost and
// coefficients at their initial values); an unconverged calibration recommends nothing.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "fiv/fiv_calibration.hpp"
#include "fiv/fiv_reference.hpp"

namespace maris::fiv {
namespace {

constexpr const char* kHeader =
    "flow_speed,submergence_ratio,amplitude,amplitude_sigma,frequency,frequency_sigma,power,power_sigma\n"
    "m/s,-,m,m,Hz,Hz,W,W\n";

TEST(FivInputLimits, ANanReferenceCellIsAnInputErrorNamingItsLine) {
  const std::string good = std::string(kHeader) + "0.5,1.11,0.017,,0.5127,,,\n";
  EXPECT_EQ(parseReferencePoints(good, "ref.csv").size(), 1u);
  try {
    parseReferencePoints(std::string(kHeader) + "0.5,1.11,nan,,0.5127,,,\n", "ref.csv");
    FAIL() << "NaN cell accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"ref.csv\": line 3, column 3 (amplitude): expected a finite number"), std::string::npos) << e.what();
  }
  // Infinity means deep water only in submergence_ratio; elsewhere it is refused.
  EXPECT_EQ(parseReferencePoints(std::string(kHeader) + "0.5,inf,0.017,,,,,\n", "ref.csv").size(), 1u);
  EXPECT_THROW(parseReferencePoints(std::string(kHeader) + "0.5,1.1,inf,,,,,\n", "ref.csv"), InputError);
}

TEST(FivInputLimits, AnUnconvergedCalibrationSaysSoAndRecommendsNothing) {
  CalibrationResult cal;
  cal.names = {"structure.stiffness"};
  cal.initial = {100.0};
  cal.fitted = {123.0};
  cal.standard_error = {1.0};
  cal.cost_initial = 10.0;
  cal.cost = 5.0;
  cal.iterations = 25;
  // Not converged: a warning that says so and recommends nothing; converged: no warning, the note with the values
  // to save is returned for the method line.
  for (const bool converged : {false, true}) {
    cal.converged = converged;
    Results r;
    const std::string note = addCalibrationResults(r, cal);
    ASSERT_EQ(r.warnings.size(), converged ? 0u : 1u);
    EXPECT_EQ(note.empty(), !converged) << note;
    const std::string& text = converged ? note : r.warnings.front();
    EXPECT_EQ(text.find("did not converge") != std::string::npos, !converged) << text;
    EXPECT_EQ(text.find("structure.stiffness=123") != std::string::npos, converged) << text;
  }
}

}  // namespace
}  // namespace maris::fiv
