#include "wec/wec_frequency.hpp"

#include <cmath>
#include <numbers>

namespace maris::wec {

FrequencyResponse solveFrequency(const WecModel& model, const FloatModel& f, double omega, double pto_damping) {
  // Interacting floats: the coupled system, of which this float's row is returned.
  if (model.coupled) {
    const auto i = static_cast<int>(&f - model.floats.data());
    return solveCoupledFrequency(model, omega, i, pto_damping)[static_cast<std::size_t>(i)];
  }
  const double b_pto = pto_damping < 0.0 ? f.pto_damping : pto_damping;
  const double rx = f.arm_length * std::cos(f.theta0), rz = f.arm_length * std::sin(f.theta0);
  const FloatHydro h = f.hydro->at(omega);
  const FloatExcitation x = excitationAt(model, f, omega);
  const double c_hs = model.density * model.gravity * f.waterplane_area;
  const Complex iw(0.0, omega);

  FrequencyResponse r;
  r.omega = omega;
  r.inertia = f.inertia_hinge + h.heave.added_mass * rx * rx + h.surge.added_mass * rz * rz;
  r.damping = h.heave.damping * rx * rx + h.surge.damping * rz * rz;
  r.stiffness = c_hs * rx * rx + f.pto_stiffness;
  r.excitation = rx * x.heave - rz * x.surge;
  const Complex impedance = -omega * omega * r.inertia + iw * (b_pto + r.damping) + r.stiffness;
  r.pitch = r.excitation / impedance;

  // Float centre motion and the loads on it.
  const Complex xi_x = -rz * r.pitch, xi_z = rx * r.pitch;
  const Complex q_x = x.surge + (omega * omega * h.surge.added_mass - iw * h.surge.damping) * xi_x;
  const Complex q_z = x.heave + (omega * omega * h.heave.added_mass - iw * h.heave.damping) * xi_z - c_hs * xi_z;
  r.hinge_fx = q_x + omega * omega * f.mass * xi_x;
  r.hinge_fz = q_z + omega * omega * f.mass * xi_z;
  r.moment_y = rx * q_z - rz * q_x - (iw * b_pto + f.pto_stiffness) * r.pitch;

  // Power, capture width and bounds.
  r.power = 0.5 * b_pto * omega * omega * std::norm(r.pitch);
  const double energy_flux = model.density * model.gravity * model.gravity / (4.0 * omega);  // per a²
  r.capture_width = r.power / energy_flux;
  r.capture_width_bound = 3.0 * model.gravity / (omega * omega);  // 3λ/(2π), λ = 2πg/ω²
  const double reactance = omega * r.inertia - r.stiffness / omega;
  r.optimal_damping = std::sqrt(r.damping * r.damping + reactance * reactance);
  r.power_bound = r.damping > 0.0 ? std::norm(r.excitation) / (8.0 * r.damping) : 0.0;
  return r;
}

double naturalFrequency(const WecModel& model, const FloatModel& f) {
  auto g = [&](double w) {
    const FrequencyResponse r = solveFrequency(model, f, w, 0.0);
    return r.stiffness - w * w * r.inertia;
  };
  double lo = 0.05, g_lo = g(lo);
  if (g_lo <= 0.0) return 0.0;
  for (double hi = lo * 1.05; hi <= 10.0; hi *= 1.05) {
    const double g_hi = g(hi);
    if (g_hi <= 0.0) {
      // Bisection to 1e-12 relative.
      while (hi - lo > 1e-12 * hi) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) > 0.0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    lo = hi;
  }
  return 0.0;
}

Complex freeDecayEigenvalue(const WecModel& model, const FloatModel& f) {
  const double rx = f.arm_length * std::cos(f.theta0), rz = f.arm_length * std::sin(f.theta0);
  const double j_inf = f.inertia_hinge + f.heave.a_inf * rx * rx + f.surge.a_inf * rz * rz;
  const double k_theta = model.density * model.gravity * f.waterplane_area * rx * rx + f.pto_stiffness;
  auto transfer = [](const ModalKernel& fit, Complex s) {
    Complex h(0.0, 0.0);
    for (const auto& m : fit.modes) {
      h += m.residue / (s - m.pole);
      if (m.paired) h += std::conj(m.residue) / (s - std::conj(m.pole));
    }
    return h;
  };
  auto z = [&](Complex s) {
    return s * s * j_inf + s * (f.pto_damping + rx * rx * transfer(f.heave.fit, s) + rz * rz * transfer(f.surge.fit, s)) +
           k_theta;
  };
  const double wn = naturalFrequency(model, f);
  Complex s(0.0, wn > 0.0 ? wn : 1.0);
  for (int i = 0; i < 100; ++i) {
    const Complex h = 1e-7 * (1.0 + std::abs(s));
    const Complex step = z(s) / ((z(s + h) - z(s - h)) / (2.0 * h));
    s -= step;
    if (std::abs(step) < 1e-13 * std::abs(s)) return s;
  }
  return {0.0, 0.0};
}

double irregularMeanPower(const WecModel& model, const FloatModel& f, const std::string& spectrum, double hs,
                          double tp, double gamma) {
  const double wp = 2.0 * std::numbers::pi / tp;
  const int n = 2000;
  const double lo = 0.2 * wp, hi = 6.0 * wp, h = (hi - lo) / n;
  std::vector<double> omega(n + 1);
  for (int i = 0; i <= n; ++i) omega[static_cast<std::size_t>(i)] = lo + h * i;
  const auto s = spectrumDensity(spectrum, hs, tp, gamma, omega);
  double p = 0.0;
  for (int i = 0; i <= n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const FrequencyResponse r = solveFrequency(model, f, omega[k]);
    p += (i == 0 || i == n ? 0.5 : 1.0) * h * 2.0 * r.power * s[k];  // ½Bω²|Θ|²·a², a² = 2SΔω
  }
  return p;
}

ResponseSpectra responseSpectra(const WecModel& model, const FloatModel& f, const std::string& spectrum, double hs,
                                double tp, double gamma, const std::vector<double>& omega) {
  ResponseSpectra r;
  r.omega = omega;
  r.wave = spectrumDensity(spectrum, hs, tp, gamma, omega);
  const std::size_t n = omega.size();
  for (auto* v : {&r.pitch, &r.hinge_fx, &r.hinge_fz, &r.moment_y}) v->resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const FrequencyResponse h = solveFrequency(model, f, omega[k]);
    r.pitch[k] = std::norm(h.pitch) * r.wave[k];
    r.hinge_fx[k] = std::norm(h.hinge_fx) * r.wave[k];
    r.hinge_fz[k] = std::norm(h.hinge_fz) * r.wave[k];
    r.moment_y[k] = std::norm(h.moment_y) * r.wave[k];
  }
  // m0 by the trapezoid rule on the (possibly uneven) grid.
  auto sd = [&](const std::vector<double>& s) {
    double m0 = 0.0;
    for (std::size_t k = 1; k < n; ++k) m0 += 0.5 * (omega[k] - omega[k - 1]) * (s[k] + s[k - 1]);
    return std::sqrt(m0);
  };
  r.sd_pitch = sd(r.pitch);
  r.sd_fx = sd(r.hinge_fx);
  r.sd_fz = sd(r.hinge_fz);
  r.sd_moment = sd(r.moment_y);
  return r;
}

