// The three designs of a study: counts, values, order, units and seeds. Expected values are closed
// forms (evenly spaced values, powers of ten) or properties of the design (one sample per stratum).
#include <cmath>
#include <random>
#include <set>

#include "study_test_util.hpp"

namespace maris::study::test {

// The ship scene's built-in scenario is the base: fields of every kind (number, integer, choice).
// Outside the anonymous namespace: its TEST_F classes have external linkage (GCC -Wsubobject-linkage).
class StudyDesign : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findBuiltin("ship_default")) GTEST_SKIP() << "needs the ship scene";
  }
  static Study read(const Json& document) { return studyFromJson(document, std::filesystem::temp_directory_path()); }
};

TEST_F(StudyDesign, GridIsTheFullFactorialWithTheLastParameterFastest) {
  const Study study = read(studyOver("ship_default", "grid",
                                     {{"water.kind", {"fresh", "sea"}}, {"hull.length", {{"from", 2}, {"to", 4}, {"count", 3}}}}));
  ASSERT_EQ(study.parameters.size(), 2u);
  EXPECT_EQ(study.parameters[0].path, "hull.length");  // alphabetical order of path
  EXPECT_EQ(study.parameters[0].unit, "m");
  EXPECT_EQ(study.parameters[1].path, "water.kind");
  EXPECT_EQ(study.parameters[1].unit, "-");
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 6u);
  const double lengths[] = {2, 2, 3, 3, 4, 4};
  const char* kinds[] = {"fresh", "sea", "fresh", "sea", "fresh", "sea"};
  for (std::size_t c = 0; c < 6; ++c) {
    EXPECT_EQ(cases[c].id, caseId(c, 6));
    EXPECT_EQ(cases[c].values[0].get<double>(), lengths[c]) << c;  // (2a + 4b)/2 is exact
    EXPECT_EQ(cases[c].values[1], kinds[c]) << c;
    EXPECT_EQ(cases[c].scenario.parameters["hull"]["length"].get<double>(), lengths[c]);
    EXPECT_EQ(cases[c].scenario.parameters["water"]["kind"], kinds[c]);
    EXPECT_EQ(cases[c].scenario.scene, "ship");
  }
  EXPECT_EQ(cases[0].id, "0001");
  EXPECT_TRUE(caseErrors(study, cases, false).empty());
}

TEST_F(StudyDesign, LogSpacingIsEvenInTheLogarithmWithExactEnds) {
  const Study study = read(studyOver("ship_default", "grid",
                                     {{"hull.beam", {{"from", 0.1}, {"to", 10}, {"count", 5}, {"spacing", "log"}}}}));
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 5u);
  EXPECT_EQ(cases.front().values[0].get<double>(), 0.1);
  EXPECT_EQ(cases.back().values[0].get<double>(), 10.0);
  for (int i = 0; i < 5; ++i) {
    const double expected = std::pow(10.0, -1.0 + 0.5 * i);  // closed form 10^(-1 + i/2)
    EXPECT_NEAR(cases[i].values[0].get<double>(), expected, 4e-16 * expected) << i;
  }
}

TEST_F(StudyDesign, IntegerRangesGiveWholeNumbersAndRefuseRepeats) {
  const Study study = read(studyOver("ship_default", "grid", {{"speed.count", {{"from", 2}, {"to", 10}, {"count", 5}}}}));
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_TRUE(cases[i].values[0].is_number_integer()) << cases[i].values[0];
    EXPECT_EQ(cases[i].values[0].get<long long>(), 2 + 2 * i);
  }
  const std::string text = inputErrorText(
      [] { read(studyOver("ship_default", "grid", {{"speed.count", {{"from", 2}, {"to", 4}, {"count", 5}}}})); });
  EXPECT_NE(text.find("grid.speed.count.count"), std::string::npos) << text;
  EXPECT_NE(text.find("repeated whole numbers"), std::string::npos) << text;
}

