#include "rbcstab/continuation/orbit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/continuation/detail/forced_flow.hpp"
#include "rbcstab/continuation/detail/minimal_augmentation.hpp"
#include "rbcstab/continuation/detail/rest_direction.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/phasor.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/quadrature.hpp"

namespace rbcstab {

namespace {


// Central-difference step in p: cube root of eps balances truncation against rounding.
using detail::fd_step;

using detail::ForcedFlow;
using detail::winding_angle;

IntegratorOptions integrator_options(const OrbitOptions& o) {
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = o.rtol;
  io.atol = o.atol;
  io.poll = o.poll;
  return io;
}

}  // namespace

void ForcedSystem::parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const {
  const double h = fd_step(p);
  std::vector<double> fm(fp.size());
  rhs(t, x, p + h, fp);
  rhs(t, x, p - h, fm);
  for (std::size_t i = 0; i < fp.size(); ++i) fp[i] = (fp[i] - fm[i]) / (2 * h);
}

void ForcedSystem2::parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                                         std::span<double> fp) const {
  const double h = fd_step(p1);
  std::vector<double> fm(fp.size());
  rhs(t, x, p1 + h, p2, fp);
  rhs(t, x, p1 - h, p2, fm);
  for (std::size_t i = 0; i < fp.size(); ++i) fp[i] = (fp[i] - fm[i]) / (2 * h);
}

// ---------------------------------------------------------------- reduced in-plane system

ReducedForcedSystem::ReducedForcedSystem(const Scene& scene, ContinuationParameter free) : scene_(scene), free_(free) {
  scene_.validate();
  init_ = oriented_initial_state(scene_);
}

const ReducedModel& ReducedForcedSystem::model(double p) const {
  auto it = cache_.find(p);
  if (it != cache_.end()) return it->second;
  if (cache_.size() >= 8) cache_.clear();  // no reference is held across calls (see parameter_derivative)
  const Scene at = with_parameter(scene_, free_, p);  // throws InvalidArgument outside p's domain
  // beta turns the rest shape: its direction is rebuilt per value (cached with the model).
  return cache_
      .try_emplace(p, at.parameters, free_ == ContinuationParameter::beta ? oriented_initial_state(at) : init_)
      .first->second;
}

void ReducedForcedSystem::rhs(double t, std::span<const double> x, double p, std::span<double> f) const {
  model(p).rhs(t, x, f);
}

void ReducedForcedSystem::jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const {
  StructuredJacobian sj;
  double dfdt[3];
  model(p).jacobian(t, x, sj, dfdt);
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> D;
  sj.to_dense(std::span<double>(D.data(), 9));
  J = D;
}

ReducedForcedSystem::Slopes ReducedForcedSystem::coefficient_slopes(double p) const {
  auto it = slopes_.find(p);
  if (it != slopes_.end()) return it->second;
  // d(1/Lambda)/dp and d kappa/dp by central differences of two scalar functions of the parameters
  // (constants during an integration, so their rounding does not disturb the error control).
  auto coefficients = [&](double q) {
    const Parameters pq = with_parameter(scene_, free_, q).parameters;
    return std::pair<double, double>(1 / pq.Lambda(), pq.inv_Lambda_S());
  };
  Slopes d;
  if (free_ == ContinuationParameter::beta) {
    // beta turns the rest shape only: 1/Lambda and kappa do not depend on it (and beta = 0, pi are
    // both edges of its domain, where a difference would step outside); the direction's slope is exact.
    d.kappa = coefficients(p).second;
    const detail::RestDirection r = detail::rest_direction(p, false);
    d.dz0 = r.dz0, d.dw0 = r.dw0;
    if (slopes_.size() >= 8) slopes_.clear();
    slopes_.emplace(p, d);
    return d;
  }
  const double h = fd_step(p);
  const auto c0 = coefficients(p), plus = coefficients(p + h);
  d.kappa = c0.second;
  try {
    const auto minus = coefficients(p - h);
    d.dinvL = (plus.first - minus.first) / (2 * h);
    d.dkappa = (plus.second - minus.second) / (2 * h);
  } catch (const InvalidArgument&) {
    // p on the edge of its domain (lambda = 0): second-order one-sided difference.
    const auto c2 = coefficients(p + 2 * h);
    d.dinvL = (4 * plus.first - 3 * c0.first - c2.first) / (2 * h);
    d.dkappa = (4 * plus.second - 3 * c0.second - c2.second) / (2 * h);
  }
  if (slopes_.size() >= 8) slopes_.clear();
  slopes_.emplace(p, d);
  return d;
}

