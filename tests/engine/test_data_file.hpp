// Test helper: the text of a data file below tests/data (each folder there has a README with the files'
// provenance and terms). A missing or unreadable file fails the test and throws, so that nothing runs on
// empty data: the data is part of the repository.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include "source_tree.hpp"

namespace maris::test_files {

inline std::string readTestDataFile(const std::string& relative) {
  const std::string path = maris::test::sourceDir() + "/tests/data/" + relative;
  std::ifstream in(path, std::ios::binary);
  if (!in.good()) {
    ADD_FAILURE() << "test data file missing or unreadable: " << path;
    throw std::runtime_error("test data file missing: " + path);
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace maris::test_files
