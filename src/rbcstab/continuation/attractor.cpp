#include "rbcstab/continuation/attractor.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "rbcstab/continuation/detail/forced_flow.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/phasor.hpp"

namespace rbcstab {

void PeriodicRefinementOptions::validate() const {
  require(std::isfinite(period) && period > 0, "period", period, "finite and > 0");
  plain.validate();
  variational.validate();
  require(std::isfinite(residual_tol) && residual_tol > 0 && residual_tol < 1, "residual_tol", residual_tol, "(0, 1)");
  require(max_iterations >= 1 && max_iterations <= 100, "max_iterations", max_iterations, "an integer in [1, 100]");
  require(std::isfinite(max_contraction) && max_contraction > 0 && max_contraction < 1, "max_contraction",
          max_contraction, "(0, 1)");
}

PeriodRun run_period(const ForcedSystem& system, double p, double t0, const Eigen::VectorXd& x0, double period,
                     const IntegratorOptions& options, const Quadrature& integrands) {
  const Eigen::Index n = system.dimension();
  require(x0.size() == n, "x0", static_cast<double>(x0.size()), "a state of the system's dimension");
  const detail::ForcedFlow plain(system, p, detail::ForcedFlow::Mode::plain);
  const bool with_integrals = integrands.count > 0 && integrands.rate;
  const std::size_t nq = with_integrals ? integrands.count : 0;
  std::optional<WithQuadratures> augmented;
  if (with_integrals) augmented.emplace(plain, integrands);
  const System& flow = with_integrals ? static_cast<const System&>(*augmented) : plain;
  std::vector<double> z(static_cast<std::size_t>(n) + nq, 0.0);
  std::copy(x0.data(), x0.data() + n, z.begin());
  const double grid[1] = {t0 + period};
  const IntegrationResult r = integrate(flow, z, t0, grid, options, {});
  PeriodRun out;
  out.work = r.counters;
  out.ok = r.status == IntegrationStatus::success;
  if (!out.ok) {
    out.reason = r.reason;
    return out;
  }
  out.x = Eigen::Map<const Eigen::VectorXd>(r.y.data(), n);
  out.integrals = Eigen::Map<const Eigen::VectorXd>(r.y.data() + n, static_cast<Eigen::Index>(nq));
  return out;
}

PeriodicRefinement refine_periodic_orbit(const ForcedSystem& system, double p, double t0, const Eigen::VectorXd& x0,
                                         const PeriodicRefinementOptions& options, const Quadrature& integrands) {
  options.validate();
  const Eigen::Index n = system.dimension();
  require(x0.size() == n, "x0", static_cast<double>(x0.size()), "a state of the system's dimension");
  require(std::isfinite(t0), "t0", t0, "finite");
  const auto un = static_cast<std::size_t>(n);
  const double grid[1] = {t0 + options.period};
  PeriodicRefinement r;

  // The monodromy and the chord matrix DE = |x0|^2 M + 2 phi x0^T - I (M - I without a conserved norm).
  const detail::ForcedFlow variational(system, p, detail::ForcedFlow::Mode::monodromy);
  std::vector<double> y(un + un * un, 0.0);
  for (std::size_t i = 0; i < un; ++i) {
    y[i] = x0[static_cast<Eigen::Index>(i)];
    y[un + i * un + i] = 1;
  }
  const IntegrationResult v = integrate(variational, y, t0, grid, options.variational, {});
  r.work += v.counters;
  if (v.status != IntegrationStatus::success) {
    r.reason = "the variational run failed: " + v.reason;
    return r;
  }
  const Eigen::VectorXd phi0 = Eigen::Map<const Eigen::VectorXd>(v.y.data(), n);
  const Eigen::MatrixXd M = Eigen::Map<const Eigen::MatrixXd>(v.y.data() + n, n, n);
  const bool norm = system.conserves_norm();
  auto E_of = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& phi) -> Eigen::VectorXd {
    return norm ? Eigen::VectorXd(x.squaredNorm() * phi - x) : Eigen::VectorXd(phi - x);
  };
  Eigen::MatrixXd DE = norm ? Eigen::MatrixXd(x0.squaredNorm() * M + 2 * phi0 * x0.transpose()) : M;
  DE.diagonal().array() -= 1;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(DE);
  if (!lu.isInvertible()) {
    r.reason = "the chord matrix is singular (a multiplier 1 besides the trivial one)";
    return r;
  }

