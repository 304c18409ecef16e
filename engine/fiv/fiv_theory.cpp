#include "fiv/fiv_theory.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace maris::fiv {

double logarithmicDecrement(double damping_ratio) {
  return 2.0 * std::numbers::pi * damping_ratio / std::sqrt(1.0 - damping_ratio * damping_ratio);
}

double sinusoidDamperPower(double damping, double omega, double amplitude) {
  return 0.5 * damping * omega * omega * amplitude * amplitude;
}

double sweptFluidPower(double density, double speed, double length, double side, double amplitude) {
  return 0.5 * density * speed * speed * speed * length * (side + 2.0 * amplitude);
}

double betzEfficiency(double power, double fluid_power) {
  return fluid_power > 0.0 ? power / (fluid_power * kBetzLimit) : 0.0;
}

double gallopingOnsetSpeed(double damping, double density, double side, double length, double slope_a1,
                           double surface_factor) {
  const double drive = density * side * length * slope_a1 * surface_factor;
  return drive > 0.0 ? 2.0 * damping / drive : std::numeric_limits<double>::infinity();
}

double averagedForceCoefficient(const ForceCurve& curve, double velocity_ratio) {
  if (velocity_ratio <= 0.0) return curve.initialSlope();
  // Periodic trapezoid rule: exact for trigonometric polynomials of degree < n (the 7th-order
  // polynomial gives degree 8); 256 points also resolve table kinks to ~1e-5.
  constexpr int n = 256;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double theta = 2.0 * std::numbers::pi * (i + 0.5) / n;
    sum += curve(velocity_ratio * std::sin(theta)) * std::sin(theta);
  }
  return sum * (2.0 / n) / velocity_ratio;
}

std::vector<HarmonicBalanceRoot> harmonicBalanceRoots(const ForceCurve& curve, double balance, double r_max) {
  std::vector<HarmonicBalanceRoot> roots;
  constexpr int n = 2000;
  auto f = [&](double r) { return averagedForceCoefficient(curve, r) - balance; };
  double r0 = 1e-6 * r_max, f0 = f(r0);
  for (int i = 1; i <= n; ++i) {
    const double r1 = r_max * i / n, f1 = f(r1);
    if ((f0 > 0.0) != (f1 > 0.0)) {
      // Bisection to machine-level precision of r.
      double lo = r0, hi = r1, flo = f0;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm > 0.0) == (flo > 0.0)) { lo = mid; flo = fm; } else { hi = mid; }
      }
      roots.push_back({0.5 * (lo + hi), f0 > 0.0});  // G falls through S: stable
    }
    r0 = r1;
    f0 = f1;
  }
  return roots;
}

std::vector<HarmonicBalanceRoot> harmonicBalanceAtSpeed(const FivModel& model, double speed, double surface_factor) {
  if (speed <= 0.0 || surface_factor <= 0.0) return {};
  const double balance = 2.0 * model.damping / (model.density * model.side * model.length * speed * surface_factor);
  return harmonicBalanceRoots(model.curve, balance);
}

}  // namespace maris::fiv
