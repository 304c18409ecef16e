// The portable random draws: the engine's stream is the standard's, the mappings are exact or statistically right.
#include <cmath>
#include <cstddef>
#include <random>

#include <gtest/gtest.h>

#include "core/portable_random.hpp"

using maris::standardNormal;
using maris::uniform01;

TEST(PortableRandom, Mt19937_64AndUniform01AreThePortableStream) {
  // C++ standard [rand.predef]: the 10000th draw of a default-constructed mt19937_64 is 9981545732273789042.
  std::mt19937_64 rng;
  rng.discard(9999);
  EXPECT_EQ(rng(), 9981545732273789042ULL);
  EXPECT_EQ(uniform01(0), 0.0);
  EXPECT_EQ(uniform01(~0ULL), 1.0 - 0x1.0p-53);
  EXPECT_EQ(uniform01(1ULL << 63), 0.5);
}

TEST(PortableRandom, StandardNormalUsesTwoDrawsAndIsFiniteAtTheEnds) {
  std::mt19937_64 a(42), b(42);
  (void)standardNormal(a);
  b.discard(2);
  EXPECT_EQ(a(), b());
  // The largest possible magnitude comes from the smallest u1 = 2^-53: √(−2 ln 2^-53) = 8.57 (finite).
  EXPECT_NEAR(std::sqrt(-2.0 * std::log(0x1.0p-53)), 8.572, 1e-3);
}

TEST(PortableRandom, StandardNormalHasTheNormalMomentsAndDistribution) {
  // N = 400 000 variates. Tolerances are 5 standard errors of each estimate under the normal law:
  // mean σ/√N = 1.6e-3; variance √(2/N) = 2.2e-3; a probability p has √(p(1−p)/N) ≤ 7.9e-4.
  constexpr std::size_t n = 400000;
  std::mt19937_64 rng(20261129u);
  double sum = 0.0, sum2 = 0.0;
  std::size_t within1 = 0, within2 = 0, below_minus1 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double z = standardNormal(rng);
    ASSERT_TRUE(std::isfinite(z));
    sum += z;
    sum2 += z * z;
    within1 += std::abs(z) < 1.0;
    within2 += std::abs(z) < 2.0;
    below_minus1 += z < -1.0;
  }
  const double count = static_cast<double>(n);
  const double mean = sum / count;
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(count));
  EXPECT_NEAR(sum2 / count - mean * mean, 1.0, 5.0 * std::sqrt(2.0 / count));
  // Φ(1) − Φ(−1) = erf(1/√2), Φ(2) − Φ(−2) = erf(√2), Φ(−1) = ½ erfc(1/√2).
  const double tolerance = 5.0 * std::sqrt(0.25 / count);
  EXPECT_NEAR(static_cast<double>(within1) / count, std::erf(1.0 / std::sqrt(2.0)), tolerance);
  EXPECT_NEAR(static_cast<double>(within2) / count, std::erf(std::sqrt(2.0)), tolerance);
  EXPECT_NEAR(static_cast<double>(below_minus1) / count, 0.5 * std::erfc(1.0 / std::sqrt(2.0)), tolerance);
}