void ReducedForcedSystem::parameter_derivative(double t, std::span<const double> x, double p,
                                               std::span<double> fp) const {
  // f depends on p only through 1/Lambda and kappa = 1/(Lambda S) (ReducedModel::rhs):
  //   f = mu y + (-y1, y0, 0) - (0, 1/Lambda, 0) + kappa g(t),  mu = (y1/Lambda - kappa y.g) / |y|^2,
  // with g = (Re z0(t), Im z0(t), w0) the rest shape's direction, so df/dp is exact in y and t:
  //   df/d(1/Lambda) = (y1/Q) y - e_y,  df/dkappa = g - (y.g/Q) y.
  // Central differences of f itself would put rounding noise (~eps |f| / h) into the sensitivity
  // equation and force rk8pd at rtol 1e-12 into small steps (measured: ~6x slower shooting).
  // beta enters only through the direction g (1/Lambda and kappa fixed): df/dbeta = kappa (g' - (y.g'/Q) y)
  // with g' = (Re, Im of z0'(0) e^{it}, w0') exact (detail/rest_direction.hpp); zero when kappa = 0.
  const bool beta = free_ == ContinuationParameter::beta;
  const Slopes d = coefficient_slopes(p);
  if (d.kappa == 0 && !beta) {
    // kappa = 0: the model dropped the rest shape's direction; difference f in p instead.
    ForcedSystem::parameter_derivative(t, x, p, fp);
    return;
  }
  const ReducedModel& m = model(p);
  const std::complex<double> z0 = m.z0(t);
  const double g[3] = {z0.real(), z0.imag(), m.w0()};
  double dg[3] = {0, 0, 0};
  if (beta) {
    const std::complex<double> dz0 = d.dz0 * unit_phasor(t);
    dg[0] = dz0.real(), dg[1] = dz0.imag(), dg[2] = d.dw0;
  }
  const double Q = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  const double yg = x[0] * g[0] + x[1] * g[1] + x[2] * g[2];
  const double ydg = x[0] * dg[0] + x[1] * dg[1] + x[2] * dg[2];
  for (std::size_t i = 0; i < 3; ++i) {
    const double dfdinvL = x[1] / Q * x[i] - (i == 1 ? 1.0 : 0.0);
    const double dfdkappa = g[i] - yg / Q * x[i];
    const double dfdg = d.kappa * (dg[i] - ydg / Q * x[i]);
    fp[i] = d.dinvL * dfdinvL + d.dkappa * dfdkappa + dfdg;
  }
}

Eigen::VectorXd ReducedForcedSystem::relaxed_state(double T, const std::function<void()>& poll) const {
  require(std::isfinite(T) && T > 0, "T", T, "a finite number > 0");
  const ReducedModel& m = model(start_parameter());
  const std::vector<double> y0 = m.initial_state();
  const double grid[1] = {kTwoPi * std::ceil(T / kTwoPi)};
  IntegratorOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.poll = poll;
  const IntegrationResult r = integrate(m, y0, 0.0, grid, o, {});
  return Eigen::Vector3d(r.y[0], r.y[1], r.y[2]);
}

// ---------------------------------------------------------------- options, names

void OrbitOptions::validate() const {
  require(segments >= 1 && segments <= 1000, "segments", segments, "an integer in [1, 1000]");
  require(std::isfinite(rtol) && rtol >= 1e-15 && rtol <= 1e-6, "rtol", rtol, "[1e-15, 1e-6] (Floquet multipliers need a tight tolerance)");
  require(std::isfinite(atol) && atol > 0 && atol <= 1e-6, "atol", atol, "(0, 1e-6]");
  require(samples_per_segment >= 4 && samples_per_segment <= 100000, "samples_per_segment", samples_per_segment,
          "an integer in [4, 100000]");
}

// ---------------------------------------------------------------- the shooting problem

PeriodicOrbitProblem::PeriodicOrbitProblem(const ForcedSystem& system, const OrbitOptions& options)
    : sys_(system), o_(options), n_(system.dimension()), N_(options.segments) {
  o_.validate();
  require(n_ >= 2, "dimension", static_cast<double>(n_), ">= 2 (components 0 and 1 are the winding plane)");
}

