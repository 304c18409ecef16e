// Test helper: the benchmark hull data of /work/shared/data/hulls (see its README for provenance).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace maris::ship::test_data {

// shared/data/hulls: MARIS_SHARED_DIR (<source>/../shared) in the main checkout; a helper work tree sits one
// level deeper (<work>/wt/<name>), so its shared folder is <source>/../../shared.
inline std::string hullsDir() {
  for (const std::string& dir : {std::string(MARIS_SHARED_DIR), std::string(MARIS_SOURCE_DIR) + "/../../shared"})
    if (std::filesystem::exists(dir + "/data/hulls")) return dir + "/data/hulls/";
  ADD_FAILURE() << "shared/data/hulls not found next to " << MARIS_SOURCE_DIR;
  return {};
}

// The text of a file below shared/data/hulls ("kcs/particulars.json").
inline std::string readSharedHullFile(const std::string& relative) {
  std::ifstream in(hullsDir() + relative);
  EXPECT_TRUE(in.good()) << relative;
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace maris::ship::test_data
