// Tests whose cost lies in repeating, at large n or over long simulated times, code paths that smaller
// tests already run. Their numbers are checked in the Release build. Under AddressSanitizer and
// UndefinedBehaviorSanitizer (the second half of the test command, 10 to 20 times slower) they skip
// with the name of the smaller test that runs the same code paths under the sanitizers; CTest lists them
// as skipped, never as passed.
#pragma once

#include <gtest/gtest.h>

#include "sanitized_build.hpp"

// `covered_by`: the test (Suite.Name) that runs the same code paths under the sanitizers.
#define MARIS_RELEASE_ONLY(covered_by)                                                                   \
  do {                                                                                                   \
    if (::maris::test::kSanitizedBuild)                                                                  \
      GTEST_SKIP() << "numbers checked in the Release build; under the sanitizers " covered_by           \
                      " runs the same code paths";                                                       \
  } while (false)
