// Closed-form solutions shared by tests and benchmarks (style.md §10). Each cites its source.
#pragma once

#include <cmath>

namespace maris {

struct OscillatorState {
  double position = 0.0;  // [m] (or any unit of x)
  double velocity = 0.0;  // [m/s]
};

// Free response of the linear oscillator x'' + 2ζω_n x' + ω_n² x = 0 with x(0) = x0, x'(0) = v0
// (e.g. Rao, Mechanical Vibrations, §2.6):
//   ζ < 1:  x = e^{−ζω_n t} (x0 cos ω_d t + (v0 + ζω_n x0)/ω_d · sin ω_d t),   ω_d = ω_n √(1 − ζ²)
//   ζ = 1:  x = e^{−ω_n t} (x0 + (v0 + ω_n x0) t)
//   ζ > 1:  x = A e^{r_1 t} + B e^{r_2 t},  r_{1,2} = −ω_n (ζ ∓ √(ζ² − 1)),  A + B = x0,  r_1 A + r_2 B = v0
// The overdamped roots are formed without cancellation (r_slow = ω_n² / r_fast), so very stiff cases
// (e.g. roots −1 and −1e5) are accurate. omega_n [rad/s] > 0, zeta [-] ≥ 0, t [s].
inline OscillatorState dampedOscillator(double omega_n, double zeta, double x0, double v0, double t) {
  OscillatorState s;
  if (zeta < 1.0) {
    const double wd = omega_n * std::sqrt(1.0 - zeta * zeta);
    const double decay = std::exp(-zeta * omega_n * t);
    const double b = (v0 + zeta * omega_n * x0) / wd;
    const double c = std::cos(wd * t), sn = std::sin(wd * t);
    s.position = decay * (x0 * c + b * sn);
    s.velocity = decay * ((b * wd - zeta * omega_n * x0) * c - (x0 * wd + zeta * omega_n * b) * sn);
  } else if (zeta == 1.0) {
    const double decay = std::exp(-omega_n * t);
    const double b = v0 + omega_n * x0;
    s.position = decay * (x0 + b * t);
    s.velocity = decay * (b - omega_n * (x0 + b * t));
  } else {
    const double r_fast = -omega_n * (zeta + std::sqrt(zeta * zeta - 1.0));
    const double r_slow = omega_n * omega_n / r_fast;
    const double a_slow = (v0 - r_fast * x0) / (r_slow - r_fast);
    const double a_fast = x0 - a_slow;
    const double e_slow = std::exp(r_slow * t), e_fast = std::exp(r_fast * t);
    s.position = a_slow * e_slow + a_fast * e_fast;
    s.velocity = a_slow * r_slow * e_slow + a_fast * r_fast * e_fast;
  }
  return s;
}

// Undamped case x'' + ω² x = 0: x = x0 cos ωt + (v0/ω) sin ωt.
inline OscillatorState harmonicOscillator(double omega, double x0, double v0, double t) {
  return dampedOscillator(omega, 0.0, x0, v0, t);
}

// Energy per unit mass of the undamped oscillator: E = (v² + ω² x²)/2 [m²/s²].
inline double oscillatorEnergy(double omega, const OscillatorState& s) {
  return 0.5 * (s.velocity * s.velocity + omega * omega * s.position * s.position);
}

// Energy ratio per step of classical RK4 on x'' + ω² x = 0 with step h (exact, from the stability
// polynomial R(z) = 1 + z + z²/2 + z³/6 + z⁴/24 at z = iωh; |R|² = 1 − (ωh)⁶/72 + (ωh)⁸/576):
// after n steps the energy is E0·ratio^n, so RK4 loses energy at a rate ∝ h⁵ over a fixed time.
inline double rk4OscillatorEnergyRatioPerStep(double omega_h) {
  const double y2 = omega_h * omega_h, y6 = y2 * y2 * y2;
  return 1.0 - y6 / 72.0 + y6 * y2 / 576.0;
}

}  // namespace maris
