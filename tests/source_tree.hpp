// Where a test finds the source tree (its data files) and the built maris-cli: relative to the test
// executable's own folder. CMake passes only relative paths (e.g. "../../.."), never absolute ones, so the
// compile line of every test file is the same in every clone with the same build layout, and a shared
// compiler cache (ccache) serves a fresh clone's tests as well as its engine.
#pragma once

#include <filesystem>
#include <string>

namespace maris::test {

inline std::filesystem::path executableFolder() { return std::filesystem::canonical("/proc/self/exe").parent_path(); }

// The source tree's root, absolute and without a trailing separator.
inline std::string sourceDir() { return std::filesystem::canonical(executableFolder() / MARIS_SOURCE_FROM_BINARY).string(); }

#ifdef MARIS_CLI_FROM_BINARY
// The maris-cli of the same build.
inline std::string cliPath() { return (executableFolder() / MARIS_CLI_FROM_BINARY).lexically_normal().string(); }
#endif

}  // namespace maris::test
