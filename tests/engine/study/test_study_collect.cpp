// study.csv from cases' statuses and scalars (collectScalars): what `study collect` writes after reading
// the case folders, and what the desktop application writes from results in memory.
#include "study/study_collect.hpp"
#include "study_test_util.hpp"

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
  const std::vector<StudyParameter> parameters = {{"hull.length", "m", ParamKind::Real}};
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

}  // namespace maris::study::test
