// Orbit branches from HB and PD points: the critical direction, the multiplicity check, the first point.
#include "rbcstab/continuation/orbit_switch.hpp"

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

std::string complex_text(std::complex<double> z) {
  return format_value(z.real()) + (z.imag() < 0 ? " - " : " + ") + format_value(std::abs(z.imag())) + "i";
}

// The values on the stability boundary (eigenvalues: Re = 0, the pairs' Im >= 0 member; multipliers: |mu| = 1).
std::vector<std::complex<double>> critical_values(const Eigen::VectorXcd& spectrum, StabilityKind kind, double tol) {
  std::vector<std::complex<double>> out;
  for (const std::complex<double>& z : spectrum) {
    const double scale = std::max(1.0, std::abs(z));
    const double distance = kind == StabilityKind::eigenvalues ? std::abs(z.real()) : std::abs(std::abs(z) - 1);
    if (distance <= tol * scale && z.imag() >= -tol * scale) out.push_back(z);
  }
  return out;
}

std::string list_values(const std::vector<std::complex<double>>& v) {
  std::string s;
  for (const auto& z : v) s += (s.empty() ? "" : ", ") + complex_text(z);
  return s;
}

// The labels of `type` in the branch at the point's parameter (within 1e-8 relative): the modes a model's
// multiple onset carries.
std::string labels_at(const Branch& branch, const SpecialPoint& point) {
  std::string s;
  for (const SpecialPoint& q : branch.special_points) {
    if (q.type != SpecialPointType::HB && q.type != SpecialPointType::BP) continue;
    if (std::abs(q.p - point.p) > 1e-8 * (1 + std::abs(point.p))) continue;
    s += (s.empty() ? "" : ", ") + std::string(to_string(q.type));
    if (q.mode_l)
      s += " (l = " + std::to_string(*q.mode_l) + (q.mode_m ? ", m = " + std::to_string(*q.mode_m) : "") + ")";
    if (q.type == SpecialPointType::HB) s += " omega " + format_value(q.eigenvalue.imag());
  }
  return s;
}

// Newton off the point along d, then the engine away from p0.
void start_branch(const ContinuationProblem& problem, const Eigen::VectorXd& X0, const Eigen::VectorXd& delta,
                  double p0, const OrbitSwitchOptions& options, OrbitSwitchResult& out) {
  Eigen::VectorXd base(X0.size() + 1), d = Eigen::VectorXd::Zero(X0.size() + 1);
  base << X0, p0;
  d.head(delta.size()) = delta;
  const double h = d.norm();
  d /= h;
  out.direction = d;
  Eigen::VectorXd X;
  if (!correct_on_hyperplane(problem, base, d, h, options.continuation.newton_tol, options.max_newton, X)) {
    out.message = "the corrector did not converge off the point (try another amplitude)";
    return;
  }
  const Eigen::Index n = problem.dimension();
  // p - p0 ~ eps^2 near a generic HB or PD: its sign at the first point says which side the new branch lies on.
  ContinuationOptions o = options.continuation;
  o.direction = X[n] >= p0 ? Direction::forward : Direction::backward;
  out.branch = continue_branch(problem, X.head(n), X[n], o);
  out.switched = !out.branch.points.empty();
  out.message = out.branch.message;
}

}  // namespace

void OrbitSwitchOptions::validate() const {
  require(std::isfinite(amplitude) && amplitude > 0, "amplitude", amplitude, "a finite number > 0");
  require(std::isfinite(critical_tol) && critical_tol > 0 && critical_tol < 1, "critical_tol", critical_tol,
          "in (0, 1)");
  require(max_newton >= 1, "max_newton", max_newton, "an integer >= 1");
  orbit.validate();
  continuation.validate();
}

OrbitSwitchResult switch_at_hopf(const AutonomousSystem& system, const SpecialPoint& hb,
                                 const OrbitSwitchOptions& options) {
  options.validate();
  require(hb.type == SpecialPointType::HB, "special_point", static_cast<double>(static_cast<int>(hb.type)),
          "an HB (Hopf point)");
  const Eigen::Index n = system.dimension();
  require(hb.x.size() == n, "special_point", static_cast<double>(hb.x.size()), "a state of the system's dimension");
  OrbitSwitchResult out;
  Eigen::MatrixXd J;
  system.jacobian(std::span<const double>(hb.x.data(), static_cast<std::size_t>(n)), hb.p, J);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, true);
  const auto critical = critical_values(es.eigenvalues(), StabilityKind::eigenvalues, options.critical_tol);
  if (critical.size() != 1 || !(critical[0].imag() > 0)) {
    out.message = "not a simple Hopf point at " + system.parameter_name() + " = " + format_value(hb.p) +
                  ": the eigenvalues on the imaginary axis are " + (critical.empty() ? "none" : list_values(critical)) +
                  " (a simple HB has one pair +- i omega and no zero eigenvalue)";
    return out;
  }
  Eigen::Index i = 0;
  (es.eigenvalues() - Eigen::VectorXcd::Constant(n, critical[0])).cwiseAbs().minCoeff(&i);
  const double omega = es.eigenvalues()[i].imag();
  Eigen::VectorXcd q = es.eigenvectors().col(i);
  // Rotate q so that its largest component k is real: then x_k(t) ~ Re(q_k e^{i omega t}) has its extremum at
  // t = 0, which is the orbit problem's phase condition f_k(x_0) = 0.
  Eigen::Index k = 0;
  q.cwiseAbs().maxCoeff(&k);
  q *= std::conj(q[k]) / std::abs(q[k]);
  q /= q.cwiseAbs().maxCoeff();
  auto problem = std::make_unique<AutonomousOrbitProblem>(system, static_cast<int>(k), options.orbit);
  const int N = problem->segments();
  out.period = kTwoPi / omega;
  Eigen::VectorXd X0(n * N + 1), delta = Eigen::VectorXd::Zero(n * N + 1);
  for (int j = 0; j < N; ++j) {
    X0.segment(j * n, n) = hb.x;
    const std::complex<double> e = std::polar(1.0, kTwoPi * j / N);
    delta.segment(j * n, n) = options.amplitude * (q * e).real();
  }
  X0[n * N] = out.period;
  start_branch(*problem, X0, delta, hb.p, options, out);
  out.problem = std::move(problem);
  return out;
}

