#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/monotone_cubic.hpp"

using maris::MonotoneCubic;

// A step in the data is where a natural spline overshoots; PCHIP must stay within the data range
// (negative half-breadths beside a keel, negative damping beside a peak).
TEST(MonotoneCubic, StepDataNeverOvershoot) {
  const MonotoneCubic f({0, 1, 2, 3, 4}, {0, 0, 1, 1, 1});
  for (double x = 0.0; x <= 4.0; x += 0.01) {
    EXPECT_GE(f(x), -1e-15);
    EXPECT_LE(f(x), 1.0 + 1e-15);
  }
  EXPECT_DOUBLE_EQ(f(0.5), 0.0);  // flat intervals stay flat
  EXPECT_DOUBLE_EQ(f(3.5), 1.0);
}

// Hermite cubics with the secant as slope reproduce straight lines exactly (round-off only).
TEST(MonotoneCubic, ReproducesLinearData) {
  const std::vector<double> x{0.0, 0.3, 1.0, 1.1, 2.5};
  std::vector<double> y;
  for (double xi : x) y.push_back(2.0 - 3.0 * xi);
  const MonotoneCubic f(x, y);
  for (double t = 0.0; t <= 2.5; t += 0.013) EXPECT_NEAR(f(t), 2.0 - 3.0 * t, 1e-13);
}

// Monotone data give a monotone interpolant, even with very uneven node spacing.
TEST(MonotoneCubic, MonotoneDataStayMonotone) {
  const MonotoneCubic f({0.0, 0.01, 0.5, 0.52, 3.0, 3.1}, {0.0, 0.9, 1.0, 5.0, 5.1, 9.0});
  double previous = f(0.0);
  for (double t = 0.001; t <= 3.1; t += 0.001) {
    const double v = f(t);
    EXPECT_GE(v, previous - 1e-12) << "at x = " << t;
    previous = v;
  }
}

// Outside the nodes: the end values, or the caller's value through valueOr().
TEST(MonotoneCubic, EndsClampOrReturnTheGivenValue) {
  const MonotoneCubic f({1.0, 2.0, 3.0}, {4.0, 5.0, 7.0});
  EXPECT_DOUBLE_EQ(f(0.0), 4.0);
  EXPECT_DOUBLE_EQ(f(9.0), 7.0);
  EXPECT_DOUBLE_EQ(f.valueOr(0.5, -1.0), -1.0);
  EXPECT_DOUBLE_EQ(f.valueOr(3.5, -1.0), -1.0);
  EXPECT_DOUBLE_EQ(f.valueOr(2.0, -1.0), 5.0);  // nodes are interpolated exactly
}

// On smooth monotone data the error falls at least as h² (PCHIP's order away from extrema is 3;
// the limited end slopes are second order): halving h must cut the largest error by > 3.5.
TEST(MonotoneCubic, ConvergesOnSmoothData) {
  auto maxError = [](int n) {
    std::vector<double> x(n + 1), y(n + 1);
    for (int i = 0; i <= n; ++i) {
      x[i] = 1.5 * i / n;
      y[i] = std::sin(x[i]);
    }
    const MonotoneCubic f(x, y);
    double e = 0.0;
    for (double t = 0.0; t <= 1.5; t += 1e-4) e = std::max(e, std::abs(f(t) - std::sin(t)));
    return e;
  };
  const double e1 = maxError(10), e2 = maxError(20), e3 = maxError(40);
  EXPECT_LT(e1, 1e-3);
  EXPECT_GT(e1 / e2, 3.5);
  EXPECT_GT(e2 / e3, 3.5);
}
