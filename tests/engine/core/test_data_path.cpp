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
