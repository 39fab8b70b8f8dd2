#include "rbcstab/continuation/monodromy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/full_model.hpp"

namespace rbcstab {

void MonodromyOptions::validate() const {
  require(std::isfinite(period) && period > 0, "period", period, "> 0");
  require(implicit_from_L >= 0, "implicit_from_L", implicit_from_L, ">= 0 (0: never)");
  for (const auto* io : {&integrator, &implicit}) {
    io->validate();
    if (is_implicit(io->stepper) && io->stepper != Stepper::rosenbrock)
      throw InvalidArgument("stepper", "stepper = " + to_string(io->stepper) +
                                           " needs the dense Jacobian of the variational system; the monodromy "
                                           "action integrates with rosenbrock (block-triangular O(n) solves) or an "
                                           "explicit stepper (rk8pd, rkck, rkf45, msadams)");
  }
}

namespace {

// Linear algebra of the variational system for the Rosenbrock stepper. Its Jacobian is block lower
// triangular, J_aug = [[J, 0], [K, J]] with K x = d/de [J(y + e x) v] = F''(y)[x, v], so
// (I - c J_aug) [x1; x2] = [b1; b2] is two structured O(n) solves of the base level:
//   (I - c J) x1 = b1,   (I - c J) x2 = b2 + c K x1.
// K is the second derivative of F, symmetric in its two arguments, so K x1 = d/de [J(y + e v) x1]: the
// two Jacobians J(y +- e v) are formed once per step (linearize) and every stage's K x1 is a central
// difference of two O(n) products. Likewise dF_aug/dt = (dF/dt, (dJ/dt) v) with
// (dJ/dt) v = d/de [dF/dt(t, y + e v)], the central difference of the level's analytic dF/dt.
// Step: |e v| = cbrt(eps) |y| balances the truncation error (e |v| / |y|)^2 ~ 4e-11 against rounding
// eps / cbrt(eps) ~ 4e-11 (relative to the nonlinear scale |y| of F, whose tension sigma(y) is
// homogeneous of degree 0 in y up to the drive). That ~1e-10 relative error in K and dJ/dt v only
// perturbs the matrix W = I - c J_aug and the dF/dt term of the stages: the Rosenbrock step stays
// consistent (order 1 needs no Jacobian at all) and the order conditions that involve J are violated
// by O(1e-10 |K|) terms that multiply h^2 f, far below the local error tolerated per step; the tests
// compare with rk8pd (which uses no Jacobian) to 1e-7.
class VariationalSolver final : public ShiftedSolver {
 public:
  explicit VariationalSolver(const System& base) : base_(base), n_(base.dimension()) {}
  void linearize(double t, std::span<const double> yv, std::span<double> dfdt) override {
    const auto y = yv.first(n_), v = yv.subspan(n_, n_);
    base_.jacobian(t, y, J_, dfdt.first(n_));
    double ny = 0, nv = 0;
    for (std::size_t i = 0; i < n_; ++i) {
      ny += y[i] * y[i];
      nv += v[i] * v[i];
    }
    ny = std::sqrt(ny);
    nv = std::sqrt(nv);
    auto dJv_dt = dfdt.subspan(n_, n_);
    has_K_ = nv > 0;
    if (!has_K_) {  // v = 0: K = F''[., v] = 0 and (dJ/dt) v = 0
      std::fill(dJv_dt.begin(), dJv_dt.end(), 0.0);
      return;
    }
    const double e = std::cbrt(std::numeric_limits<double>::epsilon()) * (ny > 0 ? ny : 1.0) / nv;
    yp_.resize(n_);
    ym_.resize(n_);
    dfp_.resize(n_);
    dfm_.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      yp_[i] = y[i] + e * v[i];
      ym_[i] = y[i] - e * v[i];
    }
    base_.jacobian(t, yp_, Jp_, dfp_);
    base_.jacobian(t, ym_, Jm_, dfm_);
    inv_2e_ = 1 / (2 * e);
    for (std::size_t i = 0; i < n_; ++i) dJv_dt[i] = (dfp_[i] - dfm_[i]) * inv_2e_;
  }
  bool solve(double c, std::span<const double> b, std::span<double> x) override {
    const auto x1 = x.first(n_), x2 = x.subspan(n_, n_);
    if (!J_.solve_shifted(c, b.first(n_), x1)) return false;
    rhs2_.assign(b.begin() + static_cast<std::ptrdiff_t>(n_), b.end());
    if (has_K_) {
      Kp_.resize(n_);
      Km_.resize(n_);
      Jp_.apply(x1, Kp_);
      Jm_.apply(x1, Km_);
      for (std::size_t i = 0; i < n_; ++i) rhs2_[i] += c * (Kp_[i] - Km_[i]) * inv_2e_;
    }
    return J_.solve_shifted(c, rhs2_, x2);
  }

