#include "core/version.hpp"

// The only file that includes the generated header: a new commit recompiles this file alone.
#include "version_info.hpp"

namespace maris {

std::string projectVersion() { return MARIS_PROJECT_VERSION; }

std::string commitId() { return MARIS_GIT_DESCRIBE; }

std::string versionText() {
  const std::string commit = commitId();
  return commit.empty() ? projectVersion() : projectVersion() + " (git " + commit + ")";
}

}  // namespace maris
