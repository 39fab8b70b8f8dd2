#include "rbcstab/continuation/hopf_curve.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "rbcstab/continuation/detail/minimal_augmentation.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

HopfCurveProblem::HopfCurveProblem(const TwoParameterProblem& base, const SpecialPoint& hb, double p2) : base_(base) {
  if (hb.type != SpecialPointType::HB || hb.status != LocationStatus::located)
    throw InvalidArgument("hb", "a Hopf curve starts from a located HB point (got " + to_string(hb.type) + ", " +
                                    to_string(hb.status) + ")");
  const Eigen::Index n = base.dimension();
  require(hb.x.size() == n, "hb", static_cast<double>(hb.x.size()), "a point of the base problem's dimension");
  require(n >= 2, "dimension", static_cast<double>(n), ">= 2 (a Hopf pair needs two eigenvalues)");
  const double omega = std::abs(hb.eigenvalue.imag());
  require(omega > 0, "hb.eigenvalue", omega, "a nonzero imaginary part omega (omega = 0 is a Bogdanov-Takens point)");
  Eigen::MatrixXd J;
  base.jacobian(hb.x, hb.p, p2, J);
  const Eigen::MatrixXd A = J * J + omega * omega * Eigen::MatrixXd::Identity(n, n);
  detail::null_borders(A, 2, B_, C_);
  start_.resize(n + 2);
  start_ << hb.x, hb.p, omega * omega;

  // Choose the two entries of G whose equations, with F = 0, give the best-conditioned Jacobian in
  // (x, p1, kappa) at the start (central differences; the choice only needs to be regular).
  const std::array<std::array<int, 4>, 6> pairs = {{{0, 0, 1, 1}, {0, 0, 0, 1}, {0, 0, 1, 0},
                                                     {0, 1, 1, 0}, {0, 1, 1, 1}, {1, 0, 1, 1}}};
  double best = -1;
  std::array<int, 4> chosen = entries_;
  for (const auto& e : pairs) {
    entries_ = e;  // residual() reads the pair under trial
    Eigen::MatrixXd Jx(n + 2, n + 2);
    Eigen::VectorXd Rp, Rm, X = start_;
    for (Eigen::Index j = 0; j < n + 2; ++j) {
      const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(X[j]));
      X[j] = start_[j] + h;
      residual(X, p2, Rp);
      X[j] = start_[j] - h;
      residual(X, p2, Rm);
      X[j] = start_[j];
      Jx.col(j) = (Rp - Rm) / (2 * h);
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jx);
    const double s = svd.singularValues()(n + 1) / svd.singularValues()(0);  // inverse condition number
    if (s > best) {
      best = s;
      chosen = e;
    }
  }
  entries_ = chosen;
}

Eigen::Matrix2d HopfCurveProblem::G(const Eigen::VectorXd& x, double p1, double kappa, double p2) const {
  const Eigen::Index n = base_.dimension();
  Eigen::MatrixXd J;
  base_.jacobian(x, p1, p2, J);
  const Eigen::MatrixXd A = J * J + kappa * Eigen::MatrixXd::Identity(n, n);
  return detail::bordered_g(A, B_, C_);
}

void HopfCurveProblem::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  const Eigen::Index n = base_.dimension();
  const Eigen::VectorXd x = X.head(n);
  Eigen::VectorXd F(n);
  base_.residual(x, X[n], p2, F);
  const Eigen::Matrix2d g = G(x, X[n], X[n + 1], p2);
  R.resize(n + 2);
  R.head(n) = F;
  R[n] = g(entries_[0], entries_[1]);
  R[n + 1] = g(entries_[2], entries_[3]);
}

Eigen::VectorXcd HopfCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  const Eigen::Index n = base_.dimension();
  return base_.spectrum(X.head(n), X[n], p2);
}

double HopfCurveProblem::omega(const Eigen::VectorXd& X) const {
  const double kappa = X[base_.dimension() + 1];
  return kappa > 0 ? std::sqrt(kappa) : 0.0;
}

}  // namespace rbcstab
