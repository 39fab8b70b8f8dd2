#include "rbcstab/continuation/fold_curve.hpp"

#include <cmath>
#include <limits>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/detail/minimal_augmentation.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

void TwoParameterProblem::parameter_derivative(const Eigen::VectorXd& x, double p1, double p2,
                                               Eigen::VectorXd& Fp) const {
  const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(p1));
  Eigen::VectorXd Fm;
  residual(x, p1 + h, p2, Fp);
  residual(x, p1 - h, p2, Fm);
  Fp = (Fp - Fm) / (2 * h);
}

void TwoParameterProblem::jacobian(const Eigen::VectorXd& x, double p1, double p2, Eigen::MatrixXd& J) const {
  const Eigen::Index n = dimension();
  J.resize(n, n);
  Eigen::VectorXd xp = x, xm = x, Fp(n), Fm(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(x[j]));
    xp[j] = x[j] + h;
    xm[j] = x[j] - h;
    residual(xp, p1, p2, Fp);
    residual(xm, p1, p2, Fm);
    J.col(j) = (Fp - Fm) / (xp[j] - xm[j]);
    xp[j] = xm[j] = x[j];
  }
}

void SingularityCurveProblem::start_at(const SpecialPoint& point, double p2) {
  const Eigen::Index n = base_.dimension();
  require(point.x.size() == n, "point", static_cast<double>(point.x.size()), "a point of the base problem's dimension");
  Eigen::MatrixXd A, B, C;
  singular_matrix(point.x, point.p, p2, A);
  detail::null_borders(A, 1, B, C);  // left / right singular vectors of the smallest singular value
  b_ = B.col(0);
  c_ = C.col(0);
  start_.resize(n + 1);
  start_ << point.x, point.p;
}

CertifiedSpectrum SingularityCurveProblem::certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const {
  const Eigen::Index n = base_.dimension();
  return base_.certified_spectrum(X.head(n), X[n], p2, refine);
}

double SingularityCurveProblem::test_function(const Eigen::VectorXd& x, double p1, double p2) const {
  Eigen::MatrixXd A;
  singular_matrix(x, p1, p2, A);
  return detail::bordered_g(A, b_, c_)(0, 0);
}

void SingularityCurveProblem::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  const Eigen::Index n = base_.dimension();
  const Eigen::VectorXd x = X.head(n);
  Eigen::VectorXd F(n);
  base_.residual(x, X[n], p2, F);
  R.resize(n + 1);
  R.head(n) = F;
  R[n] = test_function(x, X[n], p2);
}

Eigen::VectorXcd TwoParameterProblem::spectrum(const Eigen::VectorXd& x, double p1, double p2) const {
  Eigen::MatrixXd J;
  jacobian(x, p1, p2, J);
  return Eigen::EigenSolver<Eigen::MatrixXd>(J, false).eigenvalues();
}

CertifiedSpectrum TwoParameterProblem::certified_spectrum(const Eigen::VectorXd& x, double p1, double p2, bool) const {
  Eigen::MatrixXd J;
  jacobian(x, p1, p2, J);
  return bound_by_eigenvalues(spectrum(x, p1, p2), J, kFiniteDifferenceAccuracy);
}

FoldCurveProblem::FoldCurveProblem(const TwoParameterProblem& base, const SpecialPoint& lp, double p2)
    : SingularityCurveProblem(base) {
  // LPC: a fold of a fixed-period shooting system (orbit.hpp), the same singularity of dF/dx.
  if ((lp.type != SpecialPointType::LP && lp.type != SpecialPointType::LPC) || lp.status != LocationStatus::located)
    throw InvalidArgument("lp", "a fold curve starts from a located LP or LPC point (got " + to_string(lp.type) + ", " +
                                    to_string(lp.status) + ")");
  start_at(lp, p2);
}

Eigen::VectorXcd FoldCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  const Eigen::Index n = base_.dimension();
  return base_.spectrum(X.head(n), X[n], p2);
}

}  // namespace rbcstab
