// Result containers: CSV with names and units rows that round-trips doubles; summary.json.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <unistd.h>

#include "core/csv_field.hpp"
#include "core/results.hpp"

namespace maris {
namespace {

TEST(Results, CsvHasNameRowUnitRowAndExactNumbers) {
  Table t;
  t.name = "tip";
  t.add("time", "s", {0.0, 0.1});
  t.add("tip x, lateral", "m", {1.0 / 3.0, -2e-300});
  t.add("ratio", "", {1.0, 2.0});
  const std::string csv = t.toCsv();
  std::istringstream in(csv);
  std::string names, units, row1;
  std::getline(in, names);
  std::getline(in, units);
  std::getline(in, row1);
  EXPECT_EQ(names, "time,\"tip x, lateral\",ratio");
  EXPECT_EQ(units, "s,m,-");
  const auto comma = row1.find(',');
  const double x = std::stod(row1.substr(comma + 1));
  EXPECT_EQ(x, 1.0 / 3.0);  // 17 significant digits round-trip a double exactly
}

// The desktop application runs in the user's locale (Qt sets it from the environment), where printf writes a
// decimal comma: CSV numbers must not follow it. A German locale is built into a scratch folder with
// localedef (glibc's, from the locale sources Debian ships) so that the check runs on any machine.
TEST(Results, CsvNumbersUseAPointInADecimalCommaLocale) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("maris_locale_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string make = "localedef -i de_DE -f UTF-8 '" + (dir / "de_DE.UTF-8").string() + "' >/dev/null 2>&1";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  const std::string old_locpath = std::getenv("LOCPATH") ? std::getenv("LOCPATH") : "";
  ::setenv("LOCPATH", dir.c_str(), 1);
  ASSERT_NE(std::setlocale(LC_NUMERIC, "de_DE.UTF-8"), nullptr);
  char printed[16];
  std::snprintf(printed, sizeof printed, "%.2g", 0.5);
  const std::string printf_text = printed;
  Table t;
  t.add("x", "m", {0.5, -1.25e-7});
  const std::string csv = t.toCsv();
  std::setlocale(LC_NUMERIC, "C");
  if (old_locpath.empty()) ::unsetenv("LOCPATH"); else ::setenv("LOCPATH", old_locpath.c_str(), 1);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(printf_text, "0,5");  // the locale was in effect
  EXPECT_EQ(csv, "x\nm\n0.5\n-1.2499999999999999e-07\n");
  EXPECT_EQ(csvNumber(0.1), "0.10000000000000001");
  EXPECT_EQ(csvNumber(std::nan("")), "nan");
}

TEST(Results, SummaryCarriesUnitsAndSolverStatistics) {
  Results r;
  r.addScalar("tip_deflection", 0.25, "m", "Tip deflection");
  r.addScalar("undefined", std::nan(""), "-", "Not computed");
  r.stats.steps = 10;
  r.stats.method = "RK4";
  r.warnings.push_back("note");
  const Json j = summaryJson(r);
  EXPECT_EQ(j["results"]["tip_deflection"]["unit"], "m");
  EXPECT_EQ(j["results"]["tip_deflection"]["value"], 0.25);
  EXPECT_TRUE(j["results"]["undefined"]["value"].is_null());  // NaN is not valid JSON
  EXPECT_EQ(j["solver"]["steps"], 10);
  EXPECT_EQ(j["warnings"][0], "note");
}

TEST(Results, LabelsForPeopleNamesForFiles) {
  Table t;
  t.name = "curve";
  t.add("froude", "-", {0.3}, "Fn");
  t.add("c_wave", "-", {1e-3});
  EXPECT_EQ(displayLabel(t.columns[0]), "Fn");
  EXPECT_EQ(displayLabel(t.columns[1]), "C wave");  // no label declared: the name made readable
  EXPECT_EQ(t.toCsv().substr(0, t.toCsv().find('\n')), "froude,c_wave");  // the CSV keeps machine names
  Results r;
  r.addScalar("max_bending_stress", 2.7e7, "Pa", "Largest bending stress", "max σ_b");
  r.addScalar("steps", 10, "-", "Steps");
  EXPECT_EQ(displayLabel(r.scalars[0]), "max σ_b");
  EXPECT_EQ(displayLabel(r.scalars[1]), "Steps");
  const Json j = summaryJson(r);
  EXPECT_EQ(j["results"]["max_bending_stress"]["label"], "max σ_b");
  EXPECT_FALSE(j["results"]["steps"].contains("label"));  // only declared labels are written
}

TEST(Results, LookupByName) {
  Results r;
  r.tables.push_back(Table{"a", "A", {}});
  r.addScalar("s", 1.0, "m", "");
  EXPECT_NE(r.findTable("a"), nullptr);
  EXPECT_EQ(r.findTable("b"), nullptr);
  EXPECT_NE(r.findScalar("s"), nullptr);
}

}  // namespace
}  // namespace maris
