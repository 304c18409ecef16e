// When a study's case counts as complete. The study runner syncs its cases in batches, so after a power
// loss a case folder can hold a summary.json that is empty or cut short: such a case is not complete
// (`--resume` runs it again) and collecting counts it as not run, not as a result.
#include "study/study_collect.hpp"
#include "study/study_folder.hpp"
#include "study_test_util.hpp"

namespace maris::study::test {

TEST(StudyFolder, ACaseIsCompleteOnlyWhenItsSummaryParsesAsAJsonObject) {
  const ScratchFolder scratch("maris_study_folder_complete");
  const StudyFolder folder{scratch.path};
  const std::string summary =
      R"({"results": {"tip_deflection": {"value": 0.25, "unit": "m"}, "note": {"text": "x"}}})" "\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0002", ""},                                     // zero length: renamed into place, data not on the disk
      {"0003", summary.substr(0, summary.size() / 2)},  // cut short
      {"0004", "[1, 2]\n"},                             // JSON, not an object
      {"0005", summary}};
  std::filesystem::create_directories(folder.caseRun("0001"));  // a folder without summary.json
  for (const auto& [id, text] : cases) {
    std::filesystem::create_directories(folder.caseRun(id));
    scratch.write("cases/" + id + "/summary.json", text);
  }
  for (const char* id : {"0001", "0002", "0003", "0004", "0006"}) EXPECT_FALSE(folder.caseComplete(id)) << id;
  EXPECT_TRUE(folder.caseComplete("0005"));
  ASSERT_TRUE(folder.caseSummary("0005").has_value());
  EXPECT_EQ((*folder.caseSummary("0005"))["results"]["tip_deflection"]["value"], 0.25);

  // Collected: the torn cases are missing (run again by --resume), the complete one gives its scalar.
  StudyManifest manifest;
  manifest.parameters = {{"geometry.length", "m", ParamKind::Real, ""}};
  for (int i = 1; i <= 6; ++i) {
    manifest.ids.push_back("000" + std::to_string(i));
    manifest.values.push_back({Json(10.0 * i)});
  }
  const CollectedStudy collected = collectStudy(folder, manifest);
  ASSERT_EQ(collected.cases.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(collected.cases[i].status, i == 4 ? CaseStatus::Ok : CaseStatus::Missing) << collected.cases[i].id;
  ASSERT_EQ(collected.result_names, std::vector<std::string>{"tip_deflection"});
  EXPECT_EQ(collected.cases[4].results[0], 0.25);
  EXPECT_EQ(collected.result_labels, std::vector<std::string>{""});  // the summary declares no label
}

// The study's plots label each result as its runs did: the label a case's summary.json declares for the scalar
// ("" where none does, and the plot makes the name readable).
TEST(StudyFolder, CollectedResultsCarryTheLabelsTheirSummariesDeclare) {
  const ScratchFolder scratch("maris_study_folder_labels");
  const StudyFolder folder{scratch.path};
  std::filesystem::create_directories(folder.caseRun("0001"));
  scratch.write("cases/0001/summary.json",
                R"({"results": {"end_z": {"value": -1.5, "unit": "m", "label": "Bottom end z"},)"
                R"( "steps": {"value": 10, "unit": "-"}}})" "\n");
  StudyManifest manifest;
  manifest.parameters = {{"geometry.length", "m", ParamKind::Real, ""}};
  manifest.ids = {"0001"};
  manifest.values = {{Json(10.0)}};
  const CollectedStudy collected = collectStudy(folder, manifest);
  ASSERT_EQ(collected.result_names, (std::vector<std::string>{"end_z", "steps"}));
  EXPECT_EQ(collected.result_labels, (std::vector<std::string>{"Bottom end z", ""}));
  manifest.json = Json{{"design", "table"}};
  const auto plots = studyPlots(collected, manifest);
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0].title, "Bottom end z against geometry.length");
  EXPECT_EQ(plots[1].title, "Steps against geometry.length");  // no labels: the name made readable, the path
  EXPECT_EQ(plots[0].file_stem, "end_z_vs_geometry.length");  // file names keep the result's name
}

}  // namespace maris::study::test
