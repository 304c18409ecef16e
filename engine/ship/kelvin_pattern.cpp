#include "ship/kelvin_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace maris::ship {

WavePattern kelvinWavePattern(GridKochin& kochin, double speed, double gravity, double x_stern, double length_behind,
                              double half_width, int nx, int ny) {
  const double k0 = gravity / (speed * speed);
  const HullGrid& grid = kochin.grid();
  const double x_mid = grid.x_aft + 0.5 * (grid.nx() - 1) * grid.dx;
  kochin.prepare(speed);

  // λ range: up to where |A|² cos³θ (the spectrum) falls below 1e-6 of its largest value.
  double peak = 0, lambda_max = 1.0;
  for (double lambda = 1.0; lambda < 200.0; lambda *= 1.02) {
    double f = 0, c = 0;
    kochin.evaluate(k0, lambda, f, c);
    const double density = f * lambda * lambda * lambda;
    peak = std::max(peak, density);
    if (density > 1e-6 * peak) lambda_max = lambda;
  }
  // Nodes in u (λ = cosh u): 6 per radian of the phase k0 (|x'| λ + |y| λ² sin θ) at the farthest point.
  const double u_max = std::acosh(lambda_max);
  const double r_far = std::abs(x_stern - length_behind - x_mid) + half_width;
  const int nu = std::clamp(static_cast<int>(6.0 * k0 * r_far * lambda_max * lambda_max * u_max), 200, 20000);
  const double du = u_max / nu;
  std::vector<std::complex<double>> weight(nu + 1);  // A(θ) dθ (trapezoid in u; dθ = du / cosh u)
  Eigen::VectorXd kappa(nu + 1), ky(nu + 1);
  for (int k = 0; k <= nu; ++k) {
    const double u = k * du, lambda = std::cosh(u);
    const std::complex<double> F = kochin.amplitude(k0, lambda);
    const double end = (k == 0 || k == nu) ? 0.5 : 1.0;
    weight[k] = (-2.0 / std::numbers::pi) * k0 * lambda * lambda * lambda * F * (end * du / lambda);
    kappa[k] = k0 * lambda;                       // k cos θ
    ky[k] = k0 * lambda * lambda * std::tanh(u);  // k sin θ (sin θ = tanh u)
  }

  WavePattern w;
  w.x.resize(nx);
  w.y.resize(ny);
  for (int i = 0; i < nx; ++i) w.x[i] = x_stern - length_behind * (i + 1.0) / nx;
  for (int j = 0; j < ny; ++j) w.y[j] = -half_width + 2.0 * half_width * j / (ny - 1);
  // ζ_ij = Σ_k Re(A_k e^{−iκ_k x'_i}) · 2 cos(k_y,k y_j): ±θ pair up (the hull is symmetric), one GEMM.
  Eigen::MatrixXd along(nx, nu + 1), across(nu + 1, ny);
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k <= nu; ++k) along(i, k) = (weight[k] * std::polar(1.0, -kappa[k] * (w.x[i] - x_mid))).real();
  for (int k = 0; k <= nu; ++k)
    for (int j = 0; j < ny; ++j) across(k, j) = 2.0 * std::cos(ky[k] * w.y[j]);
  w.elevation = along * across;
  return w;
}

}  // namespace maris::ship
