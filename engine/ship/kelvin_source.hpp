// The free-surface elevation of the Kelvin (Havelock) source and of Michell's centre-plane source sheet: the
// non-oscillatory ("local") part that ship_wave_field.hpp adds to the waves.
//
// A source of outflow q [m³/s] at depth h below the free surface of a stream of speed U in the −x direction (the
// ship moves to +x) raises the free surface by ζ = (U/g) ∂φ/∂x. From the Fourier representation of φ with the
// linear free-surface condition φ_xx + k0 φ_z = 0 (k0 = g/U², Rayleigh's vanishing damping: waves downstream), the
// radial wave-number integral done in closed form (Havelock's decomposition; F. Noblesse, J. Eng. Math. 15, 1981;
// Wehausen & Laitone, "Surface waves", 1960, §13), at a point x' = x − ξ, y of the free surface:
//   ζ = −(q/2π²U) ∫_{−π/2}^{π/2} sec θ Im[−1/Z + K e^{KZ} E1(KZ)] dθ               (local part)
//     + (q/πU) ∫_{−π/2}^{π/2} H(−ϖ) K sec θ e^{−Kh} cos(Kϖ) dθ                       (wave part)
// with ϖ = x' cos θ + y sin θ, Z = −h + iϖ, K = k0 sec²θ, E1 the exponential integral (principal branch: its cut
// on the negative real axis is where the wave term switches on, and the sum is continuous). The local part is
// not oscillatory: e^{w} E1(w) ~ 1/w − 1/w² + … for large |w|, so it decays like 1/r² and tends, as U → 0, to the
// rigid-lid (double-body) elevation q x'/(2π U k0 r³), r² = x'² + y² + h².
//
// For the hull, a sheet of sources of density q = −2U ∂Y/∂ξ per unit area (Michell) with Y bilinear: the ξ
// integral of the local part over a panel of constant ∂Y/∂ξ is a difference of e^{KZ} E1(KZ) at its ends (that
// function is the primitive of −1/Z + K e^{KZ} E1(KZ)), and the depth integral, with ∂Y/∂ξ linear between
// waterlines, is closed form too (primitives of e^w E1(w) and w e^w E1(w)); only θ is done numerically.
#pragma once

#include <complex>
#include <functional>

#include <Eigen/Core>

#include "ship/hull_form.hpp"

namespace maris::ship {

// e^w E1(w), principal branch (cut on the negative real axis, E1(x + i0) there; a zero imaginary part is read as
// +0). Power series for small |w| and near the negative real axis, continued fraction in between, asymptotic
// series for |w| ≥ 20. Relative accuracy about 1e-13 away from w = 0.
std::complex<double> scaledExponentialIntegral(std::complex<double> w);

// Elevation of one source of outflow q at depth h below the free surface, per unit q/U [1/m]: the total, its
// local part (the first integral above) and the wave part with the downstream condition x' < 0 of
// ship_wave_field.hpp (H(−x') instead of H(−ϖ)). k0 = g/U² [1/m]; θ by composite 8-point Gauss–Legendre on
// `theta_panels` panels.
struct SourceElevation {
  double total = 0;
  double local = 0;
  double wave = 0;
};
SourceElevation kelvinSourceElevation(double x_rel, double y, double depth, double k0, int theta_panels);

// The local part of the thin-ship elevation [m] at free-surface points (x_i, y_j) (points inside the waterline
// are not computed: 0) for the hull grid at k0 = g/U² [1/m]. The hull is resampled to `stations` × `waterlines`
// nodes for points within 0.2 L of it, halved and quartered beyond 0.2 L and 0.5 L (the local part is smooth on
// the scale of the hull there); open ends become ramps a quarter of a station long. θ per station node, on each
// side of the angle where its ϖ = 0: 8-point Gauss–Legendre on `theta_panels` panels graded toward that angle
// (sizes ×4) and `outer_panels` equal panels over the outer three quarters. On the 3D view's grid (Wigley model,
// Fn 0.35) the defaults differ by 0.6 % of the largest local elevation from a 65 × 11 sheet with 6 + 8 panels.
// Rows of x run on all cores. `cancelled` (may be empty; called from those threads) is polled once per row; once
// it returns true the rest is left at 0.
Eigen::MatrixXd thinShipLocalElevation(const HullGrid& grid, double k0, const Eigen::VectorXd& x,
                                       const Eigen::VectorXd& y, int stations = 49, int waterlines = 9,
                                       int theta_panels = 2, int outer_panels = 3,
                                       const std::function<bool()>& cancelled = {});

}  // namespace maris::ship
