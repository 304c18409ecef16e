// The segment's inverse mass W_i = M_i⁻¹ turned to the global frame, a step of every right-hand side.
//
// segmentMass (riser_model) builds a rod's Newton-Euler mass about its end A_i with its added mass: unchanged by any
// turn about its axis x', and so is its inverse. Each 3×3 block of such a matrix is a I + b e eᵀ + c [e]× with
// e = x' (symmetric blocks: c = 0), and R (a I + b e eᵀ + c [e]×) Rᵀ = a I + b t tᵀ + c [t]× with t = R e: the
// global W_i from the tangent alone, without the six 3×3 products of R W_local Rᵀ.
#pragma once

#include "riser/riser_model.hpp"

namespace maris::riser {

// Coefficients (a, b, c) of the blocks of an inverse mass in the segment's frame: translation (TL), coupling (TR,
// a/α rows/columns) and rotation (BR).
struct AxisymmetricInverseMass {
  Vec3 translation = Vec3::Zero();  // (a, b, c) of the top-left block
  Vec3 coupling = Vec3::Zero();     // of the top-right block (the bottom-left one is its transpose)
  Vec3 rotation = Vec3::Zero();     // of the bottom-right block
};

// Reads the coefficients off `local` (unchecked: for a matrix of that form, as segmentMass's inverse always is).
AxisymmetricInverseMass axisymmetricCoefficients(const Mat6& local);

// The same, checked; false when `local` is not of that form to 1e-13 of each block's largest entry
// (then the caller rotates it in full).
bool axisymmetricInverseMass(const Mat6& local, AxisymmetricInverseMass& out);

// W = R W_local Rᵀ from the coefficients and the tangent t = R e_x.
void rotateInverseMass(const AxisymmetricInverseMass& local, const Vec3& tangent, Mat6& w);

}  // namespace maris::riser
