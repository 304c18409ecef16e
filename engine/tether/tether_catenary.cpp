#include "tether/tether_catenary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/text_format.hpp"

namespace maris::tether {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kVerticalHangSpanRatio = 1e-14;  // S/L below which the tether is treated as hanging vertically
constexpr double kNearlyTautCondition = 1e6;      // condition number above which the shape is "nearly taut"

// ln(sinh(xi)/xi) for xi >= 0 without cancellation: series below 1, asymptotic form above 20.
double logSinhOverX(double xi) {
  if (xi < 1.0) {
    // sinh(xi)/xi - 1 = sum_{k>=1} xi^(2k)/(2k+1)!
    const double x2 = xi * xi;
    double term = x2 / 6.0, sum = 0.0;
    for (int k = 1; k < 30 && term > 1e-18 * sum; ++k) {
      sum += term;
      term *= x2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    }
    return std::log1p(sum);
  }
  if (xi > 20.0) return xi - std::log(2.0 * xi) + std::log1p(-std::exp(-2.0 * xi));
  return std::log(std::sinh(xi) / xi);
}

// d/dxi ln(sinh(xi)/xi) = coth(xi) - 1/xi; its Laurent series below 0.1 avoids the cancellation.
double logSinhOverXSlope(double xi) {
  if (xi < 0.1) {
    const double x2 = xi * xi;
    return xi * (1.0 / 3.0 + x2 * (-1.0 / 45.0 + x2 * (2.0 / 945.0 + x2 * (-1.0 / 4725.0 + x2 * (2.0 / 93555.0)))));
  }
  return 1.0 / std::tanh(xi) - 1.0 / xi;
}

// q^2 - S^2 = (L - S)(L + S) - dH^2 with the rounding errors of L + S, the product and dH^2 compensated by fma.
double chordDeficit(double span, double rise, double length) {
  const double a = length - span;
  const double b = length + span;
  const double bb = b - length;
  const double b_error = (length - (b - bb)) + (span - bb);  // exact: b + b_error = L + S
  const double p = a * b;
  const double p_error = std::fma(a, b, -p);  // exact: p + p_error = a b
  return std::fma(-rise, rise, p) + p_error + a * b_error;
}

// Solves ln(sinh xi / xi) = ln_r for xi > 0 (ln_r > 0). Newton is monotone after the first step on this convex,
// increasing function; the bracket [lo, hi] guards against any step that would leave it.
double solveSinhRatio(double ln_r, int& iterations) {
  double xi = ln_r < 2.0 ? std::sqrt(6.0 * ln_r) : std::log(2.0) + ln_r + std::log(std::log(2.0) + ln_r);
  double lo = 0.0, hi = kInf;
  for (iterations = 1; iterations <= 200; ++iterations) {
    const double f = logSinhOverX(xi) - ln_r;
    if (f == 0.0) break;
    const double step = f / logSinhOverXSlope(xi);
    if (std::abs(step) <= 4.0 * kEps * xi) {
      xi -= step;
      break;
    }
    (f > 0.0 ? hi : lo) = xi;
    xi -= step;
    if (!(xi > lo && xi < hi)) xi = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * lo;
  }
  return xi;
}

Catenary failed(CatenaryRegime regime, std::string message, double span, double rise, double length) {
  Catenary c;
  c.regime = regime;
  c.message = std::move(message);
  // Non-finite inputs are not echoed back: no field of a Catenary is ever NaN.
  c.span = std::isfinite(span) ? span : 0.0;
  c.rise = std::isfinite(rise) ? rise : 0.0;
  c.length = std::isfinite(length) ? length : 0.0;
  return c;
}

Catenary verticalHang(double span, double rise, double length, std::string message) {
  Catenary c;
  c.regime = CatenaryRegime::VerticalHang;
  c.message = std::move(message);
  c.length = length;
  c.span = span;
  c.rise = rise;
  c.constant = kInf;
  c.inverse_constant = 0.0;
  c.vertex_offset = 0.5 * span;
  c.sag = 0.5 * (length - rise);
  c.condition_number = 1.0;
  c.has_geometry = true;
  return c;
}

// Classifies a catenary with finite C by the vertex position and the conditioning of the span.
void classify(Catenary& c) {
  const double q = std::sqrt((c.length - c.rise) * (c.length + c.rise));
  const double deficit = chordDeficit(c.span, c.rise, c.length) / (q + c.span);  // q - S
  c.condition_number = 1.0 + c.span / std::max(deficit, kEps * q);
  if (c.vertex_offset < 0.0 || c.vertex_offset > c.span) {
    c.regime = CatenaryRegime::VertexOutsideSpan;
    c.message = formatText("the lowest point lies %.3g m beyond an attachment point (span %.6g m, rise %.6g m): the "
                           "paper's sag/height-offset model needs it between them",
                           c.vertex_offset < 0.0 ? -c.vertex_offset : c.vertex_offset - c.span, c.span, c.rise);
  } else if (c.condition_number > kNearlyTautCondition) {
    c.regime = CatenaryRegime::NearlyTaut;
    c.message = formatText("nearly taut: the sag is ill-conditioned in the span, |d ln H/d ln S| ~ %.3g", c.condition_number);
  } else {
    c.regime = CatenaryRegime::Regular;
  }
}

}  // namespace

