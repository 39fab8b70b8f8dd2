// Normal forms at LPC, PD and NS of orbit branches (period_map_normal_form.hpp): the forced orbit's period map or the
// autonomous orbit's Poincare map (poincare_map.hpp) as a MapProblem whose residual is P(y, p) - y, differentiated
// by detail::Multilinear with steps sized for shootings; one set of Kuznetsov's formulas for maps serves both.
// docs/continuation.md, "Normal forms".
#include "rbcstab/continuation/period_map_normal_form.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <utility>

#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/normal_form_analysis.hpp"
#include "rbcstab/continuation/poincare_map.hpp"

#include "rbcstab/continuation/detail/multilinear.hpp"
#include "rbcstab/continuation/detail/normal_form_core.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

void PeriodMapSteps::validate() const {
  for (const auto& [name, v] : {std::pair{"steps.second", second}, std::pair{"steps.third", third}})
    require(std::isfinite(v) && v > 0 && v <= 0.1, name, v, "a number in (0, 0.1]");
}

namespace {

using cd = std::complex<double>;
using detail::extend;
using detail::extend_complex;
using detail::kKernel;
using detail::kSingular;
using detail::kVanish;
using detail::Multilinear;
using detail::normal_form_degenerate;
using detail::normal_form_not_computed;

double sign_of(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

// The period map of `orbit` as a problem in y = x0: residual P(y, p) - y, A the monodromy, parameter derivative P_p.
class PeriodMap final : public MapProblem {
 public:
  explicit PeriodMap(const PeriodicOrbitProblem& orbit) : orbit_(orbit), n_(orbit.system().dimension()) {}
  Eigen::Index dimension() const override { return n_; }
  // One plain integration over the period (relax for one period: no variational equations, 1/(n + 2) of a
  // shooting's work); NaN when it fails.
  void residual(const Eigen::VectorXd& y, double p, Eigen::VectorXd& F) const override {
    const OrbitRelaxation r = orbit_.relax(y, p, std::numeric_limits<double>::min(), 1, 1);
    F = r.failure.empty() ? Eigen::VectorXd(r.x - y) : Eigen::VectorXd::Constant(n_, std::nan(""));
  }
  Eigen::MatrixXd map_jacobian(const Eigen::VectorXd& y, double p) const override {
    return orbit_.floquet(orbit_.shooting_guess(y, p), p).monodromy;
  }
  // The segments' sensitivities s_j carried through the segment maps M_j (the shooting Jacobian's diagonal
  // blocks; with one segment that block is M_0 - I): d x_{j+1}/dp = M_j d x_j/dp + s_j from x_0 = y.
  void parameter_derivative(const Eigen::VectorXd& y, double p, Eigen::VectorXd& Fp) const override {
    const Eigen::VectorXd X = orbit_.shooting_guess(y, p);
    Eigen::MatrixXd J;
    Eigen::VectorXd s;
    orbit_.jacobian(X, p, J);
    orbit_.parameter_derivative(X, p, s);
    const int N = orbit_.segments();
    Fp = Eigen::VectorXd::Zero(n_);
    for (int j = 0; j < N; ++j) {
      Eigen::MatrixXd M = J.block(j * n_, j * n_, n_, n_);
      if (N == 1) M += Eigen::MatrixXd::Identity(n_, n_);
      Fp = M * Fp + s.segment(j * n_, n_);
    }
  }

 private:
  const PeriodicOrbitProblem& orbit_;
  Eigen::Index n_;
};

// B and C of P at (y0, p), each Richardson-extrapolated from its step and half of it (steps in units of scale).
class MapForms {
 public:
  MapForms(const MapProblem& map, const Eigen::VectorXd& y0, double p, const PeriodMapSteps& steps, double scale)
      : coarse_(map, y0, p, steps.second * scale, steps.third * scale),
        fine_(map, y0, p, steps.second * scale / 2, steps.third * scale / 2) {}
  template <class V>
  V B(const V& u, const V& v) const {
    using S = typename V::Scalar;
    return V((fine_.B(u, v) * S(4) - coarse_.B(u, v)) / S(3));
  }
  template <class V>
  V C(const V& u, const V& v, const V& w) const {
    using S = typename V::Scalar;
    return V((fine_.C(u, v, w) * S(4) - coarse_.C(u, v, w)) / S(3));
  }

 private:
  Multilinear coarse_, fine_;
};

// Why no period-map normal form is computed for this problem ("" when one is).
std::string map_refusal(const PeriodicOrbitProblem& problem) {
  if (problem.system().conserves_norm())
    return "a norm-conserving system: its period map has the trivial multiplier 1 off the sphere";
  return "";
}

// (I - A) regular: no multiplier 1 besides the critical one(s) (a multiplier 1 makes the centre manifold larger).
bool one_is_not_a_multiplier(const Eigen::MatrixXd& A) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd::Identity(A.rows(), A.cols()) - A);
  return svd.singularValues()[A.rows() - 1] > kKernel * svd.singularValues()[0];
}

