// Which Maris this is: the semantic version from CMake's project(VERSION) and, when it was built
// from a git checkout, `git describe --always --dirty` of that checkout at build time.
#pragma once

#include <string>

namespace maris {

// "0.1.0"
std::string projectVersion();
// "1a2b3c4", "1a2b3c4-dirty" (uncommitted changes), "v0.1.0-3-g1a2b3c4" after a tag; "" when not
// built from a git checkout.
std::string commitId();
// "0.1.0 (git 1a2b3c4)", or "0.1.0" without a commit.
std::string versionText();

}  // namespace maris