const PeriodicOrbitProblem::Shooting& PeriodicOrbitProblem::shoot(const Eigen::VectorXd& X, double p) const {
  if (cache_.valid && cache_.p == p && cache_.X.size() == X.size() && cache_.X == X) return cache_;
  cache_.valid = false;
  cache_.X = X;
  cache_.p = p;
  cache_.ok = true;
  const auto n = static_cast<std::size_t>(n_);
  const ForcedFlow aug(sys_, p, ForcedFlow::Mode::variational);
  const IntegratorOptions io = integrator_options(o_);
  cache_.phi.assign(static_cast<std::size_t>(N_), Eigen::VectorXd());
  cache_.s.assign(static_cast<std::size_t>(N_), Eigen::VectorXd());
  cache_.M.assign(static_cast<std::size_t>(N_), Eigen::MatrixXd());
  std::vector<double> y0(n + n * n + n, 0.0);
  for (int j = 0; j < N_; ++j) {
    const double t0 = kTwoPi * j / N_, t1 = kTwoPi * (j + 1) / N_;
    std::fill(y0.begin(), y0.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      y0[i] = X[static_cast<Eigen::Index>(static_cast<std::size_t>(j) * n + i)];
      y0[n + i * n + i] = 1;  // Phi(t0) = I
    }
    const double grid[1] = {t1};
    const IntegrationResult r = integrate(aug, y0, t0, grid, io, {});
    ++integrations_;
    const auto js = static_cast<std::size_t>(j);
    if (r.status != IntegrationStatus::success) {
      cache_.ok = false;
      break;
    }
    cache_.phi[js] = Eigen::Map<const Eigen::VectorXd>(r.y.data(), n_);
    cache_.M[js] = Eigen::Map<const Eigen::MatrixXd>(r.y.data() + n, n_, n_);
    cache_.s[js] = Eigen::Map<const Eigen::VectorXd>(r.y.data() + n + n * n, n_);
  }
  cache_.valid = true;
  return cache_;
}

void PeriodicOrbitProblem::residual(const Eigen::VectorXd& X, double p, Eigen::VectorXd& F) const {
  const Shooting& sh = shoot(X, p);
  F.resize(n_ * N_);
  // A failed integration (the orbit leaves the integrator's reach) is not an exception: NaN makes
  // the engine's corrector fail and shrink the step, as for any non-converging Newton.
  if (!sh.ok) {
    F.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int j = 0; j < N_; ++j) {
    const auto js = static_cast<std::size_t>(j);
    const Eigen::Index next = ((j + 1) % N_) * n_;
    F.segment(j * n_, n_) = sh.phi[js] - X.segment(next, n_);
  }
  if (sys_.conserves_norm()) F.head(n_) += (X.head(n_).squaredNorm() - 1) * sh.phi[0];
}

// The cyclic shooting Jacobian: M_j on the diagonal blocks, -I coupling x_{j+1}, and the closing block
// coupling x_0 scaled by closing_sign (-I: periodic x_N = x_0; +I: anti-periodic x_N = -x_0).
const PeriodicOrbitProblem::Shooting& PeriodicOrbitProblem::cyclic_jacobian(const Eigen::VectorXd& X, double p,
                                                                            double closing_sign,
                                                                            Eigen::MatrixXd& J) const {
  const Shooting& sh = shoot(X, p);
  const Eigen::Index m = n_ * N_;
  J.setZero(m, m);
  if (!sh.ok) {
    J.setConstant(std::numeric_limits<double>::quiet_NaN());
    return sh;
  }
  for (int j = 0; j < N_; ++j) {
    J.block(j * n_, j * n_, n_, n_) += sh.M[static_cast<std::size_t>(j)];
    const double sign = j + 1 == N_ ? closing_sign : -1.0;
    J.block(j * n_, ((j + 1) % N_) * n_, n_, n_) += sign * Eigen::MatrixXd::Identity(n_, n_);
  }
  return sh;
}

void PeriodicOrbitProblem::jacobian(const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) const {
  const Shooting& sh = cyclic_jacobian(X, p, -1.0, J);
  if (!sh.ok) return;
  if (sys_.conserves_norm()) {
    const Eigen::VectorXd x0 = X.head(n_);
    J.block(0, 0, n_, n_) += (x0.squaredNorm() - 1) * sh.M[0] + 2 * sh.phi[0] * x0.transpose();
  }
}

