#pragma once
// Shared by the two-parameter curves (fold, PD, Hopf, NS): minimal augmentation (Govaerts 2000) of a matrix
// A(x, p) that becomes rank deficient by k on the curve. With borders B, C (n x k) the bordered system
//   [A B; C^T 0] [V; G] = [0; I_k]
// is regular near the curve and G (k x k) vanishes exactly where rank A = n - k.
#include <array>
#include <cmath>
#include <limits>
#include "rbcstab/continuation/dense.hpp"

namespace rbcstab::detail {

// Borders from the SVD of A at the starting point: B = left, C = right singular vectors of the k
// smallest singular values (the null spaces at the point itself).
inline void null_borders(const Eigen::MatrixXd& A, Eigen::Index k, Eigen::MatrixXd& B, Eigen::MatrixXd& C) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  B = svd.matrixU().rightCols(k);
  C = svd.matrixV().rightCols(k);
}

inline Eigen::MatrixXd bordered_g(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C) {
  const Eigen::Index n = A.rows(), k = B.cols();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + k, n + k);
  M.topLeftCorner(n, n) = A;
  M.topRightCorner(n, k) = B;
  M.bottomLeftCorner(k, n) = C.transpose();
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n + k, k);
  E.bottomRows(k).setIdentity();
  return M.partialPivLu().solve(E).bottomRows(k);
}

// Rank-2 curves (Hopf: J^2 + kappa I; NS: M^2 - 2 kappa M + I) append two of G's four entries to the
// m equations F = 0 in the unknowns X = (x, p1, kappa). Which two is decided once, at the start.
using GEntries = std::array<int, 4>;  // (i1, j1, i2, j2)

// dG/dX for all four entries (rows G00, G01, G10, G11) by central differences of g(X) -> G, step
// cbrt(eps)(1 + |X_j|): G is smooth in X and only Newton's rate depends on these rows.
template <class GOfX>
Eigen::MatrixXd g_entry_derivatives(const Eigen::VectorXd& X, const GOfX& g) {
  Eigen::MatrixXd D(4, X.size());
  Eigen::VectorXd Y = X;
  const auto entries = [&](const Eigen::VectorXd& Z) {
    const Eigen::Matrix2d G = g(Z);
    return Eigen::Vector4d(G(0, 0), G(0, 1), G(1, 0), G(1, 1));
  };
  for (Eigen::Index j = 0; j < X.size(); ++j) {
    const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(X[j]));
    Y[j] = X[j] + h;
    const Eigen::Vector4d gp = entries(Y);
    Y[j] = X[j] - h;
    const Eigen::Vector4d gm = entries(Y);
    Y[j] = X[j];
    D.col(j) = (gp - gm) / (2 * h);
  }
  return D;
}

// J's last two rows = the rows of dG for the entries e.
inline void set_g_rows(Eigen::MatrixXd& J, const Eigen::MatrixXd& dG, const GEntries& e) {
  const Eigen::Index m = J.rows() - 2;
  J.row(m) = dG.row(2 * e[0] + e[1]);
  J.row(m + 1) = dG.row(2 * e[2] + e[3]);
}

// The pair whose rows, under the m x (m + 2) rows dF/dX, give the best-conditioned square Jacobian
// (largest inverse condition number); the choice only needs to be regular. J's last two rows are
// overwritten.
inline GEntries best_conditioned_entries(Eigen::MatrixXd J, const Eigen::MatrixXd& dG) {
  const Eigen::Index m = J.rows() - 2;
  constexpr std::array<GEntries, 6> pairs = {
      {{0, 0, 1, 1}, {0, 0, 0, 1}, {0, 0, 1, 0}, {0, 1, 1, 0}, {0, 1, 1, 1}, {1, 0, 1, 1}}};
  double best = -1;
  GEntries chosen = pairs[0];
  for (const auto& e : pairs) {
    set_g_rows(J, dG, e);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
    const double s = svd.singularValues()(m + 1) / svd.singularValues()(0);
    if (s > best) {
      best = s;
      chosen = e;
    }
  }
  return chosen;
}

// The curve's residual [F; G(e1); G(e2)].
inline void rank_two_residual(const Eigen::VectorXd& F, const Eigen::Matrix2d& G, const GEntries& e,
                              Eigen::VectorXd& R) {
  const Eigen::Index m = F.size();
  R.resize(m + 2);
  R.head(m) = F;
  R[m] = G(e[0], e[1]);
  R[m + 1] = G(e[2], e[3]);
}

}  // namespace rbcstab::detail
