#pragma once
// Random numbers that are the same on every platform for the same seed.
//
// std::mt19937_64's sequence is fixed by the C++ standard ([rand.predef]), but the mapping of the standard
// distributions (std::uniform_real_distribution, std::normal_distribution) is left to each library, so a
// seeded sea, design of experiments or noisy measurement would differ between libstdc++, libc++ and MSVC.
// Maris draws from std::mt19937_64 and maps the draws itself, here.

#include <cstdint>
#include <random>

namespace maris {

// The 53 high bits of one mt19937_64 draw, scaled to [0, 1): exact, no rounding.
double uniform01(std::uint64_t draw);

// One standard normal variate (mean 0, variance 1) from two uniform draws by the Box–Muller transform
// (G. E. P. Box, M. E. Muller, "A note on the generation of random normal deviates", Ann. Math. Statist. 29
// (1958) 610–611): z = √(−2 ln u₁) cos(2π u₂) with u₁ in (0, 1]. Uses exactly two draws per variate; the
// result is bitwise the same wherever log, sqrt and cos are (glibc's are correctly rounded in practice;
// another libm may differ in the last bit).
double standardNormal(std::mt19937_64& engine);

}  // namespace maris
