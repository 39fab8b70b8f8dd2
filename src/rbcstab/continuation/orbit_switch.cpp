// Orbit branches from HB and PD points: the critical direction, the multiplicity check, the first point.
#include "rbcstab/continuation/orbit_switch.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
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

// Newton off the point along d (d has no p component, so the hyperplane d.(X - X_0) = h holds any p): from
// p_guess when it is finite, then (or else) from p0.
void first_point(const ContinuationProblem& problem, const Eigen::VectorXd& X0, const Eigen::VectorXd& delta, double p0,
                 double p_guess, const OrbitSwitchOptions& options, OrbitSwitchStart& out) {
  Eigen::VectorXd base(X0.size() + 1), d = Eigen::VectorXd::Zero(X0.size() + 1);
  base << X0, p0;
  d.head(delta.size()) = delta;
  const double h = d.norm();
  d /= h;
  out.direction = d;
  const Eigen::Index n = problem.dimension();
  const auto solve = [&](double p_start, Eigen::VectorXd& X) {
    X = base + h * d;
    X[n] = p_start;
    return newton_on_hyperplane(problem, base, d, h, options.continuation.newton_tol, options.max_newton, X);
  };
  Eigen::VectorXd X;
  if (!(std::isfinite(p_guess) && solve(p_guess, X)) && !solve(p0, X)) {
    out.message = "the corrector did not converge off the point (try another amplitude)";
    return;
  }
  out.found = true;
  out.x = X.head(n);
  out.p = X[n];
  // p - p0 ~ eps^2 near a generic HB or PD: its sign at the first point says which side the new branch lies on.
  out.away = X[n] >= p0 ? Direction::forward : Direction::backward;
}

OrbitSwitchStart refusal(std::string message) {
  OrbitSwitchStart out;
  out.refused = true;
  out.message = std::move(message);
  return out;
}

// The parameter the point's amplitude law (an HB's hopf_normal_form, a PD's period-map normal form) gives for an orbit
// whose distance |x - x*|_2 is `peak`: |x - x*| ~ amplitude |p - p*|^(1/2) on `side`. NaN without a usable law.
double predicted_parameter(const SpecialPoint& hb, NormalFormKind kind, double peak) {
  if (!hb.normal_form) return std::numeric_limits<double>::quiet_NaN();
  const NormalForm& nf = *hb.normal_form;
  if (nf.kind != kind || nf.criticality == Criticality::degenerate || !(nf.amplitude > 0) ||
      !std::isfinite(nf.amplitude) || nf.exponent != 0.5 || (nf.side != 1 && nf.side != -1))
    return std::numeric_limits<double>::quiet_NaN();
  const double r = peak / nf.amplitude;
  return hb.p + nf.side * r * r;
}

OrbitSwitchStart hopf_start(const AutonomousSystem& system, const SpecialPoint& hb, const OrbitSwitchOptions& options) {
  options.validate();
  require(hb.type == SpecialPointType::HB, "special_point", static_cast<double>(static_cast<int>(hb.type)),
          "an HB (Hopf point)");
  const Eigen::Index n = system.dimension();
  require(hb.x.size() == n, "special_point", static_cast<double>(hb.x.size()), "a state of the system's dimension");
  Eigen::MatrixXd J;
  system.jacobian(std::span<const double>(hb.x.data(), static_cast<std::size_t>(n)), hb.p, J);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, true);
  const auto critical = critical_values(es.eigenvalues(), StabilityKind::eigenvalues, options.critical_tol);
  if (critical.size() != 1 || !(critical[0].imag() > 0))
    return refusal("not a simple Hopf point at " + system.parameter_name() + " = " + format_value(hb.p) +
                   ": the eigenvalues on the imaginary axis are " +
                   (critical.empty() ? "none" : list_values(critical)) +
                   " (a simple HB has one pair +- i omega and no zero eigenvalue)");
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
  // The predictor's peak |x - x_HB|_2 over t: eps times the largest singular value of [Re q, Im q].
  Eigen::MatrixXd reim(n, 2);
  reim << q.real(), q.imag();
  const double peak = options.amplitude * Eigen::JacobiSVD<Eigen::MatrixXd>(reim).singularValues()[0];
  auto problem = std::make_unique<AutonomousOrbitProblem>(system, static_cast<int>(k), options.orbit);
  const int N = problem->segments();
  OrbitSwitchStart out;
  out.period = kTwoPi / omega;
  out.predicted_p = predicted_parameter(hb, NormalFormKind::hopf, peak);
  Eigen::VectorXd X0(n * N + 1), delta = Eigen::VectorXd::Zero(n * N + 1);
  for (int j = 0; j < N; ++j) {
    X0.segment(j * n, n) = hb.x;
    const std::complex<double> e = std::polar(1.0, kTwoPi * j / N);
    delta.segment(j * n, n) = options.amplitude * (q * e).real();
  }
  X0[n * N] = out.period;
  first_point(*problem, X0, delta, hb.p, out.predicted_p, options, out);
  if (out.found) out.problem = std::move(problem);
  return out;
}