OrbitSwitchResult switch_at_period_doubling(const PeriodicOrbitProblem& problem, const SpecialPoint& pd,
                                            const OrbitSwitchOptions& options) {
  options.validate();
  require(pd.type == SpecialPointType::PD, "special_point", static_cast<double>(static_cast<int>(pd.type)),
          "a PD (period doubling)");
  require(pd.x.size() == problem.dimension(), "special_point", static_cast<double>(pd.x.size()),
          "a point of this orbit problem");
  OrbitSwitchResult out;
  const Floquet fl = problem.floquet(pd.x, pd.p);
  const auto critical = critical_values(fl.multipliers, StabilityKind::multipliers, options.critical_tol);
  if (critical.size() != 1 || !(critical[0].real() < 0)) {
    out.message = "not a simple period doubling at " + problem.parameter_name() + " = " + format_value(pd.p) +
                  ": the multipliers on the unit circle are " + (critical.empty() ? "none" : list_values(critical)) +
                  " (a simple PD has one multiplier -1)";
    return out;
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(fl.monodromy, true);
  Eigen::Index i = 0;
  (es.eigenvalues() - Eigen::VectorXcd::Constant(es.eigenvalues().size(), -1.0)).cwiseAbs().minCoeff(&i);
  Eigen::VectorXd v = es.eigenvectors().col(i).real();
  v /= v.norm();
  const Eigen::Index m = problem.dimension();
  const Eigen::VectorXd V = problem.variation(pd.x, pd.p, v);
  OrbitOptions o = problem.options();  // the parent's tolerances, on the same segment times
  o.segments = 2 * problem.segments();
  auto doubled = std::make_unique<PeriodicOrbitProblem>(problem.system(), o, 2 * problem.periods());
  Eigen::VectorXd X0(2 * m), delta(2 * m);
  X0 << pd.x, pd.x;
  delta << options.amplitude * V, -options.amplitude * V;
  out.period = 2 * kTwoPi * problem.periods();
  start_branch(*doubled, X0, delta, pd.p, options, out);
  out.problem = std::move(doubled);
  return out;
}

OrbitSwitchResult switch_at(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& point,
                            const OrbitSwitchOptions& options) {
  if (point.type == SpecialPointType::HB) {
    if (const auto* eq = dynamic_cast<const AutonomousEquilibriumProblem*>(&problem))
      return switch_at_hopf(eq->system(), point, options);
    OrbitSwitchResult out;
    const auto critical =
        critical_values(problem.spectrum(point.x, point.p), StabilityKind::eigenvalues, options.critical_tol);
    if (critical.size() > 1) {
      out.message = "a multiple Hopf point at " + problem.parameter_name() + " = " + format_value(point.p) +
                    ": eigenvalues on the imaginary axis " + list_values(critical) +
                    "; labels there: " + labels_at(branch, point) +
                    ". Switching needs one simple pair (the symmetric onset is a family of orbits, "
                    "docs/continuation.md)";
      return out;
    }
    out.message =
        "a simple HB, but switching at an HB is supported on branches of autonomous systems' equilibria "
        "only (AutonomousEquilibriumProblem), not this problem kind";
    return out;
  }
  if (point.type == SpecialPointType::PD) {
    if (const auto* orbit = dynamic_cast<const PeriodicOrbitProblem*>(&problem))
      return switch_at_period_doubling(*orbit, point, options);
    OrbitSwitchResult out;
    out.message = "switching at a PD is supported on forced periodic-orbit branches only";
    return out;
  }
  OrbitSwitchResult out;
  out.message = std::string("no orbit switch at a ") + std::string(to_string(point.type)) +
                " point (HB and PD only; BP: switch_branch)";
  return out;
}

}  // namespace rbcstab
