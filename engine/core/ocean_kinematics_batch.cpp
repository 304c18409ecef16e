// Batched wave kinematics (contract in core/ocean_kinematics_batch.hpp).
//
// The kernels are branch-free so that `#pragma omp simd` (this file is compiled with -fopenmp-simd: no OpenMP
// runtime, only the SIMD directives) turns the loops over the components into vector code:
//   sin/cos: x = q π/2 + r with q = nearest integer of 2x/π, π/2 split into a 33-bit head (q·head exact for
//            |q| < 2^20) and its remainder (Cody & Waite 1980, Software Manual for the Elementary Functions);
//            |r| ≤ π/4 + tiny, Taylor series of sin to r^17 and cos to r^16 (next terms < 1e-19 and 2e-18);
//            the quadrant q mod 4 swaps and signs the pair.
//   exp:     x = n ln 2 + r, |r| ≤ ½ ln 2 (ln 2 split likewise), Taylor to r^13 (next term < 4e-18), times 2^n
//            assembled in the exponent bits.
// The nearest integer uses the 1.5·2^52 shifter: after t = y + 1.5·2^52 the low bits of t hold round(y).
#include "core/ocean_kinematics_batch.hpp"
#include "core/ocean_stretching.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

namespace maris::ocean {
namespace {

constexpr double kShifter = 0x1.8p52;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kHalfPiHead = 0x1.921fb544p+0, kHalfPiTail = 0x1.0b4611a626331p-34;
constexpr double kInverseTwoPi = 0x1.45f306dc9c883p-3;
constexpr double kTwoPiHead = 0x1.921fb544p+2, kTwoPiTail = 0x1.0b4611a626331p-32;
constexpr double kLog2E = 0x1.71547652b82fep+0;
constexpr double kLn2Head = 0x1.62e42fefp-1, kLn2Tail = 0x1.473de6af278edp-34;
constexpr double kLargestExpArgument = 708.0;  // e^±708 is a normal double
constexpr double kLargestRatioArgument = 700.0;  // depthSums' ratio form: 2^±n with |n| ≤ 1010 are normal doubles
// Per-component arrays are padded to a multiple of this (the AVX-512 lanes; AVX2's 4 and SSE2's 2 divide it).
constexpr std::size_t kLanes = 8;
constexpr double kLargestSinArgument = 1e5;    // |q| < 2^17: q·(π/2 head) exact with room
constexpr double kLargestTimePhase = 6e6;      // |n| < 2^20 turns: n·(2π head) exact
// A point whose phases differ from the anchor's by at most this much (|k_max d| ≤ 0.2 rad) takes them by rotation;
// rotatePhase's series and elevationSeries then stop below 0.2^13/13! = 1.3e-19 (sine) and 0.2^14/14! (cosine).
constexpr double kRotationLimit = 0.2;
constexpr int kElevationTerms = 13;  // d^0 … d^12 (elevationSeries)

// Taylor coefficients 1/k!, k = 0…17.
constexpr double inverseFactorial(int k) {
  double f = 1.0;
  for (int i = 2; i <= k; ++i) f *= i;
  return 1.0 / f;
}

[[gnu::always_inline]] inline void sinCosKernel(double x, double& sine, double& cosine) {
  const double shifted = x * kTwoOverPi + kShifter;
  const double q = shifted - kShifter;
  const std::int64_t quadrant = std::bit_cast<std::int64_t>(shifted) - std::bit_cast<std::int64_t>(kShifter);
  const double r = (x - q * kHalfPiHead) - q * kHalfPiTail;
  const double r2 = r * r;
  // sin r = r (1 − r²/3! + r⁴/5! − …), cos r = 1 − r²/2! + r⁴/4! − …
  constexpr double s3 = -inverseFactorial(3), s5 = inverseFactorial(5), s7 = -inverseFactorial(7),
                   s9 = inverseFactorial(9), s11 = -inverseFactorial(11), s13 = inverseFactorial(13),
                   s15 = -inverseFactorial(15), s17 = inverseFactorial(17);
  constexpr double c2 = -inverseFactorial(2), c4 = inverseFactorial(4), c6 = -inverseFactorial(6),
                   c8 = inverseFactorial(8), c10 = -inverseFactorial(10), c12 = inverseFactorial(12),
                   c14 = -inverseFactorial(14), c16 = inverseFactorial(16);
  const double ps =
      r + r * r2 * (s3 + r2 * (s5 + r2 * (s7 + r2 * (s9 + r2 * (s11 + r2 * (s13 + r2 * (s15 + r2 * s17)))))));
  const double pc =
      1.0 + r2 * (c2 + r2 * (c4 + r2 * (c6 + r2 * (c8 + r2 * (c10 + r2 * (c12 + r2 * (c14 + r2 * c16)))))));
  // Quadrant 0: (s, c); 1: (c, −s); 2: (−s, −c); 3: (−c, s).
  const bool swap = (quadrant & 1) != 0;
  const double sine_base = swap ? pc : ps, cosine_base = swap ? ps : pc;
  const auto sine_sign = static_cast<std::uint64_t>(quadrant & 2) << 62;
  const auto cosine_sign = static_cast<std::uint64_t>((quadrant + 1) & 2) << 62;
  sine = std::bit_cast<double>(std::bit_cast<std::uint64_t>(sine_base) ^ sine_sign);
  cosine = std::bit_cast<double>(std::bit_cast<std::uint64_t>(cosine_base) ^ cosine_sign);
}

[[gnu::always_inline]] inline double expKernel(double x) {
  x = x < -kLargestExpArgument ? -kLargestExpArgument : x;
  x = x > kLargestExpArgument ? kLargestExpArgument : x;
  const double shifted = x * kLog2E + kShifter;
  const double n = shifted - kShifter;
  const std::int64_t power = std::bit_cast<std::int64_t>(shifted) - std::bit_cast<std::int64_t>(kShifter);
  const double r = (x - n * kLn2Head) - n * kLn2Tail;
  constexpr double e2 = inverseFactorial(2), e3 = inverseFactorial(3), e4 = inverseFactorial(4),
                   e5 = inverseFactorial(5), e6 = inverseFactorial(6), e7 = inverseFactorial(7),
                   e8 = inverseFactorial(8), e9 = inverseFactorial(9), e10 = inverseFactorial(10),
                   e11 = inverseFactorial(11), e12 = inverseFactorial(12), e13 = inverseFactorial(13);
  const double p =
      1.0 + r * (1.0 + r * (e2 + r * (e3 + r * (e4 + r * (e5 + r * (e6 + r * (e7 + r * (e8 + r * (e9 + r * (e10 +
                                                                                   r * (e11 + r * (e12 + r * e13))))))))))));
  return p * std::bit_cast<double>(static_cast<std::uint64_t>(power + 1023) << 52);
}

// The per-point sums, vectorised over the components (AVX-512 and AVX2 + FMA clones on processors that have them).
struct PointSums {
  double eta = 0.0, u = 0.0, w = 0.0, du = 0.0, dw = 0.0;
};

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define MARIS_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define MARIS_SIMD_CLONES
#endif

// cos ψ_j, sin ψ_j for ψ_j = k_j s + θ_j, and η = Σ a_j cos ψ_j (unramped).
MARIS_SIMD_CLONES double phasesAndElevation(std::size_t n, double s, const double* __restrict k,
                                            const double* __restrict theta, const double* __restrict amplitude,
                                            double* __restrict cos_psi, double* __restrict sin_psi) {
  double eta = 0.0;
#pragma omp simd reduction(+ : eta)
  for (std::size_t j = 0; j < n; ++j) {
    double sn, cs;
    sinCosKernel(k[j] * s + theta[j], sn, cs);
    cos_psi[j] = cs;
    sin_psi[j] = sn;
    eta += amplitude[j] * cs;
  }
  return eta;
}

// cos ψ, sin ψ of a point a distance d further along the waves than an anchor point whose cos, sin are given
// (ψ = ψ_anchor + x, x = k d, |x| ≤ kRotationLimit): the angle addition with cos x − 1 and sin x from their Taylor
// series (to x^12 and x^11).
[[gnu::always_inline]] inline void rotatePhase(double x, double anchor_cos, double anchor_sin, double& cosine,
                                               double& sine) {
  constexpr double s3 = -inverseFactorial(3), s5 = inverseFactorial(5), s7 = -inverseFactorial(7),
                   s9 = inverseFactorial(9), s11 = -inverseFactorial(11);
  constexpr double c2 = -inverseFactorial(2), c4 = inverseFactorial(4), c6 = -inverseFactorial(6),
                   c8 = inverseFactorial(8), c10 = -inverseFactorial(10), c12 = inverseFactorial(12);
  const double x2 = x * x;
  const double sine_x = x + x * x2 * (s3 + x2 * (s5 + x2 * (s7 + x2 * (s9 + x2 * s11))));
  const double cosine_minus_one = x2 * (c2 + x2 * (c4 + x2 * (c6 + x2 * (c8 + x2 * (c10 + x2 * c12)))));
  cosine = anchor_cos + (anchor_cos * cosine_minus_one - anchor_sin * sine_x);
  sine = anchor_sin + (anchor_sin * cosine_minus_one + anchor_cos * sine_x);
}

// The elevation's Taylor coefficients in the distance d from an anchor: with A_j = a_j cos ψ_j, B_j = a_j sin ψ_j
// at the anchor, η(d) = Σ_j A_j cos k_j d − B_j sin k_j d = Σ_m e_m d^m with
//   e_2i = (−1)^i Σ_j A_j k_j^2i / (2i)!,  e_2i+1 = (−1)^(i+1) Σ_j B_j k_j^2i+1 / (2i+1)!,  m ≤ 12,
// the same series as rotatePhase's (each term's remainder ≤ a_j |k_j d|^13/13! ≤ 1.3e-19 a_j): the elevation of a
// rotated point in 12 operations instead of a rotation of every component. Its rounding: the terms are bounded by
// Σ a_j |k_j d|^m/m!, so a few units in the last place of Σ a_j.
MARIS_SIMD_CLONES void elevationSeries(std::size_t n, const double* __restrict k, const double* __restrict amplitude,
                                       const double* __restrict cos_psi, const double* __restrict sin_psi,
                                       double* __restrict series) {
  double p0 = 0, p1 = 0, p2 = 0, p3 = 0, p4 = 0, p5 = 0, p6 = 0, q0 = 0, q1 = 0, q2 = 0, q3 = 0, q4 = 0, q5 = 0;
#pragma omp simd reduction(+ : p0, p1, p2, p3, p4, p5, p6, q0, q1, q2, q3, q4, q5)
  for (std::size_t j = 0; j < n; ++j) {
    const double kk = k[j] * k[j];
    double a = amplitude[j] * cos_psi[j], b = amplitude[j] * sin_psi[j] * k[j];
    p0 += a, a *= kk, p1 += a, a *= kk, p2 += a, a *= kk, p3 += a, a *= kk, p4 += a, a *= kk, p5 += a, a *= kk, p6 += a;
    q0 += b, b *= kk, q1 += b, b *= kk, q2 += b, b *= kk, q3 += b, b *= kk, q4 += b, b *= kk, q5 += b;
  }
  const double p[] = {p0, p1, p2, p3, p4, p5, p6}, q[] = {q0, q1, q2, q3, q4, q5};
  for (int i = 0; i <= 6; ++i) series[2 * i] = (i % 2 ? -1.0 : 1.0) * p[i] * inverseFactorial(2 * i);
  for (int i = 0; i <= 5; ++i) series[2 * i + 1] = (i % 2 ? 1.0 : -1.0) * q[i] * inverseFactorial(2 * i + 1);
}

// The linear kinematics sums at the stretched height z' over the components j < kept: the first `ratio_count` by
// the ratio form
//   C_j = cosh k_j(z'+h)/sinh k_j h,  S_j = sinh k_j(z'+h)/sinh k_j h,
// the others (deep water; kh > 300, where the mirror term e^{−k(z'+2h)} ≤ e^{−kh} < 1e-130 of the component's
// surface value; or k(z'+h) > 700, where it is below e^{−1400} of it) by C_j = S_j = e^{k_j z'}/(1 − e^{−2 k_j h})
// (1 in deep water). The factors 1/(2 sinh kh) and 1/(1 − e^{−2kh}) come multiplied into the components' a ω and
// a ω² (`ratio_*`, `exponential_*`).
// Ratio form: u = k(z'+h) = n ln 2 + r, |r| ≤ ½ ln 2, one reduction for e^u and e^{−u}: with E and O the even and
// odd Taylor series of e^r (cosh r to r^12, sinh r to r^13: next terms < 5e-18) and a = 2^n, b = 2^{−n},
//   2 cosh u = (a + b) E + (a − b) O,  2 sinh u = (a − b) E + (a + b) O,
// no division and no second exponential. Near the sea bed (n = 0) a − b = 0
// exactly, so 2 sinh u = 2 O: the odd series itself, without the cancellation of e^u − e^{−u} (which held the sea
// bed's sinh to the rounding of e^u, not of sinh u); for n ≥ 1 the two terms cancel by at most a factor 2.3. The
// caller keeps 0 ≤ u ≤ 700 (z' ≥ −h; `ratio_count` ends before the first k_j (z'+h) > 700), so the loop needs no
// range clamp, which GCC vectorises only into masked code.
MARIS_SIMD_CLONES void depthSums(std::size_t kept, std::size_t ratio_count, double d, double z, double z_plus_h,
                                 const double* __restrict k, const double* __restrict ratio_velocity,
                                 const double* __restrict ratio_acceleration,
                                 const double* __restrict exponential_velocity,
                                 const double* __restrict exponential_acceleration,
                                 const double* __restrict anchor_cos, const double* __restrict anchor_sin,
                                 PointSums& out) {
  constexpr double c2 = inverseFactorial(2), c4 = inverseFactorial(4), c6 = inverseFactorial(6),
                   c8 = inverseFactorial(8), c10 = inverseFactorial(10), c12 = inverseFactorial(12);
  constexpr double s3 = inverseFactorial(3), s5 = inverseFactorial(5), s7 = inverseFactorial(7),
                   s9 = inverseFactorial(9), s11 = inverseFactorial(11), s13 = inverseFactorial(13);
  double u = 0.0, w = 0.0, du = 0.0, dw = 0.0;
#pragma omp simd reduction(+ : u, w, du, dw)
  for (std::size_t j = 0; j < ratio_count; ++j) {
    const double x = k[j] * z_plus_h;
    const double shifted = x * kLog2E + kShifter;
    const double nearest = shifted - kShifter;
    const std::int64_t power = std::bit_cast<std::int64_t>(shifted) - std::bit_cast<std::int64_t>(kShifter);
    const double r = (x - nearest * kLn2Head) - nearest * kLn2Tail;
    const double r2 = r * r;
    const double even = 1.0 + r2 * (c2 + r2 * (c4 + r2 * (c6 + r2 * (c8 + r2 * (c10 + r2 * c12)))));
    const double odd = r + r * r2 * (s3 + r2 * (s5 + r2 * (s7 + r2 * (s9 + r2 * (s11 + r2 * s13)))));
    const double up = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + power) << 52);
    const double down = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - power) << 52);
    const double sum = up + down, difference = up - down;
    const double ch = sum * even + difference * odd, sh = difference * even + sum * odd;  // 2 cosh u, 2 sinh u
    double cos_psi, sin_psi;
    rotatePhase(k[j] * d, anchor_cos[j], anchor_sin[j], cos_psi, sin_psi);
    u += ratio_velocity[j] * ch * cos_psi;
    w += ratio_velocity[j] * sh * sin_psi;
    du += ratio_acceleration[j] * ch * sin_psi;
    dw -= ratio_acceleration[j] * sh * cos_psi;
  }
