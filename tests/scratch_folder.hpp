// A fresh, empty folder for the running test, under the system's temporary folder: named by the process and
// the test (ctest runs the tests of one executable in parallel processes), emptied if a killed earlier run
// left it. The fixture removes it in TearDown.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace maris::test {

inline std::filesystem::path freshTestFolder(const std::string& prefix) {
  const auto folder = std::filesystem::temp_directory_path() /
                      (prefix + std::to_string(::getpid()) + "_" +
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace maris::test