double deviationSamplingError(const std::vector<double>& omega, const std::vector<double>& s, double duration) {
  double m0 = 0.0, square = 0.0;
  for (std::size_t k = 1; k < omega.size(); ++k) {
    const double h = 0.5 * (omega[k] - omega[k - 1]);
    m0 += h * (s[k] + s[k - 1]);
    square += h * (s[k] * s[k] + s[k - 1] * s[k - 1]);
  }
  return m0 > 0.0 && duration > 0.0 ? std::sqrt(std::numbers::pi * square / (2.0 * duration)) / m0 : 0.0;
}

ResponseDeviations discreteResponseDeviations(const WecModel& model, const FloatModel& f, const IncidentWaves& waves) {
  ResponseDeviations d;
  for (const auto& c : waves.field.components()) {
    const FrequencyResponse h = solveFrequency(model, f, c.omega);
    const double a2 = 0.5 * c.amplitude * c.amplitude;
    d.pitch += a2 * std::norm(h.pitch);
    d.fx += a2 * std::norm(h.hinge_fx);
    d.fz += a2 * std::norm(h.hinge_fz);
    d.moment += a2 * std::norm(h.moment_y);
  }
  d.pitch = std::sqrt(d.pitch);
  d.fx = std::sqrt(d.fx);
  d.fz = std::sqrt(d.fz);
  d.moment = std::sqrt(d.moment);
  return d;
}

}  // namespace maris::wec
