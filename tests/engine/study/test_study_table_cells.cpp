// One cell of a table field as a varied parameter ("current.profile[1].speed"): the cell is set in each case
// and the table's other cells are the base's; a cell's value is checked against its column's range; a row that
// the base does not have, a column that the table does not have and a malformed cell path are refused by name.
#include "study_test_util.hpp"

namespace maris::study::test {

namespace {

// The riser in a sea with a four-row current profile (depth 0, 50, 150, 300 m; speed 0.8, 0.6, 0.3, 0.1 m/s).
constexpr const char* kBase = "riser_vessel_rao_sea";

}  // namespace

// Outside the anonymous namespace: its TEST_F classes have external linkage (GCC -Wsubobject-linkage).
class StudyTableCells : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findBuiltin(kBase)) GTEST_SKIP() << "needs the riser scene";
  }
  static Study read(const Json& document) { return studyFromJson(document, std::filesystem::temp_directory_path()); }
  static const Json& profile(const StudyCase& c) { return c.scenario.parameters["current"]["profile"]; }
};

TEST_F(StudyTableCells, AGridOverOneCellSetsThatCellAndKeepsTheOthers) {
  const Json base_profile = findBuiltin(kBase)->scenario.parameters["current"]["profile"];
  ASSERT_EQ(base_profile.size(), 4u);
  const Study study =
      read(studyOver(kBase, "grid", {{"parameters.current.profile[1].speed", {0.2, 0.4, 1.2}},
                                     {"waves.significant_height", {2.0, 3.0}}}));
  ASSERT_EQ(study.parameters.size(), 2u);
  EXPECT_EQ(study.parameters[0].path, "current.profile[1].speed");  // "parameters." dropped, as for fields
  EXPECT_EQ(study.parameters[0].unit, "m/s");                        // the column's unit
  EXPECT_EQ(study.parameters[0].kind, ParamKind::Real);
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 6u);
  const double speeds[] = {0.2, 0.2, 0.4, 0.4, 1.2, 1.2};
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Json& rows = profile(cases[c]);
    ASSERT_EQ(rows.size(), 4u) << c;
    EXPECT_EQ(rows[1]["speed"].get<double>(), speeds[c]) << c;
    EXPECT_EQ(rows[1]["depth"], base_profile[1]["depth"]) << c;
    EXPECT_EQ(rows[1]["heading_deg"], base_profile[1]["heading_deg"]) << c;
    for (std::size_t r : {0u, 2u, 3u}) EXPECT_EQ(rows[r], base_profile[r]) << c << " row " << r;
  }
  EXPECT_TRUE(caseErrors(study, cases, false).empty()) << describeErrors(caseErrors(study, cases, false));
}

TEST_F(StudyTableCells, ACellInATableDesignAndInSetAndItsColumnsRange) {
  ScratchFolder folder("maris_study_table_cells");
  {
    std::ofstream(folder.path / "cells.csv") << "current.profile[0].speed,current.profile[3].heading_deg\n"
                                                "m/s,deg\n0.5,0\n25,90\n";
  }
  Json document = studyOver(kBase, "table", "cells.csv");
  document["set"] = {{"current.profile[2].depth", 120.0}};
  const Study study = studyFromJson(document, folder.path);
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(profile(cases[0])[0]["speed"].get<double>(), 0.5);
  EXPECT_EQ(profile(cases[1])[3]["heading_deg"].get<double>(), 90.0);
  EXPECT_EQ(profile(cases[1])[2]["depth"].get<double>(), 120.0);  // "set" changed one cell of the base
  // A speed of 25 m/s is outside the column's range [-20, 20]: case 0002 is refused, named with the cell.
  const std::string errors = describeErrors(caseErrors(study, cases, false));
  EXPECT_NE(errors.find("1 of 2 cases are invalid: 0002"), std::string::npos) << errors;
  EXPECT_NE(errors.find("case 0002: parameters.current.profile[0].speed = 25"), std::string::npos) << errors;
}

TEST_F(StudyTableCells, BadCellPathsAreRefusedByName) {
  const auto text = [&](const char* path) {
    return inputErrorText([&] { read(studyOver(kBase, "grid", {{path, {0.1, 0.2}}})); });
  };
  EXPECT_NE(text("current.profile[4].speed").find("row 4 is not in the base scenario's current.profile, which has 4 rows"),
            std::string::npos) << text("current.profile[4].speed");
  EXPECT_NE(text("current.profile[1].sped").find("sped is not a column of current.profile; did you mean 'speed'?"),
            std::string::npos) << text("current.profile[1].sped");
  EXPECT_NE(text("current.profle[1].speed").find("current.profle is not a table of scene 'riser'; did you mean "
                                                 "'current.profile'?"),
            std::string::npos) << text("current.profle[1].speed");
  for (const char* malformed : {"current.profile[x].speed", "current.profile[1]", "current.profile[1.speed",
                                "current.profile[-1].speed", "[1].speed"})
    EXPECT_NE(text(malformed).find("a cell of a table is written TABLE[ROW].COLUMN"), std::string::npos)
        << malformed << ": " << text(malformed);
  // The whole table is still refused as a design parameter, with the cell form proposed.
  EXPECT_NE(text("current.profile").find("is a table; a design varies single values, such as one cell "
                                         "(current.profile[0].depth)"),
            std::string::npos) << text("current.profile");
}

// A study names its parameters for people by the scene's schema: a field by its label, a cell by its column's
// label, the table and the row counted from 1 (as the parameter editor numbers rows); the same from the schema
// alone (what a study folder written without labels gets), and nothing for a path the schema lacks.
TEST_F(StudyTableCells, ParametersCarryTheSchemasLabelsAndACellItsTableAndRow) {
  const Study study =
      read(studyOver(kBase, "grid", {{"parameters.current.profile[1].speed", {0.2, 0.4}},
                                     {"waves.significant_height", {2.0, 3.0}}}));
  ASSERT_EQ(study.parameters.size(), 2u);
  EXPECT_EQ(study.parameters[0].label, "Speed of current profile row 2");
  EXPECT_EQ(study.parameters[1].label, "Significant wave height H_s");
  const Schema& schema = study.scene->schema;
  EXPECT_EQ(studyParameterLabel(schema, "current.profile[1].speed"), "Speed of current profile row 2");
  EXPECT_EQ(studyParameterLabel(schema, "parameters.waves.significant_height"), "Significant wave height H_s");
  EXPECT_EQ(studyParameterLabel(schema, "geometry.length"), "Length L");
  EXPECT_EQ(studyParameterLabel(schema, "no.such_field"), "");
  EXPECT_EQ(displayLabel(StudyParameter{"no.such_field", "m", ParamKind::Real, ""}), "no.such_field");
}

}  // namespace maris::study::test
