// Helpers of the study tests: a study document over a built-in base, parsed as if from a folder.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "catalog.hpp"
#include "core/errors.hpp"
#include "study/study.hpp"

namespace maris::study::test {

// The messages of an InputError thrown by `f`, one per line ("" if nothing was thrown).
template <class F>
std::string inputErrorText(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return describeErrors(e.errors());
  }
  return "";
}

inline Json studyOver(const std::string& base, const char* design, Json value) {
  return Json{{"format", kStudyFormat}, {"name", "test"}, {"base", base}, {design, std::move(value)}};
}

// A fresh folder under the temporary directory, removed by the destructor.
struct ScratchFolder {
  std::filesystem::path path;
  explicit ScratchFolder(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() { std::filesystem::remove_all(path); }
  void write(const std::string& file, const std::string& text) const { std::ofstream(path / file) << text; }
};

}  // namespace maris::study::test
