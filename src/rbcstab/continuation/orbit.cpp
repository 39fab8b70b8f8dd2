// Periodic orbits by multiple shooting: the shooting problem, its Floquet data, the relaxation to an
// orbit, an orbit's summary over one period and its state at any time.
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/tunable_options.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/detail/forced_flow.hpp"
#include "rbcstab/continuation/detail/shooting.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/quadrature.hpp"

namespace rbcstab {

namespace detail {

IntegratorOptions orbit_integrator_options(const OrbitOptions& o) {
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = o.rtol;
  io.atol = o.atol;
  io.poll = o.poll;
  return io;
}

std::size_t shoot_segments(const ForcedSystem& sys, const Eigen::VectorXd& X, double p, int N, double length,
                           const IntegratorOptions& io, ShootingFlows& out) {
  const Eigen::Index n_ = sys.dimension();
  const auto n = static_cast<std::size_t>(n_);
  const ForcedFlow aug(sys, p, ForcedFlow::Mode::variational);
  out.ok = true;
  out.phi.assign(static_cast<std::size_t>(N), Eigen::VectorXd());
  out.s.assign(static_cast<std::size_t>(N), Eigen::VectorXd());
  out.M.assign(static_cast<std::size_t>(N), Eigen::MatrixXd());
  std::vector<double> y0(n + n * n + n, 0.0);
  std::size_t count = 0;
  for (int j = 0; j < N; ++j) {
    const double t0 = length * j / N, t1 = length * (j + 1) / N;
    std::fill(y0.begin(), y0.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      y0[i] = X[static_cast<Eigen::Index>(static_cast<std::size_t>(j) * n + i)];
      y0[n + i * n + i] = 1;  // Phi(t0) = I
    }
    const double grid[1] = {t1};
    const IntegrationResult r = integrate(aug, y0, t0, grid, io, {});
    ++count;
    const auto js = static_cast<std::size_t>(j);
    if (r.status != IntegrationStatus::success) {
      out.ok = false;
      break;
    }
    out.phi[js] = Eigen::Map<const Eigen::VectorXd>(r.y.data(), n_);
    out.M[js] = Eigen::Map<const Eigen::MatrixXd>(r.y.data() + n, n_, n_);
    out.s[js] = Eigen::Map<const Eigen::VectorXd>(r.y.data() + n + n * n, n_);
  }
  return count;
}

Eigen::MatrixXd monodromy_product(const ShootingFlows& sh) {
  Eigen::MatrixXd M = sh.M[0];
  for (std::size_t j = 1; j < sh.M.size(); ++j) M = sh.M[j] * M;
  return M;
}

Eigen::VectorXd segment_variation(const ShootingFlows& sh, const Eigen::VectorXd& v0) {
  const Eigen::Index n = v0.size(), N = static_cast<Eigen::Index>(sh.M.size());
  Eigen::VectorXd V = Eigen::VectorXd::Constant(n * N, std::numeric_limits<double>::quiet_NaN());
  if (!sh.ok) return V;
  V.head(n) = v0;
  for (Eigen::Index j = 1; j < N; ++j)
    V.segment(j * n, n) = sh.M[static_cast<std::size_t>(j - 1)] * V.segment((j - 1) * n, n);
  return V;
}

Eigen::VectorXd sensitivity_product(const ShootingFlows& sh) {
  Eigen::VectorXd s = sh.s[0];
  for (std::size_t j = 1; j < sh.s.size(); ++j) s = sh.M[j] * s + sh.s[j];
  return s;
}

}  // namespace detail

namespace {

using detail::ForcedFlow;
using detail::winding_angle;

IntegratorOptions integrator_options(const OrbitOptions& o) { return detail::orbit_integrator_options(o); }

}  // namespace

// ---------------------------------------------------------------- options, names

void OrbitOptions::validate() const {
  for (const TunableOption& o : tunable_options())  // each field's domain (tunable_options.hpp)
    if (o.orbit) o.check(o.get(ContinuationOptions{}, *this));
}

// ---------------------------------------------------------------- the shooting problem

PeriodicOrbitProblem::PeriodicOrbitProblem(const ForcedSystem& system, const OrbitOptions& options, int periods)
    : sys_(system),
      o_(options),
      n_(system.dimension()),
      N_(options.segments),
      periods_(periods),
      length_(kTwoPi * periods) {
  o_.validate();
  require(periods >= 1 && periods <= 64, "periods", periods, "an integer in [1, 64]");
  require(n_ >= 2, "dimension", static_cast<double>(n_), ">= 2 (components 0 and 1 are the winding plane)");
}

const PeriodicOrbitProblem::Shooting& PeriodicOrbitProblem::shoot(const Eigen::VectorXd& X, double p) const {
  if (cache_.valid && cache_.p == p && cache_.X.size() == X.size() && cache_.X == X) return cache_;
  cache_.valid = false;
  cache_.X = X;
  cache_.p = p;
  integrations_ += detail::shoot_segments(sys_, X, p, N_, length_, integrator_options(o_), cache_);
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
  fl.monodromy = detail::monodromy_product(sh);
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

Eigen::VectorXd PeriodicOrbitProblem::variation(const Eigen::VectorXd& X, double p, const Eigen::VectorXd& v0) const {
  require(v0.size() == n_, "v0", static_cast<double>(v0.size()), "a vector of the system's dimension");
  return detail::segment_variation(shoot(X, p), v0);
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
  const PeriodicOrbitProblem refined(sys_, fine, periods_);
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
  for (int j = 1; j < N_; ++j) grid.push_back(length_ * j / N_);
  const ForcedFlow plain(sys_, p, ForcedFlow::Mode::plain);
  int k = 1;
  integrate(plain, std::span<const double>(x0.data(), static_cast<std::size_t>(n_)), 0.0, grid, integrator_options(o_),
            [&](double, std::span<const double> y) {
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
    for (int j = 1; j <= k; ++j) grid.push_back(length_ * j);
    int done = 0;
    const IntegrationResult res = integrate(plain, std::span<const double>(r.x.data(), static_cast<std::size_t>(n_)),
                                            0.0, grid, io, [&](double, std::span<const double> y) {
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

OrbitSummary PeriodicOrbitProblem::summary(const Eigen::VectorXd& X, double p, bool extrema) const {
  const auto n = static_cast<std::size_t>(n_);
  const int S = o_.samples_per_segment;
  const double h = length_ / (N_ * S);
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
    for (int k = 1; k <= S; ++k) grid.push_back(length_ * j / N_ + k * h);
    xs.push_back(xj);
    theta.push_back(th);
    int k = 1;
    const IntegrationResult r =
        integrate(with_angle, y0, length_ * j / N_, grid, io, [&](double, std::span<const double> y) {
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
      integrate(plain, std::span<const double>(xj.data(), n), length_ * j / N_, grid, io,
                [&](double, std::span<const double> y) {
                  if (k < S) {
                    xs.emplace_back(Eigen::Map<const Eigen::VectorXd>(y.data(), n_));
                    theta.push_back(theta.back() + std::remainder(std::atan2(y[1], y[0]) - theta.back(), kTwoPi));
                  }
                  ++k;
                });
      ++integrations_;
      th = theta.back() +
           std::remainder(std::atan2(X[((j + 1) % N_) * n_ + 1], X[((j + 1) % N_) * n_]) - theta.back(), kTwoPi);
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
  if (o.Psi0 <= -kPi) o.Psi0 += kTwoPi;
  o.r_min = o.r_max = o.r0;
  o.Psi_min = o.Psi_max = o.Psi0;
  o.mean = Eigen::VectorXd::Zero(n_);
  std::size_t k_rmin = 0, k_rmax = 0, k_Pmin = 0, k_Pmax = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double r = r_of(xs[k]);
    if (r < o.r_min) o.r_min = r, k_rmin = k, o.t_r_min = static_cast<double>(k) * h;
    if (r > o.r_max) o.r_max = r, k_rmax = k;
    const double Psi = o.Psi0 - (theta[k] - theta0);
    if (Psi < o.Psi_min) o.Psi_min = Psi, k_Pmin = k;
    if (Psi > o.Psi_max) o.Psi_max = Psi, k_Pmax = k;
    o.mean += xs[k];
  }
  o.mean /= static_cast<double>(xs.size());
  // The period's end (the state is back at x_0): a tumbling orbit's Psi range spans 2 pi |winding|.
  o.Psi_min = std::min(o.Psi_min, o.Psi0 - total);
  o.Psi_max = std::max(o.Psi_max, o.Psi0 - total);

  // The extrema are the solution's, not the samples': each sampled extremum is refined to the zero of
  // g(t), the quantity's time derivative up to a positive factor, between the neighbouring samples
  // (Illinois secant to 1e-10 in t; each trial integrates from the left sample), every trial state
  // updating the extremum. r_min is a smooth function of p, so the transition function below is
  // continuous and its zero can be located as a UZ event.
  const std::size_t K = xs.size();
  auto f_at = [&](double t, const Eigen::VectorXd& x) {
    Eigen::VectorXd f(n_);
    sys_.rhs(t, std::span<const double>(x.data(), n), p, std::span<double>(f.data(), n));
    return f;
  };
  // d/dt |z|^2 / 2 (r's direction: |x| is conserved where r is normalised) and -d(arg z)/dt |z|^2 (Psi's).
  auto g_r = [&](double t, const Eigen::VectorXd& x) {
    const Eigen::VectorXd f = f_at(t, x);
    return x[0] * f[0] + x[1] * f[1];
  };
  auto g_Psi = [&](double t, const Eigen::VectorXd& x) {
    const Eigen::VectorXd f = f_at(t, x);
    return -(x[0] * f[1] - x[1] * f[0]);
  };
  // sign: +1 at a minimum (g from - to +), -1 at a maximum; visit(t, x, theta) at every trial state.
  auto refine = [&](std::size_t kext, double sign, const auto& g_of, const auto& visit) {
    const std::size_t kl = (kext + K - 1) % K, kr = (kext + 1) % K;
    const double ta = static_cast<double>(kext) * h - h, tb = static_cast<double>(kext) * h + h;
    const Eigen::VectorXd xa = xs[kl];
    // The continuous angle at the left sample (at t = -h: the last sample's, one period earlier).
    const double theta_a = theta[kl] - (kext == 0 ? total : 0.0);
    double a = ta, b = tb;
    double ga = sign * g_of(ta, xa), gb = sign * g_of(tb, xs[kr]);
    if (!(ga < 0 && gb > 0)) return;
    int side = 0;
    for (int it = 0; it < 60 && b - a > 1e-10; ++it) {
      double t = a - ga * (b - a) / (gb - ga);
      if (!(t > a && t < b) || it % 4 == 3) t = 0.5 * (a + b);
      const double grid[1] = {t};
      const IntegrationResult res = integrate(plain, std::span<const double>(xa.data(), n), ta, grid, io, {});
      ++integrations_;
      if (res.status != IntegrationStatus::success) break;
      const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(res.y.data(), n_);
      visit(t, x, theta_a + std::remainder(std::atan2(x[1], x[0]) - theta_a, kTwoPi));
      const double g = sign * g_of(t, x);
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
  };
  refine(k_rmin, 1.0, g_r, [&](double t, const Eigen::VectorXd& x, double) {
    if (r_of(x) < o.r_min) o.r_min = r_of(x), o.t_r_min = std::fmod(t + length_, length_);
  });
  if (extrema) {
    refine(k_rmax, -1.0, g_r, [&](double, const Eigen::VectorXd& x, double) { o.r_max = std::max(o.r_max, r_of(x)); });
    // Psi near t = 0 of a tumbling orbit: its range is the continuous Psi over [0, 2 pi], not a window
    // shifted before 0, so only interior samples are refined there.
    const bool wraps = o.winding != 0;
    auto Psi_of = [&](double th_x) { return o.Psi0 - (th_x - theta0); };
    if (!(wraps && (k_Pmin == 0 || k_Pmin + 1 == K)))
      refine(k_Pmin, 1.0, g_Psi,
             [&](double, const Eigen::VectorXd&, double th_x) { o.Psi_min = std::min(o.Psi_min, Psi_of(th_x)); });
    if (!(wraps && (k_Pmax == 0 || k_Pmax + 1 == K)))
      refine(k_Pmax, -1.0, g_Psi,
             [&](double, const Eigen::VectorXd&, double th_x) { o.Psi_max = std::max(o.Psi_max, Psi_of(th_x)); });
  }
  o.transition_function = o.winding == 0 ? o.r_min : -o.r_min;
  return o;
}

OrbitPoint PeriodicOrbitProblem::point_at(const Eigen::VectorXd& X, double p, double t) const {
  const auto n = static_cast<std::size_t>(n_);
  double tw = std::fmod(t, length_);
  if (tw < 0) tw += length_;
  OrbitPoint o;
  o.segment = std::min(N_ - 1, static_cast<int>(std::floor(tw * N_ / length_)));
  const double tj = length_ * o.segment / N_;
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
  return UserEvent{name,
                   [this](const Eigen::VectorXd& X, double p) { return summary(X, p, false).transition_function; }};
}

}  // namespace rbcstab