const char* toString(CatenaryRegime regime) {
  switch (regime) {
    case CatenaryRegime::Regular: return "regular";
    case CatenaryRegime::NearlyTaut: return "nearly taut";
    case CatenaryRegime::VertexOutsideSpan: return "lowest point outside the span";
    case CatenaryRegime::VerticalHang: return "vertical hang";
    case CatenaryRegime::Overstretched: return "overstretched";
    case CatenaryRegime::Degenerate: return "degenerate";
  }
  return "unknown";
}

double catenaryConstant(double sag, double rise, double length) {
  const double w = 2.0 * sag + rise;
  const double denominator = (length - w) * (length + w);  // C_D = L^2 - (2H + dH)^2
  if (denominator <= 0.0) return kInf;
  const double numerator = w + 2.0 * length * std::sqrt(sag * (sag + rise) / ((length - rise) * (length + rise)));
  return 2.0 * numerator / denominator;
}

CatenaryConstantGradient catenaryConstantGradient(double sag, double rise, double length) {
  const double H = sag, dH = rise, L = length;
  const double w = 2.0 * H + dH;
  const double q2 = (L - dH) * (L + dH);
  const double root = std::sqrt(H * (H + dH));
  const double num = w + 2.0 * L * root / std::sqrt(q2);
  const double den = (L - w) * (L + w);
  const double num_H = 2.0 + L * w / (root * std::sqrt(q2));
  const double num_dH = 1.0 + L * H * (L * L + 2.0 * H * dH + dH * dH) / (q2 * std::sqrt(q2) * root);
  const double den_H = -4.0 * w;
  const double den_dH = -2.0 * w;
  return {2.0 * (num_H * den - den_H * num) / (den * den), 2.0 * (num_dH * den - den_dH * num) / (den * den)};
}

Catenary catenaryFromShape(double sag, double rise, double length) {
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(sag) || !std::isfinite(rise))
    return failed(CatenaryRegime::Degenerate, formatText("length %.6g m, sag %.6g m and rise %.6g m must be finite with "
                                                         "length > 0", length, sag, rise), 0.0, rise, length);
  if (sag < 0.0 || sag + rise < 0.0)
    return failed(CatenaryRegime::VertexOutsideSpan,
                  formatText("sag H = %.6g m and H + dH = %.6g m must both be >= 0 (lowest point between the ends)", sag,
                             sag + rise), 0.0, rise, length);
  const double w = 2.0 * sag + rise;
  if (w > length)
    return failed(CatenaryRegime::Degenerate, formatText("2H + dH = %.6g m exceeds the length %.6g m", w, length), 0.0,
                  rise, length);
  if (w == length)
    return verticalHang(0.0, rise, length, formatText("2H + dH = L = %.6g m: the tether hangs vertically (C infinite)",
                                                      length));
  if (sag == 0.0 && rise == 0.0)
    return failed(CatenaryRegime::Overstretched, "H = dH = 0 is the straight taut tether (chord = length)", length,
                  rise, length);
  Catenary c;
  c.length = length;
  c.rise = rise;
  c.sag = sag;
  c.constant = catenaryConstant(sag, rise, length);
  if (!std::isfinite(c.constant))
    return verticalHang(0.0, rise, length, formatText("2H + dH = %.17g m is L to round-off: vertical hang", w));
  c.inverse_constant = 1.0 / c.constant;
  // D = asinh(sqrt(CH (CH + 2)))/C is acosh(1 + CH)/C without the cancellation in 1 + CH for small CH.
  const double ch2 = c.constant * sag, ch1 = c.constant * (sag + rise);
  const double d2 = std::asinh(std::sqrt(ch2 * (ch2 + 2.0))) / c.constant;
  const double d1 = std::asinh(std::sqrt(ch1 * (ch1 + 2.0))) / c.constant;
  c.vertex_offset = d2;
  c.span = d1 + d2;
  c.has_geometry = true;
  classify(c);
  return c;
}

