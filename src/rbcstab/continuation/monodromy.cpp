#include "rbcstab/continuation/monodromy.hpp"

#include <cmath>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void MonodromyOptions::validate() const {
  require(std::isfinite(period) && period > 0, "period", period, "> 0");
  integrator.validate();
  if (is_implicit(integrator.stepper))
    throw InvalidArgument("stepper", "the monodromy action integrates the variational system with an explicit stepper "
                                     "(rk8pd, rkck, rkf45); got " + to_string(integrator.stepper));
}

namespace {

// (y, v)' = (F(t, y), J(t, y) v): the state and one tangent vector.
class VariationalSystem final : public System {
 public:
  explicit VariationalSystem(const System& base) : base_(base), n_(base.dimension()) {}
  ModelLevel level() const override { return base_.level(); }
  std::size_t dimension() const override { return 2 * n_; }
  int L() const override { return base_.L(); }
  void rhs(double t, std::span<const double> yv, std::span<double> d) const override {
    const auto y = yv.first(n_);
    base_.rhs(t, y, d.first(n_));
    dfdt_.resize(n_);
    base_.jacobian(t, y, J_, dfdt_);
    J_.apply(yv.subspan(n_, n_), d.subspan(n_, n_));
  }
  void jacobian(double, std::span<const double>, StructuredJacobian&, std::span<double>) const override {
    // Unreachable: MonodromyOptions::validate admits explicit steppers only.
    throw std::logic_error("VariationalSystem has no structured Jacobian");
  }
  Observation observe(double t, std::span<const double> yv) const override { return base_.observe(t, yv.first(n_)); }
  std::vector<double> initial_state() const override { return {}; }
  ModeAmplitudes amplitudes(double t, std::span<const double> yv) const override {
    return base_.amplitudes(t, yv.first(n_));
  }

 private:
  const System& base_;
  std::size_t n_;
  mutable StructuredJacobian J_;
  mutable std::vector<double> dfdt_;
};

}  // namespace

MonodromyAction::MonodromyAction(const System& system, std::span<const double> y0, double t0,
                                 const MonodromyOptions& options)
    : system_(system), y0_(y0.begin(), y0.end()), t0_(t0), options_(options) {
  options.validate();
  require(y0.size() == system.dimension(), "y0", static_cast<double>(y0.size()), "the system's dimension");
  require(std::isfinite(t0), "t0", t0, "finite");
}

bool MonodromyAction::apply(std::span<const double> v, std::span<double> out) const {
  const std::size_t n = y0_.size();
  ++applications_;
  double norm = 0;
  for (double x : v) norm += x * x;
  norm = std::sqrt(norm);
  std::fill(out.begin(), out.end(), 0.0);
  if (norm == 0) return true;
  std::vector<double> yv(2 * n);
  std::copy(y0_.begin(), y0_.end(), yv.begin());
  for (std::size_t i = 0; i < n; ++i) yv[n + i] = v[i] / norm;
  const VariationalSystem sys(system_);
  const double grid[1] = {t0_ + options_.period};
  const IntegrationResult r = integrate(sys, yv, t0_, grid, options_.integrator, {});
  counters_.steps += r.counters.steps;
  counters_.failed_steps += r.counters.failed_steps;
  counters_.rhs_evaluations += r.counters.rhs_evaluations;
  if (r.status != IntegrationStatus::success) {
    failure_ = "variational integration failed at t = " + std::to_string(r.t_reached) + ": " + r.reason;
    return false;
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = norm * r.y[n + i];
  return true;
}

Eigen::MatrixXd MonodromyAction::dense(bool* ok) const {
  const std::size_t n = y0_.size();
  Eigen::MatrixXd M(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  std::vector<double> e(n, 0.0), col(n);
  bool all = true;
  for (std::size_t j = 0; j < n; ++j) {
    e[j] = 1;
    all = apply(e, col) && all;
    e[j] = 0;
    for (std::size_t i = 0; i < n; ++i) M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = col[i];
  }
  if (ok) *ok = all;
  return M;
}

FloquetResult leading_floquet_multipliers(const System& system, std::span<const double> y0, double t0,
                                          const MonodromyOptions& options, ArpackOptions arpack) {
  const MonodromyAction action(system, y0, t0, options);
  arpack.which = ArpackWhich::largest_magnitude;
  bool failed = false;
  const LinearOperator op = [&](std::span<const double> x, std::span<double> y) {
    if (!failed && !action.apply(x, y)) failed = true;
    if (failed) std::fill(y.begin(), y.end(), 0.0);  // ARPACK then stops quickly; the status reports it
  };
  FloquetResult out;
  out.arpack = arpack_eigenvalues(action.dimension(), op, {}, arpack);
  if (failed) {
    out.arpack.status = ArpackStatus::failed;
    out.arpack.message = action.failure_reason();
  }
  out.integrations = action.applications();
  out.counters = action.counters();
  return out;
}

}  // namespace rbcstab
