// Natural frequencies and mode shapes of the segment chain, linearised about a static equilibrium
// (the paper's "procedure of [60]", issue 10). Joint coordinates, no damping, no drag, top held.
#pragma once

#include <vector>

#include "riser/riser_statics.hpp"

namespace maris::riser {

struct RiserModes {
  std::vector<double> frequencies;           // [rad/s] ascending, constraint (zero) modes removed
  std::vector<std::vector<Vec3>> shapes;     // [-] node displacements (n+2 nodes) per mode, largest = 1
};

// Linearises q̈ = f(q) about the static state (q = rotation increments of the dynamic segments, 2 per
// segment without torsion, plus the free top coordinates) by central differences of the O(n)
// accelerations, A = ∂f/∂q, and solves the eigenproblem of -A: ω² = eigenvalues. Directions that
// violate a held bottom end have zero eigenvalues (the constrained acceleration keeps Φ̈ = 0) and are
// dropped. Dense O(N³) in N ≈ 3n: meant for n up to a few hundred. Returns at most `count` modes.
RiserModes computeModes(const RiserModel& model, const StaticSolution& statics, int count);

}  // namespace maris::riser