Catenary catenaryFromSpan(double span, double rise, double length) {
  if (!(length > 0.0) || !std::isfinite(length) || !(span >= 0.0) || !std::isfinite(span) || !std::isfinite(rise))
    return failed(CatenaryRegime::Degenerate, formatText("length %.6g m, span %.6g m and rise %.6g m must be finite with "
                                                         "length > 0 and span >= 0", length, span, rise), span, rise,
                  length);
  const double deficit = chordDeficit(span, rise, length);  // q^2 - S^2
  if (!(deficit > 0.0))
    return failed(CatenaryRegime::Overstretched,
                  formatText("chord %.9g m >= length %.9g m: an inextensible tether cannot span it (rise %.6g m)",
                             std::hypot(span, rise), length, rise),
                  span, rise, length);
  if (span <= kVerticalHangSpanRatio * length)
    return verticalHang(span, rise, length, formatText("span %.3g m <= 1e-14 L: the tether hangs vertically", span));
  const double q = std::sqrt((length - rise) * (length + rise));
  const double r_minus_1 = deficit / (span * (q + span));  // r - 1, r = q/S
  Catenary c;
  c.length = length;
  c.span = span;
  c.rise = rise;
  const double xi = solveSinhRatio(std::log1p(r_minus_1), c.iterations);
  c.constant = 2.0 * xi / span;
  c.inverse_constant = 0.5 * span / xi;
  // Vertex: tanh(C (S/2 - x0)) = dH/L.
  c.vertex_offset = 0.5 * span * (1.0 - std::atanh(rise / length) / xi);
  const double half = std::sinh(0.5 * c.constant * c.vertex_offset);
  c.sag = 2.0 * half * half * c.inverse_constant;
  c.has_geometry = true;
  classify(c);
  return c;
}

PlanePoint catenaryPointAtArcLength(const Catenary& c, double arc_length) {
  const double sigma = std::clamp(arc_length, 0.0, c.length);
  if (c.regime == CatenaryRegime::VerticalHang) {
    if (sigma <= c.sag) return {0.0, -sigma};
    return {c.span, -c.sag + (sigma - c.sag)};
  }
  const double C = c.constant;
  // Signed arc length from the vertex: P2 sits at -sinh(C x0)/C.
  const double from_vertex = sigma - std::sinh(C * c.vertex_offset) * c.inverse_constant;
  const double x = c.vertex_offset + std::asinh(C * from_vertex) * c.inverse_constant;
  // cosh(C(x - x0)) - cosh(C x0) = 2 sinh(C x/2) sinh(C (x - 2 x0)/2).
  const double z = 2.0 * std::sinh(0.5 * C * x) * std::sinh(0.5 * C * (x - 2.0 * c.vertex_offset)) *
                   c.inverse_constant;
  return {x, z};
}

double catenaryTension(const Catenary& c, double wet_weight_per_length, double arc_length) {
  const double sigma = std::clamp(arc_length, 0.0, c.length);
  // T = w sqrt(1/C^2 + s^2), s the signed arc length from the vertex; = (w/C) cosh(C (x - x0)).
  const double from_vertex = c.regime == CatenaryRegime::VerticalHang
                                 ? sigma - c.sag
                                 : sigma - std::sinh(c.constant * c.vertex_offset) * c.inverse_constant;
  return wet_weight_per_length * std::hypot(c.inverse_constant, from_vertex);
}

EndAngles catenaryEndAngles(const Catenary& c) {
  if (c.regime == CatenaryRegime::VerticalHang) return {-0.5 * std::numbers::pi, 0.5 * std::numbers::pi};
  const double C = c.constant;
  return {std::atan(std::sinh(-C * c.vertex_offset)), std::atan(std::sinh(C * (c.span - c.vertex_offset)))};
}

}  // namespace maris::tether