#pragma omp simd reduction(+ : u, w, du, dw)
  for (std::size_t j = ratio_count; j < kept; ++j) {
    const double e = expKernel(k[j] * z);
    double cos_psi, sin_psi;
    rotatePhase(k[j] * d, anchor_cos[j], anchor_sin[j], cos_psi, sin_psi);
    u += exponential_velocity[j] * e * cos_psi;
    w += exponential_velocity[j] * e * sin_psi;
    du += exponential_acceleration[j] * e * sin_psi;
    dw -= exponential_acceleration[j] * e * cos_psi;
  }
  out.u = u, out.w = w, out.du = du, out.dw = dw;
}

// cos and sin of phase_j − ω_j t reduced to [−π, π]; false (outputs unspecified) if some |phase_j − ω_j t| is
// beyond the reduction's range.
MARIS_SIMD_CLONES bool reducedHarmonicPhases(std::size_t n, const double* __restrict phase,
                                             const double* __restrict omega, double t, double* __restrict cosine,
                                             double* __restrict sine) {
  bool in_range = true;
#pragma omp simd reduction(&& : in_range)
  for (std::size_t j = 0; j < n; ++j) {
    const double psi = phase[j] - omega[j] * t;
    in_range = in_range && std::abs(psi) < kLargestTimePhase;
    const double turns_shifted = psi * kInverseTwoPi + kShifter;
    const double turns = turns_shifted - kShifter;
    double sn, cs;
    sinCosKernel((psi - turns * kTwoPiHead) - turns * kTwoPiTail, sn, cs);
    cosine[j] = cs;
    sine[j] = sn;
  }
  return in_range;
}

}  // namespace

