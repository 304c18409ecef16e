// Radiation memory of one mode (Cummins 1962): F_rad(t) = −A∞ q̈(t) − ∫₀ᵗ K(τ) q̇(t − τ) dτ.
//
//   K(t)  = (2/π) ∫₀^∞ B(ω) cos(ωt) dω                      [N/m]  (paper eq 5)
//   K̂(ω) = ∫₀^∞ K(t) e^{−iωt} dt = B(ω) + iω (A(ω) − A∞)         (e^{+iωt} convention)
//   A∞    = A(ω) + (1/ω) ∫₀^∞ K(t) sin(ωt) dt   for every ω       (Ogilvie 1964)
//
// Two ways to evaluate the convolution: a modal (Prony) state-space fit K(t) ≈ Σ r_i e^{p_i t}
// (poles from the eigensystem realization algorithm, Kung 1978 / Juang & Pappa 1985, on a Hankel
// matrix of K samples; residues by least squares), and direct trapezoidal convolution as the reference.
#pragma once

#include <complex>
#include <functional>
#include <vector>

#include "core/run_context.hpp"

namespace maris::wec {

// K(t) sampled at t_j = j·dt, j = 0..n−1.
struct RadiationKernel {
  double dt = 0.0;              // [s]
  std::vector<double> values;   // [N/m] K(j·dt)
  double duration() const { return dt * static_cast<double>(values.size() - 1); }
  // Linear interpolation between samples; 0 beyond the last sample.
  double at(double t) const;
};

// K(t) from B(ω) on [0, omega_max] (B taken as 0 beyond), B piecewise linear on a grid of spacing
// d_omega and each segment integrated exactly against cos(ωt) (Filon-type, no aliasing for large t).
// Checks `context` (if given) for cancellation every 256 samples of K.
RadiationKernel computeKernel(const std::function<double(double)>& damping, double omega_max, double d_omega,
                              double duration, double dt, const RunContext* context = nullptr);

// A∞ from A(ω) at one frequency and the kernel (Ogilvie); the sine transform is integrated exactly
// for K piecewise linear.
double ogilvieAddedMassInfinity(const RadiationKernel& kernel, double omega, double added_mass);

// A∞ from tabulated A(ω), B(ω) alone (no A∞ in the source, e.g. Nemoh): the kernel from B on [0, omega_max]
// (B = 0 beyond), Ogilvie's value at each of `points` frequencies spread evenly over [omega_lo, omega_hi], then
// their mean; the spread (max − min) is the estimate's error bar (it grows when B is cut off too early).
struct OgilvieEstimate {
  double a_inf = 0.0;   // [kg]
  double spread = 0.0;  // [kg]
};
OgilvieEstimate ogilvieAddedMassInfinityOverBand(const std::function<double(double)>& damping,
                                                 const std::function<double(double)>& added_mass, double omega_max,
                                                 double omega_lo, double omega_hi, int points = 20);

// K(t) ≈ Σ_i Re-part-paired r_i e^{p_i t}: real poles carry real residues; a complex pair is stored
// once (Im p > 0) and contributes 2 Re(r e^{pt}).
struct ModalKernel {
  struct Mode {
    std::complex<double> pole;      // [1/s], Re < 0
    std::complex<double> residue;   // [N/(m·s)]
    bool paired = false;            // true: complex pair, 2 real states
  };
  std::vector<Mode> modes;
  double r_squared = 0.0;           // coefficient of determination of the fit on the kernel samples
  int order = 0;                    // number of real states
  double at(double t) const;                              // K_fit(t)
  std::complex<double> transfer(double omega) const;      // K̂_fit(ω) = Σ r/(iω − p) (+ conjugates)
  bool stable() const;                                    // every Re p < 0
};

struct KernelFitOptions {
  int max_order = 16;          // largest number of real states tried
  double r_squared_target = 0.9995;
  int samples = 300;           // kernel samples used to build the Hankel matrix
};
// Fits in increasing order 2, 4, ... until r_squared ≥ target (or max_order; the best fit is kept).
// Unstable ERA poles are reflected into the left half plane before the residues are fitted.
ModalKernel fitModalKernel(const RadiationKernel& kernel, const KernelFitOptions& options = {});

// Quality of a fit in the frequency domain on [omega_lo, omega_hi] against the source coefficients:
// max |B_fit − B| and max |ω(A_fit − A) | relative to max B there, and min Re K̂_fit / max B (passivity).
struct FitQuality {
  double damping_error = 0.0;
  double added_mass_error = 0.0;
  double min_real_part = 0.0;
};
FitQuality assessFit(const ModalKernel& fit, const std::function<double(double)>& damping,
                     const std::function<double(double)>& added_mass, double a_inf, double omega_lo,
                     double omega_hi, int points = 200);

// Direct convolution ∫₀ᵗ K(τ) v(t − τ) dτ on a uniform time grid (trapezoid), velocity history kept in
// a ring buffer. The kernel is tapered by a half-cosine over its last 10 % so truncation injects no energy.
class DirectConvolution {
 public:
  DirectConvolution() = default;
  DirectConvolution(const RadiationKernel& kernel_at_step);  // kernel sampled at the time step
  void push(double velocity);  // stores v(t_n) after a completed step (first push: t = 0)
  double valueNow() const;     // the integral at the last pushed time [N]
  std::size_t kernelSize() const { return kernel_.size(); }

 private:
  std::vector<double> kernel_;   // tapered K(j·dt)
  std::vector<double> history_;  // ring buffer of v, history_[head_] is the newest
  std::size_t count_ = 0, head_ = 0;
  double dt_ = 0.0;
};

}  // namespace maris::wec
