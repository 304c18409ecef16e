// Whether the tests run under AddressSanitizer and UndefinedBehaviorSanitizer (the second half of the test
// command, 10 to 20 times slower): tests that size their work by it say why (engine/release_only.hpp).
#pragma once

namespace maris::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace maris::test
