// The Kelvin source's free-surface elevation (kelvin_source.hpp): the exponential integral against tabulated
// values, the closed-form radial integral against a direct numerical evaluation of the Fourier double integral,
// and the low-Froude (rigid-lid) limit.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "ship/kelvin_source.hpp"

using namespace maris::ship;

namespace {

using Complex = std::complex<double>;

// 16-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun table 25.4), positive half.
constexpr double kNodes16[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
constexpr double kWeights16[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                  0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};

template <class F>
Complex integrate(F f, double a, double b, int panels) {
  Complex sum = 0.0;
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int q = 0; q < 8; ++q)
      sum += 0.5 * h * kWeights16[q] * (f(mid - 0.5 * h * kNodes16[q]) + f(mid + 0.5 * h * kNodes16[q]));
  }
  return sum;
}

// The elevation per unit q/U of a source at depth h (k0 = 1) straight from its Fourier representation
//   ζ = −(1/4π²) ∬ iα e^{−kh} e^{i(αx + βy)} / (k0 k − α² − iεα) dα dβ,  ε → 0+,
// (the linear free-surface condition with Rayleigh damping, stream in −x), in polar coordinates α = k cos θ,
// β = k sin θ over the whole circle θ ∈ (−π, π): the k integral by the Sokhotski–Plemelj formula,
// 1/(k − K + iδ) → PV 1/(k − K) − iπ sgn δ δ(k − K), with the principal value done numerically after
// subtracting the pole. Nothing of the closed form (exponential integral, its branches, the θ folding) is used.
double fourierElevation(double x, double y, double h) {
  const double eta = -h;
  auto inner = [&](double theta) {
    const double c = std::cos(theta), s = std::sin(theta), K = 1.0 / (c * c), varpi = x * c + y * s;
    const Complex Z(eta, varpi);
    auto g = [&](double k) { return k * std::exp(k * Z); };
    const double k_max = 45.0 / h;  // e^{−kh} below 1e-19 beyond
    const double width = 1.0 / std::max(std::abs(varpi), h);
    Complex pv;
    if (K > 1.5 * k_max) {
      pv = integrate([&](double k) { return g(k) / (k - K); }, 0.0, k_max, static_cast<int>(k_max / width) + 4);
    } else {
      const Complex gK = g(K);
      const int n = static_cast<int>(2 * K / width) + 8;  // even: the pole sits between panels
      pv = integrate([&](double k) { return (g(k) - gK) / (k - K); }, 0.0, 2.0 * K, 2 * (n / 2 + 1));
      const double end = std::max(2.0 * K, k_max) + 2.0 * K;
      pv += integrate([&](double k) { return g(k) / (k - K); }, 2.0 * K, end, static_cast<int>((end - 2 * K) / width) + 4);
    }
    const double sign = c > 0 ? 1.0 : -1.0;
    return (Complex(0.0, 1.0) / c * (pv - Complex(0.0, std::numbers::pi * sign) * K * std::exp(K * Z))).real();
  };
  // Both halves of the circle, away from θ = ±π/2 by panels that end there (the integrand → 0 there).
  const double pi = std::numbers::pi;
  const Complex a = integrate(inner, -pi, -0.5 * pi, 150), b = integrate(inner, -0.5 * pi, 0.5 * pi, 300),
                c = integrate(inner, 0.5 * pi, pi, 150);
  return (a + b + c).real() / (4.0 * pi * pi);
}

}  // namespace

