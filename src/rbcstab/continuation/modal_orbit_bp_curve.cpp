#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"

#include <cmath>
#include <limits>

#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/quadrature.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

using detail::fd_step;

}  // namespace

ModalOrbitBranchPointCurve::ModalOrbitBranchPointCurve(const Scene& scene, ContinuationParameter p1,
                                                       ContinuationParameter p2, int l, const OrbitOptions& options)
    : scene_(scene),
      p1_(p1),
      p2_(p2),
      l_(l),
      options_(options),
      system_(scene, p1, p2),  // require_independent(p1, p2, "p2")
      base_(system_, options),
      n_(base_.dimension()) {
  require(l >= 3 && l <= scene.L, "l", l, "in [3, L = " + std::to_string(scene.L) + "]");
  if (p1 == ContinuationParameter::beta || p2 == ContinuationParameter::beta)
    throw InvalidArgument("beta",
                          "the ellipsoidal-orbit BP curve needs a fixed in-plane rest shape: beta cannot be "
                          "a free parameter (a tilted rest shape forces v~ away from 0)");
  if (!has_untilted_rest_shape(scene))
    throw InvalidArgument("beta", "beta = " + std::to_string(scene.beta) +
                                      ": the rest shape's m = 1 content forces v~ (no ellipsoidal orbit with v~ = 0); "
                                      "allowed: beta in {0, pi/2, pi}, or Delta0 = 0, or C = inf");
}

bool ModalOrbitBranchPointCurve::has_untilted_rest_shape(const Scene& scene) {
  const Parameters& q = scene.parameters;
  return std::abs(std::sin(2 * scene.beta)) < 1e-12 || q.Delta0 == 0 || !std::isfinite(q.C);
}

Parameters ModalOrbitBranchPointCurve::parameters(double p1, double p2) const {
  return with_parameter(with_parameter(scene_, p2_, p2), p1_, p1).parameters;
}

double ModalOrbitBranchPointCurve::segment_integral(const ReducedModel& m, const Eigen::Vector3d& x, int j) const {
  const int N = options_.segments;
  const double t0 = kTwoPi * j / N, t1 = kTwoPi * (j + 1) / N;
  const WithQuadratures sq(m, tension_integral(m));  // integrated with rk8pd only
  const double y0[4] = {x[0], x[1], x[2], 0.0};
  const double grid[1] = {t1};
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = options_.rtol;
  io.atol = options_.atol;
  const IntegrationResult r = integrate(sq, y0, t0, grid, io, {});
  ++quadratures_;
  if (r.status != IntegrationStatus::success) return std::numeric_limits<double>::quiet_NaN();
  return r.y[3];
}

double ModalOrbitBranchPointCurve::sigma_bar(const Eigen::VectorXd& X, double p1, double p2) const {
  const ReducedModel& m = system_.at(p2).model(p1);
  double sum = 0;
  for (int j = 0; j < options_.segments; ++j) sum += segment_integral(m, X.segment<3>(3 * j), j);
  return sum / kTwoPi;
}

void ModalOrbitBranchPointCurve::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  const double p1 = X[n_];
  Eigen::VectorXd F;
  base_.residual(X.head(n_), p1, p2, F);
  R.resize(n_ + 1);
  R.head(n_) = F;
  // sigma_bar - sigma_l^c = Upsilon_l(sigma_bar) / |dUpsilon_l/dsigma| (Upsilon_l affine in sigma).
  R[n_] = sigma_bar(X.head(n_), p1, p2) - sigma_c(l_, parameters(p1, p2).alpha());
}

