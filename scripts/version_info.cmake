# Writes OUT, the header that engine/core/version.cpp includes: the project version (VERSION, from
# CMake's project()) and, when SOURCE_DIR is itself a git checkout, `git describe --always --dirty`
# (empty otherwise, e.g. a source tarball). Run by every build (engine/CMakeLists.txt); OUT is
# rewritten only when its content changes, so an unchanged commit recompiles and relinks nothing.
#   cmake -DSOURCE_DIR=... -DVERSION=0.1.0 -DGIT=/usr/bin/git -DOUT=.../version_info.hpp -P version_info.cmake
set(describe "")
if(GIT AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" describe --always --dirty
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(result EQUAL 0 AND output MATCHES "^[A-Za-z0-9._+-]+$")
    set(describe "${output}")
  endif()
endif()
set(content "// Generated at build time by scripts/version_info.cmake; included by engine/core/version.cpp only.
#define MARIS_PROJECT_VERSION \"${VERSION}\"
#define MARIS_GIT_DESCRIBE \"${describe}\"
")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL content)
  file(WRITE "${OUT}" "${content}")
endif()
