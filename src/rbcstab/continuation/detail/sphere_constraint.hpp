#pragma once
// The area constraint of the equilibrium problems (reduced, modal, full): a flow F with x.F = 0
// conserves Q = |x|^2, so DF is singular along the family of spheres. Newton solves
// G = F + (Q - 1) x instead (x.G = (Q - 1) Q forces Q = 1 at a zero; DG = DF + 2 x x^T at Q = 1 is
// regular at a hyperbolic equilibrium because x is DF's left null vector), and stability is the
// spectrum of DF on the tangent plane x^perp, which DF leaves invariant.
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/problem.hpp"

namespace rbcstab::detail {

// G = F + (|x|^2 - 1) x, in place.
inline void add_sphere_constraint(const Eigen::VectorXd& x, Eigen::VectorXd& F) { F += (x.squaredNorm() - 1) * x; }

// DG = DF + (|x|^2 - 1) I + 2 x x^T, in place.
inline void add_sphere_constraint_jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& DF) {
  DF.diagonal().array() += x.squaredNorm() - 1;
  DF.noalias() += 2 * x * x.transpose();
}

// Orthonormal basis of x^perp: the last n - 1 columns of x's Householder Q.
inline Eigen::MatrixXd tangent_basis(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size();
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(x).householderQ() * Eigen::MatrixXd::Identity(n, n);
  return Q.rightCols(n - 1);
}

// Eigenvalues of DF restricted to x^perp (n - 1 of them).
inline Eigen::VectorXcd tangent_spectrum(const Eigen::MatrixXd& DF, const Eigen::VectorXd& x) {
  const Eigen::MatrixXd T = tangent_basis(x);
  return Eigen::EigenSolver<Eigen::MatrixXd>(T.transpose() * DF * T, false).eigenvalues();
}

// The same values with first-order error bounds (certified_eigenvalues of T^T DF T); eta: DF's relative
// accuracy, to which the product's own rounding is added.
inline CertifiedSpectrum certified_tangent_spectrum(const Eigen::MatrixXd& DF, const Eigen::VectorXd& x, double eta) {
  const Eigen::MatrixXd T = tangent_basis(x);
  return certified_eigenvalues(T.transpose() * DF * T, eta + assembly_accuracy(x.size()));
}

}  // namespace rbcstab::detail
