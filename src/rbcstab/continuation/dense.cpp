#include "rbcstab/continuation/dense.hpp"

// The one instantiation of each decomposition that dense.hpp declares.
template class Eigen::PartialPivLU<Eigen::MatrixXd>;
template class Eigen::FullPivLU<Eigen::MatrixXd>;
template class Eigen::FullPivLU<Eigen::MatrixXcd>;
template class Eigen::HouseholderQR<Eigen::MatrixXd>;
template class Eigen::JacobiSVD<Eigen::MatrixXd>;
template class Eigen::EigenSolver<Eigen::MatrixXd>;
