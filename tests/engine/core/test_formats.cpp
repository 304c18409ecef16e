// The external-format readers (core/formats) on real files of each format (tests/data/wamit, nemoh,
// peer_at2; provenance and terms in the README beside each), checked against an independent route:
// WAMIT's text report against its numeric files (the same run printed twice), Nemoh against WAMIT (two
// boundary-element codes on the same floating sphere, radius 5 m, depth 50 m), the .AT2 header against the
// values that follow it, and the hemisphere's infinite-frequency added mass against its closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "core/formats/format_detect.hpp"
#include "core/formats/peer_at2.hpp"
#include "core/formats/tecplot.hpp"
#include "core/formats/wamit.hpp"
#include "engine/test_data_file.hpp"

namespace maris::formats {
namespace {

using test_files::readTestDataFile;

using std::numbers::pi;

// (period, i, j) -> (A, B) of a .1 file or a report.
std::map<std::tuple<double, int, int>, std::pair<double, double>> byKey(const std::vector<WamitCoefficientRow>& rows) {
  std::map<std::tuple<double, int, int>, std::pair<double, double>> m;
  for (const auto& r : rows) m[{r.period, r.i, r.j}] = {r.added_mass, r.damping.value_or(0.0)};
  return m;
}

}  // namespace

// The report (.out) and the numeric file (.1) of one WAMIT run print the same coefficients to 7 significant
// digits: every (period, I, J) of the .1 file is in the report and agrees to 1e-6 of the period's largest value.
TEST(Formats, WamitReportAndNumericFilesOfOneRunAgree) {
  const auto one = parseWamit1(readTestDataFile("wamit/sphere.1"), "hydro", "sphere.1");
  const auto three = parseWamit3(readTestDataFile("wamit/sphere.3"), "hydro", "sphere.3");
  const WamitReport report = parseWamitOut(readTestDataFile("wamit/sphere.out"), "hydro", "sphere.out");
  EXPECT_EQ(report.gravity, 9.81);
  EXPECT_EQ(report.length_scale, 1.0);
  EXPECT_EQ(report.water_depth, 50.0);
  ASSERT_EQ(one.size(), 288u);  // the 289 lines less the header
  const auto from_report = byKey(report.coefficients);
  std::map<double, double> largest;
  for (const auto& r : one) largest[r.period] = std::max(largest[r.period], std::abs(r.added_mass));
  int compared = 0;
  for (const auto& r : one) {
    if (r.period <= 0.0) continue;  // the limits: the report prints them in another layout
    const auto it = from_report.find({r.period, r.i, r.j});
    ASSERT_NE(it, from_report.end()) << "T = " << r.period << ", " << r.i << r.j;
    EXPECT_NEAR(it->second.first, r.added_mass, 1e-6 * largest[r.period]);
    EXPECT_NEAR(it->second.second, r.damping.value_or(0.0), 1e-6 * largest[r.period]);
    ++compared;
  }
  EXPECT_GT(compared, 200);
  // Excitation: modulus and phase of every .3 line (heading 0) are in the report; Re, Im follow from them.
  ASSERT_EQ(three.size(), 36u);
  for (const auto& x : three) {
    EXPECT_NEAR(std::hypot(x.re, x.im), x.modulus, 1e-6 * x.modulus);
    const auto match = std::find_if(report.excitation.begin(), report.excitation.end(), [&](const WamitExcitationRow& r) {
      return r.period == x.period && r.heading == x.heading && r.i == x.i;
    });
    ASSERT_NE(match, report.excitation.end()) << "T = " << x.period << ", I = " << x.i;
    EXPECT_NEAR(match->modulus, x.modulus, 1e-6 * std::max(1.0, x.modulus));
  }
}

// A floating hemisphere's heave added mass at infinite frequency is half its displaced mass,
// A33(∞) = ½ ρ (2/3) π a³ (Hulme 1982, J. Fluid Mech. 121, 443-463): in WAMIT's units (ρ L³, L = 1 m) for
// a = 5 m, 130.90. WAMIT's panels give it to 0.1 %.
TEST(Formats, WamitInfiniteFrequencyHeaveAddedMassIsHalfTheDisplacedMass) {
  const auto one = parseWamit1(readTestDataFile("wamit/sphere.1"), "hydro", "sphere.1");
  const double closed = 0.5 * (2.0 / 3.0) * pi * 125.0;
  const auto row = std::find_if(one.begin(), one.end(), [](const auto& r) { return r.period == 0.0 && r.i == 3 && r.j == 3; });
  ASSERT_NE(row, one.end());
  EXPECT_FALSE(row->damping.has_value());
  EXPECT_NEAR(row->added_mass, closed, 1e-3 * closed);
}

// Nemoh v3 (ρ = 1000 kg/m³, g = 9.81, h = 50 m in the example's Nemoh.cal) against WAMIT on the same sphere at
// the two frequencies both tabulate (ω = 1.42 and 2.82 rad/s; WAMIT's periods 4.424781 s and 2.228081 s):
// heave added mass and damping agree within 2 % (two panel codes, two meshes). WAMIT's values are
// non-dimensional: A = Ā ρ L³, B = B̄ ρ L³ ω with L = 1 m.
TEST(Formats, NemohTecplotAgreesWithWamitOnTheSameSphere) {
  const TecplotFile radiation =
      parseTecplot(readTestDataFile("nemoh/RadiationCoefficients.tec"), "hydro", "RadiationCoefficients.tec");
  ASSERT_EQ(radiation.zones.size(), 6u);  // one zone per degree of freedom
  const TecplotZone& heave = radiation.zones[2];
  EXPECT_NE(heave.title.find("DoF   3"), std::string::npos) << heave.title;
  ASSERT_EQ(heave.rows.size(), 6u);
  for (const auto& row : heave.rows) ASSERT_EQ(row.size(), 13u);  // ω and (A, B) for 6 forces
  const auto wamit = byKey(parseWamit1(readTestDataFile("wamit/sphere.1"), "hydro", "sphere.1"));
  const double rho = 1000.0;
  for (const auto& [row_index, period] : {std::pair{1, 4.424781}, std::pair{2, 2.228081}}) {
    const auto& row = heave.rows[static_cast<std::size_t>(row_index)];
    const double omega = row[0];
    EXPECT_NEAR(omega, 2.0 * pi / period, 1e-5 * omega);
    const auto [a_bar, b_bar] = wamit.at({period, 3, 3});
    const double a_wamit = a_bar * rho, b_wamit = b_bar * rho * omega;
    EXPECT_NEAR(row[5], a_wamit, 0.02 * a_wamit) << "A33 at omega = " << omega;
    EXPECT_NEAR(row[6], b_wamit, 0.02 * b_wamit) << "B33 at omega = " << omega;
  }
  const TecplotFile excitation = parseTecplot(readTestDataFile("nemoh/ExcitationForce.tec"), "hydro", "ExcitationForce.tec");
  ASSERT_FALSE(excitation.zones.empty());
  EXPECT_EQ(excitation.zones[0].rows.size(), 6u);
}

// The .AT2 header says 1800 points at 0.02 s; the reader returns exactly those, in m/s² (g = 9.80665), the
// first and last values as the file prints them.
TEST(Formats, PeerAt2RecordHasTheHeadersPointsAndStep) {
  const PeerRecord record = parsePeerAt2(readTestDataFile("peer_at2/SHL000.AT2"), "input.accelerogram_file", "SHL000.AT2");
  EXPECT_EQ(record.dt, 0.02);
  ASSERT_EQ(record.acceleration.size(), 1800u);
  EXPECT_NE(record.title.find("CAPE MENDOCINO"), std::string::npos) << record.title;
  EXPECT_DOUBLE_EQ(record.acceleration.front(), -0.2302583e-2 * kStandardGravity);
  const double peak = *std::max_element(record.acceleration.begin(), record.acceleration.end(),
                                        [](double a, double b) { return std::abs(a) < std::abs(b); });
  EXPECT_GT(std::abs(peak), 0.05 * kStandardGravity);  // a strong-motion record, not an empty one
  // A truncated record is refused, naming the field and the count.
  std::string text = readTestDataFile("peer_at2/SHL000.AT2");
  text.resize(text.size() / 2);
  try {
    parsePeerAt2(text, "input.accelerogram_file", "SHL000.AT2");
    ADD_FAILURE() << "a truncated record was read";
  } catch (const InputError& e) {
    EXPECT_NE(describeErrors(e.errors()).find("input.accelerogram_file"), std::string::npos) << describeErrors(e.errors());
  }
}

// Each real file is recognised as its format; a NetCDF/HDF5 file (Capytaine's native output) is named as an
// unsupported format, and a plain CSV is a table.
TEST(Formats, EachRealFileIsRecognisedAndBinaryDatasetsAreNamed) {
  EXPECT_EQ(detectFormat(readTestDataFile("wamit/sphere.1")), FileFormat::wamit_numeric);
  EXPECT_EQ(detectFormat(readTestDataFile("wamit/sphere.3")), FileFormat::wamit_numeric);
  EXPECT_EQ(detectFormat(readTestDataFile("wamit/sphere.out")), FileFormat::wamit_out);
  EXPECT_EQ(detectFormat(readTestDataFile("nemoh/RadiationCoefficients.tec")), FileFormat::tecplot);
  EXPECT_EQ(detectFormat(readTestDataFile("peer_at2/SHL000.AT2")), FileFormat::peer_at2);
  EXPECT_EQ(detectFormat(std::string("\x89HDF\r\n\x1a\n", 8) + std::string(64, '\0')), FileFormat::netcdf);
  EXPECT_EQ(detectFormat(std::string("CDF\x01", 4) + std::string(64, '\0')), FileFormat::netcdf);
  EXPECT_FALSE(formatName(FileFormat::netcdf).empty());
  EXPECT_EQ(detectFormat("time,acceleration\ns,m/s^2\n0,0.1\n0.01,0.2\n"), FileFormat::table);
}

}  // namespace maris::formats
