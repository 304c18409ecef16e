#include "ship/kelvin_source.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

namespace maris::ship {

namespace {

using Complex = std::complex<double>;

// 8-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun table 25.4).
constexpr std::array<double, 4> kGaussNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                            0.9602898564975363};
constexpr std::array<double, 4> kGaussWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                              0.1012285362903763};

// Nodes and weights of composite 8-point Gauss–Legendre on (a, b).
void compositeGaussRule(double a, double b, int panels, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.clear();
  weights.clear();
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int q = 0; q < 4; ++q)
      for (double sign : {-1.0, 1.0}) {
        nodes.push_back(mid + sign * 0.5 * h * kGaussNodes[q]);
        weights.push_back(0.5 * h * kGaussWeights[q]);
      }
  }
}

// Nodes and weights on (0, 1) graded toward 0: panels [4^{−k−1}, 4^{−k}] for 0 < k < panels − 1 and
// [0, 4^{1−panels}], with [1/4, 1] cut into `outer` equal panels; 8-point Gauss–Legendre on each.
void gradedGaussRule(int panels, int outer, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.clear();
  weights.clear();
  auto add = [&](double left, double right) {
    const double mid = 0.5 * (left + right), half = 0.5 * (right - left);
    for (int q = 0; q < 4; ++q)
      for (double sign : {-1.0, 1.0}) {
        nodes.push_back(mid + sign * half * kGaussNodes[q]);
        weights.push_back(half * kGaussWeights[q]);
      }
  };
  for (int k = 0; k < outer; ++k) add(0.25 + 0.75 * k / outer, 0.25 + 0.75 * (k + 1) / outer);
  double right = 0.25;
  for (int p = 1; p < panels; ++p) {
    const double left = p + 1 < panels ? 0.25 * right : 0.0;
    add(left, right);
    right = left;
  }
}

// A zero imaginary part is read as +0: the value on the cut is E1(x + i0) whatever the sign of the zero.
Complex onUpperEdge(Complex w) { return w.imag() == 0.0 ? Complex(w.real(), 0.0) : w; }

enum class E1Method { Series, ContinuedFraction, Asymptotic };

// The series converges everywhere but loses digits where |e^{−w}| ≪ e^{|w|} (right half-plane, or far from the
// negative real axis at large |w|): there by at most e^{12} ≈ 2e5 for |w| ≤ 12 in the left half-plane. The
// continued fraction converges slowly near the negative real axis; the asymptotic series, summed to 24 terms
// (12 from |w| = 40), is accurate to 1e-11 from |w| = 25.
E1Method e1Method(Complex w) {
  const double a2 = std::norm(w);
  if (a2 >= 625.0) return E1Method::Asymptotic;
  if (a2 <= 16.0 || (w.real() <= 0 && a2 <= 144.0) || (w.real() < 0 && std::abs(w.imag()) < 0.5 * std::abs(w.real())))
    return E1Method::Series;
  return E1Method::ContinuedFraction;
}

// Σ_{n≥1} (−w)^n / (n n!): E1(w) = −γ − ln w − S(w).
Complex e1Series(Complex w) {
  Complex term = 1.0, sum = 0.0;
  const double stop = std::norm(w);
  for (int n = 1; n < 400; ++n) {
    term *= -w / static_cast<double>(n);
    const Complex add = term / static_cast<double>(n);
    sum += add;
    if (n * n > stop && std::norm(add) < 1e-34 * std::norm(sum)) break;
  }
  return sum;
}

// e^w E1(w) by the continued fraction 1/(w + 1 − 1/(w + 3 − 4/(w + 5 − …))) (modified Lentz; Numerical
// Recipes §6.3).
Complex e1ContinuedFraction(Complex w) {
  Complex b = w + 1.0, c = 1e300, d = 1.0 / b, h = d;
  for (int i = 1; i < 2000; ++i) {
    const double an = -static_cast<double>(i) * i;
    b += 2.0;
    d = 1.0 / (an * d + b);
    c = b + an / c;
    const Complex del = c * d;
    h *= del;
    if (std::norm(del - 1.0) < 1e-30) break;
  }
  return h;
}