// mt19937_64's sequence is fixed by the C++ standard ([rand.predef]: the 10000th output of a
// default-constructed engine is 9981545732273789042), so a seed gives the same sample everywhere.
TEST_F(StudyDesign, LatinHypercubeHasOneSamplePerStratumAndRepeatsForASeed) {
  std::mt19937_64 reference;
  reference.discard(9999);
  ASSERT_EQ(reference(), 9981545732273789042ull);

  const Json bounds = {{"hull.length", {2, 4}}, {"hull.beam", {{"from", 0.1}, {"to", 1}, {"spacing", "log"}}}};
  const Json design = {{"count", 20}, {"seed", 42}, {"bounds", bounds}};
  const auto cases = expandStudy(read(studyOver("ship_default", "latin_hypercube", design)));
  ASSERT_EQ(cases.size(), 20u);
  std::set<int> length_strata, beam_strata;
  for (const auto& c : cases) {
    const double beam = c.values[0].get<double>(), length = c.values[1].get<double>();  // hull.beam < hull.length
    ASSERT_GE(length, 2.0);
    ASSERT_LE(length, 4.0);
    ASSERT_GE(beam, 0.1);
    ASSERT_LE(beam, 1.0);
    length_strata.insert(static_cast<int>(std::floor((length - 2.0) / 2.0 * 20)));
    beam_strata.insert(static_cast<int>(std::floor(std::log(beam / 0.1) / std::log(10.0) * 20)));
  }
  EXPECT_EQ(length_strata.size(), 20u);  // every one of the 20 intervals holds exactly one case
  EXPECT_EQ(beam_strata.size(), 20u);    // also in log(beam)

  const auto again = expandStudy(read(studyOver("ship_default", "latin_hypercube", design)));
  for (std::size_t c = 0; c < cases.size(); ++c) EXPECT_EQ(again[c].values, cases[c].values) << c;
  Json other = design;
  other["seed"] = 43;
  const auto different = expandStudy(read(studyOver("ship_default", "latin_hypercube", other)));
  std::size_t same = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) same += different[c].values == cases[c].values;
  EXPECT_LT(same, 2u);
}

TEST_F(StudyDesign, TableRowsAreCasesAndItsPathIsRelativeToTheStudy) {
  ScratchFolder folder("maris_study_table");
  folder.write("loads.csv", "# two hulls in two waters\nhull.length, water.kind\n2.5, fresh\n3.5, sea\n4, sea\n");
  folder.write("numbers.csv", "hull.length;hull.beam\nm;m\n2.5;0.3\n3.5;0.4\n");
  Json document = studyOver("ship_default", "table", "loads.csv");
  const Study study = studyFromJson(document, folder.path);
  EXPECT_EQ(study.table_file, folder.path / "loads.csv");
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(study.parameters[0].path, "hull.length");  // the columns' order
  EXPECT_EQ(cases[1].values[0].get<double>(), 3.5);
  EXPECT_EQ(cases[1].values[1], "sea");
  EXPECT_EQ(cases[2].values[0].get<double>(), 4.0);
  const auto with_units = expandStudy(studyFromJson(studyOver("ship_default", "table", "numbers.csv"), folder.path));
  ASSERT_EQ(with_units.size(), 2u);  // the units row is not a case
  EXPECT_EQ(with_units[1].values[1].get<double>(), 0.4);

  folder.write("bad.csv", "hull.lenght,hull.beam\n2,0.3\n");
  folder.write("units.csv", "hull.length\nmm\n2000\n");
  folder.write("ragged.csv", "hull.length,hull.beam\n2,0.3\n3\n");
  const auto bad = inputErrorText([&] { studyFromJson(studyOver("ship_default", "table", "bad.csv"), folder.path); });
  EXPECT_NE(bad.find("did you mean 'hull.length'"), std::string::npos) << bad;
  const auto units = inputErrorText([&] { studyFromJson(studyOver("ship_default", "table", "units.csv"), folder.path); });
  EXPECT_NE(units.find("unit 'm'"), std::string::npos) << units;
  const auto ragged = inputErrorText([&] { studyFromJson(studyOver("ship_default", "table", "ragged.csv"), folder.path); });
  EXPECT_NE(ragged.find("table line 3"), std::string::npos) << ragged;
  const auto missing = inputErrorText([&] { studyFromJson(studyOver("ship_default", "table", "none.csv"), folder.path); });
  EXPECT_NE(missing.find("table"), std::string::npos) << missing;
}

