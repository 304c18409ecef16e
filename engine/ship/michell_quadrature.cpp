#include "ship/michell_quadrature.hpp"

#include <cassert>
#include <cmath>

namespace maris::ship {

FilonCoefficients filonCoefficients(double t) {
  const double t2 = t * t;
  if (std::abs(t) < 0.2) {
    // Taylor series (exact rational coefficients); the first omitted term is O(θ^14) < 1e-13 relative.
    const double alpha =
        t * t2 * (2.0 / 45 + t2 * (-2.0 / 315 + t2 * (2.0 / 4725 + t2 * (-8.0 / 467775 +
                                                                        t2 * (4.0 / 8513505 - t2 * 2.0 / 212837625)))));
    const double beta =
        2.0 / 3 + t2 * (2.0 / 15 + t2 * (-4.0 / 105 + t2 * (2.0 / 567 + t2 * (-4.0 / 22275 +
                                                                              t2 * (4.0 / 675675 - t2 * 8.0 / 58046625)))));
    const double gamma =
        4.0 / 3 + t2 * (-2.0 / 15 + t2 * (1.0 / 210 + t2 * (-1.0 / 11340 + t2 * (1.0 / 997920 +
                                                                                t2 * (-1.0 / 129729600 + t2 / 23351328000.0)))));
    return {alpha, beta, gamma};
  }
  const double s = std::sin(t), c = std::cos(t), t3 = t2 * t;
  return {(t2 + t * s * c - 2.0 * s * s) / t3, 2.0 * (t * (1.0 + c * c) - 2.0 * s * c) / t3,
          4.0 * (s - t * c) / t3};
}

std::complex<double> filonIntegral(const Eigen::Ref<const Eigen::VectorXd>& f, double x0, double h, double kappa) {
  const Eigen::Index n = f.size() - 1;
  assert(n >= 2 && n % 2 == 0);
  const auto [alpha, beta, gamma] = filonCoefficients(kappa * h);
  // cos/sin(κ x_i) by a rotation recurrence, re-synchronised every 64 nodes to bound round-off growth.
  const double cd = std::cos(kappa * h), sd = std::sin(kappa * h);
  double c = 0.0, s = 0.0;
  double c_even = 0.0, s_even = 0.0, c_odd = 0.0, s_odd = 0.0;
  double c_first = 0.0, s_first = 0.0, c_last = 0.0, s_last = 0.0;
  for (Eigen::Index i = 0; i <= n; ++i) {
    if (i % 64 == 0) {
      const double phase = kappa * (x0 + static_cast<double>(i) * h);
      c = std::cos(phase);
      s = std::sin(phase);
    } else {
      const double c_next = c * cd - s * sd;
      s = s * cd + c * sd;
      c = c_next;
    }
    const double fc = f[i] * c, fs = f[i] * s;
    if (i % 2 == 0) {
      c_even += fc;
      s_even += fs;
    } else {
      c_odd += fc;
      s_odd += fs;
    }
    if (i == 0) {
      c_first = c;
      s_first = s;
    }
    if (i == n) {
      c_last = c;
      s_last = s;
    }
  }
  // Even sums count the end nodes with weight 1/2 (Simpson's pattern).
  c_even -= 0.5 * (f[0] * c_first + f[n] * c_last);
  s_even -= 0.5 * (f[0] * s_first + f[n] * s_last);
  const double cos_part = h * (alpha * (f[n] * s_last - f[0] * s_first) + beta * c_even + gamma * c_odd);
  const double sin_part = h * (-alpha * (f[n] * c_last - f[0] * c_first) + beta * s_even + gamma * s_odd);
  return {cos_part, sin_part};
}

double expTrapezoidDeepWeight(double K) {
  if (K < 0.5) {
    // Σ (-1)^n (n+1) K^n / (n+2)!, 14 terms: truncation < 0.5^14/16! ≈ 3e-18.
    double term = 0.5, sum = 0.0;  // term = K^n/(n+2)!
    for (int n = 0; n < 14; ++n) {
      sum += ((n % 2) ? -1.0 : 1.0) * (n + 1) * term;
      term *= K / (n + 3);
    }
    return sum;
  }
  const double E = std::exp(-K);
  return (1.0 - E - K * E) / (K * K);
}

double expTrapezoidShallowWeight(double K) {
  if (K < 0.5) {
    double term = 0.5, sum = 0.0;
    for (int n = 0; n < 14; ++n) {
      sum += ((n % 2) ? -1.0 : 1.0) * term;
      term *= K / (n + 3);
    }
    return sum;
  }
  return (K - 1.0 + std::exp(-K)) / (K * K);
}

void expTrapezoidWeights(double b, double dz, Eigen::Ref<Eigen::VectorXd> w, int* last_nonzero) {
  const Eigen::Index n = w.size();
  assert(n >= 2 && b >= 0.0 && dz > 0.0);
  const double K = b * dz;
  const double deep = dz * expTrapezoidDeepWeight(K), shallow = dz * expTrapezoidShallowWeight(K);
  const double E = std::exp(-K);
  w.setZero();
  // Interval j spans [z_{j+1}, z_j]; its upper node carries e^{b z_j} = E^j (a recurrence: one exp per call).
  double upper = 1.0;
  int last = 0;
  for (Eigen::Index j = 0; j + 1 < n; ++j) {
    if (upper < 1e-300) break;
    w[j] += shallow * upper;
    w[j + 1] += deep * upper;
    last = static_cast<int>(j + 1);
    upper *= E;
  }
  if (last_nonzero) *last_nonzero = last;
}

double wigleyLengthFactor(double length, double beam, double kappa) {
  const double a = 0.5 * length, t = kappa * a;
  // sin t/κ² − a cos t/κ = (a²/t²)(sin t − t cos t) = a² Σ_{n≥1} (−1)^{n+1} 2n t^{2n−1}/(2n+1)!.
  double bracket;
  if (std::abs(t) < 0.5) {
    double term = t / 6.0, sum = 0.0;  // t^{2n-1}/(2n+1)! for n = 1
    for (int n = 1; n <= 10; ++n) {
      sum += ((n % 2) ? 1.0 : -1.0) * 2.0 * n * term;
      term *= t * t / ((2.0 * n + 2.0) * (2.0 * n + 3.0));
    }
    bracket = a * a * sum;
  } else {
    bracket = std::sin(t) / (kappa * kappa) - a * std::cos(t) / kappa;
  }
  return 8.0 * beam / (length * length) * bracket;
}

double wigleyDepthFactor(double draft, double b) {
  const double bT = b * draft;
  if (bT < 2.0) {
    // T Σ_n (−bT)^n/n! [1/(n+1) − 1/(n+3)]; 40 terms: 2^40/40! < 1e-35.
    double term = 1.0, sum = 0.0;
    for (int n = 0; n < 40; ++n) {
      sum += term * (1.0 / (n + 1) - 1.0 / (n + 3));
      term *= -bT / (n + 1);
    }
    return draft * sum;
  }
  const double e = std::exp(-bT);
  return 1.0 / b - 2.0 / (b * b * b * draft * draft) + e * (2.0 / (b * b * draft) + 2.0 / (b * b * b * draft * draft));
}

double wigleyKochinSquared(double length, double beam, double draft, double k0, double lambda) {
  const double X = wigleyLengthFactor(length, beam, k0 * lambda);
  const double Z = wigleyDepthFactor(draft, k0 * lambda * lambda);
  return X * X * Z * Z;
}

}  // namespace maris::ship