// The normal forms of a map at its fixed point x0 (a period map's or a Poincare map's); difference steps in units
// of `scale`.
NormalForm map_fold(const MapProblem& map, const Eigen::VectorXd& x0, double p, const PeriodMapSteps& steps,
                    double scale) {
  const NormalFormKind kind = NormalFormKind::fold_of_cycles;
  Eigen::MatrixXd J;
  Eigen::VectorXd Pp;
  map.jacobian(x0, p, J);
  map.parameter_derivative(x0, p, Pp);
  if (!J.allFinite() || !Pp.allFinite()) return normal_form_not_computed(kind, "a shooting failed at the point");
  const MapForms D(map, x0, p, steps, scale);
  NormalForm nf = detail::fold_from_derivatives(J, Pp, [&](const Eigen::VectorXd& e) { return D.B(e, e); });
  nf.kind = kind;
  return nf;
}

NormalForm map_flip(const MapProblem& map, const Eigen::VectorXd& x0, double p, const PeriodMapSteps& steps,
                    double scale) {
  const NormalFormKind kind = NormalFormKind::period_doubling;
  NormalForm pd;
  pd.kind = kind;
  const Eigen::MatrixXd A = map.map_jacobian(x0, p);
  if (!A.allFinite()) return normal_form_not_computed(kind, "a shooting failed at the point");
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A, true), est(A.transpose(), true);
  Eigen::Index i = 0, it = 0;
  (es.eigenvalues().array() + 1.0).abs().minCoeff(&i);
  (est.eigenvalues().array() + 1.0).abs().minCoeff(&it);
  const auto near_minus_one = ((es.eigenvalues().array() + 1.0).abs() <= 1e-4).count();
  if (near_minus_one != 1)
    return normal_form_degenerate(pd, "degenerate (" + std::to_string(near_minus_one) + " multipliers near -1)");
  Eigen::VectorXd q = es.eigenvectors().col(i).real(), w = est.eigenvectors().col(it).real();
  q /= q.norm();
  if (!(std::abs(w.dot(q)) > kSingular * w.norm())) return normal_form_degenerate(pd, "<w, q> = 0");
  w /= w.dot(q);
  if (!one_is_not_a_multiplier(A)) return normal_form_degenerate(pd, "a multiplier 1 besides -1 (I - A singular)");
  const Eigen::FullPivLU<Eigen::MatrixXd> I_A(Eigen::MatrixXd::Identity(A.rows(), A.cols()) - A);
  const MapForms D(map, x0, p, steps, scale);
  const Eigen::VectorXd eq = extend(q, 0.0);
  const Eigen::VectorXd h2 = I_A.solve(D.B(eq, eq));
  const Eigen::VectorXd Bqh = D.B(eq, extend(h2, 0.0)), Cqqq = D.C(eq, eq, eq);
  Eigen::VectorXd Pp;
  map.parameter_derivative(x0, p, Pp);
  // d mu / dp = <w, (dA/dp) q>, dA/dp = D^2 P[., (x_p, 1)] along the orbit x0(p) (x_p = A x_p + P_p).
  const double mu_p = w.dot(D.B(eq, extend(I_A.solve(Pp), 1.0)));
  if (!Cqqq.allFinite() || !Bqh.allFinite() || !std::isfinite(mu_p))
    return normal_form_not_computed(kind, "a shooting of the period map failed near the point");
  const double cubic = w.dot(Cqqq) / 6, quadratic = w.dot(Bqh) / 2, c = cubic + quadratic;
  pd.coefficients = {{"c", c}, {"cubic", cubic}, {"quadratic", quadratic}, {"mu_p", mu_p}};
  if (std::abs(c) <= kVanish * std::max({std::abs(cubic), std::abs(quadratic), 1e-300}))
    return normal_form_degenerate(pd, "c = 0 to its accuracy");
  pd.criticality = c > 0 ? Criticality::supercritical : Criticality::subcritical;
  // The second iterate eta -> (1 + 2 beta) eta - 2 c eta^3 (beta = -(mu + 1)) has the fixed points eta^2 = beta / c.
  if (mu_p != 0) {
    pd.amplitude = std::sqrt(std::abs(mu_p / c));
    pd.exponent = 0.5;
    pd.side = -sign_of(mu_p * c);
  }
  return pd;
}