void ModalOrbitBranchPointCurve::jacobian(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const {
  const double p1 = X[n_];
  J.setZero(n_ + 1, n_ + 1);
  Eigen::MatrixXd Jx;
  base_.jacobian(X.head(n_), p1, p2, Jx);
  Eigen::VectorXd Fp;
  base_.parameter_derivative(X.head(n_), p1, p2, Fp);
  J.topLeftCorner(n_, n_) = Jx;
  J.col(n_).head(n_) = Fp;
  // Row of g: x_j only moves segment j's integral; p1 moves every segment and sigma_l^c(alpha).
  const ReducedModel& m = system_.at(p2).model(p1);
  for (Eigen::Index i = 0; i < n_; ++i) {
    const int j = static_cast<int>(i / 3);
    Eigen::Vector3d xp = X.segment<3>(3 * j), xm = xp;
    const double h = fd_step(xp[i % 3]);
    xp[i % 3] += h;
    xm[i % 3] -= h;
    J(n_, i) = (segment_integral(m, xp, j) - segment_integral(m, xm, j)) / (2 * h * kTwoPi);
  }
  const double h = fd_step(p1);
  Eigen::VectorXd Rp, Rm, Xp = X, Xm = X;
  Xp[n_] += h;
  Xm[n_] -= h;
  const auto g = [&](const Eigen::VectorXd& Y) {
    return sigma_bar(Y.head(n_), Y[n_], p2) - sigma_c(l_, parameters(Y[n_], p2).alpha());
  };
  J(n_, n_) = (g(Xp) - g(Xm)) / (2 * h);
}

Eigen::VectorXcd ModalOrbitBranchPointCurve::spectrum(const Eigen::VectorXd& X, double p2) const {
  const double p1 = X[n_];
  const Eigen::VectorXcd red = base_.multipliers(X.head(n_), p1, p2);
  const double sb = sigma_bar(X.head(n_), p1, p2);
  const Parameters q = parameters(p1, p2);
  const int L = scene_.L;
  Eigen::VectorXcd out(red.size() + 2 + (L - 2));
  out.head(red.size()) = red;
  Eigen::Index k = red.size();
  const double rho2 = std::exp(kTwoPi * Upsilon_l(q, 2, sb));  // the v~ plane (2 equal real multipliers)
  out[k++] = rho2;
  out[k++] = rho2;
  for (int l = 3; l <= L; ++l) out[k++] = std::exp(kTwoPi * Upsilon_l(q, l, sb));
  return out;
}

CertifiedSpectrum ModalOrbitBranchPointCurve::certified_spectrum(const Eigen::VectorXd& X, double p2,
                                                                 bool refine) const {
  const double p1 = X[n_];
  const CertifiedSpectrum red = base_.certified_spectrum(X.head(n_), p1, p2, refine);
  CertifiedSpectrum c;
  c.values = spectrum(X, p2);
  c.errors.resize(c.values.size());
  c.errors.head(red.errors.size()) = red.errors;
  const double sb = sigma_bar(X.head(n_), p1, p2);
  const Parameters q = parameters(p1, p2);
  const double d_sigma = options_.rtol * (1 + std::abs(sb));
  for (Eigen::Index k = red.errors.size(); k < c.values.size(); ++k) {
    const int l = k < red.errors.size() + 2 ? 2 : static_cast<int>(k - red.errors.size()) + 1;  // v~ plane: l = 2
    const double slope = Upsilon_l(q, l).slope;                                                 // dUpsilon_l/dsigma
    c.errors[k] =
        kTwoPi * std::abs(c.values[k]) * (std::abs(slope) * d_sigma + 4 * std::numeric_limits<double>::epsilon());
  }
  return c;
}

Eigen::VectorXd ModalOrbitBranchPointCurve::start_from_modal(const Eigen::VectorXd& X_modal, double p1_bp) const {
  const Eigen::Index nm = 5 + (scene_.L - 2);
  const int N = options_.segments;
  if (X_modal.size() != nm * N)
    throw InvalidArgument("X_modal", "size " + std::to_string(X_modal.size()) +
                                         " must be (5 + L - 2) x segments = " + std::to_string(nm * N));
  Eigen::VectorXd X(n_ + 1);
  for (int j = 0; j < N; ++j) X.segment<3>(3 * j) = X_modal.segment<3>(nm * j);
  X[n_] = p1_bp;
  return X;
}

int ellipsoidal_orbit_critical_mode(const Parameters& q, int L, double sigma_bar) {
  require_L(L, 3, kMaxL, "a critical mode l >= 3");
  int best = 3;
  for (int l = 4; l <= L; ++l)
    if (std::abs(Upsilon_l(q, l, sigma_bar)) < std::abs(Upsilon_l(q, best, sigma_bar))) best = l;
  return best;
}

}  // namespace rbcstab
