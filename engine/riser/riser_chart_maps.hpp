// The maps of a segment's three chart coordinates θ (riser_implicit) to its orientation and body angular
// velocity: R = R_ref E(θ) about a reference R_ref, ω_body = M(θ) θ̇, and the rate term Ṁ θ̇ of the angular
// acceleration, α_body = M θ̈ + Ṁ θ̇.
#pragma once

#include "riser/riser_model.hpp"

namespace maris::riser {

//   RotationVector: E = exp([θ]×), M = J_r(θ). Used with torsion.
//   SwingTwist:     E = exp([0, θ_y, θ_z]×) exp(θ_x [e_x]×): a swing of the axis, then a spin θ_x about it;
//                   M = exp(θ_x[e_x]×)ᵀ J_r(θ_s) P + e_x e_xᵀ with θ_s = Pθ = (0, θ_y, θ_z). Used without torsion,
//                   where the spin has neither stiffness nor inertia (its rate is held at zero): the axis
//                   t = R e_x then does not depend on θ_x, whereas with the rotation vector a Newton correction
//                   of the free spin also turns the axis once the segment has swung.
// Both have E = M = I at θ = 0.
enum class ChartKind { RotationVector, SwingTwist };

struct ChartMaps {
  Mat3 turn;       // E(θ)
  Mat3 rate_map;   // M(θ)
  Vec3 rate_term;  // Ṁ θ̇ (zero when θ̇ is); exact, no differences
};
ChartMaps chartMaps(ChartKind kind, const Vec3& theta, const Vec3& rate = Vec3::Zero());

// θ of a turn E (the inverse of chartMaps' turn; SwingTwist: the swing is the shortest turn of e_x to E e_x, so
// |θ_s| ≤ π). Exactly 0 for E = I.
Vec3 chartCoordinates(ChartKind kind, const Mat3& turn);

}  // namespace maris::riser
