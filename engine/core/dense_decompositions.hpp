// Eigen's dense decompositions of dynamic-size double matrices, compiled once (dense_decompositions.cpp)
// instead of in every file that solves with them. Each is a large template: an EigenSolver<MatrixXd> alone
// costs tens of CPU-seconds to compile at -O3, and five scene files use it. Including this header makes the
// compiler call the one instantiation (explicit instantiation declarations, C++ [temp.explicit]); the code
// and the flags it is compiled with are the same, so the results are too.
#pragma once

#include <Eigen/Dense>

extern template class Eigen::EigenSolver<Eigen::MatrixXd>;
extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
extern template class Eigen::BDCSVD<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::PartialPivLU<Eigen::MatrixXd>;
