// Steady free-surface elevation around and behind a thin ship, for the 3D view: the complete linear thin-ship
// (Michell) elevation ζ = (U/g) ∂φ/∂x on z = 0, and its wave component.
//
// The hull is Michell's centre-plane source sheet of density q = −2U ∂Y/∂x, each source a Kelvin (Havelock)
// source. In the decomposition of that source (F. Noblesse, "Alternative integral representations for the Green
// function of the theory of ship wave resistance", Journal of Engineering Mathematics 15, 241–265, 1981;
// kelvin_source.hpp) its elevation is a non-oscillatory local part decaying like 1/r² and a wave part. Summing
// the wave parts of the sources ahead of a point (each source's waves taken downstream of it) gives, at a point
// (x, y) of the free surface,
//   ζ_W(x, y) = Re ∫_{−π/2}^{π/2} A(x; θ) exp(−i k(θ) (x cos θ + y sin θ)) dθ,
//   A(x; θ) = −(2/π) k0 sec³θ F(x; θ),   F(x; θ) = ∬_{ξ > x} ∂Y/∂ξ e^{k z} e^{i κ ξ} dξ dz,
// κ = k0 sec θ, k = k0 sec²θ: the far-field pattern of kelvin_pattern.hpp with the Kochin function F taken over
// the part of the hull ahead of the point. Behind the stern F is the whole hull's Kochin function and ζ_W is that
// far-field pattern; beside the hull only the bow's part of the hull has made waves yet; ahead of the bow ζ_W = 0.
// The total adds the rest of the Kelvin source: its local part over the sheet (kelvin_source.hpp), and the wave
// terms that Havelock's exact form has with the sources ahead of x + y tan θ rather than ahead of x (the
// difference is not oscillatory in x). That rest is the bow's pile-up, the draw-down along the sides and the rise
// at the stern; it decays away from the hull, so far behind the stern the total is the wave pattern.
// Points inside the waterline take the elevation at the hull's side (the thin-ship sources are on the centre
// plane, so the field between the sides is not the water's).
#pragma once

#include <functional>

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
  WavePattern pattern;    // x ascending from x_from to x_to; elevation nx × ny [m]: the total (wave + local)
  Eigen::MatrixXd wave;   // [m] nx × ny: the wave component ζ_W alone
  Eigen::MatrixXd local;  // [m] nx × ny: the rest (total − wave); empty without the local part
  double lambda_max = 1;  // [-] sec θ at the end of the θ integral (the spectrum there is 1e-6 of its peak)
};

// The elevation on `region` for the hull sampled on `grid` (Y bilinear between its nodes, so ∂Y/∂x is exact
// per panel; open ends are line sources) at speed U [m/s] and gravity g [m/s²]. Without `with_local` the total
// is the wave component. `cancelled` (may be empty) is polled every few milliseconds; once it returns true the
// result is incomplete and the caller discards it.
ShipWaveField thinShipWaveField(const HullGrid& grid, double speed, double gravity, const WaveFieldRegion& region,
                                bool with_local = true, const std::function<bool()>& cancelled = {});

}  // namespace maris::ship