 private:
  const System& base_;
  std::size_t n_;
  StructuredJacobian J_, Jp_, Jm_;  // J at y and at y +- e v
  bool has_K_ = false;
  double inv_2e_ = 0;
  std::vector<double> yp_, ym_, dfp_, dfm_, Kp_, Km_, rhs2_;
};

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
    // Unreachable: J_aug is not of the form M + v w^T; rosenbrock uses make_shifted_solver() and
    // MonodromyOptions::validate rejects the dense implicit steppers.
    throw std::logic_error("VariationalSystem has no structured Jacobian");
  }
  std::unique_ptr<ShiftedSolver> make_shifted_solver() const override {
    return std::make_unique<VariationalSolver>(base_);
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

std::unique_ptr<System> make_variational_system(const System& base) {
  return std::make_unique<VariationalSystem>(base);
}

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
  const VariationalSystem sys(system_);  // per call: its scratch is not shared between threads
  const double grid[1] = {t0_ + options_.period};
  const IntegrationResult r = integrate(sys, yv, t0_, grid, options_.integrator_for(system_), {});
  counters_.steps += r.counters.steps;
  counters_.failed_steps += r.counters.failed_steps;
  counters_.rhs_evaluations += r.counters.rhs_evaluations;
  counters_.jacobian_evaluations += r.counters.jacobian_evaluations;
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

void SceneFloquetOptions::validate(int L) const {
  require(relax_periods >= 0 && relax_periods <= 1000000, "relax_periods", relax_periods, "in [0, 1e6]");
  require(max_periodicity_defect > 0, "max_periodicity_defect", max_periodicity_defect, "> 0 (inf: any state)");
  relax.validate();
  monodromy.validate();
  arpack.validate(2 * ModeAmplitudes::count(L));
}

SceneFloquetResult scene_floquet_multipliers(const Scene& scene, const SceneFloquetOptions& options) {
  const InitialState init = initial_state(scene);  // validates the scene
  options.validate(scene.L);                       // before any work: bad input computes nothing
  SceneFloquetResult out;
  // Odd-m rest-shape content below 1e-12 of the largest is rounding (the Wigner d^l_{m,0}(pi/2) of odd
  // m are ~1e-16, not 0): its 4 pi forcing is far below the integration accuracy.
  double g_max = 0, g_odd = 0;
  for (int l = 2; l <= init.g.L; ++l)
    for (int m = -l; m <= l; ++m) {
      g_max = std::max(g_max, std::abs(init.g.at(l, m)));
      if (m % 2 != 0) g_odd = std::max(g_odd, std::abs(init.g.at(l, m)));
    }
  const bool odd_m = g_odd > 1e-12 * g_max;
  out.period = (odd_m ? 2 : 1) * 2 * kPi;
  out.t0 = options.relax_periods * out.period;
  out.relax_level = choose_level(scene, init).level;
  const auto relaxing = make_system(scene.parameters, init, out.relax_level);
  InitialState relaxed = init;
  if (options.relax_periods > 0) {
    const double grid[1] = {out.t0};
    const IntegrationResult r = integrate(*relaxing, relaxing->initial_state(), 0.0, grid, options.relax, {});
    if (r.status != IntegrationStatus::success) {
      out.status = SceneFloquetStatus::relaxation_failed;
      out.message = "relaxation at the " + to_string(out.relax_level) +
                    " level failed at t = " + std::to_string(r.t_reached) + ": " +
                    run_reason(r.status, r.reason, scene.parameters);
      return out;
    }
    relaxed.f = relaxing->amplitudes(out.t0, r.y);
  }
  const FullModel full(scene.parameters, relaxed);
  const std::vector<double> y0 = full.initial_state();
  out.dimension = y0.size();
  MonodromyOptions mo = options.monodromy;
  mo.period = out.period;
  out.stepper = mo.integrator_for(full).stepper;
  const double grid[1] = {out.t0 + out.period};
  const IntegrationResult once = integrate(full, y0, out.t0, grid, mo.integrator_for(full), {});
  if (once.status != IntegrationStatus::success) {
    out.status = SceneFloquetStatus::relaxation_failed;
    out.message = "one period of the full model failed at t = " + std::to_string(once.t_reached) + ": " +
                  run_reason(once.status, once.reason, scene.parameters);
    return out;
  }
  double d = 0, n = 0;
  for (std::size_t i = 0; i < y0.size(); ++i) {
    d += (once.y[i] - y0[i]) * (once.y[i] - y0[i]);
    n += y0[i] * y0[i];
  }
  out.periodicity_defect = n > 0 ? std::sqrt(d / n) : std::sqrt(d);
  if (!(out.periodicity_defect <= options.max_periodicity_defect)) {
    out.status = SceneFloquetStatus::not_periodic;
    out.message = "the state at t0 = " + std::to_string(out.t0) + " is not periodic (defect " +
                  std::to_string(out.periodicity_defect) + " > " + std::to_string(options.max_periodicity_defect) +
                  "): relax for more periods, or accept the state with a larger max_periodicity_defect";
    return out;
  }
  out.floquet = leading_floquet_multipliers(full, y0, out.t0, mo, options.arpack);
  if (out.floquet.arpack.status != ArpackStatus::converged) {
    out.status = SceneFloquetStatus::arpack_failed;
    out.message = out.floquet.arpack.message;
  }
  return out;
}

}  // namespace rbcstab
