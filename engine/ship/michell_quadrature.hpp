// Quadrature building blocks of Michell's integral, each a small tested function:
//   - Filon–Simpson weights for ∫ f(x) e^{iκx} dx on a uniform grid (any κh, series for small κh);
//   - exponentially fitted trapezoid weights for ∫ f(z) e^{bz} dz on a uniform grid (exact for piecewise
//     linear f, any decay rate b ≥ 0, series for small b·dz);
//   - the analytic Kochin function of the Wigley hull (the independent check of the offsets path).
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

namespace maris::ship {

// Filon's coefficients α, β, γ(θ) for θ = κh (Abramowitz & Stegun 25.4.47). Series below θ = 0.2, where
// the closed forms lose digits to cancellation.
struct FilonCoefficients {
  double alpha, beta, gamma;
};
FilonCoefficients filonCoefficients(double theta);

// ∫_{x_0}^{x_N} f(x) e^{iκx} dx by Filon–Simpson with x_i = x_0 + i·h, i = 0..N, N even (f.size() odd ≥ 3).
// Exact when f is piecewise quadratic on the pairs of intervals, for any κ (including κ = 0).
std::complex<double> filonIntegral(const Eigen::Ref<const Eigen::VectorXd>& f, double x0, double h, double kappa);

// Weights w_j (j = 0..n-1) with Σ w_j f(z_j) = ∫_{z_{n-1}}^{0} f_lin(z) e^{bz} dz, z_j = -j·dz, where f_lin
// interpolates f linearly between nodes. Exact for piecewise linear f; b ≥ 0 [1/m], dz > 0 [m].
// Weights below 1e-300 of the surface value are set to zero and `last_nonzero` (if given) returns the index
// of the deepest weight that is not zero, so callers can skip the rest of the column.
void expTrapezoidWeights(double b, double dz, Eigen::Ref<Eigen::VectorXd> weights, int* last_nonzero = nullptr);

// (1 - e^{-K} - K e^{-K})/K² and (K - 1 + e^{-K})/K²: the deeper and shallower node weights of one
// interval of the exponentially fitted trapezoid (divided by dz·e^{b z_upper}). Series for K < 0.5.
double expTrapezoidDeepWeight(double K);
double expTrapezoidShallowWeight(double K);

// Wigley hull Y = (B/2)(1-(2ξ/L)²)(1-(z/T)²): Michell's Kochin function |P + iQ|² at wave number
// k0 = g/U² [1/m] and λ = sec θ, in closed form:  |P+iQ|² = X(κ)² Z(b)², κ = k0 λ, b = k0 λ²,
//   X = (8B/L²)[sin(κL/2)/κ² − (L/2) cos(κL/2)/κ],  Z = ∫_{-T}^0 (1 − z²/T²) e^{bz} dz  (from the hull equation).
double wigleyKochinSquared(double length, double beam, double draft, double k0, double lambda);
// The two factors, exposed for tests (series used near zero arguments).
double wigleyLengthFactor(double length, double beam, double kappa);
double wigleyDepthFactor(double draft, double b);

}  // namespace maris::ship