void harmonicPhases(std::size_t n, const double* phase, const double* omega, double t, double* cosine, double* sine) {
  if (reducedHarmonicPhases(n, phase, omega, t, cosine, sine)) return;
  for (std::size_t j = 0; j < n; ++j) {
    const double psi = phase[j] - omega[j] * t;
    cosine[j] = std::cos(psi);
    sine[j] = std::sin(psi);
  }
}

void fastSinCos(double x, double& sine, double& cosine) { sinCosKernel(x, sine, cosine); }

double fastExp(double x) { return expKernel(x); }

WaveKinematicsBatch::WaveKinematicsBatch(const WaveField& field, double direction_rad, double gravity,
                                         double truncation)
    : field_(field),
      cos_dir_(std::cos(direction_rad)),
      sin_dir_(std::sin(direction_rad)),
      depth_(field.depth()),
      truncation_(truncation) {
  const std::size_t n = field.size();
  const bool deep = std::isinf(depth_);
  std::vector<std::pair<double, std::size_t>> by_k;
  std::vector<double> speeds, accelerations;  // |a ω|, |a ω²| in increasing k (the tail sums)
  for (std::size_t j = 0; j < n; ++j) by_k.emplace_back(waveNumber(field.components()[j].omega, depth_, gravity), j);
  std::sort(by_k.begin(), by_k.end());
  for (const auto& [k, j] : by_k) {
    const WaveComponent& c = field.components()[j];
    k_.push_back(k);
    amplitude_.push_back(c.amplitude);
    const double a_omega = c.amplitude * c.omega, a_omega2 = c.amplitude * c.omega * c.omega;
    speeds.push_back(std::abs(a_omega));
    accelerations.push_back(std::abs(a_omega2));
    // Beyond kh = 300 the mirror term e^{−k(z+2h)} ≤ e^{−kh} < 1e-130 of the component's surface value: dropped
    // (depthSums); the components are sorted by k, so those that keep it come first.
    const bool finite = !deep && k * depth_ <= 300.0;
    if (finite) ++finite_count_;
    const double half_inverse_sinh = finite ? 0.5 / std::sinh(k * depth_) : 0.0;
    const double depth_scale = deep ? 1.0 : 1.0 / -std::expm1(-2.0 * k * depth_);
    ratio_velocity_.push_back(a_omega * half_inverse_sinh);
    ratio_acceleration_.push_back(a_omega2 * half_inverse_sinh);
    exponential_velocity_.push_back(a_omega * depth_scale);
    exponential_acceleration_.push_back(a_omega2 * depth_scale);
    omega_.push_back(c.omega);
    phase_.push_back(c.phase);
    largest_k_ = std::max(largest_k_, k);
  }
  tail_velocity_.assign(n + 1, 0.0);
  tail_acceleration_.assign(n + 1, 0.0);
  for (std::size_t j = n; j-- > 0;) {
    tail_velocity_[j] = tail_velocity_[j + 1] + speeds[j];
    tail_acceleration_[j] = tail_acceleration_[j + 1] + accelerations[j];
  }
  // The components from m on are negligible where C_m(z') ≤ B_m = ε min(T_v,0/T_v,m, T_a,0/T_a,m) (T the tail sums):
  // with C_m(z') = cosh k(z'+h)/sinh kh (e^{kz'} where the mirror term is dropped), increasing in z',
  // that is z' ≤ z*_m. The z*_m do not fall with m (C_m falls with k at z' ≤ 0, the tails fall with m); they are
  // lowered by 1e-9 (1 + |z*_m|) m, far above their rounding, so that a component is never dropped above its bound.
  negligible_below_.assign(n, -std::numeric_limits<double>::infinity());
  double previous = -std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < n && truncation_ > 0.0; ++m) {
    const double tails_v = tail_velocity_[m], tails_a = tail_acceleration_[m];
    double bound = std::numeric_limits<double>::infinity();
    if (tails_v > 0.0) bound = std::min(bound, truncation_ * tail_velocity_[0] / tails_v);
    if (tails_a > 0.0) bound = std::min(bound, truncation_ * tail_acceleration_[0] / tails_a);
    double z = std::numeric_limits<double>::infinity();
    if (std::isfinite(bound)) {
      const double k = k_[m];
      if (m < finite_count_) {
        const double argument = bound * std::sinh(k * depth_);
        z = argument >= 1.0 ? std::acosh(argument) / k - depth_ : -std::numeric_limits<double>::infinity();
      } else {
        z = std::log(bound) / k;
      }
      if (std::isfinite(z)) z -= 1e-9 * (1.0 + std::abs(z));
    }
    previous = std::max(previous, z);
    negligible_below_[m] = previous;
  }
  // Padding to whole SIMD vectors: components of zero amplitude and scales (k = k_max, keeping k sorted; ω = 0):
  // finite values that add 0.
  const std::size_t padded = (n + kLanes - 1) / kLanes * kLanes;
  for (auto* v : {&amplitude_, &ratio_velocity_, &ratio_acceleration_, &exponential_velocity_,
                  &exponential_acceleration_, &omega_, &phase_})
    v->resize(padded, 0.0);
  k_.resize(padded, largest_k_);
  if (finite_count_ == n) finite_count_ = padded;
}

