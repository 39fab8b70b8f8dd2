#include "rbcstab/continuation/problem.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {
// Central-difference step: cube root of eps balances truncation (h^2) against rounding (eps/h).
double fd_step(double v) { return std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(v)); }
}  // namespace

void ContinuationProblem::jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const {
  const Eigen::Index n = dimension();
  J.resize(n, n);
  Eigen::VectorXd xp = x, xm = x, Fp(n), Fm(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h = fd_step(x[j]);
    xp[j] = x[j] + h;
    xm[j] = x[j] - h;
    residual(xp, p, Fp);
    residual(xm, p, Fm);
    J.col(j) = (Fp - Fm) / (xp[j] - xm[j]);
    xp[j] = xm[j] = x[j];
  }
}

void ContinuationProblem::parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const {
  const Eigen::Index n = dimension();
  const double h = fd_step(p);
  Eigen::VectorXd Fm(n), F0(n), F2(n);
  Fp.resize(n);
  residual(x, p + h, Fp);
  try {
    residual(x, p - h, Fm);
  } catch (const InvalidArgument&) {
    // p sits on the edge of the problem's domain (e.g. lambda = 0): second-order one-sided difference.
    residual(x, p, F0);
    residual(x, p + 2 * h, F2);
    Fp = (4 * Fp - 3 * F0 - F2) / (2 * h);
    return;
  }
  Fp = (Fp - Fm) / (2 * h);
}

Eigen::VectorXcd ContinuationProblem::spectrum(const Eigen::VectorXd& x, double p) const {
  Eigen::MatrixXd J;
  jacobian(x, p, J);
  Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  return es.eigenvalues();
}

int count_unstable(const Eigen::VectorXcd& spectrum, StabilityKind kind, double tol) {
  int n = 0;
  for (Eigen::Index i = 0; i < spectrum.size(); ++i) {
    const bool unstable = kind == StabilityKind::eigenvalues ? spectrum[i].real() > tol : std::abs(spectrum[i]) > 1 + tol;
    n += unstable ? 1 : 0;
  }
  return n;
}

}  // namespace rbcstab
