#include "rbcstab/continuation/problem.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "rbcstab/continuation/dense.hpp"
#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {
using detail::fd_step;
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

CertifiedSpectrum certified_eigenvalues(const Eigen::MatrixXd& A, double eta) {
  const Eigen::Index n = A.rows();
  CertifiedSpectrum c;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.values.setConstant(n, {nan, nan});
  c.errors.setConstant(n, nan);
  if (n == 0 || !A.allFinite()) return c;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A, true);
  if (es.info() != Eigen::Success) return c;
  c.values = es.eigenvalues();
  c.errors.setConstant(n, std::numeric_limits<double>::infinity());
  const Eigen::MatrixXcd V = es.eigenvectors();
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(V);
  if (!lu.isInvertible()) return c;         // defective to working precision: no first-order bound
  const Eigen::MatrixXcd U = lu.inverse();  // rows: left eigenvectors with u_i^H v_i = 1
  const Eigen::MatrixXcd Ac = A.cast<std::complex<double>>();
  const double matrix_error = eta * A.norm();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double v = V.col(i).norm();
    const double residual = (Ac * V.col(i) - c.values[i] * V.col(i)).norm() / v;
    const double kappa = U.row(i).norm() * v;
    c.errors[i] = std::isfinite(kappa) ? kappa * (residual + matrix_error) : std::numeric_limits<double>::infinity();
  }
  return c;
}

double assembly_accuracy(Eigen::Index n) {
  return 8.0 * static_cast<double>(std::max<Eigen::Index>(n, 1)) * std::numeric_limits<double>::epsilon();
}

CertifiedSpectrum bound_by_eigenvalues(const Eigen::VectorXcd& values, const Eigen::MatrixXd& J, double eta) {
  CertifiedSpectrum c;
  c.values = values;
  c.errors.setConstant(c.values.size(), std::numeric_limits<double>::quiet_NaN());
  const CertifiedSpectrum j = certified_eigenvalues(J, eta);
  for (Eigen::Index i = 0; i < c.values.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < j.values.size(); ++k) {
      const double d = std::abs(c.values[i] - j.values[k]);
      if (d <= j.errors[k] && d < nearest) nearest = d, c.errors[i] = j.errors[k];
    }
  }
  return c;
}

CertifiedSpectrum ContinuationProblem::certified_spectrum(const Eigen::VectorXd& x, double p, bool) const {
  Eigen::MatrixXd J;
  jacobian(x, p, J);
  return bound_by_eigenvalues(spectrum(x, p), J, kFiniteDifferenceAccuracy);
}

int count_unstable(const Eigen::VectorXcd& spectrum, StabilityKind kind, double tol) {
  int n = 0;
  for (Eigen::Index i = 0; i < spectrum.size(); ++i) {
    const bool unstable =
        kind == StabilityKind::eigenvalues ? spectrum[i].real() > tol : std::abs(spectrum[i]) > 1 + tol;
    n += unstable ? 1 : 0;
  }
  return n;
}

}  // namespace rbcstab