// Σ_{n=first}^{N−1} (−1)^n n! / w^{n+1} by Horner's rule in 1/w: e^w E1(w) for first = 0, e^w E1(w) − 1/w for
// first = 1. N = 24 below |w| = 40, 12 above (the terms decrease up to n ≈ |w|).
Complex e1Asymptotic(Complex w, int first) {
  const Complex inv = 1.0 / w;
  const int terms = std::norm(w) >= 1600.0 ? 12 : 24;
  Complex sum = 0.0;
  double factorial = 1.0;
  for (int n = 1; n < terms; ++n) factorial *= n;  // (terms − 1)!
  for (int n = terms - 1; n >= first; --n) {
    sum = sum * inv + ((n % 2) ? -factorial : factorial);
    if (n > 0) factorial /= n;
  }
  // sum = Σ (−1)^n n! inv^{n − first}
  Complex scale = inv;
  for (int n = 0; n < first; ++n) scale *= inv;
  return sum * scale;
}

// e^w E1(w) − 1/w (no cancellation for large |w|, where both are ≈ 1/w).
Complex scaledE1MinusInverse(Complex w) {
  w = onUpperEdge(w);
  if (e1Method(w) == E1Method::Asymptotic) return e1Asymptotic(w, 1);
  return scaledExponentialIntegral(w) - 1.0 / w;
}

// The hull resampled for the local part: stations ξ_i (with a steep ramp at open ends) and waterlines
// η_j uniform from 0 down; slope jumps Δs_ij = s_{i−1}(η_j) − s_i(η_j) of ∂Y/∂ξ at the stations.
struct SheetNodes {
  std::vector<double> xi;
  Eigen::VectorXd eta;
  Eigen::MatrixXd slope_jump;  // stations × waterlines
  double dz = 0;
};

double gridHalfBreadth(const HullGrid& grid, double x, double z) {
  const double s = std::clamp((x - grid.x_aft) / grid.dx, 0.0, grid.nx() - 1.0);
  const double t = std::clamp(-z / grid.dz, 0.0, grid.nz() - 1.0);
  const int i = std::min(static_cast<int>(s), grid.nx() - 2), j = std::min(static_cast<int>(t), grid.nz() - 2);
  const double a = s - i, b = t - j;
  return (1 - a) * (1 - b) * grid.half_breadth(i, j) + a * (1 - b) * grid.half_breadth(i + 1, j) +
         (1 - a) * b * grid.half_breadth(i, j + 1) + a * b * grid.half_breadth(i + 1, j + 1);
}

SheetNodes resampleSheet(const HullGrid& grid, int stations, int waterlines) {
  stations = std::max(stations, 3);
  waterlines = std::max(waterlines, 2);
  const double x0 = grid.x_aft, x1 = grid.x(grid.nx() - 1), dx = (x1 - x0) / (stations - 1);
  SheetNodes s;
  s.dz = grid.depth() / (waterlines - 1);
  s.eta.resize(waterlines);
  for (int j = 0; j < waterlines; ++j) s.eta[j] = -j * s.dz;
  std::vector<Eigen::VectorXd> y;
  auto add = [&](double x, bool zero) {
    s.xi.push_back(x);
    Eigen::VectorXd col(waterlines);
    for (int j = 0; j < waterlines; ++j) col[j] = zero ? 0.0 : gridHalfBreadth(grid, x, s.eta[j]);
    y.push_back(col);
  };
  // Open ends (transom, bulb face) are line sources in the wave part; here they are steep ramps.
  const double ramp = 0.25 * dx;
  bool open_aft = false, open_fore = false;
  for (int j = 0; j < waterlines; ++j) {
    open_aft |= gridHalfBreadth(grid, x0, s.eta[j]) > 0;
    open_fore |= gridHalfBreadth(grid, x1, s.eta[j]) > 0;
  }
  if (open_aft) add(x0 - ramp, true);
  for (int i = 0; i < stations; ++i) add(x0 + i * dx, false);
  if (open_fore) add(x1 + ramp, true);
  const int n = static_cast<int>(s.xi.size());
  s.slope_jump = Eigen::MatrixXd::Zero(n, waterlines);
  for (int p = 0; p + 1 < n; ++p) {
    const Eigen::VectorXd slope = (y[p + 1] - y[p]) / (s.xi[p + 1] - s.xi[p]);
    s.slope_jump.row(p) -= slope.transpose();
    s.slope_jump.row(p + 1) += slope.transpose();
  }
  return s;
}

