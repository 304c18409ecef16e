// Test helper: the benchmark hull tables in tests/data/hulls (provenance, derivation and terms of every
// file in tests/data/hulls/README.md).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace maris::ship::test_data {

// The text of a file below tests/data/hulls ("kcs/particulars.json"). A missing or unreadable file fails
// the test (and throws, so that nothing runs on empty data): the data is part of the repository.
inline std::string readHullFile(const std::string& relative) {
  const std::string path = std::string(MARIS_SOURCE_DIR) + "/tests/data/hulls/" + relative;
  std::ifstream in(path);
  if (!in.good()) {
    ADD_FAILURE() << "test data file missing or unreadable: " << path;
    throw std::runtime_error("test data file missing: " + path);
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace maris::ship::test_data
