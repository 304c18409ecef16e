// Whole studies: the base scenario (built-in, file, inline), "set", every problem of a bad study at once,
// and every bad case named before anything runs.
#include "core/resources.hpp"
#include "study_test_util.hpp"

namespace maris::study::test {

// Outside the anonymous namespace: its TEST_F classes have external linkage (GCC -Wsubobject-linkage).
class StudyCases : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findBuiltin("ship_default")) GTEST_SKIP() << "needs the ship scene";
  }
};

TEST_F(StudyCases, CaseIdsAndRanges) {
  EXPECT_EQ(caseId(0, 12), "0001");
  EXPECT_EQ(caseId(9999, 10000), "10000");
  EXPECT_EQ(caseId(0, 10000), "00001");
  EXPECT_EQ(caseRanges({0, 1, 2, 5, 7, 8}, 10), "0001-0003, 0006, 0008, 0009");
}

TEST_F(StudyCases, ABadStudyReportsEveryProblemAtOnce) {
  const Json document = {{"format", "maris-study/2"},
                         {"base", "ship_defualt"},
                         {"gird", {{"hull.length", {2, 3}}}},
                         {"results", {"c_total", "c_total"}}};
  const std::string text = inputErrorText([&] { studyFromJson(document, "."); });
  EXPECT_NE(text.find("format"), std::string::npos) << text;
  EXPECT_NE(text.find("did you mean 'ship_default'"), std::string::npos) << text;
  EXPECT_NE(text.find("gird"), std::string::npos) << text;
  EXPECT_NE(text.find("did you mean 'grid'"), std::string::npos) << text;
  EXPECT_NE(text.find("results[1]"), std::string::npos) << text;
  EXPECT_NE(text.find("a study needs one design"), std::string::npos) << text;

  Json both = studyOver("ship_default", "grid", {{"hull.lenght", {2}}, {"hull.beam", {{"from", -1}, {"to", 1}, {"count", 3}, {"spacing", "log"}}}});
  both["latin_hypercube"] = Json::object();
  const std::string two = inputErrorText([&] { studyFromJson(both, "."); });
  EXPECT_NE(two.find("cannot be combined"), std::string::npos) << two;
  const std::string grid = inputErrorText([&] {
    studyFromJson(studyOver("ship_default", "grid", {{"hull.lenght", {2}}, {"hull.beam", {{"from", -1}, {"to", 1}, {"count", 3}, {"spacing", "log"}}}}), ".");
  });
  EXPECT_NE(grid.find("grid.hull.lenght: is not a parameter of scene 'ship'; did you mean 'hull.length'?"),
            std::string::npos) << grid;
  EXPECT_NE(grid.find("grid.hull.beam.spacing"), std::string::npos) << grid;
  const std::string lhs = inputErrorText([&] {
    studyFromJson(studyOver("ship_default", "latin_hypercube", {{"count", 0}, {"bounds", {{"water.kind", {0, 1}}}}}), ".");
  });
  EXPECT_NE(lhs.find("latin_hypercube.count"), std::string::npos) << lhs;
  EXPECT_NE(lhs.find("latin_hypercube.seed: is missing"), std::string::npos) << lhs;
  EXPECT_NE(lhs.find("latin_hypercube.bounds.water.kind"), std::string::npos) << lhs;
}

TEST_F(StudyCases, EveryBadCaseIsNamedBeforeAnythingRuns) {
  // hull.length must lie in (0, 1000] m: cases 2 and 4 are out of range, found by the scene's own schema.
  const Study study = studyFromJson(studyOver("ship_default", "grid", {{"hull.length", {2, -1, 3, 5000}}}), ".");
  const auto cases = expandStudy(study);
  const auto errors = caseErrors(study, cases, false);
  ASSERT_EQ(errors.size(), 3u) << describeErrors(errors);
  EXPECT_EQ(errors[0].path, "cases");
  EXPECT_NE(errors[0].message.find("2 of 4 cases are invalid: 0002, 0004"), std::string::npos) << errors[0].message;
  EXPECT_EQ(errors[1].path, "case 0002: parameters.hull.length");
  EXPECT_EQ(errors[2].path, "case 0004: parameters.hull.length");
}

TEST_F(StudyCases, TooManyCasesAreRefusedBeforeExpansion) {
  const Json big = {{"from", 1}, {"to", 2}, {"count", 1000}};
  const std::string text = inputErrorText(
      [&] { studyFromJson(studyOver("ship_default", "grid", {{"hull.length", big}, {"hull.beam", {{"from", 0.1}, {"to", 0.2}, {"count", 1000}}}}), "."); });
  EXPECT_NE(text.find("the limit is 100000"), std::string::npos) << text;
}