// The local elevation of the sheet at (x, y): (1/π²) ∫ sec²θ Re Σ_i ∫ Δs_i(η) G(K Z_i) dη dθ with
// G(w) = e^w E1(w) (the primitive in ξ of the source's local term), Z_i = η + i ϖ_i, ϖ_i = (x − ξ_i) cos θ + y sin θ.
// With Δs linear between waterlines the η integral takes the primitives ∫ G dw and ∫ w G dw. G is split as
// 1/w + (G − 1/w):
//  - the 1/w part gives primitives ln w and w; its θ integral is the double-body (rigid-lid) elevation of the sheet,
//    −(1/π k0) Σ_i ∫ Δs_i(η) / √(ρ_i² + η²) dη (ρ_i² = (x − ξ_i)² + y²), done in closed form: in θ it is a
//    row of narrow peaks (width |η|/ρ_i) that a quadrature would need thousands of nodes for;
//  - the rest, primitives G and (w − 1) G − ln w, is smooth in θ but for a logarithmic singularity at ϖ_i = 0 from
//    the waterline nodes (G ≈ −ln w near w = 0): −Δs_i(0)/(π² k0) ln|ϖ_i| is subtracted from the integrand and its
//    integral, −Δs_i(0)/(π k0) (ln ρ_i − ln 2) (∫ ln|cos| over a period is −π ln 2), added back.
double sheetLocalElevation(const SheetNodes& s, double k0, double x, double y, const std::vector<double>& theta,
                           const std::vector<double>& weight, std::vector<Complex>& work) {
  const int n = static_cast<int>(s.xi.size()), m = static_cast<int>(s.eta.size());
  const double pi = std::numbers::pi, floor = 1e-9 * (std::abs(s.xi.back() - s.xi.front()) + s.dz);
  work.resize(2 * static_cast<std::size_t>(m));
  // Double-body part and the logarithms added back.
  double rigid_lid = 0, logs = 0;
  for (int i = 0; i < n; ++i) {
    const double rho = std::max(std::hypot(x - s.xi[i], y), floor);
    logs += -s.slope_jump(i, 0) / (pi * k0) * std::log(rho);
    for (int j = 0; j + 1 < m; ++j) {
      const double a = s.slope_jump(i, j + 1), b = s.slope_jump(i, j), lo = s.eta[j + 1], up = s.eta[j];
      const double d_asinh = std::asinh(up / rho) - std::asinh(lo / rho);
      const double d_root = std::hypot(rho, up) - std::hypot(rho, lo);
      rigid_lid += a * d_asinh + (b - a) / s.dz * (d_root - lo * d_asinh);
    }
  }
  rigid_lid *= -1.0 / (pi * k0);
  // θ node by node: each node's integrand is smooth but at its own ϖ_i = 0 (the logarithm, a kink where its wave
  // term switches on, peaks of width |η|/ρ_i and 1/(K ρ_i)), so each gets its own rule graded toward that angle.
  double sum = 0;

  for (int i = 0; i < n; ++i) {
    bool any = false;
    for (int j = 0; j < m; ++j) any |= s.slope_jump(i, j) != 0;
    if (!any) continue;
    // On the track (y = 0) ϖ_i = (x − ξ_i) cos θ vanishes at both ends, θ = ±π/2: the rules grade toward them.
    const bool track = y == 0;
    const double theta_i = track ? 0.0 : std::atan(-(x - s.xi[i]) / y);
    for (double side : {-1.0, 1.0}) {
      const double reach = side > 0 ? 0.5 * pi - theta_i : theta_i + 0.5 * pi;
      for (std::size_t q = 0; q < theta.size(); ++q) {
        const double th = theta_i + side * reach * (track ? 1.0 - theta[q] : theta[q]);
        const double c = std::cos(th), sn = std::sin(th), K = k0 / (c * c);
        if (c <= 0) continue;
        double varpi = (x - s.xi[i]) * c + y * sn;
        if (std::abs(varpi) < floor) varpi = std::copysign(floor, varpi);
        for (int j = 0; j < m; ++j) {
          const Complex w(K * s.eta[j], K * varpi), gj = scaledExponentialIntegral(w);
          work[2 * j] = gj;
          work[2 * j + 1] = (w - 1.0) * gj - std::log(onUpperEdge(w));
        }
        // Interval [η_{j+1}, η_j], Δs linear: ∫ Δs G dη = a ΔP1/K + (b − a)(ΔP2 − w_lo ΔP1)/(K² h),
        // a, b the jumps at the deeper and shallower waterline.
        Complex total = 0.0;
        for (int j = 0; j + 1 < m; ++j) {
          const double a = s.slope_jump(i, j + 1), b = s.slope_jump(i, j);
          const Complex d1 = work[2 * j] - work[2 * j + 2], d2 = work[2 * j + 1] - work[2 * j + 3];
          const Complex w_lo(K * s.eta[j + 1], K * varpi);
          const Complex linear = (d2 - w_lo * d1) / (K * K * s.dz);
          total += a * (d1 / K - linear) + b * linear;
        }
        const double singular = s.slope_jump(i, 0) / k0 * std::log(std::abs(varpi));
        sum += reach * weight[q] * (total.real() / (c * c) + singular);
      }
    }
  }
  return sum / (pi * pi) + logs + rigid_lid;
}

}  // namespace