// The unit eigenvector of M's multiplier -1 when it is the only critical one of `multipliers` (empty, with the
// refusal in `why`, otherwise).
std::optional<Eigen::VectorXd> flip_vector(const Eigen::VectorXcd& multipliers, const Eigen::MatrixXd& M,
                                           const std::string& name, double p, double tol, std::string& why) {
  const auto critical = critical_values(multipliers, StabilityKind::multipliers, tol);
  if (critical.size() != 1 || !(critical[0].real() < 0)) {
    why = "not a simple period doubling at " + name + " = " + format_value(p) +
          ": the multipliers on the unit circle are " + (critical.empty() ? "none" : list_values(critical)) +
          " (a simple PD has one multiplier -1)";
    return std::nullopt;
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(M, true);
  Eigen::Index i = 0;
  (es.eigenvalues() - Eigen::VectorXcd::Constant(es.eigenvalues().size(), -1.0)).cwiseAbs().minCoeff(&i);
  const Eigen::VectorXd v = es.eigenvectors().col(i).real();
  return Eigen::VectorXd(v / v.norm());
}

void require_pd(const ContinuationProblem& problem, const SpecialPoint& pd, const OrbitSwitchOptions& options) {
  options.validate();
  require(pd.type == SpecialPointType::PD, "special_point", static_cast<double>(static_cast<int>(pd.type)),
          "a PD (period doubling)");
  require(pd.x.size() == problem.dimension(), "special_point", static_cast<double>(pd.x.size()),
          "a point of this orbit problem");
}

// The doubled orbit's first point: the orbit's unknowns (states X) twice plus eps times the linearised solution V of
// the flip vector (+V over the first turn, -V over the second), Newton from the PD's law for the distance eps.
void doubled_first_point(const ContinuationProblem& doubled, const Eigen::VectorXd& X, const Eigen::VectorXd& V,
                         const Eigen::VectorXd& tail, const SpecialPoint& pd, const OrbitSwitchOptions& options,
                         OrbitSwitchStart& out) {
  const Eigen::Index m = X.size();
  Eigen::VectorXd X0(2 * m + tail.size()), delta = Eigen::VectorXd::Zero(2 * m + tail.size());
  X0 << X, X, tail;
  delta.head(2 * m) << options.amplitude * V, -options.amplitude * V;
  out.predicted_p = predicted_parameter(pd, NormalFormKind::period_doubling, options.amplitude);
  first_point(doubled, X0, delta, pd.p, out.predicted_p, options, out);
}

OrbitSwitchStart period_doubling_start(const PeriodicOrbitProblem& problem, const SpecialPoint& pd,
                                       const OrbitSwitchOptions& options) {
  require_pd(problem, pd, options);
  const Floquet fl = problem.floquet(pd.x, pd.p);
  std::string why;
  const auto v = flip_vector(fl.multipliers, fl.monodromy, problem.parameter_name(), pd.p, options.critical_tol, why);
  if (!v) return refusal(why);
  OrbitOptions o = problem.options();  // the parent's tolerances, on the same segment times
  o.segments = 2 * problem.segments();
  auto doubled = std::make_unique<PeriodicOrbitProblem>(problem.system(), o, 2 * problem.periods());
  OrbitSwitchStart out;
  out.period = 2 * kTwoPi * problem.periods();
  doubled_first_point(*doubled, pd.x, problem.variation(pd.x, pd.p, *v), Eigen::VectorXd(), pd, options, out);
  if (out.found) out.problem = std::move(doubled);
  return out;
}

// The same for an autonomous orbit: twice the segments, the period 2 T as the doubled unknowns' last entry, the same
// phase component.
OrbitSwitchStart autonomous_period_doubling_start(const AutonomousOrbitProblem& problem, const SpecialPoint& pd,
                                                  const OrbitSwitchOptions& options) {
  require_pd(problem, pd, options);
  std::string why;
  const auto v = flip_vector(problem.spectrum(pd.x, pd.p), problem.monodromy(pd.x, pd.p), problem.parameter_name(),
                             pd.p, options.critical_tol, why);
  if (!v) return refusal(why);
  OrbitOptions o = problem.options();
  o.segments = 2 * problem.segments();
  auto doubled = std::make_unique<AutonomousOrbitProblem>(problem.system(), problem.phase_component(), o);
  OrbitSwitchStart out;
  out.period = 2 * AutonomousOrbitProblem::period(pd.x);
  doubled_first_point(*doubled, pd.x.head(pd.x.size() - 1), problem.variation(pd.x, pd.p, *v),
                      Eigen::VectorXd::Constant(1, out.period), pd, options, out);
  if (out.found) out.problem = std::move(doubled);
  return out;
}

// The start continued away from the special point.
OrbitSwitchResult continued(OrbitSwitchStart start, const OrbitSwitchOptions& options) {
  OrbitSwitchResult out;
  out.message = std::move(start.message);
  out.direction = std::move(start.direction);
  out.period = start.period;
  out.rotating_wave_of = start.rotating_wave_of;
  if (!start.found) return out;
  ContinuationOptions o = options.continuation;
  o.direction = start.away;
  out.branch = continue_branch(*start.problem, start.x, start.p, o);
  out.switched = !out.branch.points.empty();
  out.message = out.branch.message;
  out.problem = std::move(start.problem);
  return out;
}

// This model's l >= 3 onset (model/rotating_wave.hpp): an HB of the full model whose pair is an unforced l-block's
// i m/2, crossing with that block's BP (l, m = 0) on the same branch. Not refused (refused false) otherwise.
OrbitSwitchStart rotating_wave_onset(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& hb,
                                     const std::vector<std::complex<double>>& critical) {
  const auto* full = dynamic_cast<const FullEquilibriumProblem*>(&problem);
  if (!full || !hb.mode_l || !hb.mode_m || *hb.mode_l < 3 || *hb.mode_m < 1) return {};
  const int l = *hb.mode_l, m = *hb.mode_m;
  if (!full->model(hb.p).unforced(l)) return {};
  int bp = -1;
  for (std::size_t k = 0; k < branch.special_points.size(); ++k) {
    const SpecialPoint& q = branch.special_points[k];
    if (q.type == SpecialPointType::BP && q.mode_l == l && q.mode_m == 0 &&
        std::abs(q.p - hb.p) <= 1e-8 * (1 + std::abs(hb.p)))
      bp = static_cast<int>(k);
  }
  if (bp < 0) return {};
  const std::string L = std::to_string(l), M = std::to_string(m);
  OrbitSwitchStart out = refusal(
      "the onset of the unforced l = " + L + " block at " + problem.parameter_name() + " = " + format_value(hb.p) +
      ": its pairs Upsilon_" + L + " +- i m/2, m = 1.." + L + ", cross with its BP (l = " + L +
      ", m = 0) there (Upsilon_l is the same for every m). The orbits born at this pair are exact rotating waves: "
      "the states of the branch from that BP with the l = " +
      L + " block turned into mode m = " + M + ", rotating at m/2 = " + format_value(0.5 * m) +
      " (period 4 pi/m = " + format_value(4 * kPi / m) +
      "), by the block's phase symmetry (rotating_wave); they are not followed as separate branches (switch at the "
      "BP for that branch) and their stability is not computed. Eigenvalues on the imaginary axis: " +
      list_values(critical) + "; labels there: " + labels_at(branch, hb));
  out.rotating_wave_of = bp;
  return out;
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
  return continued(hopf_start(system, hb, options), options);
}

OrbitSwitchResult switch_at_period_doubling(const PeriodicOrbitProblem& problem, const SpecialPoint& pd,
                                            const OrbitSwitchOptions& options) {
  return continued(period_doubling_start(problem, pd, options), options);
}

OrbitSwitchStart orbit_switch_start(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& point,
                                    const OrbitSwitchOptions& options) {
  if (point.type == SpecialPointType::HB) {
    if (const auto* eq = dynamic_cast<const AutonomousEquilibriumProblem*>(&problem))
      return hopf_start(eq->system(), point, options);
    const auto critical =
        critical_values(problem.spectrum(point.x, point.p), StabilityKind::eigenvalues, options.critical_tol);
    if (OrbitSwitchStart w = rotating_wave_onset(problem, branch, point, critical); w.refused) return w;
    if (critical.size() > 1)
      return refusal("a multiple Hopf point at " + problem.parameter_name() + " = " + format_value(point.p) +
                     ": eigenvalues on the imaginary axis " + list_values(critical) +
                     "; labels there: " + labels_at(branch, point) +
                     ". Switching needs one simple pair (the symmetric onset is a family of orbits, "
                     "docs/continuation.md)");
    return refusal(
        "a simple HB, but switching at an HB is supported on branches of autonomous systems' equilibria "
        "only (AutonomousEquilibriumProblem), not this problem kind");
  }
  if (point.type == SpecialPointType::PD) {
    if (const auto* orbit = dynamic_cast<const PeriodicOrbitProblem*>(&problem))
      return period_doubling_start(*orbit, point, options);
    if (const auto* orbit = dynamic_cast<const AutonomousOrbitProblem*>(&problem))
      return autonomous_period_doubling_start(*orbit, point, options);
    return refusal(
        "switching at a PD is supported on periodic-orbit branches only (PeriodicOrbitProblem, "
        "AutonomousOrbitProblem), not this problem kind");
  }
  return refusal(std::string("no orbit switch at a ") + std::string(to_string(point.type)) +
                 " point (HB and PD only; BP: switch_branch)");
}

OrbitSwitchResult switch_at(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& point,
                            const OrbitSwitchOptions& options) {
  return continued(orbit_switch_start(problem, branch, point, options), options);
}

}  // namespace rbcstab
