// Linear (Airy) wave kinematics: dispersion, a regular wave, an irregular one-directional sea synthesised
// from a spectrum, and particle velocity and acceleration up to the instantaneous surface (Wheeler or vertical
// stretching). Frame: z up, z = 0 the still water level, seabed at z = −h (h = ∞: deep water).
//
// Each component j:  ψ_j = k_j (x cos β + y sin β) − ω_j t + φ_j,   η = Σ a_j cos ψ_j,
//   horizontal velocity (along β)  u = Σ a_j ω_j  C_j(z) cos ψ_j,   vertical  w = Σ a_j ω_j  S_j(z) sin ψ_j,
//   accelerations ∂u/∂t = Σ a_j ω_j² C_j(z) sin ψ_j,   ∂w/∂t = −Σ a_j ω_j² S_j(z) cos ψ_j,
//   C_j = cosh k(z+h)/sinh kh,  S_j = sinh k(z+h)/sinh kh  (deep water: both e^{kz}).
// (Dean & Dalrymple, Water Wave Mechanics for Engineers and Scientists, 1991, ch. 4; DNV-RP-C205, 2010, §3.2.)
// Linear theory gives the kinematics below z = 0; above it one of the stretchings below extends them to z = η.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/wave_spectrum.hpp"

namespace maris::ocean {

inline constexpr double kDeepWater = std::numeric_limits<double>::infinity();

// Root k [1/m] of ω² = g k tanh(k h) to 1e-12 relative or better: Newton on f(k) = k tanh(kh) − ω²/g from
// Eckart's (1952) approximation (within 5 % everywhere), 2–4 iterations. h = ∞ gives k = ω²/g.
// Throws std::invalid_argument when ω ≤ 0, g ≤ 0 or h ≤ 0.
double waveNumber(double omega, double depth, double gravity);

// Group velocity C_g = ½ (ω/k)(1 + 2kh / sinh 2kh) [m/s] (deep water: g/(2ω)); same arguments and errors.
double groupVelocity(double omega, double depth, double gravity);

// How the linear kinematics reach the instantaneous surface η:
//   Wheeler: evaluated at z' = h (z − η)/(h + η) (deep water z' = z − η), so z = η maps to z' = 0 and
//            z = −h to −h (Wheeler 1970, J. Petroleum Technology 22(3), 359–367);
//   Vertical: at min(z, 0) (the z = 0 values held constant up to a crest);
//   None: the linear formulas at z itself, extrapolated above z = 0 (for checks against the closed forms).
// At every stretching points above η are dry (zero velocity and acceleration).
enum class Stretching { Wheeler, Vertical, None };

enum class Discretisation {
  EqualEnergy,     // N bins of m0/N each; frequency at the bin's energy centroid, a_j = √(2 m0_band / N)
  RandomFrequency  // N equal-width bins; frequency uniform in its bin, a_j = √(2 ∫_bin S dω)
};

struct WaveComponent {
  double omega = 0.0;      // [rad/s]
  double amplitude = 0.0;  // [m]
  double phase = 0.0;      // [rad] φ_j
};

struct FluidKinematics {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // [m/s]
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // [m/s²] ∂u/∂t (linear theory: local = total)
  double elevation = 0.0;                                  // [m] η at the point's (x, y)
  bool wet = false;                                        // z ≤ η
};

// A sum of linear components travelling along one direction β, with per-component coefficients precomputed
// so that kinematics() is a loop of one sincos and two exponentials per component (and per node).
class WaveField {
 public:
  WaveField() = default;
  // direction_rad: β, the direction the waves travel towards, from +x towards +y.
  WaveField(std::vector<WaveComponent> components, double direction_rad, double depth, double gravity,
            Stretching stretching);

  double elevation(double x, double y, double t) const;  // [m]
  // Kinematics of the field scaled by a start-up ramp r(t) with rate ṙ: η → r η (wetness and stretching use
  // the scaled surface), velocity → r u, acceleration → r ∂u/∂t + ṙ u (the time derivative of r u).
  FluidKinematics kinematics(const Eigen::Vector3d& point, double t, double ramp = 1.0, double ramp_rate = 0.0) const;
  // Elevation and kinematics at M points at one time (what a structure's nodes need per step).
  void kinematics(const std::vector<Eigen::Vector3d>& points, double t, std::vector<FluidKinematics>& out) const;

  const std::vector<WaveComponent>& components() const { return components_; }
  std::size_t size() const { return components_.size(); }
  double depth() const { return depth_; }
  double variance() const;  // [m²] Σ a_j²/2: the variance of η over a long record
  double meanPeriod() const;  // [s] T_m01 = 2π Σa_j²/Σa_j²ω_j (0 without components)
  Stretching stretching() const { return stretching_; }

 private:
  std::vector<WaveComponent> components_;
  double cos_dir_ = 1.0, sin_dir_ = 0.0, depth_ = kDeepWater;
  Stretching stretching_ = Stretching::Wheeler;
  // Per component: wave-vector components, a ω, a ω², and 1/(1 − e^{−2kh}) (1 in deep water).
  std::vector<double> kx_, ky_, k_, a_omega_, a_omega2_, depth_scale_;
  // The linear kinematics at z' (already stretched) given cos ψ_j, sin ψ_j.
  void linearAt(double z_linear, const double* cos_psi, const double* sin_psi, FluidKinematics& out) const;
};

// A regular Airy wave of height H = 2a [m] and period T [s]; phase φ [rad] (η = a cos φ at the origin at t = 0).
WaveField airyWave(double height, double period, double direction_rad, double phase_rad, double depth, double gravity,
                   Stretching stretching);

// An irregular sea of `component_count` components drawn from `spectrum` over its band (bandLow–bandHigh).
// Phases (and RandomFrequency's in-bin positions) come from std::mt19937_64(seed) through core's portable uniform01(), so
// the same seed gives the bitwise same sea on every standard library. Frequencies: EqualEnergy bins have
// unequal widths and RandomFrequency's are jittered, so no common period 2π/Δω exists and the record does not
// repeat; the smallest spacing of neighbouring frequencies is reported by smallestSpacing().
WaveField irregularSea(const WaveSpectrum& spectrum, int component_count, Discretisation discretisation,
                       std::uint64_t seed, double direction_rad, double depth, double gravity, Stretching stretching);

// Half-cosine start-up ramp of a sea: r(t) = ½(1 − cos(π t/T_r)) for 0 < t < T_r, 0 for t ≤ 0, 1 from T_r on
// (T_r = 0: the sea is on from t = 0); its rate dr/dt [1/s] (0 outside (0, T_r)).
double startRamp(double t, double ramp_time);
double startRampRate(double t, double ramp_time);

// Smallest |ω_{j+1} − ω_j| of a field's components sorted by frequency [rad/s] (∞ for fewer than 2).
double smallestSpacing(const WaveField& field);

}  // namespace maris::ocean
