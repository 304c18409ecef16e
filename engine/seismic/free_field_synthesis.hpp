// Time histories of the free field (free_field.hpp) by Fourier synthesis.
//
// The incident displacement at the origin u0(t) is sampled at t_k = t0 + k·dt. Its spectrum and the
// transfer functions are evaluated at complex frequencies ω + iε (e^{-iωt} convention), the
// product is inverted with an FFT of length N ≥ 2n and multiplied by e^{εt} (Kausel & Roësset's
// "complex frequency" method). ε = ln(1e6)/(N·dt) damps what wraps around the window by 1e-6, so
// the undamped water-layer reverberation (seabed reflection ≈ 0.78 per round trip) neither aliases
// nor needs a minute-long window. Using the e^{-iωt} convention on both sides keeps the result
// causal: nothing before the first arrival (tested). Beyond the SV critical angle the plane-wave
// field is not causal in that sense (the reflections contain the input's Hilbert transform, whose
// tail precedes the arrival): there ε = 0 and a window of 8× the record (≥ 64 s with water) is used.
// The field at (x, y, t) equals the one at (0, y, t − p·x), p the horizontal slowness, so one
// history per depth serves a whole row of nodes (see sampleDelayed).
#pragma once

#include <vector>

#include "core/run_context.hpp"
#include "seismic/free_field.hpp"

namespace maris::seismic {

// Solid histories at (0, y), per the incident displacement u0: [m], [m/s], [m/s^2], [Pa].
struct SolidHistory {
  std::vector<double> ux, uy, vx, vy, ax, ay, sxx, syy, sxy;
};

// Water histories at (0, y): displacement potential φ [m^2] and its rates (p = −ρ φ̈), pressure [Pa],
// displacement [m].
struct WaterHistory {
  std::vector<double> phi, phi_dot, phi_ddot, pressure, ux, uy;
};

class FreeFieldSynthesis {
 public:
  // `incident` = u0 at t0 + k·dt, k < incident.size(); it should be zero at the start (causal input).
  // `context` (if given, outliving this object) is checked for cancellation every few thousand frequencies.
  FreeFieldSynthesis(const FreeField& field, const std::vector<double>& incident, double t0, double dt,
                     const RunContext* context = nullptr);

  SolidHistory solid(double y) const;
  WaterHistory water(double y) const;

  double t0() const { return t0_; }
  double dt() const { return dt_; }
  int sampleCount() const { return n_out_; }
  const FreeField& field() const { return field_; }

 private:
  // Throws RunCancelled every 4096th k when the context asks (cheap against the free-field solve per k).
  void checkCancel(std::size_t k) const {
    if (context_ && k % 4096 == 0) context_->throwIfCancelled();
  }
  // Inverts two Hermitian half spectra (k = 0..N/2) at once and undoes the damping.
  void invertPair(const std::vector<Complex>& first, const std::vector<Complex>& second, std::vector<double>& out_first,
                  std::vector<double>& out_second) const;

  FreeField field_;
  double t0_, dt_, eps_;
  int n_out_;
  std::size_t n_fft_;
  std::vector<Complex> omega_;          // ω_k + iε, k = 0..N/2
  const RunContext* context_ = nullptr;
  std::vector<Complex> input_spectrum_; // U0(ω_k + iε)
  std::vector<FreeFieldAmplitudes> amplitudes_;
};

// Value of a history sampled at t0 + k·dt at time t, by cubic (Catmull–Rom) interpolation;
// 0 before the first sample, the last value after the end.
double sampleDelayed(const std::vector<double>& history, double t0, double dt, double t);

}  // namespace maris::seismic
