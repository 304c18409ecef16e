// Steady wave field around and behind a thin ship, for the 3D view: the wave component of the thin-ship
// (Michell) elevation, each source contributing its waves only downstream of itself.
//
// The hull is Michell's centre-plane source sheet of density ∝ ∂Y/∂x. In Noblesse's decomposition of the Kelvin
// source (F. Noblesse, "Alternative integral representations for the Green function of the theory of ship wave
// resistance", Journal of Engineering Mathematics 15, 241–265, 1981) a source's potential is a Rankine part, a
// non-oscillatory local part decaying like 1/r², and a wave part that exists only downstream of the source. Summing
// the wave parts over the sheet gives, at a point (x, y) of the free surface,
//   ζ(x, y) = Re ∫_{−π/2}^{π/2} A(x; θ) exp(−i k(θ) (x cos θ + y sin θ)) dθ,
//   A(x; θ) = (2i/π) k0 sec³θ F(x; θ),   F(x; θ) = ∬_{ξ > x} ∂Y/∂ξ e^{k z} e^{i κ ξ} dξ dz,
// κ = k0 sec θ, k = k0 sec²θ: the far-field pattern of kelvin_pattern.hpp with the Kochin function F taken over
// the part of the hull ahead of the point. Behind the stern F is the whole hull's Kochin function and ζ is that
// far-field pattern; beside the hull only the bow's part of the hull has made waves yet; ahead of the bow ζ = 0.
// The local part (the bow's pile-up, the draw-down along the sides) is not included. Points inside the waterline
// take the elevation at the hull's side (the thin-ship sources are on the centre plane).
#pragma once

#include "ship/hull_form.hpp"
#include "ship/kelvin_pattern.hpp"

namespace maris::ship {

struct WaveFieldRegion {
  double x_from = 0;      // [m] aft end of the field (behind the stern: smaller x)
  double x_to = 0;        // [m] forward end of the field (ahead of the bow)
  double half_width = 0;  // [m] the field spans |y| ≤ half_width
  int nx = 2;             // points along x (≥ 2)
  int ny = 2;             // points across (≥ 2)
};

struct ShipWaveField {
  WavePattern pattern;    // x ascending from x_from to x_to; elevation nx × ny [m]
  double lambda_max = 1;  // [-] sec θ at the end of the θ integral (the spectrum there is 1e-6 of its peak)
};

// The wave elevation on `region` for the hull sampled on `grid` (Y bilinear between its nodes, so ∂Y/∂x is exact
// per panel; open ends are line sources) at speed U [m/s] and gravity g [m/s²].
ShipWaveField thinShipWaveField(const HullGrid& grid, double speed, double gravity, const WaveFieldRegion& region);

}  // namespace maris::ship
