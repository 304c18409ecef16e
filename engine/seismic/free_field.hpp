// Free field of an elastic half-space under a water layer, driven by a plane P or SV wave
// (Bao, Liu, Li, Wang & Wang, Ocean Engineering c. 2020, §3.2; reflection coefficients: Aki & Richards 2002).
//
// Conventions for the whole seismic scene:
//   x horizontal, to the right; y vertical, up. y = 0 is the seabed of the free-field model, the
//   solid occupies y < 0, the water 0 < y < h, its pressure-release surface is y = h.
//   Harmonic time factor e^{-iωt}. The incidence angle θ is measured from the vertical; θ > 0
//   means the wave travels towards +x (it arrives from the lower left).
//   The incident wave carries unit displacement at the origin: P along its propagation direction
//   (sinθ, cosθ), SV along (cosθ, -sinθ) (so vertical SV moves +x).
//
// Each wave is written with a scaled potential amplitude a: displacement potential
// φ = a/(iω)·exp(iω(p x ± η y − t)), so u = (p, ±η)·a for P (ψ-waves analogously) and the
// stresses are σ = (−iω)·S with S independent of ω. The four unknown amplitudes (reflected P and
// SV, up- and down-going water P) satisfy the seabed conditions u_y continuous, σ_yy + p = 0,
// τ_xy = 0 and p = 0 at the water surface: one 4×4 complex system per frequency (2×2 without water).
#pragma once

#include <complex>
#include <string>

namespace maris::seismic {

using Complex = std::complex<double>;

struct ElasticMaterial {
  double density = 2700.0;  // [kg/m^3]
  double vp = 4500.0;       // [m/s] P-wave speed
  double vs = 1800.0;       // [m/s] S-wave speed
  double shearModulus() const { return density * vs * vs; }                 // μ [Pa]
  double lameLambda() const { return density * (vp * vp - 2.0 * vs * vs); }  // λ [Pa]
};

struct WaterLayer {
  double density = 1025.0;      // [kg/m^3]
  double sound_speed = 1450.0;  // [m/s]
  double depth = 600.0;         // [m] h; 0 = no water (traction-free seabed)
};

enum class WaveType { P, SV };
const char* toString(WaveType type);

// Amplitudes of the plane waves for one frequency (scaled potentials, see the header comment).
struct FreeFieldAmplitudes {
  Complex incident;       // a of the up-going incident P or b of the incident SV
  Complex reflected_p;    // a of the down-going P in the solid
  Complex reflected_s;    // b of the down-going SV in the solid
  Complex water_up;       // a of the up-going P in the water, phase reference y = 0
  Complex water_down;     // a of the down-going P in the water, phase reference y = h
};

// Field at one point for one frequency, per unit incident displacement at the origin.
struct FreeFieldPoint {
  Complex ux, uy;            // [m/m] displacement
  Complex sxx, syy, sxy;     // [Pa/m] stresses in the solid (0 in the water)
  Complex pressure;          // [Pa/m] in the water (0 in the solid)
  Complex potential;         // [m^2/m] water displacement potential φ, u = ∇φ, p = −ρ φ̈ (0 in the solid)
};

class FreeField {
 public:
  // Throws InputError (path "incidence.angle_deg") for |θ| ≥ 90°. SV beyond the critical angle
  // asin(vs/vp) is accepted: the reflected P is then evanescent (complex Snell's law, see
  // reflectedPEvanescent) and the reflection coefficients become complex and frequency independent.
  FreeField(const ElasticMaterial& solid, const WaterLayer& water, WaveType type, double angle_rad);

  // SV critical angle asin(vs/vp) [rad].
  static double criticalAngleSv(const ElasticMaterial& solid);
  // True for SV beyond the critical angle: the reflected P decays with depth as e^{−ωκ|y|},
  // κ = √(p² − 1/vp²), and travels along x with the incident wave's slowness p.
  bool reflectedPEvanescent() const { return eta_p_.imag() > 0.0; }

  // Solves the seabed/surface conditions at (possibly complex) circular frequency ω [rad/s].
  FreeFieldAmplitudes solve(Complex omega) const;
  // Sums the solid's plane waves at (x, y ≤ 0) [m] for amplitudes solved at the same ω.
  FreeFieldPoint solidAt(const FreeFieldAmplitudes& a, Complex omega, double x, double y) const;
  // Sums the water's plane waves at (x, 0 ≤ y ≤ h) [m]; zero everywhere when there is no water.
  FreeFieldPoint waterAt(const FreeFieldAmplitudes& a, Complex omega, double x, double y) const;

  // Energy balance of the solid waves for real ω: (Re η_p|a_rp|² + η_s|b_rs|²)/(η_inc|a_inc|²) − 1.
  // The water layer over a free surface carries no net flux, so this is zero up to round-off.
  double energyResidual(const FreeFieldAmplitudes& a) const;

  // Horizontal slowness p = sinθ/c_incident [s/m]; the field at x is the field at 0 delayed by p·x.
  double horizontalSlowness() const { return p_; }
  // Vertical slowness of the incident wave [s/m] (arrival time advance per metre of depth).
  double incidentVerticalSlowness() const { return type_ == WaveType::P ? eta_p_.real() : eta_s_; }
  WaveType type() const { return type_; }
  double angle() const { return angle_; }
  const ElasticMaterial& solid() const { return solid_; }
  const WaterLayer& water() const { return water_; }
  bool hasWater() const { return water_.depth > 0.0; }

 private:
  ElasticMaterial solid_;
  WaterLayer water_;
  WaveType type_;
  double angle_;
  double lambda_, mu_;
  double p_;             // horizontal slowness [s/m]
  Complex eta_p_;        // vertical P slowness in the solid [s/m]: real, or +i·κ beyond the SV critical angle
  double eta_s_;         // vertical S slowness in the solid [s/m]
  Complex eta_f_;        // vertical slowness in the water [s/m] (imaginary part ≥ 0 when evanescent)
};

}  // namespace maris::seismic
