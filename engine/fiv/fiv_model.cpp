#include "fiv/fiv_model.hpp"

#include <algorithm>
#include <numbers>

namespace maris::fiv {

namespace {

// Unscaled curve C_y0(t) for t >= 0.
double baseCurve(const ForceCurve& c, double t) {
  switch (c.kind) {
    case ForceCurve::Kind::Parkinson:
    case ForceCurve::Kind::Cubic: {
      // Polynomials are fits to static data and diverge past their range: beyond tan_max they
      // continue along their tangent (C¹), which keeps the force finite and the slope as fitted.
      const auto& a = c.coefficients;
      const double u = std::min(t, c.tan_max);
      const double u2 = u * u;
      const double value = u * (a[0] + u2 * (a[1] + u2 * (a[2] + u2 * a[3])));
      if (t <= c.tan_max) return value;
      const double slope = a[0] + u2 * (3.0 * a[1] + u2 * (5.0 * a[2] + u2 * 7.0 * a[3]));
      return value + slope * (t - u);
    }
    case ForceCurve::Kind::Table: {
      const auto& x = c.table_tan;
      if (t >= x.back()) return c.table_c_y.back();
      const auto it = std::upper_bound(x.begin(), x.end(), t);
      const std::size_t i = static_cast<std::size_t>(it - x.begin()) - 1;
      const double w = (t - x[i]) / (x[i + 1] - x[i]);
      return (1.0 - w) * c.table_c_y[i] + w * c.table_c_y[i + 1];
    }
  }
  return 0.0;
}

}  // namespace

double ForceCurve::operator()(double tan_alpha) const {
  const double t = std::abs(tan_alpha) / angle_scale;
  const double value = force_scale * angle_scale * baseCurve(*this, t);
  return tan_alpha < 0.0 ? -value : value;
}

double ForceCurve::slope(double tan_alpha) const {
  const double delta = 1e-5 * angle_scale;
  return ((*this)(tan_alpha + delta) - (*this)(tan_alpha - delta)) / (2.0 * delta);
}

double ForceCurve::initialSlope() const {
  double slope0 = coefficients[0];
  if (kind == Kind::Table) slope0 = (table_c_y[1] - table_c_y[0]) / (table_tan[1] - table_tan[0]);
  return force_scale * slope0;
}

FivModel buildFivModel(const FivParameters& p) {
  FivModel m;
  m.side = p.side;
  m.length = p.length;
  m.density = p.density;
  m.viscosity = p.kinematic_viscosity;
  m.gravity = p.gravity;
  m.mass = p.mass;
  m.added_mass = p.added_mass_coefficient * p.density * p.side * p.side * p.length;
  m.total_mass = m.mass + m.added_mass;
  m.stiffness = p.stiffness;
  m.omega_n = std::sqrt(m.stiffness / m.total_mass);
  m.f_n = m.omega_n / (2.0 * std::numbers::pi);
  const double critical = 2.0 * std::sqrt(m.stiffness * m.total_mass);
  m.damping = p.damping_input == "ratio" ? p.damping_ratio * critical : p.damping_coefficient;
  m.damping_ratio = m.damping / critical;
  m.galloping_on = p.forcing != "viv";
  m.viv_on = p.forcing != "galloping";

  ForceCurve& c = m.curve;
  if (p.galloping_curve == "parkinson") {
    c.kind = ForceCurve::Kind::Parkinson;
    c.coefficients = {p.parkinson_a1, -p.parkinson_a3, p.parkinson_a5, -p.parkinson_a7};
  } else if (p.galloping_curve == "cubic") {
    c.kind = ForceCurve::Kind::Cubic;
    c.coefficients = {p.cubic_a1, p.cubic_a3, 0.0, 0.0};
  } else {
    c.kind = ForceCurve::Kind::Table;
    for (const auto& row : p.force_table) {
      c.table_tan.push_back(std::tan(row.angle_deg * std::numbers::pi / 180.0));
      c.table_c_y.push_back(row.c_y);
    }
  }
  c.tan_max = p.polynomial_tan_max;
  c.force_scale = p.force_scale;
  c.angle_scale = p.angle_scale;

  m.strouhal = p.strouhal;
  m.lift_amplitude = p.wake_lift_amplitude;
  m.wake_epsilon = p.wake_epsilon;
  m.wake_coupling = p.wake_coupling;
  m.gallop_deficit = p.surface_gallop_deficit;
  m.viv_deficit = p.surface_viv_deficit;
  m.surface_decay = p.surface_decay;
  return m;
}

double surfaceFactor(double deficit, double decay, double submergence_ratio) {
  if (!std::isfinite(submergence_ratio)) return 1.0;
  return 1.0 - deficit * std::exp(-decay * (submergence_ratio - 0.5));
}

OperatingPoint makeOperatingPoint(const FivModel& model, double speed, double submergence_ratio) {
  OperatingPoint op;
  op.speed = speed;
  op.submergence_ratio = submergence_ratio;
  op.gallop_factor = surfaceFactor(model.gallop_deficit, model.surface_decay, submergence_ratio);
  op.viv_factor = surfaceFactor(model.viv_deficit, model.surface_decay, submergence_ratio);
  op.force_per_coefficient = 0.5 * model.density * speed * speed * model.side * model.length;
  op.wake_omega = 2.0 * std::numbers::pi * model.strouhal * speed / model.side;
  return op;
}

FivRhs::FivRhs(const FivModel& model, const OperatingPoint& op) : model_(&model), op_(op) {
  inverse_mass_ = 1.0 / model.total_mass;
  inverse_speed_ = op.speed > 0.0 ? 1.0 / op.speed : 0.0;
  galloping_gain_ = op.force_per_coefficient * op.gallop_factor;
  vortex_gain_ = op.force_per_coefficient * op.viv_factor * 0.5 * model.lift_amplitude;
  wake_coupling_over_d_ = model.wake_coupling / model.side;
  wake_damping_ = model.wake_epsilon * op.wake_omega;
  wake_omega_sq_ = op.wake_omega * op.wake_omega;
}

}  // namespace maris::fiv