void PeriodicOrbitProblem::antiperiodic_jacobian(const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) const {
  cyclic_jacobian(X, p, 1.0, J);
}

void PeriodicOrbitProblem::parameter_derivative(const Eigen::VectorXd& X, double p, Eigen::VectorXd& Fp) const {
  const Shooting& sh = shoot(X, p);
  Fp.resize(n_ * N_);
  if (!sh.ok) {
    Fp.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int j = 0; j < N_; ++j) Fp.segment(j * n_, n_) = sh.s[static_cast<std::size_t>(j)];
  if (sys_.conserves_norm()) Fp.head(n_) *= X.head(n_).squaredNorm();
}

Floquet PeriodicOrbitProblem::floquet(const Eigen::VectorXd& X, double p) const {
  const Shooting& sh = shoot(X, p);
  Floquet fl;
  if (!sh.ok) {
    fl.monodromy.setConstant(n_, n_, std::numeric_limits<double>::quiet_NaN());
    fl.multipliers.setConstant(sys_.conserves_norm() ? n_ - 1 : n_, std::numeric_limits<double>::quiet_NaN());
    return fl;
  }
  fl.monodromy = sh.M[0];
  for (int j = 1; j < N_; ++j) fl.monodromy = sh.M[static_cast<std::size_t>(j)] * fl.monodromy;
  if (!sys_.conserves_norm()) {
    fl.multipliers = Eigen::EigenSolver<Eigen::MatrixXd>(fl.monodromy, false).eigenvalues();
    return fl;
  }
  // x0^T M = x0^T (d/dt (x^T Phi) = (f + J^T x)^T Phi = 0 because x.f = 0 identically), so M maps
  // the tangent plane x0^perp into itself: its restriction carries the nontrivial multipliers.
  const Eigen::VectorXd x0 = X.head(n_);
  fl.multipliers = detail::tangent_spectrum(fl.monodromy, x0);
  fl.trivial = x0.dot(fl.monodromy * x0) / x0.squaredNorm();
  return fl;
}

Eigen::VectorXcd PeriodicOrbitProblem::spectrum(const Eigen::VectorXd& X, double p) const {
  return floquet(X, p).multipliers;
}

CertifiedSpectrum PeriodicOrbitProblem::certified_spectrum(const Eigen::VectorXd& X, double p, bool refine) const {
  const Floquet fl = floquet(X, p);
  const double eta = std::max(fl.trivial ? std::abs(*fl.trivial - 1) : 0.0, o_.rtol);
  CertifiedSpectrum c = sys_.conserves_norm() ? detail::certified_tangent_spectrum(fl.monodromy, X.head(n_), eta)
                                              : certified_eigenvalues(fl.monodromy, eta);
  c.values = fl.multipliers;  // the same numbers (one eigensolver); an integration failure: NaN
  if (!refine || !c.values.allFinite()) return c;
  OrbitOptions fine = o_;
  fine.segments = std::min(2 * N_, 1000);
  fine.rtol = std::max(o_.rtol / 100, 1e-15);
  fine.atol = o_.atol / 100;
  const PeriodicOrbitProblem refined(sys_, fine);
  const Eigen::VectorXcd mu = refined.spectrum(refined.shooting_guess(X.head(n_), p), p);
  integrations_ += refined.integrations();
  for (Eigen::Index i = 0; i < c.values.size(); ++i) {
    double d = std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < mu.size(); ++k) d = std::min(d, std::abs(c.values[i] - mu[k]));
    c.errors[i] = std::max(c.errors[i], d);
  }
  return c;
}

Eigen::VectorXd PeriodicOrbitProblem::shooting_guess(const Eigen::VectorXd& x0, double p) const {
  require(x0.size() == n_, "x0", static_cast<double>(x0.size()), "a state of the system's dimension");
  Eigen::VectorXd X(n_ * N_);
  X.head(n_) = x0;
  if (N_ == 1) return X;
  std::vector<double> grid;
  for (int j = 1; j < N_; ++j) grid.push_back(kTwoPi * j / N_);
  const ForcedFlow plain(sys_, p, ForcedFlow::Mode::plain);
  int k = 1;
  integrate(plain, std::span<const double>(x0.data(), static_cast<std::size_t>(n_)), 0.0, grid,
            integrator_options(o_), [&](double, std::span<const double> y) {
              X.segment(k * n_, n_) = Eigen::Map<const Eigen::VectorXd>(y.data(), n_);
              ++k;
            });
  ++integrations_;
  return X;
}