// A table study's weight column ("weighted_sum"): read per case, not a parameter (no column in the cases'
// values, nothing set in the scenarios); a weight that is no number >= 0, a weight column the table lacks and a
// weighted sum without a table are refused by name.
TEST_F(StudyDesign, ATablesWeightColumnIsReadPerCaseAndIsNoParameter) {
  ScratchFolder folder("maris_study_weights");
  folder.write("seas.csv", "hull.length,probability\nm,-\n2.5,0.7\n3.5,0.3\n");
  folder.write("negative.csv", "hull.length,probability\n2.5,-0.1\n3.5,x\n");
  Json document = studyOver("ship_default", "table", "seas.csv");
  document["weighted_sum"] = {{"weight", "probability"}, {"results", {"c_total"}}};
  const Study study = studyFromJson(document, folder.path);
  ASSERT_EQ(study.parameters.size(), 1u);
  EXPECT_EQ(study.parameters[0].path, "hull.length");
  EXPECT_EQ(study.weight_column, "probability");
  EXPECT_EQ(study.weights, (std::vector<double>{0.7, 0.3}));
  EXPECT_EQ(study.weighted_results, (std::vector<std::string>{"c_total"}));
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[1].values, (std::vector<Json>{Json(3.5)}));

  Json negative = document;
  negative["table"] = "negative.csv";
  const auto bad = inputErrorText([&] { studyFromJson(negative, folder.path); });
  EXPECT_NE(bad.find("table line 2, column probability = -0.1"), std::string::npos) << bad;
  EXPECT_NE(bad.find("table line 3, column probability = x: must be a weight"), std::string::npos) << bad;
  Json other = document;
  other["weighted_sum"]["weight"] = "probabilty";
  const auto misspelt = inputErrorText([&] { studyFromJson(other, folder.path); });
  EXPECT_NE(misspelt.find("is not a column of the table; did you mean 'probability'?"), std::string::npos) << misspelt;
  Json grid = studyOver("ship_default", "grid", {{"hull.length", {2.5, 3.5}}});
  grid["weighted_sum"] = document["weighted_sum"];
  const auto no_table = inputErrorText([&] { studyFromJson(grid, folder.path); });
  EXPECT_NE(no_table.find("weighted_sum"), std::string::npos) << no_table;
  EXPECT_NE(no_table.find("needs a \"table\""), std::string::npos) << no_table;
}

// A study folder's record (the study.json that `study run` writes) given where a study file belongs: one message
// saying what it is and which study file it was run from, instead of every field a study file lacks; `validate`
// takes it for a study (not a scenario) to say so.
TEST_F(StudyDesign, AStudyFoldersRecordIsNamedAsSuchNotReadAsAStudy) {
  const Json record = {{"format", "maris-study-run/1"}, {"study_file", "/data/grid.json"}, {"case_count", 20},
                       {"runs", Json::array()}};
  EXPECT_TRUE(isStudyDocument(record));
  const auto text = inputErrorText([&] { studyFromJson(record, "/"); });
  EXPECT_NE(text.find("is a study folder's record"), std::string::npos) << text;
  EXPECT_NE(text.find("run from /data/grid.json"), std::string::npos) << text;
  EXPECT_EQ(text.find("case_count"), std::string::npos) << text;
  EXPECT_FALSE(isStudyDocument(Json{{"format", "maris-scenario/1"}}));
}

// The header of a table's CSV file, as a front end offers its columns for the weight: split as the table is
// (here at ';', after comment and blank lines), cells trimmed; a file without a header row is refused by name.
TEST_F(StudyDesign, TableColumnsAreTheHeaderRowsCells) {
  ScratchFolder folder("maris_study_columns");
  folder.write("seas.csv", "# sea states\n\nhull.length ; probability\nm;-\n2.5;0.7\n");
  folder.write("empty.csv", "# only a comment\n");
  EXPECT_EQ(tableColumns(folder.path / "seas.csv"), (std::vector<std::string>{"hull.length", "probability"}));
  const auto empty = inputErrorText([&] { tableColumns(folder.path / "empty.csv"); });
  EXPECT_NE(empty.find("has no header row"), std::string::npos) << empty;
  const auto missing = inputErrorText([&] { tableColumns(folder.path / "none.csv"); });
  EXPECT_NE(missing.find("table"), std::string::npos) << missing;
}

}  // namespace maris::study::test
