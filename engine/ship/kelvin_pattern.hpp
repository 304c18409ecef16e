// Far-field Kelvin wave pattern behind the ship (paper eq 1; amplitude normalised here as below):
//   ζ(x, y) = Re ∫_{−π/2}^{π/2} A(θ) exp(−i k(θ) ((x − x_m) cos θ + y sin θ)) dθ,
//   A(θ) = −(2/π) k0 sec³θ (P + iQ)(θ),  k(θ) = k0 sec²θ,
// with x_m the mid-length of the Kochin grid (P + iQ is computed with x measured from there). |A| is the
// normalisation that makes eq 3 (wave-pattern resistance) equal eq 8 (Michell's integral); the phase is the wave
// term of the Kelvin source (kelvin_source.hpp, checked there against the source's Fourier integral) summed over
// Michell's sheet of density −2U ∂Y/∂x. Valid only downstream of the stern, a few wavelengths away: the grid starts
// behind the stern.
#pragma once

#include <Eigen/Core>

#include "ship/michell_resistance.hpp"

namespace maris::ship {

struct WavePattern {
  Eigen::VectorXd x;          // [m] stations behind the stern (same frame as the hull: from the AP, forward +)
  Eigen::VectorXd y;          // [m] transverse positions
  Eigen::MatrixXd elevation;  // [m] ζ(x_i, y_j), x.size() × y.size()
};

// Elevation on nx × ny points covering `length_behind` [m] aft of x_stern [m] and |y| ≤ half_width [m], for
// speed U [m/s]. The θ integral runs over λ = cosh u ∈ [1, λ_max] with λ_max where the spectrum has dropped
// to 1e-6 of its peak, nodes spaced to resolve the phase at the farthest point.
WavePattern kelvinWavePattern(GridKochin& kochin, double speed, double gravity, double x_stern, double length_behind,
                              double half_width, int nx, int ny);

}  // namespace maris::ship