NormalForm map_neimark_sacker(const MapProblem& map, const Eigen::VectorXd& x0, double p, const PeriodMapSteps& steps,
                              double scale) {
  const NormalFormKind kind = NormalFormKind::neimark_sacker;
  NormalForm ns;
  ns.kind = kind;
  const Eigen::MatrixXd A = map.map_jacobian(x0, p);
  if (!A.allFinite()) return normal_form_not_computed(kind, "a shooting failed at the point");
  const Eigen::Index n = A.rows();
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A, true), est(A.transpose(), true);
  const Eigen::VectorXcd& mu = es.eigenvalues();
  // The critical pairs: on the unit circle (to the location's accuracy), off the real axis.
  int pairs = 0;
  Eigen::Index i = 0;
  for (Eigen::Index k = 0; k < n; ++k)
    if (mu[k].imag() > 1e-8 && std::abs(std::abs(mu[k]) - 1) <= 1e-4) {
      ++pairs;
      i = k;
    }
  if (pairs == 0) return normal_form_not_computed(kind, "no complex pair of multipliers on the unit circle");
  if (pairs > 1) return normal_form_degenerate(ns, "degenerate (" + std::to_string(pairs) + " pairs)");
  const double theta = std::arg(mu[i]);
  for (int k = 3; k <= 4; ++k)
    if (std::abs(std::polar(1.0, k * theta) - 1.0) <= 1e-4)
      return normal_form_degenerate(
          ns, "a strong resonance 1:" + std::to_string(k) + " (theta = " + format_value(theta) + ")");
  if (!one_is_not_a_multiplier(A)) return normal_form_degenerate(ns, "a multiplier 1 (I - A singular)");
  Eigen::Index j = 0;
  (est.eigenvalues().array() - std::conj(mu[i])).abs().minCoeff(&j);
  const Eigen::VectorXcd q = es.eigenvectors().col(i).normalized();
  Eigen::VectorXcd pl = est.eigenvectors().col(j);
  const cd pq = pl.dot(q);  // p^H q
  if (!(std::abs(pq) > 1e-10 * pl.norm())) return normal_form_degenerate(ns, "<p, q> = 0");
  pl /= std::conj(pq);  // <p, q> = 1
  const Eigen::MatrixXcd Ac = A.cast<cd>(), I = Eigen::MatrixXcd::Identity(n, n);
  const MapForms D(map, x0, p, steps, scale);
  const Eigen::VectorXcd eq = extend_complex(q, 0.0), eqb = extend_complex(q.conjugate(), 0.0);
  const Eigen::VectorXcd h11 = (I - Ac).partialPivLu().solve(D.B(eq, eqb));
  const Eigen::VectorXcd h20 = (std::polar(1.0, 2 * theta) * I - Ac).partialPivLu().solve(D.B(eq, eq));
  const cd t1 = pl.dot(D.C(eq, eq, eqb)), t2 = 2.0 * pl.dot(D.B(eq, extend_complex(h11, 0.0))),
           t3 = pl.dot(D.B(eqb, extend_complex(h20, 0.0)));
  const cd e = std::polar(1.0, -theta);
  const double cubic = (e * t1 / 2.0).real(), quadratic = (e * (t2 + t3) / 2.0).real(), d = cubic + quadratic;
  // d|mu|/dp = Re(e^{-i theta} <p, (dA/dp) q>), dA/dp as for the PD.
  Eigen::VectorXd Pp;
  map.parameter_derivative(x0, p, Pp);
  const Eigen::VectorXd xp = (Eigen::MatrixXd::Identity(n, n) - A).fullPivLu().solve(Pp);
  const double modulus_p = (e * pl.dot(D.B(eq, extend_complex(xp.cast<cd>(), 1.0)))).real();
  if (!std::isfinite(d) || !std::isfinite(modulus_p))
    return normal_form_not_computed(kind, "a shooting of the period map failed near the point");
  ns.coefficients = {{"d", d}, {"cubic", cubic}, {"quadratic", quadratic}, {"theta", theta}, {"modulus_p", modulus_p}};
  if (!(std::abs(d) > kVanish * (std::abs(t1) + std::abs(t2) + std::abs(t3)) / 2))
    return normal_form_degenerate(ns, "d = 0 to its accuracy (a Chenciner point)");
  ns.criticality = d < 0 ? Criticality::supercritical : Criticality::subcritical;
  if (modulus_p != 0) {
    ns.amplitude = detail::circle_peak(q) * std::sqrt(std::abs(modulus_p / d));
    ns.exponent = 0.5;
    ns.side = -sign_of(modulus_p * d);
  }
  return ns;
}

