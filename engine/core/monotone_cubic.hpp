// Monotone piecewise-cubic Hermite interpolation (PCHIP): shape preserving, so tabulated data that are
// non-negative or monotone stay so between the nodes (no spline overshoot next to a keel or a peak).
#pragma once

#include <vector>

namespace maris {

// Through (x_k, y_k) with x strictly increasing and n ≥ 2. Slopes: Fritsch & Butland (1984) weighted
// harmonic mean inside, the limited three-point formula at the ends (Fritsch & Carlson 1980 monotonicity).
class MonotoneCubic {
 public:
  MonotoneCubic() = default;
  MonotoneCubic(std::vector<double> x, std::vector<double> y);

  // Inside [x_0, x_{n-1}] the interpolant; outside it the nearest end value.
  double operator()(double x) const;
  // Inside the interpolant; outside `outside` (e.g. 0 for a half-breadth beyond the hull).
  double valueOr(double x, double outside) const;

  const std::vector<double>& nodes() const { return x_; }
  const std::vector<double>& values() const { return y_; }

 private:
  double inside(double x) const;
  std::vector<double> x_, y_, slope_;
};

}  // namespace maris
