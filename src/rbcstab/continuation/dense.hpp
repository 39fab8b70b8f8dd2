#pragma once
// Eigen's dense module, with the decompositions of a MatrixXd that this library and its tests use declared as
// instantiated once, in dense.cpp: each file that solves, inverts or takes eigenvalues or singular values would
// otherwise compile them again at -O3 (docs/building.md "Where the compile time goes"). Include this instead of
// <Eigen/Dense>, <Eigen/LU>, <Eigen/QR>, <Eigen/SVD> or <Eigen/Eigenvalues>.
#include <Eigen/Dense>

extern template class Eigen::PartialPivLU<Eigen::MatrixXd>;
extern template class Eigen::FullPivLU<Eigen::MatrixXd>;
extern template class Eigen::FullPivLU<Eigen::MatrixXcd>;
extern template class Eigen::HouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
extern template class Eigen::EigenSolver<Eigen::MatrixXd>;
