// Initial shape of a riser whose submerged weight changes along its length (buoyancy modules, sections): the
// inextensible cable catenary taken piece by piece, each segment with its own submerged weight per length, through
// the top and the held bottom, with a grounded length on a flat bed where the line reaches it. A lazy-wave riser
// (heavy, buoyant, heavy) then starts with its sag bend, hog bend and touchdown, which the uniform catenary or the
// circular arc lack; the static Newton (riser_statics) needs far fewer iterations from it and no dynamic relaxation.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "riser/riser_model.hpp"

namespace maris::riser {

// The cable solution in the vertical plane through top and anchor (current, bending and stretch left out).
// H: horizontal tension [N]; V(s) = V_top − W(s) the vertical one, W(s) the submerged weight from the top to s.
// On each piece of constant weight w (V from V0 to V1 = V0 − w l): Δx = (H/w)(asinh(V0/H) − asinh(V1/H)),
// Δz = (√(H² + V0²) − √(H² + V1²))/w downward (straight for w = 0).
// Grounded: with a bed and the anchor on it, the line leaves the bed at s_td tangent to it (V(s_td) = 0, so
// V_top = W(s_td)) and lies straight to the anchor; s_td solves the drop, H the span (monotone in H: bisection).
// Fully suspended otherwise: V_top solves the drop. The drop may have several roots along the scan (lazy waves):
// the one of least potential energy Σ w l z̄ is taken.
struct PiecewiseCatenary {
  double horizontal_tension = 0.0;  // [N] H
  double top_vertical = 0.0;        // [N] V_top (downward pull of the line on the top support)
  double touchdown = 0.0;           // [m] arc length where the line meets the bed (= length: no grounded part)
  std::vector<Eigen::Vector3d> points;  // at the requested arc lengths
};

// `submerged` per segment of `segments` [N/m]; arc_lengths ascending within [0, length]. Empty optional when the
// geometry has no such solution (anchor out of reach, vertical line, no root): the caller keeps its own start.
std::optional<PiecewiseCatenary> piecewiseCatenary(const std::vector<Segment>& segments, const RiserSeabed* bed,
                                                   const Eigen::Vector3d& top, const Eigen::Vector3d& anchor,
                                                   double length, const std::vector<double>& arc_lengths);

// True when the segments' submerged weight per length (weight − buoyancy) differs along the riser by more than
// 1e-9 of its largest magnitude: the uniform catenary and the arc are then poor starts.
bool submergedWeightVaries(const std::vector<Segment>& segments);

}  // namespace maris::riser