TEST(KelvinSource, ExponentialIntegralMatchesTabulatedValues) {
  // Abramowitz & Stegun 5.1 (E1(1), E1(10)), 5.2 (E1(i) = −Ci(1) + i(Si(1) − π/2)) and E1(−5 + i0) = −Ei(5) − iπ
  // (Ei(5) = 40.18527535580318, A&S table 5.1). Relative 1e-12.
  struct Case {
    Complex w, e1;
  };
  const double pi = std::numbers::pi;
  const Case cases[] = {{1.0, 0.21938393439552029},
                        {10.0, 4.1569689296853243e-6},
                        {Complex(0, 1), Complex(-0.33740392290096813, 0.94608307036718301 - 0.5 * pi)},
                        {Complex(-5, 0), Complex(-40.185275355803178, -pi)},
                        {Complex(-5, -0.0), Complex(-40.185275355803178, -pi)}};
  for (const Case& c : cases) {
    const Complex got = scaledExponentialIntegral(c.w) * std::exp(-c.w);
    EXPECT_LT(std::abs(got - c.e1), 1e-12 * std::abs(c.e1)) << c.w << ": " << got << " vs " << c.e1;
  }
  // Continuity where the evaluation changes method (|w| = 4, 25 and the wedge about the negative real axis): the
  // values on both sides of each switch agree to 1e-9 relative (the function is smooth there).
  for (double r : {4.0, 25.0})
    for (double arg = 0.0; arg < 3.1; arg += 0.1) {
      const Complex in = std::polar(r * (1 - 1e-12), arg), out = std::polar(r * (1 + 1e-12), arg);
      const Complex a = scaledExponentialIntegral(in), b = scaledExponentialIntegral(out);
      EXPECT_LT(std::abs(a - b), 1e-9 * std::abs(a)) << r << " " << arg;
    }
  for (double r : {6.0, 12.0, 20.0}) {
    const double arg = std::atan2(0.5, -1.0);
    const Complex a = scaledExponentialIntegral(std::polar(r, arg - 1e-12)),
                  b = scaledExponentialIntegral(std::polar(r, arg + 1e-12));
    EXPECT_LT(std::abs(a - b), 1e-9 * std::abs(a)) << r;
  }
}

TEST(KelvinSource, ElevationMatchesTheFourierIntegral) {
  // Source 1/k0 deep (k0 = 1); points ahead, beside, behind and on the track. The closed-form k integral with
  // the exponential integral (local part) plus the Havelock wave term, θ by Gauss–Legendre, against the Fourier
  // double integral done numerically (fourierElevation). Agreement within 1e-5 of the largest value (measured
  // 1e-9: both quadratures are far finer than that).
  struct Point {
    double x, y;
  };
  const Point points[] = {{2.0, 0.0}, {0.0, 1.0}, {-1.0, 0.5}, {-3.0, 0.0}, {-4.0, 2.0}, {1.0, 1.5}};
  std::vector<double> closed, direct;
  double scale = 0;
  for (const Point& p : points) {
    closed.push_back(kelvinSourceElevation(p.x, p.y, 1.0, 1.0, 400).total);
    direct.push_back(fourierElevation(p.x, p.y, 1.0));
    scale = std::max(scale, std::abs(direct.back()));
  }
  for (std::size_t i = 0; i < closed.size(); ++i)
    EXPECT_NEAR(closed[i], direct[i], 1e-5 * scale) << points[i].x << ", " << points[i].y;
  // Behind the source the waves dominate, ahead it is calm: the radiation condition's side (|ζ| 3 source depths
  // behind more than 5 times that 2 depths ahead; measured 8.8).
  EXPECT_GT(std::abs(direct[3]), 5.0 * std::abs(direct[0]));
}

TEST(KelvinSource, SlowSourceTendsToTheRigidLidElevation) {
  // As U → 0 (k0 → ∞) the free surface acts as a rigid lid: the source and its image above give
  // φ = −q/(2π r) on z = 0 and ζ = (U/g) ∂φ/∂x = q x/(2π U k0 r³) (per unit q/U: x/(2π k0 r³)), the first term of
  // the local part's expansion in 1/(k0 r); the waves are smaller by e^{−k0 h}. The relative difference falls
  // about like 1/(k0 r): below 10 % at k0 r = 50 (measured 1.4 %, 0.1 %, 6 %) and at least 4 times smaller at
  // k0 r = 500 (measured 9.4, 4.9, 10.7 times).
  struct Point {
    double x, y, h;
  };
  for (const Point& p : {Point{1.0, 0.5, 0.5}, Point{-1.0, 0.3, 0.4}, Point{0.5, -1.0, 0.6}}) {
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.h * p.h);
    double error[2];
    for (int n = 0; n < 2; ++n) {
      const double k0 = (n == 0 ? 50.0 : 500.0) / r;
      const double rigid_lid = p.x / (2.0 * std::numbers::pi * k0 * r * r * r);
      error[n] = std::abs(kelvinSourceElevation(p.x, p.y, p.h, k0, 400).total / rigid_lid - 1.0);
    }
    EXPECT_LT(error[0], 0.1) << p.x << ", " << p.y;
    EXPECT_GT(error[0] / error[1], 4.0) << p.x << ", " << p.y;
    RecordProperty("relative_difference_k0r_50", std::to_string(error[0]));
  }
}
