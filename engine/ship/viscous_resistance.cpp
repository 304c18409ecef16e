#include "ship/viscous_resistance.hpp"

#include <cmath>
#include <stdexcept>

namespace maris::ship {

WaterProperties waterProperties(WaterKind kind, double t) {
  WaterProperties w;
  if (kind == WaterKind::Fresh) {
    constexpr double a1 = -3.983035, a2 = 301.797, a3 = 522528.9, a4 = 69.34881, a5 = 999.974950;
    w.density = a5 * (1.0 - (t + a1) * (t + a1) * (t + a2) / (a3 * (t + a4)));
    const double d = t - 12.0;
    w.kinematic_viscosity = ((0.000585 * d - 0.03361) * d + 1.2350) * 1e-6;
    return w;
  }
  constexpr double S = 35.0;
  const double rho_w = 999.842594 + t * (6.793952e-2 + t * (-9.095290e-3 + t * (1.001685e-4 + t * (-1.120083e-6 + t * 6.536332e-9))));
  const double b = 8.24493e-1 + t * (-4.0899e-3 + t * (7.6438e-5 + t * (-8.2467e-7 + t * 5.3875e-9)));
  const double c = -5.72466e-3 + t * (1.0227e-4 - t * 1.6546e-6);
  constexpr double d = 4.8314e-4;
  w.density = rho_w + b * S + c * S * std::sqrt(S) + d * S * S;
  const double e = t - 1.0;
  w.kinematic_viscosity = ((0.000659 * e - 0.05076) * e + 1.7688) * 1e-6;
  return w;
}

double ittc57FrictionCoefficient(double reynolds) {
  const double l = std::log10(reynolds) - 2.0;
  return 0.075 / (l * l);
}

ProhaskaFit prohaskaFormFactor(const std::vector<double>& froude, const std::vector<double>& c_total,
                               const std::vector<double>& c_friction) {
  const std::size_t n = froude.size();
  if (c_total.size() != n || c_friction.size() != n || n < 2)
    throw std::invalid_argument("Prohaska fit needs at least 2 points with froude, c_total and c_friction each");
  // Straight line y = a + c x through (x, y) = (Fn⁴/C_F, C_T/C_F), centred sums for accuracy.
  std::vector<double> x(n), y(n);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = std::pow(froude[i], 4) / c_friction[i];
    y[i] = c_total[i] / c_friction[i];
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 1e-300)) throw std::invalid_argument("Prohaska fit needs points at two or more different speeds");
  ProhaskaFit fit;
  fit.slope = sxy / sxx;
  fit.form_factor = my - fit.slope * mx;
  fit.points = static_cast<int>(n);
  double ss = 0;
  for (std::size_t i = 0; i < n; ++i) ss += std::pow(y[i] - fit.form_factor - fit.slope * x[i], 2);
  fit.rms_residual = std::sqrt(ss / n);
  return fit;
}

}  // namespace maris::ship
