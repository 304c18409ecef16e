// Michell's thin-ship wave resistance (J. H. Michell, Philosophical Magazine 45, 1898; paper eqs 5–8):
//
//   R_W = (4 ρ g² / (π U²)) ∫_1^∞ |P + iQ|²(λ) λ² / √(λ² − 1) dλ,
//   P + iQ = ∬ ∂Y/∂x e^{k z} e^{i κ x} dx dz,   κ = k0 λ, k = k0 λ², k0 = g/U², λ = sec θ,
//
// with Y the half-breadth (the formula counts both sides). The Kochin function P + iQ is evaluated either on a
// sampled hull grid (GridKochin: exponentially fitted trapezoid in z, integration by parts plus Filon–Simpson
// in x, which keeps the end terms of an open transom) or in closed form for the Wigley hull (WigleyKochin).
// The λ integral uses λ = cosh u (removing the 1/√(λ²−1) singularity), Gauss–Kronrod 7/15 panels one
// oscillation period 2π/(k0 L) wide, adaptive bisection until the summed |K15 − G7| meets the tolerance, and
// a power-law tail beyond λ_max fitted on the last two octaves.
#pragma once

#include <cmath>
#include <complex>
#include <vector>

#include "core/run_context.hpp"
#include "ship/hull_form.hpp"

namespace maris::ship {

// |P + iQ|² [m⁴] at basic wave number k0 [1/m] and λ = sec θ [-].
class KochinFunction {
 public:
  virtual ~KochinFunction() = default;
  // Called once per speed before any evaluate() (speed-dependent hull corrections hook in here).
  virtual void prepare(double /*speed*/) {}
  // `fine`: the value; `coarse`: the same on the grid with every other station and waterline (equal to
  // `fine` for closed forms), used for the Richardson estimate of the discretisation error.
  virtual void evaluate(double k0, double lambda, double& fine, double& coarse) = 0;
  virtual bool hasCoarse() const = 0;
  // 2^p − 1 of the Richardson estimate |fine − coarse|/(2^p − 1) for a grid converging at order p.
  virtual double richardsonDivisor() const { return 3.0; }
  virtual double length() const = 0;  // [m] longitudinal extent: sets the interference period in λ
  virtual double depth() const = 0;   // [m] draft: sets where the depth decay makes the tail algebraic
};

class GridKochin : public KochinFunction {
 public:
  explicit GridKochin(HullGrid grid, bool with_coarse = true);
  void evaluate(double k0, double lambda, double& fine, double& coarse) override;
  bool hasCoarse() const override { return with_coarse_; }
  double richardsonDivisor() const override { return std::exp2(fine_.convergence_order) - 1.0; }
  double length() const override { return (fine_.nx() - 1) * fine_.dx; }
  double depth() const override { return fine_.depth(); }
  const HullGrid& grid() const { return fine_; }
  // P + iQ [m²] itself, with x measured from the grid's mid-length (for the wave pattern).
  std::complex<double> amplitude(double k0, double lambda);

 private:
  std::complex<double> kochin(const HullGrid& g, double k0, double lambda, Eigen::VectorXd& weights,
                              Eigen::VectorXd& sections);
  HullGrid fine_, coarse_;
  bool with_coarse_;
  Eigen::VectorXd weights_, sections_, weights_coarse_, sections_coarse_;  // workspace, sized once
};

class WigleyKochin : public KochinFunction {
 public:
  WigleyKochin(double length, double beam, double draft) : length_(length), beam_(beam), draft_(draft) {}
  void evaluate(double k0, double lambda, double& fine, double& coarse) override;
  bool hasCoarse() const override { return false; }
  double length() const override { return length_; }
  double depth() const override { return draft_; }

 private:
  double length_, beam_, draft_;
};

struct MichellSettings {
  double relative_tolerance = 1e-4;     // [-] target for quadrature + tail error relative to R_W
  double wave_number_factor = 1.0;      // [-] k̂0/k0 of the paper's eq 12 (1: uncorrected)
  bool prefactor_uses_corrected_wave_number = false;  // the paper does not say whether k0² in eq 8 changes
  double short_wave_cutoff = 0.0;       // [-] r: discard waves shorter than r·cutoff_length (0: keep all)
  double cutoff_length = 0.0;           // [m] L of that criterion (Lpp)
  long max_evaluations = 4'000'000;     // Kochin evaluations before giving up on the tolerance
};

struct WaveResistance {
  double resistance = 0;        // [N] R_W including the tail estimate
  double error_estimate = 0;    // [N] quadrature + tail + grid (Richardson) error estimates
  double quadrature_error = 0;  // [N] Σ |K15 − G7| over panels
  double tail = 0;              // [N] estimated contribution beyond λ_max (included in `resistance`)
  double tail_error = 0;        // [N] half the tail (the power law is only asymptotic)
  double grid_error = 0;        // [N] |R(h) − R(2h)|/(2^p − 1), p = HullGrid::convergence_order; 0 for closed forms
  double lambda_max = 0;        // [-] end of the integrated λ range
  double tail_exponent = 0;     // [-] m of the fitted tail g ∝ λ^-m
  long evaluations = 0;         // Kochin evaluations
  int panels = 0;
  bool converged = true;        // false when max_evaluations stopped the refinement first
};

// R_W at speed U [m/s] (> 0), gravity g [m/s²], density ρ [kg/m³]. `context` (may be null) is polled for
// cancellation. Throws RunCancelled.
WaveResistance michellWaveResistance(KochinFunction& kochin, double speed, double gravity, double density,
                                     const MichellSettings& settings, const RunContext* context = nullptr);

// The angular spectrum dR_W/dθ [N/rad] (both sides of the track together, θ in [0, π/2)) at the given angles.
std::vector<double> waveSpectrum(KochinFunction& kochin, double speed, double gravity, double density,
                                 const MichellSettings& settings, const std::vector<double>& theta);

}  // namespace maris::ship
