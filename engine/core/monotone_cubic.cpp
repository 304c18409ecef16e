#include "core/monotone_cubic.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace maris {

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
  const std::size_t n = x_.size();
  assert(n >= 2 && y_.size() == n);
  std::vector<double> h(n - 1), delta(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x_[k + 1] - x_[k];
    assert(h[k] > 0.0);
    delta[k] = (y_[k + 1] - y_[k]) / h[k];
  }
  slope_.assign(n, 0.0);
  if (n == 2) {
    slope_[0] = slope_[1] = delta[0];
    return;
  }
  // Interior: zero at a local extremum (secants of opposite sign), else the weighted harmonic mean.
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (delta[k - 1] * delta[k] <= 0.0) continue;
    const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
    slope_[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k]);
  }
  // Ends: the one-sided three-point slope, limited so the end interval stays monotone.
  auto endSlope = [](double h0, double h1, double d0, double d1) {
    const double d = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (d * d0 <= 0.0) return 0.0;
    if (d0 * d1 <= 0.0 && std::abs(d) > 3.0 * std::abs(d0)) return 3.0 * d0;
    return d;
  };
  slope_[0] = endSlope(h[0], h[1], delta[0], delta[1]);
  slope_[n - 1] = endSlope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
}

double MonotoneCubic::inside(double x) const {
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  std::size_t k = it == x_.begin() ? 0 : static_cast<std::size_t>(it - x_.begin()) - 1;
  k = std::min(k, x_.size() - 2);
  const double h = x_[k + 1] - x_[k], t = (x - x_[k]) / h;
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  return h00 * y_[k] + h10 * h * slope_[k] + h01 * y_[k + 1] + h11 * h * slope_[k + 1];
}

double MonotoneCubic::operator()(double x) const {
  if (x <= x_.front()) return y_.front();
  if (x >= x_.back()) return y_.back();
  return inside(x);
}

double MonotoneCubic::valueOr(double x, double outside) const {
  if (x < x_.front() || x > x_.back()) return outside;
  return inside(x);
}

}  // namespace maris