using MapNormalForm = NormalForm (*)(const MapProblem&, const Eigen::VectorXd&, double, const PeriodMapSteps&, double);

NormalForm on_period_map(MapNormalForm form, NormalFormKind kind, const PeriodicOrbitProblem& problem,
                         const Eigen::VectorXd& X, double p, const PeriodMapSteps& steps) {
  steps.validate();
  if (const std::string why = map_refusal(problem); !why.empty()) return normal_form_not_computed(kind, why);
  const Eigen::VectorXd x0 = problem.state_at_zero(X);
  return form(PeriodMap(problem), x0, p, steps, 1 + x0.lpNorm<Eigen::Infinity>());
}

// On the section the orbit's point is xi = 0; the steps scale with the state x0 as for a forced orbit.
NormalForm on_poincare_map(MapNormalForm form, const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X,
                           double p, const PeriodMapSteps& steps) {
  steps.validate();
  const PoincareMap map(problem, X, p);
  return form(map, Eigen::VectorXd::Zero(map.dimension()), p, steps,
              1 + problem.state_at_zero(X).lpNorm<Eigen::Infinity>());
}

}  // namespace

NormalForm fold_of_cycles_normal_form(const PeriodicOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps) {
  return on_period_map(map_fold, NormalFormKind::fold_of_cycles, problem, X, p, steps);
}
NormalForm period_doubling_normal_form(const PeriodicOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                       const PeriodMapSteps& steps) {
  return on_period_map(map_flip, NormalFormKind::period_doubling, problem, X, p, steps);
}
NormalForm neimark_sacker_normal_form(const PeriodicOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps) {
  return on_period_map(map_neimark_sacker, NormalFormKind::neimark_sacker, problem, X, p, steps);
}
NormalForm fold_of_cycles_normal_form(const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps) {
  return on_poincare_map(map_fold, problem, X, p, steps);
}
NormalForm period_doubling_normal_form(const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                       const PeriodMapSteps& steps) {
  return on_poincare_map(map_flip, problem, X, p, steps);
}
NormalForm neimark_sacker_normal_form(const AutonomousOrbitProblem& problem, const Eigen::VectorXd& X, double p,
                                      const PeriodMapSteps& steps) {
  return on_poincare_map(map_neimark_sacker, problem, X, p, steps);
}

NormalForm period_map_normal_form(const ContinuationProblem& problem, const SpecialPoint& sp) {
  const NormalFormKind kind = sp.type == SpecialPointType::LPC  ? NormalFormKind::fold_of_cycles
                              : sp.type == SpecialPointType::PD ? NormalFormKind::period_doubling
                              : sp.type == SpecialPointType::NS ? NormalFormKind::neimark_sacker
                                                                : NormalFormKind::branch_point;
  if (kind == NormalFormKind::branch_point)
    return normal_form_not_computed(kind, "no period-map normal form for " + to_string(sp.type));
  const auto* orbit = dynamic_cast<const PeriodicOrbitProblem*>(&problem);
  const auto* autonomous = dynamic_cast<const AutonomousOrbitProblem*>(&problem);
  if (!orbit && !autonomous)
    return normal_form_not_computed(kind, "needs an orbit problem (PeriodicOrbitProblem or AutonomousOrbitProblem)");
  if (sp.status != LocationStatus::located) return normal_form_not_computed(kind, "the point is not located (a guess)");
  const Eigen::Index n = orbit ? orbit->system().dimension() : autonomous->system().dimension();
  if (n > kNormalFormMaxDimension)
    return normal_form_not_computed(kind,
                                    "dimension " + std::to_string(n) + " > " + std::to_string(kNormalFormMaxDimension));
  try {
    if (autonomous) {
      if (kind == NormalFormKind::fold_of_cycles) return fold_of_cycles_normal_form(*autonomous, sp.x, sp.p);
      if (kind == NormalFormKind::period_doubling) return period_doubling_normal_form(*autonomous, sp.x, sp.p);
      return neimark_sacker_normal_form(*autonomous, sp.x, sp.p);
    }
    if (kind == NormalFormKind::fold_of_cycles) return fold_of_cycles_normal_form(*orbit, sp.x, sp.p);
    if (kind == NormalFormKind::period_doubling) return period_doubling_normal_form(*orbit, sp.x, sp.p);
    return neimark_sacker_normal_form(*orbit, sp.x, sp.p);
  } catch (const InvalidArgument& e) {
    return normal_form_not_computed(kind, std::string("the system or the section refused the point: ") + e.what());
  }
}

}  // namespace rbcstab
