// The one instantiation of each decomposition declared in dense_decompositions.hpp.
#include "core/dense_decompositions.hpp"

template class Eigen::EigenSolver<Eigen::MatrixXd>;
template class Eigen::JacobiSVD<Eigen::MatrixXd>;
template class Eigen::BDCSVD<Eigen::MatrixXd>;
template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
template class Eigen::PartialPivLU<Eigen::MatrixXd>;
