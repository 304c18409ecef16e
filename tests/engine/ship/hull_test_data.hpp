// Test helper: the benchmark hull tables in tests/data/hulls (provenance, derivation and terms of every
// file in tests/data/hulls/README.md).
#pragma once

#include <string>

#include "engine/test_data_file.hpp"

namespace maris::ship::test_data {

// The text of a file below tests/data/hulls ("kcs/particulars.json"); a missing file fails the test.
inline std::string readHullFile(const std::string& relative) { return maris::test_files::readTestDataFile("hulls/" + relative); }

}  // namespace maris::ship::test_data
