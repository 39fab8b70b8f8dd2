// Autonomous systems: equilibria and periodic orbits of unknown period by multiple shooting.
#include "rbcstab/continuation/autonomous_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/continuation/detail/forced_flow.hpp"
#include "rbcstab/continuation/detail/shooting.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

// x' = f(x, p) seen as a forced system that ignores t: the shooting then integrates plain time, and a segment of
// length T / N is the rescaled segment of length 1 / N.
class IgnoringTime final : public ForcedSystem {
 public:
  explicit IgnoringTime(const AutonomousSystem& s) : s_(s) {}
  Eigen::Index dimension() const override { return s_.dimension(); }
  void rhs(double, std::span<const double> x, double p, std::span<double> f) const override { s_.rhs(x, p, f); }
  void jacobian(double, std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    s_.jacobian(x, p, J);
  }
  void parameter_derivative(double, std::span<const double> x, double p, std::span<double> fp) const override {
    s_.parameter_derivative(x, p, fp);
  }
  std::string parameter_name() const override { return s_.parameter_name(); }

 private:
  const AutonomousSystem& s_;
};

Eigen::VectorXd field(const AutonomousSystem& s, const Eigen::VectorXd& x, double p) {
  Eigen::VectorXd f(x.size());
  s.rhs(std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), p,
        std::span<double>(f.data(), static_cast<std::size_t>(f.size())));
  return f;
}

}  // namespace

void AutonomousSystem::parameter_derivative(std::span<const double> x, double p, std::span<double> fp) const {
  const double h = detail::fd_step(p);
  std::vector<double> fm(fp.size());
  rhs(x, p + h, fp);
  rhs(x, p - h, fm);
  for (std::size_t i = 0; i < fp.size(); ++i) fp[i] = (fp[i] - fm[i]) / (2 * h);
}

// ---------------------------------------------------------------- equilibria

void AutonomousEquilibriumProblem::residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const {
  F = field(sys_, x, p);
}

void AutonomousEquilibriumProblem::jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const {
  sys_.jacobian(std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), p, J);
}

void AutonomousEquilibriumProblem::parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const {
  Fp.resize(x.size());
  sys_.parameter_derivative(std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), p,
                            std::span<double>(Fp.data(), static_cast<std::size_t>(Fp.size())));
}

// ---------------------------------------------------------------- orbits

AutonomousOrbitProblem::AutonomousOrbitProblem(const AutonomousSystem& system, int phase_component,
                                               const OrbitOptions& options)
    : sys_(system),
      flow_(std::make_unique<IgnoringTime>(system)),
      k_(phase_component),
      o_(options),
      n_(system.dimension()),
      N_(options.segments) {
  o_.validate();
  require(n_ >= 2, "dimension", static_cast<double>(n_), ">= 2 (an orbit needs a plane)");
  require(k_ >= 0 && k_ < n_, "phase_component", k_, "in [0, dimension - 1]");
}

AutonomousOrbitProblem::~AutonomousOrbitProblem() = default;

const ShootingFlows& AutonomousOrbitProblem::shoot(const Eigen::VectorXd& X, double p) const {
  if (cache_valid_ && cache_p_ == p && cache_X_.size() == X.size() && cache_X_ == X) return cache_;
  cache_X_ = X;
  cache_p_ = p;
  const double T = period(X);
  if (!(std::isfinite(T) && T > 0)) {
    cache_.ok = false;  // a period <= 0 has no orbit: NaN residual, the engine shrinks its step
  } else {
    detail::shoot_segments(*flow_, X.head(n_ * N_), p, N_, T, detail::orbit_integrator_options(o_), cache_);
  }
  cache_valid_ = true;
  return cache_;
}

void AutonomousOrbitProblem::residual(const Eigen::VectorXd& X, double p, Eigen::VectorXd& F) const {
  const ShootingFlows& sh = shoot(X, p);
  F.resize(dimension());
  if (!sh.ok) {
    F.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int j = 0; j < N_; ++j)
    F.segment(j * n_, n_) = sh.phi[static_cast<std::size_t>(j)] - X.segment(((j + 1) % N_) * n_, n_);
  F[n_ * N_] = field(sys_, X.head(n_), p)[k_];
}

void AutonomousOrbitProblem::jacobian(const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) const {
  const ShootingFlows& sh = shoot(X, p);
  const Eigen::Index m = dimension();
  J.setZero(m, m);
  if (!sh.ok) {
    J.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int j = 0; j < N_; ++j) {
    const auto js = static_cast<std::size_t>(j);
    J.block(j * n_, j * n_, n_, n_) = sh.M[js];
    J.block(j * n_, ((j + 1) % N_) * n_, n_, n_) -= Eigen::MatrixXd::Identity(n_, n_);
    // phi(T / N, x_j) moves with T at the rate f(phi) / N.
    J.block(j * n_, m - 1, n_, 1) = field(sys_, sh.phi[js], p) / N_;
  }
  Eigen::MatrixXd Jf;
  const Eigen::VectorXd x0 = X.head(n_);
  sys_.jacobian(std::span<const double>(x0.data(), static_cast<std::size_t>(n_)), p, Jf);
  J.block(m - 1, 0, 1, n_) = Jf.row(k_);
}