// A base file is found beside the study, its data paths beside itself; "set" and the varied values'
// data paths are relative to the study's folder; an inline base works as a file would.
TEST_F(StudyCases, BaseFilesSetValuesAndDataPathsResolveAgainstTheirFolders) {
  ScratchFolder folder("maris_study_base");
  std::filesystem::create_directories(folder.path / "hulls");
  Scenario base = findBuiltin("ship_default")->scenario;
  base.parameters["hull"]["source"] = "offsets_file";
  base.parameters["hull"]["offsets_file"] = "wigley.csv";
  saveScenarioFile(base, folder.path / "hulls" / "base.json");
  Json document = studyOver("hulls/base.json", "grid", {{"hull.length", {2, 3}}});
  document["set"] = {{"measured.file", "points.csv"}, {"parameters.hull.beam", 0.5}};
  const Study study = studyFromJson(document, folder.path);
  EXPECT_EQ(study.base_origin, "file " + (folder.path / "hulls" / "base.json").string());
  const auto cases = expandStudy(study);
  ASSERT_EQ(cases.size(), 2u);
  const Json& p = cases[1].scenario.parameters;
  EXPECT_EQ(p["hull"]["offsets_file"], (folder.path / "hulls" / "wigley.csv").string());
  EXPECT_EQ(p["measured"]["file"], (folder.path / "points.csv").string());
  EXPECT_EQ(p["hull"]["beam"].get<double>(), 0.5);
  EXPECT_EQ(p["hull"]["length"].get<double>(), 3.0);
  // The data files do not exist: every case says so, naming the field.
  const auto errors = caseErrors(study, cases, false);
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(describeErrors(errors).find("case 0001: parameters.hull.offsets_file"), std::string::npos)
      << describeErrors(errors);

  Json inline_base = scenarioToJson(findBuiltin("ship_default")->scenario);
  Json with_inline = studyOver("ship_default", "grid", {{"water.kind", {"sea"}}});
  with_inline["base"] = inline_base;
  const Study from_inline = studyFromJson(with_inline, folder.path);
  EXPECT_EQ(from_inline.base_origin, "inline");
  EXPECT_TRUE(caseErrors(from_inline, expandStudy(from_inline), false).empty());
  inline_base.erase("scene");
  with_inline["base"] = inline_base;
  const std::string text = inputErrorText([&] { studyFromJson(with_inline, folder.path); });
  EXPECT_NE(text.find("base.scene"), std::string::npos) << text;
}

}  // namespace maris::study::test

namespace maris::study::test {

// The desktop application's first study files (Maris 0.2.0) wrote the base as {"scenario": {...}},
// {"builtin": id} or {"file": path}: each reads as the plain form gives the same cases.
TEST_F(StudyCases, BaseFormsOfTheFirstDesktopStudyFilesReadAsThePlainForms) {
  ScratchFolder folder("maris_study_old_base");
  const Scenario builtin = findBuiltin("ship_default")->scenario;
  saveScenarioFile(builtin, folder.path / "base.json");
  const Json grid = {{"hull.length", {2, 3}}};
  const auto plain = expandStudy(studyFromJson(studyOver("ship_default", "grid", grid), folder.path));
  for (const Json& base : {Json{{"builtin", "ship_default"}}, Json{{"file", "base.json"}},
                           Json{{"scenario", scenarioToJson(builtin)}}}) {
    Json document = studyOver("ship_default", "grid", grid);
    document["base"] = base;
    const auto cases = expandStudy(studyFromJson(document, folder.path));
    ASSERT_EQ(cases.size(), plain.size()) << base.dump();
    for (std::size_t c = 0; c < cases.size(); ++c)
      EXPECT_EQ(cases[c].scenario.parameters, plain[c].scenario.parameters) << base.dump();
  }
}

// A study over scenes the caller supplies (the desktop application's library): the scene comes from
// the source, and a name the source does not know is refused even if the catalog has it.
TEST_F(StudyCases, AStudyFindsItsSceneThroughTheSourceItIsGiven) {
  ScratchFolder folder("maris_study_source");
  const SceneDefinition* ship = findScene(findBuiltin("ship_default")->scenario.scene);
  ASSERT_NE(ship, nullptr);
  SceneSource only_ship;
  only_ship.scene = [ship](const std::string& name) { return name == ship->name ? ship : nullptr; };
  only_ship.builtin = [](const std::string&) -> const Scenario* { return nullptr; };
  only_ship.builtin_ids = [] { return std::vector<std::string>(); };
  Json document = studyOver("ship_default", "grid", {{"hull.length", {2, 3}}});
  document["base"] = scenarioToJson(findBuiltin("ship_default")->scenario);
  const Study study = studyFromJson(document, folder.path, only_ship);
  EXPECT_EQ(study.scene, ship);
  EXPECT_EQ(expandStudy(study).size(), 2u);
  // A built-in name is looked up in the source too: this one has none.
  const std::string text =
      inputErrorText([&] { studyFromJson(studyOver("ship_default", "grid", {{"hull.length", {2}}}), folder.path, only_ship); });
  EXPECT_NE(text.find("base"), std::string::npos) << text;
}

}  // namespace maris::study::test
