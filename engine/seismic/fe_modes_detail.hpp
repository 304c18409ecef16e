// Pieces shared by the dry (fe_modes.cpp) and the fluid–solid (fe_coupled_modes.cpp) modal analyses.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "seismic/fe_modes.hpp"

namespace maris::seismic::detail {

// Unknowns: (u_x, u_y) of every node carrying solid mass, except the clamped bottom row.
struct DofMap {
  std::vector<int> of_node;  // first dof of a node (x; y = x + 1), −1 if none
  std::vector<double> mass;  // [kg/m] per dof
  int count = 0;
};

DofMap numberDofs(const FeModel& model, bool fixed_base);

// K over the free solid dofs: per-cell 8×8 blocks plus the boundary springs.
Eigen::SparseMatrix<double> assembleStiffness(const FeModel& model, const DofMap& d);

// Shares of Σ m|u|² by material, effective masses and the normalised shape of one mode (solid part x).
void describeMode(const FeModel& model, const DofMap& d, const Eigen::VectorXd& x, SolidMode& mode);

}  // namespace maris::seismic::detail