OrbitRelaxation PeriodicOrbitProblem::relax(const Eigen::VectorXd& x0, double p, double tol, int max_periods,
                                            int chunk) const {
  require(x0.size() == n_, "x0", static_cast<double>(x0.size()), "a state of the system's dimension");
  require(std::isfinite(tol) && tol > 0, "tol", tol, "a finite number > 0");
  require(max_periods >= 1, "max_periods", max_periods, "an integer >= 1");
  require(chunk >= 1, "chunk", chunk, "an integer >= 1");
  OrbitRelaxation r;
  r.x = x0;
  const ForcedFlow plain(sys_, p, ForcedFlow::Mode::plain);
  const IntegratorOptions io = integrator_options(o_);
  Eigen::VectorXd prev = x0;
  while (r.periods < max_periods && !r.converged) {
    // The system is 2 pi-periodic in t: every chunk starts again at t = 0.
    const int k = std::min(chunk, max_periods - r.periods);
    std::vector<double> grid;
    for (int j = 1; j <= k; ++j) grid.push_back(kTwoPi * j);
    int done = 0;
    const IntegrationResult res =
        integrate(plain, std::span<const double>(r.x.data(), static_cast<std::size_t>(n_)), 0.0, grid, io,
                  [&](double, std::span<const double> y) {
                    if (r.converged) return;  // the rest of the chunk only relaxes further
                    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(y.data(), n_);
                    r.defect = (x - prev).norm();
                    r.converged = r.defect < tol;
                    prev = x;
                    ++done;
                  });
    ++integrations_;
    r.periods += done;
    r.x = prev;
    if (res.status != IntegrationStatus::success) {
      r.converged = false;
      r.failure = res.reason;
      break;
    }
  }
  return r;
}

