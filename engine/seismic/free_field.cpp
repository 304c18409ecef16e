#include "seismic/free_field.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include <Eigen/Dense>

#include "core/errors.hpp"

namespace maris::seismic {

namespace {

const Complex kI{0.0, 1.0};

// Contribution of one P (scaled potential a) or SV (scaled potential b) plane wave, per unit
// amplitude, with vertical direction s = +1 (up) or −1 (down); phase not included.
struct WaveTerms {
  Complex ux, uy, sxx, syy, sxy;
};

WaveTerms pWave(double s, double p, Complex eta_p, double lambda, double mu, double vp) {
  return {p, s * eta_p, -(lambda / (vp * vp) + 2.0 * mu * p * p), -(lambda / (vp * vp) + 2.0 * mu * eta_p * eta_p),
          -2.0 * mu * p * s * eta_p};
}

WaveTerms svWave(double s, double p, double eta_s, double mu) {
  return {s * eta_s, -p, -2.0 * mu * p * s * eta_s, 2.0 * mu * p * s * eta_s, mu * (p * p - eta_s * eta_s)};
}

}  // namespace

const char* toString(WaveType type) { return type == WaveType::P ? "P" : "SV"; }

double FreeField::criticalAngleSv(const ElasticMaterial& solid) { return std::asin(solid.vs / solid.vp); }

FreeField::FreeField(const ElasticMaterial& solid, const WaterLayer& water, WaveType type, double angle_rad)
    : solid_(solid), water_(water), type_(type), angle_(angle_rad) {
  const double deg = 180.0 / std::numbers::pi;
  if (!(std::abs(angle_rad) < 0.5 * std::numbers::pi)) {
    std::ostringstream v;
    v << angle_rad * deg;
    throw InputError("incidence.angle_deg", v.str(), "must be in (-90, 90) degrees");
  }
  lambda_ = solid.lameLambda();
  mu_ = solid.shearModulus();
  const double c_incident = type == WaveType::P ? solid.vp : solid.vs;
  p_ = std::sin(angle_rad) / c_incident;
  // Beyond the SV critical angle p > 1/vp: the reflected P is evanescent, η_p = +i·√(p² − 1/vp²), so
  // the down-going factor e^{−iωη_p y} = e^{ωκy} decays with depth (y < 0) for Re ω > 0; the synthesis
  // evaluates Re ω ≥ 0 only and fills the negative frequencies by conjugation.
  eta_p_ = std::sqrt(Complex(1.0 / (solid.vp * solid.vp) - p_ * p_, 0.0));
  eta_s_ = std::sqrt(std::max(0.0, 1.0 / (solid.vs * solid.vs) - p_ * p_));
  // Principal root: real and positive when propagating, +i·|…| (decaying upwards) when evanescent.
  eta_f_ = water.depth > 0.0 ? std::sqrt(Complex(1.0 / (water.sound_speed * water.sound_speed) - p_ * p_, 0.0))
                             : Complex(0.0);
}

FreeFieldAmplitudes FreeField::solve(Complex omega) const {
  FreeFieldAmplitudes out;
  const double vp = solid_.vp, rho = solid_.density;
  // Incident wave with unit displacement at the origin, and its seabed terms.
  WaveTerms inc;
  if (type_ == WaveType::P) {
    out.incident = vp;
    inc = pWave(+1.0, p_, eta_p_, lambda_, mu_, vp);
  } else {
    out.incident = solid_.vs;
    inc = svWave(+1.0, p_, eta_s_, mu_);
  }
  const WaveTerms rp = pWave(-1.0, p_, eta_p_, lambda_, mu_, vp);
  const WaveTerms rs = svWave(-1.0, p_, eta_s_, mu_);

  // Traction-free seabed: σ_yy = τ_xy = 0 (rows scaled by 1/ρ to O(1)).
  if (!hasWater()) {
    Eigen::Matrix2cd A;
    Eigen::Vector2cd b;
    A << rp.syy / rho, rs.syy / rho, rp.sxy / rho, rs.sxy / rho;
    b << -inc.syy * out.incident / rho, -inc.sxy * out.incident / rho;
    const Eigen::Vector2cd x = A.partialPivLu().solve(b);
    out.reflected_p = x(0);
    out.reflected_s = x(1);
    return out;
  }

  // With water: u_y continuous, σ_yy + p = 0, τ_xy = 0 at y = 0, p = 0 at y = h.
  const double rho_f = water_.density;
  const Complex d = std::exp(kI * omega * eta_f_ * water_.depth);  // down-going wave's phase at y = 0
  Eigen::Matrix4cd A = Eigen::Matrix4cd::Zero();
  Eigen::Vector4cd b = Eigen::Vector4cd::Zero();
  A.row(0) << rp.uy * vp, rs.uy * vp, -eta_f_ * vp, eta_f_ * d * vp;
  A.row(1) << rp.syy / rho, rs.syy / rho, rho_f / rho, rho_f * d / rho;
  A.row(2) << rp.sxy / rho, rs.sxy / rho, 0.0, 0.0;
  A.row(3) << 0.0, 0.0, d, 1.0;
  b << -inc.uy * out.incident * vp, -inc.syy * out.incident / rho, -inc.sxy * out.incident / rho, 0.0;
  const Eigen::Vector4cd x = A.partialPivLu().solve(b);
  out.reflected_p = x(0);
  out.reflected_s = x(1);
  out.water_up = x(2);
  out.water_down = x(3);
  return out;
}

FreeFieldPoint FreeField::solidAt(const FreeFieldAmplitudes& a, Complex omega, double x, double y) const {
  const Complex iw = kI * omega;
  const Complex phase_x = std::exp(iw * p_ * x);
  const Complex up_p = std::exp(iw * eta_p_ * y), down_p = std::exp(-iw * eta_p_ * y);
  const Complex up_s = std::exp(iw * eta_s_ * y), down_s = std::exp(-iw * eta_s_ * y);
  const WaveTerms rp = pWave(-1.0, p_, eta_p_, lambda_, mu_, solid_.vp);
  const WaveTerms rs = svWave(-1.0, p_, eta_s_, mu_);
  const bool p_incident = type_ == WaveType::P;
  const WaveTerms inc = p_incident ? pWave(+1.0, p_, eta_p_, lambda_, mu_, solid_.vp) : svWave(+1.0, p_, eta_s_, mu_);
  const Complex c_inc = a.incident * (p_incident ? up_p : up_s) * phase_x;
  const Complex c_rp = a.reflected_p * down_p * phase_x;
  const Complex c_rs = a.reflected_s * down_s * phase_x;
  const Complex to_stress = -kI * omega;  // σ = (−iω)·S
  FreeFieldPoint f;
  f.ux = inc.ux * c_inc + rp.ux * c_rp + rs.ux * c_rs;
  f.uy = inc.uy * c_inc + rp.uy * c_rp + rs.uy * c_rs;
  f.sxx = to_stress * (inc.sxx * c_inc + rp.sxx * c_rp + rs.sxx * c_rs);
  f.syy = to_stress * (inc.syy * c_inc + rp.syy * c_rp + rs.syy * c_rs);
  f.sxy = to_stress * (inc.sxy * c_inc + rp.sxy * c_rp + rs.sxy * c_rs);
  return f;
}

FreeFieldPoint FreeField::waterAt(const FreeFieldAmplitudes& a, Complex omega, double x, double y) const {
  FreeFieldPoint f;
  if (!hasWater()) return f;
  const Complex iw = kI * omega;
  const Complex phase_x = std::exp(iw * p_ * x);
  const Complex up = a.water_up * std::exp(iw * eta_f_ * y) * phase_x;
  const Complex down = a.water_down * std::exp(-iw * eta_f_ * (y - water_.depth)) * phase_x;
  f.ux = p_ * (up + down);
  f.uy = eta_f_ * (up - down);
  f.pressure = -kI * omega * water_.density * (up + down);  // p = ρ ω² φ with φ = a/(iω)
  f.potential = (up + down) / iw;
  return f;
}

double FreeField::energyResidual(const FreeFieldAmplitudes& a) const {
  // An evanescent P (Re η_p = 0) carries no vertical energy flux.
  const double eta_inc = type_ == WaveType::P ? eta_p_.real() : eta_s_;
  const double incoming = eta_inc * std::norm(a.incident);
  const double outgoing = eta_p_.real() * std::norm(a.reflected_p) + eta_s_ * std::norm(a.reflected_s);
  return outgoing / incoming - 1.0;
}

}  // namespace maris::seismic
