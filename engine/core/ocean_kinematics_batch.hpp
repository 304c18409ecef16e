// The kinematics of a WaveField at many points at one time, for structures with many load points (a riser's
// Gauss points): the same formulas as WaveField::kinematics (core/ocean_waves.hpp), evaluated so that the compiler
// can run the loop over the components in SIMD lanes.
//
// Per time: the components' time phases θ_j = φ_j − ω_j t, reduced to [−π, π] (once per time, not per point).
// Per point, with s = x cos β + y sin β the distance along the waves' direction (a one-directional sea):
//   ψ_j = k_j s + θ_j,  η = r Σ a_j cos ψ_j,  z' by the field's stretching,
//   C_j = cosh k_j(z'+h)/sinh k_j h,  S_j = sinh k_j(z'+h)/sinh k_j h  (e^{k_j z'} both in deep water and where
//   k_j h > 300), cosh and sinh from one exponential's reduction, without a division (ocean_kinematics_batch.cpp).
// Phase rotation: cos ψ_j, sin ψ_j are computed by the sine-cosine kernel at "anchor" positions s_a only: at the
// first point of a call, and where a point lies farther than 0.2/k_max from the last anchor, 0.9 × 0.2/k_max ahead
// of that point in the direction the points move along s (so the anchor serves points on both sides). Every
// other point takes them from the anchor's by angle addition, cos and sin of k_j (s − s_a) (≤ 0.2 rad) from
// Taylor series to x^12 (remainder ≤ 1.3e-19), each rotated from the exact anchor (no accumulation from point to
// point): within a few units in the last place of 1 of the kernel's values. Points along a riser, a cable or a
// pile are ordered and close together, so most of them rotate. A rotated point's η is the same series summed over
// the components once per anchor (η = Σ_m e_m (s − s_a)^m, m ≤ 12), and its phases are rotated inside the depth
// sums, for the components these keep only (the truncation below).
// Sine, cosine and exponential are polynomial kernels without branches (Cody–Waite reduction, Taylor series to
// below the double's rounding; ocean_kinematics_batch.cpp) instead of the library's calls, which do not vectorise.
// Agreement with WaveField::kinematics: ≤ 1e-13 of each quantity's scale (the sum of the components' magnitudes),
// tested at the surface, at depth, at crest and trough with Wheeler and vertical stretching, and along inclined
// lines of rotated points; on x86-64 the loop runs in AVX-512 or AVX2 lanes where the processor has them (function
// multi-versioning), SSE2 otherwise.
// Truncation (optional, `truncation` ε > 0): the components are kept sorted by k, and at a point with z' < 0 the
// depth sums stop at the first component m with C_m(z') Σ_{j≥m} a_j ω_j ≤ ε Σ_j a_j ω_j and
// C_m(z') Σ_{j≥m} a_j ω_j² ≤ ε Σ_j a_j ω_j². C_j(z') = cosh k_j(z'+h)/sinh k_j h falls with k
// for z' ≤ 0 and bounds S_j(z'), so the dropped components change each velocity component by at most ε Σ a_j ω_j
// and each acceleration component by at most ε Σ a_j ω_j² (times the ramp; the ramp-rate term likewise): an exact
// bound, not an estimate. The first such m is found among thresholds z*_m of z' computed once (no exponential per
// point) and rounded up to a multiple of 8 (whole SIMD vectors: the components up to there are summed, not
// dropped). η (and so wetness and stretching) always takes every component.
// Limits: a point with |k_max s| > 1e5 rad (s more than ≈ 70 km from the origin for 2 s waves) or a time with
// |ω_j t| > 6e6 rad takes WaveField::kinematics itself, point by point.
#pragma once

#include <atomic>
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/ocean_waves.hpp"

namespace maris::ocean {

class WaveKinematicsBatch {
 public:
  // Per-caller workspace: the time phases of the last time and the phases of the last anchor point.
  struct Scratch {
    double time = std::numeric_limits<double>::quiet_NaN();
    bool time_reduced = false;  // θ_j in [−π, π] (else the point-by-point fallback)
    std::vector<double> theta;
    std::vector<double> anchor_cos, anchor_sin;  // the exact phases of the last anchor point
    long rotated_points = 0;  // points whose phases were rotated from an anchor's (a count, for tests and benches)
  };

  WaveKinematicsBatch() = default;
  // `direction_rad` and `gravity`: the ones the field was made with (its wave numbers are recomputed from them by
  // waveNumber, bit for bit the field's own). `truncation`: ε of the truncation above (0: every component).
  WaveKinematicsBatch(const WaveField& field, double direction_rad, double gravity, double truncation = 0.0);

  // out[i] = field.kinematics(points[i], t, ramp, ramp_rate) to the accuracy stated above (and the truncation).
  void evaluate(const Eigen::Vector3d* points, std::size_t count, double t, double ramp, double ramp_rate,
                Scratch& scratch, FluidKinematics* out) const;

  const WaveField& field() const { return field_; }
  // Calls of evaluate so far (from any thread): what the waves cost a run, counted for the riser's integrator
  // choice (riser_integrator_cost) and its test.
  long evaluations() const { return evaluations_.load(std::memory_order_relaxed); }

 private:
  WaveField field_;
  double cos_dir_ = 1.0, sin_dir_ = 0.0, depth_ = kDeepWater, largest_k_ = 0.0;
  double truncation_ = 0.0;
  // The components with kh ≤ 300 in finite water (the first ones): their depth sums keep the mirror term.
  std::size_t finite_count_ = 0;
  mutable std::atomic<long> evaluations_{0};
  // Per component, in increasing k: k, a, a ω and a ω² times 1/(2 sinh kh) (0 where the mirror term is dropped)
  // and times 1/(1 − e^{−2kh}) (1 in deep water), ω, φ; padded to whole SIMD vectors (ocean_kinematics_batch.cpp).
  // And the tail sums Σ_{j≥m} |a_j ω_j|, Σ_{j≥m} |a_j ω_j²| (n + 1 entries, the last 0).
  std::vector<double> k_, amplitude_, ratio_velocity_, ratio_acceleration_, exponential_velocity_,
      exponential_acceleration_, omega_, phase_;
  std::vector<double> tail_velocity_, tail_acceleration_;
  // z*_m: at stretched heights z' ≤ z*_m every component from m on is negligible (nondecreasing in m).
  std::vector<double> negligible_below_;
  // Components whose depth sums the point at stretched height z' (≤ 0 or not) needs.
  std::size_t keptComponents(double z) const;
};

// The kernels, exposed for their test: sin and cos of x for |x| ≤ 1e5 and e^x for |x| ≤ 708, within a few
// units in the last place of std::sin, std::cos, std::exp.
void fastSinCos(double x, double& sine, double& cosine);
double fastExp(double x);

// cos ψ_i and sin ψ_i of ψ_i = phase_i − ω_i t, i < n, in SIMD lanes: each ψ_i is first reduced to [−π, π] with 2π
// in two parts (as the batch's time phases: no error beyond the rounding of ω_i t itself), then the kernels above
// (within a few units in the last place of std::cos, std::sin). Where some |ψ_i| ≥ 6e6 rad: std::cos, std::sin.
// For harmonic syntheses at one point (the vessel motion of the riser's sea).
void harmonicPhases(std::size_t n, const double* phase, const double* omega, double t, double* cosine, double* sine);

}  // namespace maris::ocean
