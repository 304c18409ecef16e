// Catenary functions against closed forms (paper eq. 2 special cases, length and span identities) and against an
// independent long-double bisection of sinh(xi) - xi = (r - 1) xi (well-conditioned, extreme and round-trip cases).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tether/tether_catenary.hpp"
#include "tether_test_constants.hpp"

namespace maris::tether {
namespace {

using test::kL;

struct GridPoint {
  double sag, rise;
};

// A grid H x dH restricted to shapes with the lowest point between the ends and 2H + dH < L.
std::vector<GridPoint> feasibleGrid() {
  std::vector<GridPoint> grid;
  for (double h : {1e-3, 0.05, 0.2, 0.35, 0.6, 0.74})
    for (double dh : {-0.3, -0.1, 0.0, 0.1, 0.3, 0.5})
      if (h + dh >= 0.0 && 2.0 * h + dh < kL) grid.push_back({h, dh});
  return grid;
}

TEST(TetherCatenary, LevelShapeConstantMatchesClosedForm) {
  // dH = 0: C = 8H/(L^2 - 4H^2) (eq. 2 with dH = 0); 1e-12 is round-off of a few operations.
  const double H = 0.35;
  EXPECT_NEAR(catenaryConstant(H, 0.0, kL), 8.0 * H / (kL * kL - 4.0 * H * H), 1e-12 * 1.59);
  EXPECT_NEAR(catenaryConstant(H, 0.0, kL), 1.5909090909090909, 1e-12 * 1.59);
}

TEST(TetherCatenary, ZeroSagConstantMatchesClosedForm) {
  // H = 0: C = 2 dH/(L^2 - dH^2).
  EXPECT_NEAR(catenaryConstant(0.0, 0.3, kL), 2.0 * 0.3 / (kL * kL - 0.09), 1e-12 * 0.28);
}

TEST(TetherCatenary, LengthAndSpanIdentitiesHoldOnGrid) {
  for (const auto& g : feasibleGrid()) {
    const Catenary c = catenaryFromShape(g.sag, g.rise, kL);
    ASSERT_TRUE(c.has_geometry) << g.sag << " " << g.rise << " " << c.message;
    const double C = c.constant, d2 = c.vertex_offset, d1 = c.span - c.vertex_offset;
    // L = (sinh(C D2) + sinh(C D1))/C, round-off 1e-12 L.
    EXPECT_NEAR((std::sinh(C * d2) + std::sinh(C * d1)) / C, kL, 1e-12 * kL) << g.sag << " " << g.rise;
    // L^2 - dH^2 = (2/C)^2 sinh^2(C S/2).
    const double sh = 2.0 / C * std::sinh(0.5 * C * c.span);
    EXPECT_NEAR(sh * sh, kL * kL - g.rise * g.rise, 1e-12 * kL * kL) << g.sag << " " << g.rise;
    // The curve passes through P1: z(S) = dH.
    EXPECT_NEAR(catenaryPointAtArcLength(c, kL).z, g.rise, 1e-12 * kL);
    EXPECT_NEAR(catenaryPointAtArcLength(c, kL).x, c.span, 1e-12 * kL);
  }
}

TEST(TetherCatenary, ShapeTableOfAnIndependentComputationIsReproduced) {
  // Reference values computed by an independent Python implementation (outside this repository); 9 significant digits shown.
  struct Row {
    double H, dH, C, D, dD;
  } rows[] = {{0.35, 0.0, 1.590909091, 0.6358634302, 0.0},          {0.35, 0.2, 2.479724961, 0.4988829211, 0.1081829601},
              {0.35, -0.2, 0.9623860995, 0.8305650652, -0.2787488169}, {0.43, 0.0, 2.277542373, 0.5729635317, 0.0},
              {0.74, 0.0, 99.32885906, 0.05037756754, 0.0},           {0.2, 0.5, 2.35239638, 0.3976956557, 0.2946557759}};
  for (const auto& r : rows) {
    const Catenary c = catenaryFromShape(r.H, r.dH, kL);
    EXPECT_NEAR(c.constant, r.C, 6e-10 * r.C);
    EXPECT_NEAR(c.vertex_offset, r.D, 6e-10);
    EXPECT_NEAR(c.span - 2.0 * c.vertex_offset, r.dD, 6e-10);
  }
}

TEST(TetherCatenary, InverseQuadraticRecoversSag) {
  // H is the smaller root of A H^2 + B H + K = 0 (the paper's eq. 2 inverted, as in the authors' public lab code); rel 1e-10 (the
  // quadratic itself loses digits to cancellation in K - this checks C, not the quadratic).
  for (const auto& g : feasibleGrid()) {
    if (g.sag < 0.01) continue;
    const double C = catenaryConstant(g.sag, g.rise, kL), dH = g.rise;
    const double A = -4.0 * C * C * (kL * kL - dH * dH);
    const double B = -4.0 * C * dH * (C * (kL * kL - dH * dH) - 2.0 * dH) - 8.0 * kL * kL * C;
    const double K = std::pow(C * (kL * kL - dH * dH) - 2.0 * dH, 2);
    const double disc = std::sqrt(B * B - 4.0 * A * K);
    const double r1 = (-B + disc) / (2.0 * A), r2 = (-B - disc) / (2.0 * A);
    const double root = std::abs(r1 - g.sag) < std::abs(r2 - g.sag) ? r1 : r2;
    EXPECT_NEAR(root, g.sag, 1e-9 * kL) << g.sag << " " << g.rise;
  }
}

// ---- Independent reference: bisection in long double on F(xi) = (sinh xi - xi)/xi - (r - 1) ----

struct Reference {
  long double constant, sag;
};

// Exact-ish q^2 - S^2 in long double: a double product needs 106 bits, so split it with fmal.
long double deficitLong(double S, double dH, double L) {
  const long double a = static_cast<long double>(L) - S, b = static_cast<long double>(L) + S;  // both exact
  const long double p = a * b, pe = std::fmal(a, b, -p);
  const long double r = static_cast<long double>(dH) * dH, re = std::fmal(dH, dH, -r);
  return (p - r) + (pe - re);
}

long double sinhMinusXOverX(long double xi) {
  if (xi < 0.5L) {
    long double term = xi * xi / 6.0L, sum = 0.0L;
    for (int k = 1; k < 40; ++k) {
      sum += term;
      term *= xi * xi / ((2.0L * k + 2.0L) * (2.0L * k + 3.0L));
    }
    return sum;
  }
  return (std::sinh(xi) - xi) / xi;
}

Reference referenceFromSpan(double S, double dH, double L) {
  const long double q = std::sqrt(static_cast<long double>(L - dH) * static_cast<long double>(L + dH));
  const long double r_minus_1 = deficitLong(S, dH, L) / (S * (q + S));
  long double lo = 0.0L, hi = 1.0L;
  while (sinhMinusXOverX(hi) < r_minus_1) hi *= 2.0L;
  for (int i = 0; i < 200; ++i) {
    const long double mid = 0.5L * (lo + hi);
    (sinhMinusXOverX(mid) < r_minus_1 ? lo : hi) = mid;
  }
  const long double xi = 0.5L * (lo + hi);
  const long double C = 2.0L * xi / S;
  const long double x0 = 0.5L * S - std::atanh(static_cast<long double>(dH) / L) / C;
  const long double s = std::sinh(0.5L * C * x0);
  return {C, 2.0L * s * s / C};
}

TEST(TetherCatenary, LevelSpanSolveMatchesLongDoubleFromNearlyTautToVerticalHang) {
  // Level spans: the solve is well conditioned in C; 1e-14 relative (an independent implementation measured 1.5e-15).
  for (double gap : {1e-12, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2, 0.1, 0.5, 0.9, 0.99, 0.999999, 1.0 - 1e-9}) {
    const double S = kL * (1.0 - gap);
    const Catenary c = catenaryFromSpan(S, 0.0, kL);
    const Reference ref = referenceFromSpan(S, 0.0, kL);
    ASSERT_TRUE(c.has_geometry) << gap;
    EXPECT_NEAR(c.constant, static_cast<double>(ref.constant), 1e-14 * static_cast<double>(ref.constant)) << gap;
    EXPECT_NEAR(c.sag, static_cast<double>(ref.sag), 1e-14 * static_cast<double>(ref.sag)) << gap;
    EXPECT_LE(c.iterations, 8) << gap;
  }
}

TEST(TetherCatenary, SlopedSpanSolveMatchesLongDoubleWithinConditioning) {
  // Sloped spans: the sag is ill-conditioned near taut, kappa ~ q/(q - S); tolerance 1e-14 kappa + 1e-14 (A5).
  for (double dH : {-0.6, -0.1, 0.1, 0.3, 1.2})
    for (double gap : {1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.5, 0.9, 1.0 - 1e-6}) {
      const double q = std::sqrt(kL * kL - dH * dH);
      const double S = q * (1.0 - gap);
      const Catenary c = catenaryFromSpan(S, dH, kL);
      const Reference ref = referenceFromSpan(S, dH, kL);
      ASSERT_TRUE(c.has_geometry) << dH << " " << gap << " " << c.message;
      const double kappa = q / (q - S);
      const double tol_rel = 1e-14 * kappa + 1e-14;
      EXPECT_NEAR(c.constant, static_cast<double>(ref.constant), tol_rel * static_cast<double>(ref.constant));
      EXPECT_NEAR(c.sag, static_cast<double>(ref.sag), tol_rel * std::abs(static_cast<double>(ref.sag)) + 1e-16)
          << dH << " " << gap;
    }
}

TEST(TetherCatenary, SpanSolveConvergesInFewIterationsOverTwentySixDecades) {
  // r - 1 from 1e-14 to 1e12: <= 8 Newton iterations and a residual at round-off of ln r.
  for (double e = -14; e <= 12; e += 0.5) {
    const double r = 1.0 + std::pow(10.0, e);
    const double S = kL / r;
    const Catenary c = catenaryFromSpan(S, 0.0, kL);
    ASSERT_TRUE(c.has_geometry) << e;
    EXPECT_LE(c.iterations, 8) << "r - 1 = 1e" << e;
    const double xi = 0.5 * c.constant * S;
    const double ln_r = std::log1p((kL - S) / S);
    const double lhs = xi < 1.0 ? std::log1p(static_cast<double>(sinhMinusXOverX(xi))) : std::log(std::sinh(xi) / xi);
    EXPECT_LE(std::abs(lhs - ln_r), 4e-15 * ln_r + 1e-300) << e;
  }
}

TEST(TetherCatenary, RoundTripShapeToSpanToShape) {
  // Shape -> span -> shape: error ~ rounding of S amplified by the conditioning.
  for (const auto& g : feasibleGrid()) {
    const Catenary a = catenaryFromShape(g.sag, g.rise, kL);
    const Catenary b = catenaryFromSpan(a.span, a.rise, kL);
    ASSERT_TRUE(b.has_geometry);
    EXPECT_NEAR(b.sag, g.sag, (1e-15 * kL / (kL - a.span) + 1e-12) * std::max(g.sag, 1e-3)) << g.sag << " " << g.rise;
  }
}

TEST(TetherCatenary, EveryRegimeIsNamedWithoutNaN) {
  const auto finite = [](const Catenary& c) {
    return std::isfinite(c.sag) && std::isfinite(c.span) && std::isfinite(c.vertex_offset) && !std::isnan(c.constant);
  };
  const Catenary over = catenaryFromSpan(1.4, 0.6, kL);  // chord 1.523 > 1.5
  EXPECT_EQ(over.regime, CatenaryRegime::Overstretched);
  EXPECT_FALSE(over.has_geometry);
  EXPECT_NE(over.message.find("chord"), std::string::npos);
  const Catenary hang = catenaryFromSpan(0.0, 0.3, kL);
  EXPECT_EQ(hang.regime, CatenaryRegime::VerticalHang);
  EXPECT_DOUBLE_EQ(hang.sag, 0.6);  // (L - dH)/2
  EXPECT_EQ(hang.inverse_constant, 0.0);
  const Catenary outside = catenaryFromSpan(1.0, 1.1, kL);  // steep, nearly taut span: vertex beyond P2
  EXPECT_EQ(outside.regime, CatenaryRegime::VertexOutsideSpan);
  EXPECT_TRUE(outside.has_geometry);
  EXPECT_EQ(catenaryFromShape(0.6, 0.4, kL).regime, CatenaryRegime::Degenerate);  // 2H + dH = 1.6 > L
  EXPECT_EQ(catenaryFromShape(0.5, 0.5, kL).regime, CatenaryRegime::VerticalHang);  // 2H + dH = L
  EXPECT_EQ(catenaryFromShape(0.1, -0.2, kL).regime, CatenaryRegime::VertexOutsideSpan);
  EXPECT_EQ(catenaryFromShape(0.0, 0.0, kL).regime, CatenaryRegime::Overstretched);
  const Catenary taut = catenaryFromSpan(kL * (1.0 - 1e-12), 0.0, kL);
  EXPECT_EQ(taut.regime, CatenaryRegime::NearlyTaut);
  EXPECT_GT(taut.condition_number, 1e11);
  for (const Catenary& c : {over, hang, outside, taut, catenaryFromSpan(-1.0, 0.0, kL),
                            catenaryFromSpan(std::numeric_limits<double>::quiet_NaN(), 0.0, kL)})
    EXPECT_TRUE(finite(c)) << toString(c.regime);
}

TEST(TetherCatenary, PointsLieOnTheCurveAtTheirArcLength) {
  // Arc length between consecutive sampled points ~ chord (fine sampling); z = (cosh(C(x - x0)) - cosh(C x0))/C.
  const Catenary c = catenaryFromSpan(1.1, 0.2, kL);
  double length = 0.0;
  PlanePoint prev = catenaryPointAtArcLength(c, 0.0);
  const int n = 20000;
  for (int i = 1; i <= n; ++i) {
    const PlanePoint p = catenaryPointAtArcLength(c, kL * i / n);
    length += std::hypot(p.x - prev.x, p.z - prev.z);
    const double z = (std::cosh(c.constant * (p.x - c.vertex_offset)) - std::cosh(c.constant * c.vertex_offset)) /
                     c.constant;
    EXPECT_NEAR(p.z, z, 1e-13);
    prev = p;
  }
  EXPECT_NEAR(length, kL, 1e-8);  // chord sum underestimates by ~ L (C h)^2/24, h = L/n: ~1e-9
}

TEST(TetherCatenary, TensionsAndEndAnglesBalanceTheWeight) {
  // Vertical force balance: T2 sin(-angle2) + T1 sin(angle1) = w L; horizontal: T cos(angle) = w/C at both ends.
  const double w = 0.9;  // [N/m]
  const Catenary c = catenaryFromSpan(1.2, -0.25, kL);
  const EndAngles e = catenaryEndAngles(c);
  const double t2 = catenaryTension(c, w, 0.0), t1 = catenaryTension(c, w, kL);
  EXPECT_NEAR(-t2 * std::sin(e.at_follower) + t1 * std::sin(e.at_leader), w * kL, 1e-12);
  EXPECT_NEAR(t2 * std::cos(e.at_follower), w / c.constant, 1e-12);
  EXPECT_NEAR(t1 * std::cos(e.at_leader), w / c.constant, 1e-12);
}

TEST(TetherCatenary, ConstantGradientMatchesFiniteDifferences) {
  // Central differences with h = 1e-6: truncation ~ h^2 C''' and round-off ~ eps C/h, both < 1e-7 relative.
  for (const auto& g : feasibleGrid()) {
    if (g.sag < 0.01 || g.sag + g.rise < 0.01 || 2 * g.sag + g.rise > kL - 0.05) continue;
    const double h = 1e-6;
    const auto grad = catenaryConstantGradient(g.sag, g.rise, kL);
    const double fd_h = (catenaryConstant(g.sag + h, g.rise, kL) - catenaryConstant(g.sag - h, g.rise, kL)) / (2 * h);
    const double fd_r = (catenaryConstant(g.sag, g.rise + h, kL) - catenaryConstant(g.sag, g.rise - h, kL)) / (2 * h);
    EXPECT_NEAR(grad.d_sag, fd_h, 1e-6 * std::abs(fd_h) + 1e-7);
    EXPECT_NEAR(grad.d_rise, fd_r, 1e-6 * std::abs(fd_r) + 1e-7);
  }
}

}  // namespace
}  // namespace maris::tether
