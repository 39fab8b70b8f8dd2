#pragma once
// Shared by the two-parameter curves (fold, Hopf): minimal augmentation (Govaerts 2000) of a matrix
// A(x, p) that becomes rank deficient by k on the curve. With borders B, C (n x k) the bordered system
//   [A B; C^T 0] [V; G] = [0; I_k]
// is regular near the curve and G (k x k) vanishes exactly where rank A = n - k.
#include <Eigen/Dense>
#include <Eigen/SVD>

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

}  // namespace rbcstab::detail
