// The inverse mass W_i = M_i⁻¹ of a segment in the global frame, from its tangent alone.
// segmentMass (riser_model.cpp) builds every segment's Newton-Euler mass axisymmetric: each of its 3×3 blocks, and
// so each block of its inverse and of the reaction matrix's products W_i D'_i, commutes with every turn about the
// segment's axis e and is a 1 + b e eᵀ + c [e]× (P = e eᵀ and X = [e]× span that algebra with 1: P² = P,
// PX = XP = 0, X² = P − 1). Turned to the global frame by R_i (t = R_i e) such a block is a 1 + b t tᵀ + c [t]×,
// so W_i is never formed by 3×3 products with R_i, and the reaction matrix's blocks are sums of a few of them, with
// the three numbers of each block read off the local inverse mass (segmentInverseMass).
#pragma once

#include "riser/riser_model.hpp"

namespace maris::riser {

// a 1 + b e eᵀ + c [e]× in the segment's frame; at(t) the same block in the global frame (tangent t).
struct AxialBlock {
  double a = 0.0, b = 0.0, c = 0.0;

  AxialBlock transposed() const { return {a, b, -c}; }
  Mat3 at(const Vec3& t) const {
    Mat3 g;
    const double bx = b * t.x(), by = b * t.y(), bz = b * t.z();
    const double cx = c * t.x(), cy = c * t.y(), cz = c * t.z();
    g << a + bx * t.x(), bx * t.y() - cz, bx * t.z() + cy,  //
        by * t.x() + cz, a + by * t.y(), by * t.z() - cx,   //
        bz * t.x() - cy, bz * t.y() + cx, a + bz * t.z();
    return g;
  }
};

// W_i's blocks (W is symmetric: the force's angular acceleration is couplingᵀ) and the products of W_i with
// D'_i = [1; [d_i]×], d_i = l_i t_i (the response to a force at the far end), that the reaction matrix is made of.
struct SegmentInverseMass {
  AxialBlock force, coupling, moment;  // W = [force, coupling; couplingᵀ, moment]
  AxialBlock far_force;                // top rows of W D': the origin's acceleration per unit far-end force
  AxialBlock far_end;                  // D'ᵀ W D': the far end's acceleration per unit far-end force

  // W g for g = (force, moment), in the global frame of tangent t. Inlined by force: GCC kept it a call, 6.5 % of
  // the right-hand side's samples.
  [[gnu::always_inline]] Vec6 apply(const Vec3& t, const Vec6& g) const {
    const Vec3 f = g.head<3>(), q = g.tail<3>();
    const double tf = t.dot(f), tq = t.dot(q);
    const Vec3 xf = t.cross(f), xq = t.cross(q);
    Vec6 out;
    out.head<3>() = force.a * f + coupling.a * q + (force.b * tf + coupling.b * tq) * t + force.c * xf + coupling.c * xq;
    out.tail<3>() = coupling.a * f + moment.a * q + (coupling.b * tf + moment.b * tq) * t - coupling.c * xf + moment.c * xq;
    return out;
  }
};

// The blocks of a segment's local inverse mass (riser_model's inverse_mass_local, axisymmetric about x) and its
// length. The numbers are read off the matrix: a from the two transverse diagonal entries (their mean), b from the
// axial one, c from the two off-diagonal transverse ones; test RiserInverseMass checks that the blocks give the
// matrix back and W_i = R_i W_local R_iᵀ for turned segments.
inline AxialBlock axialBlockOf(const Mat3& local) {
  const double a = 0.5 * (local(1, 1) + local(2, 2));
  return {a, local(0, 0) - a, 0.5 * (local(2, 1) - local(1, 2))};
}

// The products with the arm [d]× = l [e]× = (0, 0, l) in closed form (with P² = P, PX = XP = 0, X² = P − 1,
// (a, b, c)·(0, 0, l) = (−c l, c l, a l) and (0, 0, l)·(a, b, c) = (−l c, l c, l a)): a few operations per segment,
// cheap enough to be done at every right-hand side.
inline SegmentInverseMass segmentInverseMass(const Mat6& local, double length) {
  SegmentInverseMass w;
  w.force = axialBlockOf(local.topLeftCorner<3, 3>());
  w.coupling = axialBlockOf(local.topRightCorner<3, 3>());
  w.moment = axialBlockOf(local.bottomRightCorner<3, 3>());
  const double l = length;
  // W D' = [force + coupling [d]×; couplingᵀ + moment [d]×], D'ᵀ W D' = its top rows − [d]× its bottom rows.
  w.far_force = {w.force.a - w.coupling.c * l, w.force.b + w.coupling.c * l, w.force.c + w.coupling.a * l};
  const AxialBlock far_turn{w.coupling.a - w.moment.c * l, w.coupling.b + w.moment.c * l, -w.coupling.c + w.moment.a * l};
  w.far_end = {w.far_force.a + l * far_turn.c, w.far_force.b - l * far_turn.c, w.far_force.c - l * far_turn.a};
  return w;
}

}  // namespace maris::riser