std::size_t WaveKinematicsBatch::keptComponents(double z) const {
  const std::size_t padded = k_.size();
  if (!(truncation_ > 0.0) || !(z < 0.0) || padded == 0) return padded;
  // The first m whose threshold z*_m lies at or above z (every component from there on negligible), rounded up to
  // whole SIMD vectors: the components up to there are summed, not dropped (a loop without a scalar remainder).
  const auto m = static_cast<std::size_t>(std::lower_bound(negligible_below_.begin(), negligible_below_.end(), z) -
                                          negligible_below_.begin());
  return std::min(padded, (m + kLanes - 1) / kLanes * kLanes);
}

void WaveKinematicsBatch::evaluate(const Eigen::Vector3d* points, std::size_t count, double t, double ramp,
                                   double ramp_rate, Scratch& scratch, FluidKinematics* out) const {
  const std::size_t n = k_.size();
  evaluations_.fetch_add(1, std::memory_order_relaxed);
  if (scratch.theta.size() != n || !(scratch.time == t)) {
    scratch.theta.resize(n);
    scratch.time_reduced = true;
    for (std::size_t j = 0; j < n; ++j) {
      const double theta = phase_[j] - omega_[j] * t;
      scratch.time_reduced = scratch.time_reduced && std::abs(theta) < kLargestTimePhase;
      // θ − 2π·turns with 2π in two parts: the reduction adds no error beyond θ's own rounding.
      const double turns = std::nearbyint(theta * kInverseTwoPi);
      scratch.theta[j] = (theta - turns * kTwoPiHead) - turns * kTwoPiTail;
    }
    scratch.time = t;
  }
  scratch.anchor_cos.resize(n);
  scratch.anchor_sin.resize(n);
  double series[kElevationTerms];  // the elevation's Taylor coefficients in the distance from the anchor
  // anchor_cos, anchor_sin hold the exact phases at s = anchor_s. A new anchor is placed 0.9 of the rotation's
  // reach ahead of the point that needs it, in the direction the points have been moving along s, so that it
  // serves the points on both sides of it.
  bool anchored = false;
  double anchor_s = 0.0, anchor_eta = 0.0, previous_s = 0.0;
  const double reach = largest_k_ > 0.0 ? kRotationLimit / largest_k_ : 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d& p = points[i];
    const double s = p.x() * cos_dir_ + p.y() * sin_dir_;
    if (!scratch.time_reduced || !(std::abs(s) * largest_k_ < kLargestSinArgument)) {
      out[i] = field_.kinematics(p, t, ramp, ramp_rate);
      continue;
    }
    FluidKinematics& f = out[i];
    if (!anchored || !(std::abs(s - anchor_s) * largest_k_ <= kRotationLimit)) {
      const double ahead = anchored ? s + std::copysign(0.9 * reach, s - previous_s) : s;
      anchor_s = std::abs(ahead) * largest_k_ < kLargestSinArgument ? ahead : s;
      anchor_eta = phasesAndElevation(n, anchor_s, k_.data(), scratch.theta.data(), amplitude_.data(),
                                      scratch.anchor_cos.data(), scratch.anchor_sin.data());
      elevationSeries(n, k_.data(), amplitude_.data(), scratch.anchor_cos.data(), scratch.anchor_sin.data(), series);
      anchored = true;
    }
    previous_s = s;
    const double d = s - anchor_s;
    double unramped_eta = anchor_eta;
    if (d != 0.0) {
      unramped_eta = series[kElevationTerms - 1];
      for (int m = kElevationTerms - 1; m-- > 0;) unramped_eta = series[m] + d * unramped_eta;
      ++scratch.rotated_points;
    }
    const double eta = ramp * unramped_eta;
    f.elevation = eta;
    f.wet = p.z() <= eta;
    f.velocity.setZero();
    f.acceleration.setZero();
    if (!f.wet) continue;
    const double z = stretchedZ(p.z(), eta, depth_, field_.stretching());
    PointSums sums;
    const std::size_t kept = keptComponents(z);
    std::size_t ratio_count = std::min(kept, finite_count_);
    const double z_plus_h = z + depth_;  // ≥ 0 in finite water (z' ≥ −h); exact near the sea bed
    if (ratio_count > 0 && k_[ratio_count - 1] * z_plus_h > kLargestRatioArgument)  // z' far above the surface
      ratio_count = static_cast<std::size_t>(
          std::upper_bound(k_.begin(), k_.begin() + static_cast<std::ptrdiff_t>(ratio_count),
                           kLargestRatioArgument / z_plus_h) - k_.begin());
    depthSums(kept, ratio_count, d, z, z_plus_h, k_.data(), ratio_velocity_.data(), ratio_acceleration_.data(),
              exponential_velocity_.data(), exponential_acceleration_.data(), scratch.anchor_cos.data(),
              scratch.anchor_sin.data(), sums);
    const Eigen::Vector3d velocity(sums.u * cos_dir_, sums.u * sin_dir_, sums.w);
    const Eigen::Vector3d acceleration(sums.du * cos_dir_, sums.du * sin_dir_, sums.dw);
    f.velocity = ramp * velocity;
    f.acceleration = ramp * acceleration + ramp_rate * velocity;
  }
}

}  // namespace maris::ocean
