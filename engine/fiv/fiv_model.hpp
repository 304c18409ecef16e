// Reduced-order model of a 1-DOF square cylinder in cross-flow near a free surface.
//
// Conventions: x along the current U, y the cross-flow displacement of the cylinder centre from its
// rest position, positive towards the free surface (up); the span lies along the third axis. The
// cylinder centre rests at depth h below the undisturbed free surface; h* = h/D (∞: no surface).
//
// Equation of motion (per span L; m_t = m + m_a):
//   m_t ÿ + c ẏ + k y = ½ρU²DL [ κ_g(h*) C_y(ẏ/U) + κ_v(h*) (C_L0/2) q ]
//   q̈ + ε Ω_f (q² − 1) q̇ + Ω_f² q = (A/D) ÿ,        Ω_f = 2π St U / D
// C_y: quasi-steady transverse force (Parkinson & Smith 1964; Barrero-Gil et al. 2010; or a table),
// q: Facchinetti, de Langre & Biolley (2004) wake variable with acceleration coupling, combined
// additively as Tamura & Shimada (1987). κ(h*) = 1 − a exp(−b(h* − ½)) is our calibrated free-surface
// factor (no published correlation is known to us; a, b fitted to the paper's power ratios); κ = 1 for h* = ∞.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "fiv/fiv_parameters.hpp"

namespace maris::fiv {

inline constexpr double kDeep = std::numeric_limits<double>::infinity();  // h* of the no-surface case

// C_y(tan α) with odd symmetry; built once from the parameters.
struct ForceCurve {
  enum class Kind { Parkinson, Cubic, Table } kind = Kind::Parkinson;
  std::array<double, 4> coefficients{};  // polynomial: C_y = c0 t + c1 t³ + c2 t⁵ + c3 t⁷ (signs included)
  double tan_max = 0.35;                  // polynomial continues along its tangent beyond |t| = tan_max
  std::vector<double> table_tan;          // table abscissae tan α (ascending, from 0)
  std::vector<double> table_c_y;          // table values
  double force_scale = 1.0;               // multiplies C_y
  double angle_scale = 1.0;               // C_y(t) = s·C_y0(t/s)

  double operator()(double tan_alpha) const;
  double slope(double tan_alpha) const;  // dC_y/d(tan α), central difference (exact enough for a step bound)
  double initialSlope() const;  // dC_y/d(tan α) at 0 (A1 for Parkinson), including both scales
};

// Derived constants of the model, computed once from validated parameters.
struct FivModel {
  double side = 0.0, length = 0.0;          // [m] D, L
  double density = 0.0, viscosity = 0.0;    // [kg/m³], [m²/s]
  double gravity = 9.81;                    // [m/s²]
  double mass = 0.0, added_mass = 0.0;      // [kg] m, m_a
  double total_mass = 0.0;                  // [kg] m_t = m + m_a
  double stiffness = 0.0;                   // [N/m] k
  double damping = 0.0;                     // [N·s/m] c
  double damping_ratio = 0.0;               // [-] ξ = c / (2√(k m_t))
  double omega_n = 0.0;                     // [rad/s] natural frequency in water √(k/m_t)
  double f_n = 0.0;                         // [Hz]
  bool galloping_on = true, viv_on = true;
  ForceCurve curve;
  double strouhal = 0.13, lift_amplitude = 1.0, wake_epsilon = 0.3, wake_coupling = 12.0;
  double gallop_deficit = 0.0, viv_deficit = 0.0, surface_decay = 1.0;
};

FivModel buildFivModel(const FivParameters& p);

// κ(h*) = 1 − a exp(−b (h* − ½)), 1 for h* = ∞ (deficit a, decay b).
double surfaceFactor(double deficit, double decay, double submergence_ratio);

// Constants of the right-hand side at one operating point (speed U, submergence h*).
struct OperatingPoint {
  double speed = 0.0;              // [m/s] U
  double submergence_ratio = kDeep;  // [-] h*
  double gallop_factor = 1.0;      // [-] κ_g
  double viv_factor = 1.0;         // [-] κ_v
  double force_per_coefficient = 0.0;  // [N] ½ρU²DL
  double wake_omega = 0.0;         // [rad/s] Ω_f
};

OperatingPoint makeOperatingPoint(const FivModel& model, double speed, double submergence_ratio);

// State layout: y [m], ẏ [m/s], q [-], q̇ [1/s], ∫cẏ²dt [J], ∫Fẏdt [J].
using State = std::array<double, 6>;
inline constexpr int kStateSize = 6;

// Fluid force components [N] at a state: galloping (quasi-steady) and vortex (wake) parts.
struct FluidForce {
  double galloping = 0.0;
  double vortex = 0.0;
  double total() const { return galloping + vortex; }
};

// The 6-state right-hand side; inline because the limit-cycle loop calls it 4 times per step.
class FivRhs {
 public:
  FivRhs(const FivModel& model, const OperatingPoint& op);

  FluidForce force(const State& s) const {
    FluidForce f;
    if (model_->galloping_on && op_.speed > 0.0)
      f.galloping = galloping_gain_ * model_->curve(s[1] * inverse_speed_);
    if (model_->viv_on) f.vortex = vortex_gain_ * s[2];
    return f;
  }

  void derivative(const State& s, State& ds) const {
    const double force_total = force(s).total();
    const double accel = (force_total - model_->damping * s[1] - model_->stiffness * s[0]) * inverse_mass_;
    ds[0] = s[1];
    ds[1] = accel;
    ds[2] = s[3];
    ds[3] = model_->viv_on
                ? wake_coupling_over_d_ * accel - wake_damping_ * (s[2] * s[2] - 1.0) * s[3] - wake_omega_sq_ * s[2]
                : 0.0;
    ds[4] = model_->damping * s[1] * s[1];
    ds[5] = force_total * s[1];
  }

  // One classical RK4 step of size h.
  void step(State& s, double h) const {
    State k1, k2, k3, k4, tmp;
    derivative(s, k1);
    for (int i = 0; i < kStateSize; ++i) tmp[i] = s[i] + 0.5 * h * k1[i];
    derivative(tmp, k2);
    for (int i = 0; i < kStateSize; ++i) tmp[i] = s[i] + 0.5 * h * k2[i];
    derivative(tmp, k3);
    for (int i = 0; i < kStateSize; ++i) tmp[i] = s[i] + h * k3[i];
    derivative(tmp, k4);
    for (int i = 0; i < kStateSize; ++i) s[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }

  // Largest real decay rate [1/s] of the linearised system while |ẏ/U| <= tan_alpha:
  // (c + ½ρUDLκ_g |dC_y/d tanα|) / m_t. RK4 needs h·rate below ≈ 2.8 (real-axis stability limit).
  double decayRate(double tan_alpha) const {
    const double fluid = model_->galloping_on && op_.speed > 0.0
                             ? galloping_gain_ * inverse_speed_ * std::abs(model_->curve.slope(tan_alpha))
                             : 0.0;
    return (model_->damping + fluid) * inverse_mass_;
  }

  const FivModel& model() const { return *model_; }
  const OperatingPoint& point() const { return op_; }

 private:
  const FivModel* model_;
  OperatingPoint op_;
  double inverse_mass_ = 0.0, inverse_speed_ = 0.0, galloping_gain_ = 0.0, vortex_gain_ = 0.0;
  double wake_coupling_over_d_ = 0.0, wake_damping_ = 0.0, wake_omega_sq_ = 0.0;
};

}  // namespace maris::fiv
