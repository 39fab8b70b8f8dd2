#include "rbcstab/continuation/branch_point_curve.hpp"

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/core/error.hpp"

namespace rbcstab {

BranchPointCurveProblem::BranchPointCurveProblem(const TwoParameterProblem& base, const SpecialPoint& bp, double p2)
    : base_(base) {
  if (bp.type != SpecialPointType::BP || bp.status != LocationStatus::located)
    throw InvalidArgument("bp", "a branch-point curve starts from a located BP point (got " + to_string(bp.type) +
                                    ", " + to_string(bp.status) + ")");
  const Eigen::Index n = base.dimension();
  require(bp.x.size() == n, "bp", static_cast<double>(bp.x.size()), "a point of the base problem's dimension");
  Eigen::MatrixXd J;
  Eigen::VectorXd Fp;
  base.jacobian(bp.x, bp.p, p2, J);
  base.parameter_derivative(bp.x, bp.p, p2, Fp);
  Eigen::MatrixXd A(n, n + 1);
  A << J, Fp;
  // psi: the left singular vector of the smallest singular value of [F_x F_p1] (its left null vector at a BP).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullU);
  start_.resize(2 * n + 2);
  start_ << bp.x, bp.p, 0.0, svd.matrixU().col(n - 1);
}

void BranchPointCurveProblem::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  const Eigen::Index n = base_.dimension();
  const Eigen::VectorXd x = X.head(n), psi = X.tail(n);
  const double p1 = X[n], mu = X[n + 1];
  Eigen::VectorXd F, Fp;
  Eigen::MatrixXd J;
  base_.residual(x, p1, p2, F);
  base_.jacobian(x, p1, p2, J);
  base_.parameter_derivative(x, p1, p2, Fp);
  R.resize(2 * n + 2);
  R.head(n) = F + mu * psi;
  R.segment(n, n) = J.transpose() * psi;
  R[2 * n] = Fp.dot(psi);
  R[2 * n + 1] = psi.squaredNorm() - 1;
}

Eigen::VectorXcd BranchPointCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  const Eigen::Index n = base_.dimension();
  return base_.spectrum(X.head(n), X[n], p2);
}

CertifiedSpectrum BranchPointCurveProblem::certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const {
  const Eigen::Index n = base_.dimension();
  return base_.certified_spectrum(X.head(n), X[n], p2, refine);
}

}  // namespace rbcstab
