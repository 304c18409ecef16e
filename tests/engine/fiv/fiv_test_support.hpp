// Small builders shared by the fiv tests: parameter sets with a chosen mass-damping, and direct
// time marching of the model for envelope checks.
#pragma once

#include <cmath>
#include <numbers>

#include "fiv/fiv_limit_cycle.hpp"
#include "fiv/fiv_model.hpp"

namespace maris::fiv::testing {

// Paper defaults (D = 0.09 m, ξ = 0.1, f_n = 0.5 Hz) with only the quasi-steady galloping force.
inline FivParameters gallopingOnly() {
  FivParameters p;
  p.forcing = "galloping";
  return p;
}

// A weakly nonlinear galloping set: mass parameter n_m = ρD²L/(2 m_t) and damping ratio ξ chosen,
// f_n = 0.5 Hz, no added mass (so m_t = m).
inline FivParameters weaklyNonlinearGalloping(double mass_parameter, double damping_ratio) {
  FivParameters p = gallopingOnly();
  p.added_mass_coefficient = 0.0;
  p.mass = p.density * p.side * p.side * p.length / (2.0 * mass_parameter);
  const double omega = 2.0 * std::numbers::pi * 0.5;
  p.stiffness = p.mass * omega * omega;
  p.damping_input = "ratio";
  p.damping_ratio = damping_ratio;
  return p;
}

// Envelope of y over `periods` natural periods after `skip` periods: max |y| in the last period.
inline double amplitudeAfter(const FivRhs& rhs, State& s, double periods, int steps_per_period = 64) {
  const double period = 2.0 * std::numbers::pi / rhs.model().omega_n;
  const double h = period / steps_per_period;
  const long n = static_cast<long>(std::round(periods * steps_per_period));
  double amplitude = 0.0;
  for (long i = 0; i < n; ++i) {
    rhs.step(s, h);
    if (i >= n - steps_per_period) amplitude = std::max(amplitude, std::abs(s[0]));
  }
  return amplitude;
}

}  // namespace maris::fiv::testing