Complex scaledExponentialIntegral(Complex w) {
  w = onUpperEdge(w);
  switch (e1Method(w)) {
    case E1Method::Asymptotic:
      return e1Asymptotic(w, 0);
    case E1Method::ContinuedFraction:
      return e1ContinuedFraction(w);
    case E1Method::Series:
      break;
  }
  return std::exp(w) * (-std::numbers::egamma - std::log(w) - e1Series(w));
}

SourceElevation kelvinSourceElevation(double x_rel, double y, double depth, double k0, int theta_panels) {
  const double pi = std::numbers::pi;
  // Local part: a rule on each side of the angle where ϖ = 0 (the integrand jumps there with the wave term, and
  // has peaks of width h/r next to it), graded toward it.
  std::vector<double> theta, weight;
  gradedGaussRule(10, 8, theta, weight);
  // On the track (y = 0) ϖ = x' cos θ vanishes at both ends, θ = ±π/2: the rules grade toward them.
  const bool track = y == 0;
  const double theta0 = track ? 0.0 : std::atan(-x_rel / y);
  double local = 0;
  for (double side : {-1.0, 1.0}) {
    const double reach = side > 0 ? 0.5 * pi - theta0 : theta0 + 0.5 * pi;
    for (std::size_t q = 0; q < theta.size(); ++q) {
      const double th = theta0 + side * reach * (track ? 1.0 - theta[q] : theta[q]), c = std::cos(th);
      if (c <= 0) continue;
      const double sec = 1.0 / c, K = k0 * sec * sec, varpi = x_rel * c + y * std::sin(th);
      // −1/Z + K e^{KZ} E1(KZ) = K (e^w E1(w) − 1/w), w = KZ.
      const Complex f = K * scaledE1MinusInverse(Complex(-K * depth, K * varpi));
      local += reach * weight[q] * (-1.0 / (2.0 * pi * pi)) * sec * f.imag();
    }
  }
  // Wave parts: oscillatory, composite Gauss–Legendre on each side of θ0 (where H(−ϖ) switches).
  std::vector<double> right_nodes, right_weights;
  const int left_panels = std::max(1, static_cast<int>(std::lround(theta_panels * (theta0 / pi + 0.5))));
  compositeGaussRule(-0.5 * pi, theta0, left_panels, theta, weight);
  compositeGaussRule(theta0, 0.5 * pi, std::max(1, theta_panels - left_panels), right_nodes, right_weights);
  theta.insert(theta.end(), right_nodes.begin(), right_nodes.end());
  weight.insert(weight.end(), right_weights.begin(), right_weights.end());
  double wave_havelock = 0, wave_downstream = 0;
  for (std::size_t q = 0; q < theta.size(); ++q) {
    const double c = std::cos(theta[q]), sec = 1.0 / c, K = k0 * sec * sec;
    const double varpi = x_rel * c + y * std::sin(theta[q]);
    const double wave = weight[q] / pi * K * sec * std::exp(-K * depth) * std::cos(K * varpi);
    if (varpi < 0) wave_havelock += wave;
    if (x_rel < 0) wave_downstream += wave;
  }
  return {local + wave_havelock, local, wave_downstream};
}