OrbitSummary PeriodicOrbitProblem::summary(const Eigen::VectorXd& X, double p) const {
  const auto n = static_cast<std::size_t>(n_);
  const int S = o_.samples_per_segment;
  const double h = kTwoPi / (N_ * S);
  const ForcedFlow plain(sys_, p, ForcedFlow::Mode::plain);
  const WithQuadratures with_angle(plain, winding_angle());
  const IntegratorOptions io = integrator_options(o_);
  const bool norm = sys_.conserves_norm();
  auto r_of = [&](const Eigen::VectorXd& x) { return std::hypot(x[0], x[1]) / (norm ? x.norm() : 1.0); };

  // Uniform samples t_k = k h, k = 0 .. N S - 1, with the continuous angle of z.
  std::vector<Eigen::VectorXd> xs;
  std::vector<double> theta;
  xs.reserve(static_cast<std::size_t>(N_ * S));
  double th = std::atan2(X[1], X[0]);
  const double theta0 = th;
  for (int j = 0; j < N_; ++j) {
    const Eigen::VectorXd xj = X.segment(j * n_, n_);
    // Continue the angle across segments (x_j equals the previous segment's end to Newton's tolerance).
    if (j > 0) th += std::remainder(std::atan2(xj[1], xj[0]) - th, kTwoPi);
    std::vector<double> y0(xj.data(), xj.data() + n_);
    y0.push_back(th);
    std::vector<double> grid;
    for (int k = 1; k <= S; ++k) grid.push_back(kTwoPi * j / N_ + k * h);
    xs.push_back(xj);
    theta.push_back(th);
    int k = 1;
    const IntegrationResult r = integrate(with_angle, y0, kTwoPi * j / N_, grid, io, [&](double, std::span<const double> y) {
      if (k < S) {
        xs.emplace_back(Eigen::Map<const Eigen::VectorXd>(y.data(), n_));
        theta.push_back(y[n]);
      }
      ++k;
    });
    ++integrations_;
    if (r.status != IntegrationStatus::success) {
      // z passed (numerically) through 0: the angle is undefined there. Fill the segment from the
      // plain flow and read the winding from sample increments below.
      xs.resize(static_cast<std::size_t>(j * S + 1));
      theta.resize(static_cast<std::size_t>(j * S + 1));
      k = 1;
      integrate(plain, std::span<const double>(xj.data(), n), kTwoPi * j / N_, grid, io, [&](double, std::span<const double> y) {
        if (k < S) {
          xs.emplace_back(Eigen::Map<const Eigen::VectorXd>(y.data(), n_));
          theta.push_back(theta.back() + std::remainder(std::atan2(y[1], y[0]) - theta.back(), kTwoPi));
        }
        ++k;
      });
      ++integrations_;
      th = theta.back() + std::remainder(std::atan2(X[((j + 1) % N_) * n_ + 1], X[((j + 1) % N_) * n_]) - theta.back(), kTwoPi);
    } else {
      th = r.y[n];
    }
  }
  OrbitSummary o;
  const double total = th - theta0;  // the angle gained over one period (state back at x_0)
  o.winding = static_cast<int>(std::lround(total / kTwoPi));
  o.kind = o.winding == 0 ? OrbitKind::swinging : OrbitKind::tumbling;
  o.r0 = r_of(X.head(n_));
  o.Psi0 = -theta0;
  if (o.Psi0 <= -M_PI) o.Psi0 += kTwoPi;
  o.r_min = o.r_max = o.r0;
  o.Psi_min = o.Psi_max = o.Psi0;
  o.mean = Eigen::VectorXd::Zero(n_);
  std::size_t kmin = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double r = r_of(xs[k]);
    if (r < o.r_min) o.r_min = r, kmin = k, o.t_r_min = static_cast<double>(k) * h;
    o.r_max = std::max(o.r_max, r);
    const double Psi = o.Psi0 - (theta[k] - theta0);
    o.Psi_min = std::min(o.Psi_min, Psi);
    o.Psi_max = std::max(o.Psi_max, Psi);
    o.mean += xs[k];
  }
  o.mean /= static_cast<double>(xs.size());
  // The period's end (the state is back at x_0): a tumbling orbit's Psi range spans 2 pi |winding|.
  o.Psi_min = std::min(o.Psi_min, o.Psi0 - total);
  o.Psi_max = std::max(o.Psi_max, o.Psi0 - total);

  // Refine r_min: the zero of g(t) = d/dt |z|^2 / 2 = x0 f0 + x1 f1 between the neighbouring samples
  // (Illinois secant; each trial integrates from the left sample). A smooth function of p, so the
  // transition function below is continuous and its zero can be located as a UZ event.
  const std::size_t K = xs.size();
  const std::size_t kl = (kmin + K - 1) % K, kr = (kmin + 1) % K;
  const double ta = static_cast<double>(kmin) * h - h, tb = static_cast<double>(kmin) * h + h;
  const Eigen::VectorXd xa = xs[kl];
  auto state_at = [&](double t, Eigen::VectorXd& x) {
    x = xa;
    if (t == ta) return true;
    const double grid[1] = {t};
    const IntegrationResult r = integrate(plain, std::span<const double>(xa.data(), n), ta, grid, io, {});
    ++integrations_;
    if (r.status != IntegrationStatus::success) return false;
    x = Eigen::Map<const Eigen::VectorXd>(r.y.data(), n_);
    return true;
  };
  auto g_at = [&](double t, const Eigen::VectorXd& x) {
    Eigen::VectorXd f(n_);
    sys_.rhs(t, std::span<const double>(x.data(), n), p, std::span<double>(f.data(), n));
    return x[0] * f[0] + x[1] * f[1];
  };
  double a = ta, b = tb;
  double ga = g_at(ta, xa), gb = g_at(tb, xs[kr]);
  if (ga < 0 && gb > 0) {
    int side = 0;
    Eigen::VectorXd x;
    for (int it = 0; it < 60 && b - a > 1e-10; ++it) {
      double t = a - ga * (b - a) / (gb - ga);
      if (!(t > a && t < b) || it % 4 == 3) t = 0.5 * (a + b);
      if (!state_at(t, x)) break;
      if (r_of(x) < o.r_min) o.r_min = r_of(x), o.t_r_min = std::fmod(t + kTwoPi, kTwoPi);
      const double g = g_at(t, x);
      if (g == 0) break;
      if (g < 0) {
        a = t, ga = g;
        if (side == -1) gb *= 0.5;
        side = -1;
      } else {
        b = t, gb = g;
        if (side == 1) ga *= 0.5;
        side = 1;
      }
    }
  }
  o.transition_function = o.winding == 0 ? o.r_min : -o.r_min;
  return o;
}