  // Chord iterations, each from a plain run (with the caller's integrands) at the iterate.
  Eigen::VectorXd x = x0;
  Eigen::VectorXd step = -lu.solve(E_of(x0, phi0));
  double previous = step.norm();
  for (int k = 1; k <= options.max_iterations; ++k) {
    x += step;
    r.iterations = k;
    const PeriodRun pr = run_period(system, p, t0, x, options.period, options.plain, integrands);
    r.work += pr.work;
    if (!pr.ok) {
      r.reason = "a plain run failed: " + pr.reason;
      return r;
    }
    r.residual = (pr.x - x).norm();
    r.integrals = pr.integrals;
    step = -lu.solve(E_of(x, pr.x));
    // Steps at the accuracy of the runs (the first from the looser variational run) measure noise, not the
    // chord's contraction.
    const bool noise = previous <= options.residual_tol;
    r.contraction = noise || !(previous > 0) ? 0.0 : step.norm() / previous;
    previous = step.norm();
    if (!std::isfinite(r.residual) || !std::isfinite(r.contraction)) {
      r.reason = "the chord iteration produced a non-finite state";
      return r;
    }
    if (r.residual <= options.residual_tol) {
      r.converged = true;
      break;
    }
    if (r.contraction > options.max_contraction) {
      r.reason = "the chord iteration contracts by " + format_value(r.contraction) + " per step (above " +
                 format_value(options.max_contraction) + "): too far from the orbit for its linearisation";
      return r;
    }
  }
  if (!r.converged) {
    r.reason = "no periodic state within " + std::to_string(options.max_iterations) + " chord iterations (residual " +
               format_value(r.residual) + ")";
    return r;
  }
  r.x = x;
  r.distance = (x - x0).norm();

  // The multipliers: M is known at x0 only; |M(x*) - M(x0)| <~ q |DE| (what slows the chord), x0's own
  // defect moves the invariant plane (M maps x0^perp onto phi0^perp), and the run's tolerance.
  const double m_norm = M.norm();
  const double eta = std::max(
      {10 * options.variational.rtol, (phi0 - x0).norm(), m_norm > 0 ? r.contraction * DE.norm() / m_norm : 0.0});
  const Eigen::MatrixXd T = norm ? detail::tangent_basis(x0) : Eigen::MatrixXd::Identity(n, n);
  r.monodromy = T.transpose() * M * T;
  r.multipliers = certified_eigenvalues(r.monodromy, eta);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(r.monodromy.rows(), r.monodromy.cols());
  r.deviation_sum = T * (I - r.monodromy).partialPivLu().solve(T.transpose() * (x0 - x));
  return r;
}

// ---------------------------------------------------------------- the modal subsystem

ModalSubsystem::ModalSubsystem(const ModalForcedSystem& full, double p, std::vector<int> modes)
    : full_(full), p_(p), modes_(std::move(modes)) {
  for (std::size_t k = 0; k < modes_.size(); ++k)
    require(modes_[k] >= 3 && modes_[k] <= full.L() && (k == 0 || modes_[k] > modes_[k - 1]), "modes", modes_[k],
            "increasing modes in [3, L = " + std::to_string(full.L()) + "]");
  const ModalCoefficients& c = full.coefficients(p);
  c_ = c;
  c_.L = 2 + static_cast<int>(modes_.size());
  c_.Upsilon = {c.rate(2)};
  for (int l : modes_) c_.Upsilon.push_back(c.rate(l));
  // Only the l = 2 block is forced (the rest shape has no l >= 3 content at the modal level).
  const Eigen::VectorXd f0 = full.forcing(0, p).head(5), f1 = full.forcing(kPi / 2, p).head(5),
                        f2 = full.forcing(kPi, p).head(5);
  h0_ = h_cos_ = h_sin_ = h_ = Eigen::VectorXd::Zero(dimension());
  h0_.head(5) = (f0 + f2) / 2;
  h_cos_.head(5) = (f0 - f2) / 2;
  h_sin_.head(5) = f1 - h0_.head(5);
}

const Eigen::VectorXd& ModalSubsystem::forcing(double t) const {
  const std::complex<double> e = unit_phasor(t);
  h_.noalias() = h0_ + e.real() * h_cos_ + e.imag() * h_sin_;
  return h_;
}

void ModalSubsystem::rhs(double t, std::span<const double> x, double, std::span<double> f) const {
  const Eigen::Map<const Eigen::VectorXd> X(x.data(), dimension());
  Eigen::Map<Eigen::VectorXd> F(f.data(), dimension());
  modal_dynamics(c_, X, forcing(t), 0.0, F);
}

void ModalSubsystem::jacobian(double t, std::span<const double> x, double, Eigen::MatrixXd& J) const {
  const Eigen::Map<const Eigen::VectorXd> X(x.data(), dimension());
  modal_dynamics_jacobian(c_, X, forcing(t), 0.0, J);
}

double ModalSubsystem::sigma(double t, std::span<const double> x) const {
  return modal_sigma(c_, Eigen::Map<const Eigen::VectorXd>(x.data(), dimension()), forcing(t));
}

Eigen::VectorXd ModalSubsystem::restrict(const Eigen::VectorXd& x_full) const {
  Eigen::VectorXd x(dimension());
  x.head(5) = x_full.head(5);
  for (std::size_t k = 0; k < modes_.size(); ++k)
    x[5 + static_cast<Eigen::Index>(k)] = x_full[ModalEquilibriumProblem::index_of_mode(modes_[k])];
  return x;
}

Eigen::VectorXd ModalSubsystem::embed(const Eigen::VectorXd& x) const {
  Eigen::VectorXd x_full = Eigen::VectorXd::Zero(full_.dimension());
  x_full.head(5) = x.head(5);
  for (std::size_t k = 0; k < modes_.size(); ++k)
    x_full[ModalEquilibriumProblem::index_of_mode(modes_[k])] = x[5 + static_cast<Eigen::Index>(k)];
  return x_full;
}

}  // namespace rbcstab
