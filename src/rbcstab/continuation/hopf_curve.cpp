#include "rbcstab/continuation/hopf_curve.hpp"

#include <cmath>

#include "rbcstab/continuation/dense.hpp"

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

  // Two of the four entries of G, chosen at the start: the pair that, under the rows
  // [dF/dx, dF/dp1, 0], gives the best-conditioned Jacobian in (x, p1, kappa).
  Eigen::MatrixXd Jx = Eigen::MatrixXd::Zero(n + 2, n + 2);
  Eigen::VectorXd Fp;
  base.parameter_derivative(hb.x, hb.p, p2, Fp);
  Jx.topLeftCorner(n, n) = J;
  Jx.col(n).head(n) = Fp;
  entries_ = detail::best_conditioned_entries(Jx, detail::g_entry_derivatives(start_, [&](const Eigen::VectorXd& Z) {
                                                return G(Z.head(n), Z[n], Z[n + 1], p2);
                                              }));
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
  detail::rank_two_residual(F, G(x, X[n], X[n + 1], p2), entries_, R);
}

Eigen::VectorXcd HopfCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  const Eigen::Index n = base_.dimension();
  return base_.spectrum(X.head(n), X[n], p2);
}

CertifiedSpectrum HopfCurveProblem::certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const {
  const Eigen::Index n = base_.dimension();
  return base_.certified_spectrum(X.head(n), X[n], p2, refine);
}

double HopfCurveProblem::omega(const Eigen::VectorXd& X) const {
  const double kappa = X[base_.dimension() + 1];
  return kappa > 0 ? std::sqrt(kappa) : 0.0;
}

}  // namespace rbcstab
