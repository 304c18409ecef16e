// Test problems shared by the ODE tests: right-hand sides and second-order residuals with known
// behaviour (closed forms in core/closed_forms.hpp).
#pragma once

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "core/ode.hpp"

namespace maris::test {

// The damped oscillator most ODE tests integrate: ω [rad/s], ζ [-] and the start x(0), x'(0).
inline constexpr double kOmega = 2.0, kZeta = 0.1, kX0 = 1.0, kV0 = 0.5;

// x'' + 2ζω x' + ω² x = 0 as y = (x, v).
inline OdeRhs oscillatorRhs(double omega, double zeta) {
  return [omega, zeta](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt[0] = y[1];
    dydt[1] = -2.0 * zeta * omega * y[1] - omega * omega * y[0];
  };
}

// The same oscillator as a second-order system: r = acc + 2ζω v + ω² q (unit mass).
inline SecondOrderSystem oscillatorSystem(double omega, double zeta) {
  SecondOrderSystem system;
  system.size = 1;
  system.residual = [omega, zeta](double, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& acc, Eigen::VectorXd& r) {
    r[0] = acc[0] + 2.0 * zeta * omega * v[0] + omega * omega * q[0];
  };
  return system;
}

// Van der Pol: x'' − μ (1 − x²) x' + x = 0 as y = (x, v).
inline OdeRhs vanDerPolRhs(double mu) {
  return [mu](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt[0] = y[1];
    dydt[1] = mu * (1.0 - y[0] * y[0]) * y[1] - y[0];
  };
}

inline std::string positionVelocityName(Eigen::Index i) { return i == 0 ? "position" : "velocity"; }

}  // namespace maris::test
