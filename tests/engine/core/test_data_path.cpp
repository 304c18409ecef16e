#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "core/resources.hpp"

// "builtin:NAME" reads resources/data/<scene>/NAME; an unknown name lists what exists; a file path
// reads the file; an unreadable path is an InputError naming the field.
TEST(DataPath, BuiltinNamesReadTheEmbeddedFile) {
  ASSERT_TRUE(maris::isBuiltinDataPath("builtin:synthetic_kanai_tajimi.csv"));
  EXPECT_FALSE(maris::dataPathProblem("builtin:synthetic_kanai_tajimi.csv", "seismic").has_value());
  const std::string text = maris::readDataText("builtin:synthetic_kanai_tajimi.csv", "seismic", "f");
  EXPECT_EQ(text, std::string(*maris::builtinResource("data/seismic/synthetic_kanai_tajimi.csv")));
}

TEST(DataPath, UnknownBuiltinListsTheAvailableOnes) {
  const auto problem = maris::dataPathProblem("builtin:nope.csv", "seismic");
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("builtin:synthetic_kanai_tajimi.csv"), std::string::npos) << *problem;
  try {
    maris::readDataText("builtin:nope.csv", "seismic", "parameters.input.accelerogram_file");
    FAIL() << "no InputError";
  } catch (const maris::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parameters.input.accelerogram_file"), std::string::npos) << e.what();
  }
}

TEST(DataPath, FilesAreReadAndMissingFilesNamed) {
  const auto file = std::filesystem::temp_directory_path() / "maris_data_path_test.csv";
  std::ofstream(file) << "t,a\n0,1\n";
  EXPECT_FALSE(maris::dataPathProblem(file.string(), "ship").has_value());
  EXPECT_EQ(maris::readDataText(file.string(), "ship", "f"), "t,a\n0,1\n");
  std::filesystem::remove(file);
  EXPECT_TRUE(maris::dataPathProblem(file.string(), "ship").has_value());
  EXPECT_THROW(maris::readDataText(file.string(), "ship", "f"), maris::InputError);
}

// A relative data path becomes absolute against the folder of the file that holds it; built-in names,
// absolute paths, empty text and fields that are not data paths stay as they are.
TEST(DataPath, RelativePathsResolveAgainstTheFilesFolder) {
  maris::Schema schema;
  maris::ParamSpec data;
  data.path = "hull.offsets_file";
  data.kind = maris::ParamKind::Text;
  data.data_path = true;
  maris::ParamSpec name = data;
  name.path = "hull.name";
  name.data_path = false;
  maris::ParamSpec other = data;
  other.path = "measured.file";
  schema.fields = {data, name, other};
  maris::Json parameters = {{"hull", {{"offsets_file", "../data/hull.csv"}, {"name", "hull.csv"}}},
                            {"measured", {{"file", "builtin:kcs.csv"}}}};
  maris::resolveDataPaths(schema, parameters, "/studies/ships");
  EXPECT_EQ(parameters["hull"]["offsets_file"], "/studies/data/hull.csv");
  EXPECT_EQ(parameters["hull"]["name"], "hull.csv");
  EXPECT_EQ(parameters["measured"]["file"], "builtin:kcs.csv");
  parameters["measured"]["file"] = "/abs/file.csv";
  parameters["hull"]["offsets_file"] = "";
  maris::resolveDataPaths(schema, parameters, "/elsewhere");
  EXPECT_EQ(parameters["measured"]["file"], "/abs/file.csv");
  EXPECT_EQ(parameters["hull"]["offsets_file"], "");
}
