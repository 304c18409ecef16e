// study.csv from cases' statuses and scalars (collectScalars): what `study collect` writes after reading
// the case folders, and what the desktop application writes from results in memory.
#include "study/study_collect.hpp"
#include "study_test_util.hpp"

#include <cctype>

namespace maris::study::test {

namespace {

CollectedCase collectedCase(const std::string& id, CaseStatus status, double value) {
  CollectedCase c;
  c.id = id;
  c.status = status;
  c.values = {Json(value)};
  return c;
}

}  // namespace

TEST(StudyCollect, OkCasesGiveTheirScalarsOthersEmptyCellsAndTheColumnsAreSorted) {
  const std::vector<StudyParameter> parameters = {{"hull.length", "m", ParamKind::Real, ""}};
  std::vector<CollectedCase> cases = {collectedCase("0001", CaseStatus::Ok, 2.0),
                                      collectedCase("0002", CaseStatus::Failed, 3.0),
                                      collectedCase("0003", CaseStatus::Missing, 0.1)};
  const double third = 1.0 / 3.0;  // needs all 17 significant digits to read back
  std::vector<CaseScalars> scalars = {{{"resistance", {third, "N"}}, {"drag", {2.5, "N"}}},
                                      {{"resistance", {9.0, "N"}}},  // a failed case's scalars are not shown
                                      {}};
  const CollectedStudy all = collectScalars(parameters, {}, cases, scalars);
  ASSERT_EQ(all.result_names, (std::vector<std::string>{"drag", "resistance"}));
  EXPECT_EQ(studyCsv(all),
            "case,status,hull.length,drag,resistance\n"
            "-,-,m,N,N\n"
            "0001,ok,2,2.5,0.33333333333333331\n"
            "0002,failed,3,,\n"
            "0003,missing,0.10000000000000001,,\n");
  EXPECT_EQ(std::stod("0.33333333333333331"), third);

  // Requested results keep their order; an unknown one is a warning with a guess, and an empty column.
  const CollectedStudy some = collectScalars(parameters, {"resistanse", "drag"}, cases, scalars);
  EXPECT_EQ(some.result_names, (std::vector<std::string>{"resistanse", "drag"}));
  ASSERT_EQ(some.warnings.size(), 1u);
  EXPECT_NE(some.warnings[0].find("did you mean 'resistance'"), std::string::npos) << some.warnings[0];
  EXPECT_FALSE(some.cases[0].results[0].has_value());
  EXPECT_EQ(some.cases[0].results[1], 2.5);
}

// The PNG file names of a study's plots: a table cell's brackets (and any other character outside
// [A-Za-z0-9._-]) do not reach the file name, every name is unique even where two paths map to the same
// characters or differ only in case. The title names the parameter by its label, or where it has none (a folder
// whose scene this program lacks) by its path as written.
TEST(StudyCollect, PlotFileNamesArePortableAndUnique) {
  CollectedStudy collected;
  collected.parameters = {{"current.profile[1].speed", "m/s", ParamKind::Real, ""},
                          {"current.profile_1.speed", "m/s", ParamKind::Real, ""},  // the cell's stem, as a field
                          {"Current.Profile_1.Speed", "m/s", ParamKind::Real, ""},  // the same but for case
                          {"hull length (m)", "m", ParamKind::Real, ""},
                          {"water.kind", "", ParamKind::Choice, ""}};  // text: no plot
  collected.result_names = {"drag"};
  collected.result_units = {"N"};
  StudyManifest manifest;
  manifest.json = {{"design", "table"}};
  const auto plots = studyPlots(collected, manifest);
  ASSERT_EQ(plots.size(), 4u);
  EXPECT_EQ(plots[0].file_stem, "drag_vs_current.profile_1.speed");
  EXPECT_EQ(plots[1].file_stem, "drag_vs_current.profile_1.speed-2");
  EXPECT_EQ(plots[2].file_stem, "drag_vs_Current.Profile_1.Speed-3");
  EXPECT_EQ(plots[3].file_stem, "drag_vs_hull_length__m_");
  EXPECT_EQ(plots[0].title, "Drag against current.profile[1].speed");
  collected.parameters[0].label = "Speed of current profile row 2";
  collected.result_labels = {"Drag D"};
  const auto labelled = studyPlots(collected, manifest);
  EXPECT_EQ(labelled[0].title, "Drag D against Speed of current profile row 2");
  EXPECT_EQ(labelled[0].file_stem, "drag_vs_current.profile_1.speed");  // file names keep the paths
  for (const auto& plot : plots)
    for (const char c : plot.file_stem)
      EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-') << plot.file_stem;
}

// A weighted sum over a table's cases, against the sum by hand: 0.5 * 2 + 0.3 * 4 + 0.2 * 10 = 4.2 (each
// product and the running sum exact in binary to well within 1e-15 relative). A case of weight 0 needs no
// value; a case of weight > 0 without one leaves the sum out and is named.
TEST(StudyCollect, AWeightedSumIsTheSumOfWeightTimesResultOverTheCases) {
  std::vector<CollectedCase> cases = {collectedCase("0001", CaseStatus::Ok, 1.0), collectedCase("0002", CaseStatus::Ok, 2.0),
                                      collectedCase("0003", CaseStatus::Ok, 3.0),
                                      collectedCase("0004", CaseStatus::Failed, 4.0)};
  const std::vector<CaseScalars> scalars = {{{"damage", {2.0, "1/yr"}}},
                                            {{"damage", {4.0, "1/yr"}}},
                                            {{"damage", {10.0, "1/yr"}}, {"other", {1.0, "-"}}},
                                            {}};
  const auto sums = weightedSums({"damage", "other"}, {0.5, 0.3, 0.2, 0.0}, cases, scalars);
  ASSERT_EQ(sums.size(), 2u);
  EXPECT_EQ(sums[0].result, "damage");
  EXPECT_EQ(sums[0].unit, "1/yr");
  ASSERT_TRUE(sums[0].value.has_value());
  EXPECT_NEAR(*sums[0].value, 4.2, 1e-15 * 4.2);
  EXPECT_NEAR(sums[0].weight_total, 1.0, 1e-15);
  EXPECT_TRUE(sums[0].missing.empty());
  EXPECT_FALSE(sums[1].value.has_value());  // cases 0001 and 0002 have weight but no "other"
  EXPECT_EQ(sums[1].missing, (std::vector<std::string>{"0001", "0002"}));

  cases[3].status = CaseStatus::Missing;  // not run yet, with a weight: no sum
  const auto waiting = weightedSums({"damage"}, {0.5, 0.3, 0.1, 0.1}, cases, scalars);
  EXPECT_FALSE(waiting[0].value.has_value());
  EXPECT_EQ(waiting[0].missing, (std::vector<std::string>{"0004"}));
}

}  // namespace maris::study::test