void AutonomousOrbitProblem::parameter_derivative(const Eigen::VectorXd& X, double p, Eigen::VectorXd& Fp) const {
  const ShootingFlows& sh = shoot(X, p);
  Fp.resize(dimension());
  if (!sh.ok) {
    Fp.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int j = 0; j < N_; ++j) Fp.segment(j * n_, n_) = sh.s[static_cast<std::size_t>(j)];
  Eigen::VectorXd fp(n_);
  const Eigen::VectorXd x0 = X.head(n_);
  sys_.parameter_derivative(std::span<const double>(x0.data(), static_cast<std::size_t>(n_)), p,
                            std::span<double>(fp.data(), static_cast<std::size_t>(n_)));
  Fp[n_ * N_] = fp[k_];
}

Eigen::MatrixXd AutonomousOrbitProblem::monodromy(const Eigen::VectorXd& X, double p) const {
  const ShootingFlows& sh = shoot(X, p);
  if (!sh.ok) return Eigen::MatrixXd::Constant(n_, n_, std::numeric_limits<double>::quiet_NaN());
  return detail::monodromy_product(sh);
}

Eigen::VectorXd AutonomousOrbitProblem::variation(const Eigen::VectorXd& X, double p, const Eigen::VectorXd& v0) const {
  require(v0.size() == n_, "v0", static_cast<double>(v0.size()), "a vector of the system's dimension");
  return detail::segment_variation(shoot(X, p), v0);
}

Eigen::VectorXd AutonomousOrbitProblem::flow_sensitivity(const Eigen::VectorXd& X, double p) const {
  const ShootingFlows& sh = shoot(X, p);
  if (!sh.ok) return Eigen::VectorXd::Constant(n_, std::numeric_limits<double>::quiet_NaN());
  return detail::sensitivity_product(sh);
}

Eigen::VectorXd AutonomousOrbitProblem::flow(const Eigen::VectorXd& x, double t, double p) const {
  require(x.size() == n_, "x", static_cast<double>(x.size()), "a state of the system's dimension");
  require(std::isfinite(t) && t > 0, "t", t, "a finite time > 0");
  const detail::ForcedFlow plain(*flow_, p, detail::ForcedFlow::Mode::plain);
  const double grid[1] = {t};
  const IntegrationResult r = integrate(plain, std::span<const double>(x.data(), static_cast<std::size_t>(n_)), 0.0,
                                        grid, detail::orbit_integrator_options(o_), {});
  if (r.status != IntegrationStatus::success)
    return Eigen::VectorXd::Constant(n_, std::numeric_limits<double>::quiet_NaN());
  return Eigen::Map<const Eigen::VectorXd>(r.y.data(), n_);
}

Eigen::VectorXcd AutonomousOrbitProblem::spectrum(const Eigen::VectorXd& X, double p) const {
  return certified_spectrum(X, p, false).values;
}

CertifiedSpectrum AutonomousOrbitProblem::certified_spectrum(const Eigen::VectorXd& X, double p, bool) const {
  const Eigen::MatrixXd M = monodromy(X, p);
  const Eigen::VectorXd f0 = field(sys_, X.head(n_), p);
  if (!M.allFinite() || !(f0.norm() > 0)) {
    CertifiedSpectrum c;
    c.values.setConstant(n_ - 1, std::numeric_limits<double>::quiet_NaN());
    c.errors.setConstant(n_ - 1, std::numeric_limits<double>::quiet_NaN());
    return c;
  }
  const double eta = std::max((M * f0 - f0).norm() / f0.norm(), o_.rtol);
  return detail::certified_tangent_spectrum(M, f0, eta);
}

Eigen::VectorXd AutonomousOrbitProblem::shooting_guess(const Eigen::VectorXd& x0, double T, double p) const {
  require(x0.size() == n_, "x0", static_cast<double>(x0.size()), "a state of the system's dimension");
  require(std::isfinite(T) && T > 0, "T", T, "a finite period > 0");
  Eigen::VectorXd X(dimension());
  for (int j = 0; j < N_; ++j) X.segment(j * n_, n_) = x0;  // kept where an integration fails
  X[dimension() - 1] = T;
  std::vector<double> grid;
  for (int j = 1; j < N_; ++j) grid.push_back(T * j / N_);
  if (grid.empty()) return X;
  const detail::ForcedFlow plain(*flow_, p, detail::ForcedFlow::Mode::plain);
  int k = 1;
  integrate(plain, std::span<const double>(x0.data(), static_cast<std::size_t>(n_)), 0.0, grid,
            detail::orbit_integrator_options(o_), [&](double, std::span<const double> y) {
              X.segment(k * n_, n_) = Eigen::Map<const Eigen::VectorXd>(y.data(), n_);
              ++k;
            });
  return X;
}

}  // namespace rbcstab