OrbitPoint PeriodicOrbitProblem::point_at(const Eigen::VectorXd& X, double p, double t) const {
  const auto n = static_cast<std::size_t>(n_);
  double tw = std::fmod(t, kTwoPi);
  if (tw < 0) tw += kTwoPi;
  OrbitPoint o;
  o.segment = std::min(N_ - 1, static_cast<int>(std::floor(tw * N_ / kTwoPi)));
  const double tj = kTwoPi * o.segment / N_;
  std::vector<double> y(n + n * n + n, 0.0);  // (x, Phi = I, s = 0) at t_j
  for (std::size_t i = 0; i < n; ++i) {
    y[i] = X[static_cast<Eigen::Index>(static_cast<std::size_t>(o.segment) * n + i)];
    y[n + i * n + i] = 1;
  }
  if (tw > tj) {
    const double grid[1] = {tw};
    const IntegrationResult r =
        integrate(ForcedFlow(sys_, p, ForcedFlow::Mode::variational), y, tj, grid, integrator_options(o_), {});
    ++integrations_;
    if (r.status != IntegrationStatus::success) return o;
    y = r.y;
  }
  o.x = Eigen::Map<const Eigen::VectorXd>(y.data(), n_);
  o.dx = Eigen::Map<const Eigen::MatrixXd>(y.data() + n, n_, n_);
  o.dp = Eigen::Map<const Eigen::VectorXd>(y.data() + n + n * n, n_);
  o.dt.resize(n_);
  sys_.rhs(tw, std::span<const double>(o.x.data(), n), p, std::span<double>(o.dt.data(), n));
  o.ok = true;
  return o;
}

UserEvent PeriodicOrbitProblem::transition_event(const std::string& name) const {
  return UserEvent{name, [this](const Eigen::VectorXd& X, double p) { return summary(X, p).transition_function; }};
}

// ---------------------------------------------------------------- two parameters

void OrbitTwoParameterProblem::at(double p2) const {
  if (slice_.p2() != p2) {
    slice_.set_p2(p2);
    orbit_.clear_cache();
  }
}

void OrbitTwoParameterProblem::residual(const Eigen::VectorXd& X, double p1, double p2, Eigen::VectorXd& F) const {
  at(p2);
  orbit_.residual(X, p1, F);
}

void OrbitTwoParameterProblem::jacobian(const Eigen::VectorXd& X, double p1, double p2, Eigen::MatrixXd& J) const {
  at(p2);
  orbit_.jacobian(X, p1, J);
}

void OrbitTwoParameterProblem::parameter_derivative(const Eigen::VectorXd& X, double p1, double p2,
                                                    Eigen::VectorXd& Fp) const {
  at(p2);
  orbit_.parameter_derivative(X, p1, Fp);
}

void OrbitTwoParameterProblem::antiperiodic_jacobian(const Eigen::VectorXd& X, double p1, double p2,
                                                     Eigen::MatrixXd& J) const {
  at(p2);
  orbit_.antiperiodic_jacobian(X, p1, J);
}

Eigen::VectorXcd OrbitTwoParameterProblem::multipliers(const Eigen::VectorXd& X, double p1, double p2) const {
  at(p2);
  return orbit_.spectrum(X, p1);
}

CertifiedSpectrum OrbitTwoParameterProblem::certified_spectrum(const Eigen::VectorXd& X, double p1, double p2,
                                                               bool refine) const {
  at(p2);
  return orbit_.certified_spectrum(X, p1, refine);
}

OrbitSummary OrbitTwoParameterProblem::summary(const Eigen::VectorXd& X, double p1, double p2) const {
  at(p2);
  return orbit_.summary(X, p1);
}

OrbitPoint OrbitTwoParameterProblem::point_at(const Eigen::VectorXd& X, double p1, double p2, double t) const {
  at(p2);
  return orbit_.point_at(X, p1, t);
}

PeriodDoublingCurveProblem::PeriodDoublingCurveProblem(const OrbitTwoParameterProblem& base, const SpecialPoint& pd,
                                                       double p2)
    : SingularityCurveProblem(base), orbit_base_(base) {
  if (pd.type != SpecialPointType::PD || pd.status != LocationStatus::located)
    throw InvalidArgument("pd", "a PD curve starts from a located PD point (got " + to_string(pd.type) + ", " +
                                    to_string(pd.status) + ")");
  start_at(pd, p2);
}

Eigen::VectorXcd PeriodDoublingCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  const Eigen::Index n = orbit_base_.dimension();
  return orbit_base_.multipliers(X.head(n), X[n], p2);
}

}  // namespace rbcstab
