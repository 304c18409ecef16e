// The fixture of the study command-line tests that run cases: a fresh scratch folder per test, removed after it,
// and a skip where the quick built-in scene is not part of the build.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "catalog.hpp"
#include "cli_runner.hpp"
#include "scratch_folder.hpp"

namespace maris::test {

class StudyTestFolder : public ::testing::Test {
 protected:
  explicit StudyTestFolder(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    if (!findBuiltin(kQuickBuiltin)) GTEST_SKIP() << "needs the riser scene";
    dir_ = freshTestFolder(prefix_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace maris::test