Eigen::MatrixXd thinShipLocalElevation(const HullGrid& grid, double k0, const Eigen::VectorXd& x,
                                       const Eigen::VectorXd& y, int stations, int waterlines, int theta_panels,
                                       int outer_panels, const std::function<bool()>& cancelled) {
  // Three resolutions of the sheet: points within 0.2 L of the hull see its shape; beyond 0.5 L the field is smooth
  // on the scale of the hull.
  const std::array<SheetNodes, 3> sheets{resampleSheet(grid, stations, waterlines),
                                         resampleSheet(grid, (stations - 1) / 2 + 1, (waterlines - 1) / 2 + 1),
                                         resampleSheet(grid, (stations - 1) / 4 + 1, (waterlines - 1) / 4 + 1)};
  std::vector<double> theta, weight;
  gradedGaussRule(theta_panels, outer_panels, theta, weight);
  const double x_aft = grid.x_aft, x_fore = grid.x(grid.nx() - 1), length = x_fore - x_aft;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(x.size(), y.size());
  // The field is even in y (the hull is symmetric): a point whose mirror is in the grid is copied from it.
  auto mirrored = [&](Eigen::Index j) {
    const Eigen::Index mirror = y.size() - 1 - j;
    return y[j] < 0 && mirror > j && std::abs(y[mirror] + y[j]) <= 1e-12 * (1.0 + std::abs(y[j]));
  };
  auto row = [&](Eigen::Index i, std::vector<Complex>& work) {
    const double outside = std::max({x_aft - x[i], x[i] - x_fore, 0.0});
    const double half = (x[i] < x_aft || x[i] > x_fore) ? 0.0 : gridHalfBreadth(grid, x[i], 0.0) * (1.0 - 1e-9);
    for (Eigen::Index j = 0; j < y.size(); ++j) {
      if (std::abs(y[j]) < half || mirrored(j)) continue;
      const double distance = std::hypot(outside, std::abs(y[j]));
      const int level = distance < 0.2 * length ? 0 : (distance < 0.5 * length ? 1 : 2);
      out(i, j) = sheetLocalElevation(sheets[level], k0, x[i], y[j], theta, weight, work);
    }
    for (Eigen::Index j = 0; j < y.size(); ++j)
      if (mirrored(j)) out(i, j) = out(i, y.size() - 1 - j);
  };
  // Rows interleaved over the cores (each row writes its own entries only).
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
  auto worker = [&](unsigned first) {
    std::vector<Complex> work;
    for (Eigen::Index i = first; i < x.size(); i += threads) {
      if (cancelled && cancelled()) return;
      row(i, work);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (std::thread& t : pool) t.join();
  return out;
}

}  // namespace maris::ship
