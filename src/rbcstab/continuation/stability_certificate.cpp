// Stability certificates: a spectrum's margin from the stability boundary with its error (certify), widened
// by the margin's change when the state moves by its error (certify_solution, the engine's points).
#include "rbcstab/continuation/stability_certificate.hpp"

#include "rbcstab/continuation/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "rbcstab/continuation/detail/continuation_engine.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

// How far a spectral value lies on the unstable side of the boundary: Re(lambda) or |mu| - 1.
double unstable_side(std::complex<double> v, StabilityKind kind) {
  return kind == StabilityKind::eigenvalues ? v.real() : std::abs(v) - 1;
}

// The margin of a spectrum's critical value (NaN when the spectrum is empty or not finite).
double margin_of(const Eigen::VectorXcd& spectrum, StabilityKind kind) {
  double a = -std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < spectrum.size(); ++i) a = std::max(a, unstable_side(spectrum[i], kind));
  return spectrum.size() > 0 && spectrum.allFinite() ? -a : std::numeric_limits<double>::quiet_NaN();
}

Stability label(double margin, double margin_error) {
  if (!(margin_error >= 0) || !(std::abs(margin) > margin_error)) return Stability::uncertain;
  return margin > 0 ? Stability::stable : Stability::unstable;
}

// c's label after margin_error grew by a term of size `term`: an uncertain label names the largest term
// (`largest` when this one is, else the one named before; a label made uncertain only now: this one).
void relabel(StabilityCertificate& c, double previous_error, double term, CertificateTerm kind) {
  const Stability before = c.stability;
  c.stability = label(c.margin, c.margin_error);
  if (c.stability != Stability::uncertain)
    c.uncertain_because = CertificateTerm::none;
  else if (!std::isfinite(c.margin))
    c.uncertain_because = CertificateTerm::spectrum;
  else if (!(c.margin_error < std::numeric_limits<double>::infinity()))
    c.uncertain_because = CertificateTerm::error_bound;
  else if (before != Stability::uncertain || term > previous_error)
    c.uncertain_because = kind;
}

// How far a Newton solution may be off: the next Newton step, but at least the accuracy the corrector
// accepts (tol: newton_tol (1 + |X|)), since a residual that rounds to 0 gives a zero step without an
// exact state (e.g. a spectrum that cancels to 1e-32 at a degenerate point). Along a zero step the
// direction is a fixed generic one.
Eigen::VectorXd state_perturbation(const Eigen::VectorXd& step, double tol) {
  if (!step.allFinite()) return step;
  const double size = step.lpNorm<Eigen::Infinity>();
  if (size >= tol) return step;
  if (size > 0) return step * (tol / size);
  Eigen::VectorXd d(step.size());
  for (Eigen::Index i = 0; i < d.size(); ++i)
    d[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1 + static_cast<double>(i) / static_cast<double>(d.size()));
  return d * (tol / d.lpNorm<Eigen::Infinity>());
}

// Widens c by how much the margin moves when the state moves by its error (x_next, p_next: the state
// perturbed by state_perturbation).
void add_state_term(StabilityCertificate& c, const ContinuationProblem& problem, const Eigen::VectorXd& x_next,
                    double p_next) {
  if (!x_next.allFinite() || !std::isfinite(p_next)) return;  // a singular step (a fold start): no reading
  double m = 0;
  try {
    m = margin_of(problem.spectrum(x_next, p_next), problem.stability_kind());
  } catch (const InvalidArgument&) {
    return;  // the step left the problem's domain
  }
  if (!std::isfinite(m)) return;
  const double previous = c.margin_error, term = std::abs(m - c.margin);
  c.margin_error = std::max(previous, term);
  relabel(c, previous, term, CertificateTerm::state_error);
}

}  // namespace

StabilityCertificate certify(const CertifiedSpectrum& spectrum, StabilityKind kind) {
  StabilityCertificate c;
  const Eigen::VectorXcd& s = spectrum.values;
  if (s.size() == 0 || spectrum.errors.size() != s.size()) return c;
  const double inf = std::numeric_limits<double>::infinity();
  double a = -inf, lo = -inf, hi = -inf;
  bool known = true;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const double ai = unstable_side(s[i], kind), e = spectrum.errors[i];
    known = known && e >= 0;
    a = std::max(a, ai);
    lo = std::max(lo, ai - e);
    hi = std::max(hi, ai + e);
  }
  c.margin = s.allFinite() ? -a : std::numeric_limits<double>::quiet_NaN();
  c.margin_error =
      known && std::isfinite(c.margin) ? std::max(hi - a, a - lo) : std::numeric_limits<double>::quiet_NaN();
  c.stability = label(c.margin, c.margin_error);
  c.uncertain_because = c.stability != Stability::uncertain ? CertificateTerm::none
                        : !std::isfinite(c.margin)          ? CertificateTerm::spectrum
                        : !(c.margin_error < inf)           ? CertificateTerm::error_bound
                                                            : CertificateTerm::spectral_error;
  return c;
}

StabilityCertificate certify_solution(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p,
                                      double newton_tol) {
  StabilityCertificate c = certify(problem.certified_spectrum(x, p, true), problem.stability_kind());
  if (!std::isfinite(c.margin)) return c;
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  problem.residual(x, p, F);
  problem.jacobian(x, p, J);
  const Eigen::VectorXd step = J.partialPivLu().solve(-F);
  add_state_term(c, problem, x + state_perturbation(step, newton_tol * (1 + x.lpNorm<Eigen::Infinity>())), p);
  return c;
}

namespace detail {

// The certificate of corrected point q: the problem's cheap one; near the boundary (special points:
// always) the refined one, widened by the margin's change when the state moves by its error (one
// more corrector step, at least newton_tol: state_perturbation).
StabilityCertificate Engine::certificate(const Pt& q, bool special) {
  if (!o_.compute_stability) return {};
  const Eigen::VectorXd x = q.X.head(n_);
  const double p = q.X[n_];
  const StabilityKind kind = pr_.stability_kind();
  StabilityCertificate c = certify(pr_.certified_spectrum(x, p, false), kind);
  if (!special && !(std::abs(c.margin) <= o_.certificate_refine_margin)) return c;
  c = certify(pr_.certified_spectrum(x, p, true), kind);
  if (!std::isfinite(c.margin)) return c;
  assemble(q.X, q.t);  // the bordered system: the step keeps the point's arclength
  Eigen::VectorXd R = Eigen::VectorXd::Zero(N_);
  R.head(n_) = F_;
  const Eigen::VectorXd step = Eigen::PartialPivLU<Eigen::MatrixXd>(A_).solve(-R);
  const Eigen::VectorXd X1 = q.X + state_perturbation(step, o_.newton_tol * (1 + q.X.lpNorm<Eigen::Infinity>()));
  add_state_term(c, pr_, X1.head(n_), X1[n_]);
  return c;
}

// A special point located to within the bracket [lo, hi] (margins m_lo, m_hi at its ends) from q:
// its certificate, whose error also covers the margin's change across the bracket.
void Engine::set_certificate(SpecialPoint& sp, const Pt& q, double m_lo, double m_hi) {
  const StabilityCertificate c = certificate(q, true);
  StabilityCertificate w = c;
  const double bracket = std::abs(m_hi - m_lo);
  // A bracket whose margins are unknown leaves the error unknown (NaN), as the sum did.
  w.margin_error = c.margin_error + bracket;
  relabel(w, c.margin_error, std::isnan(bracket) ? std::numeric_limits<double>::infinity() : bracket,
          CertificateTerm::location);
  sp.margin = w.margin;
  sp.margin_error = w.margin_error;
  sp.stability = w.stability;
  sp.uncertain_because = w.uncertain_because;
}

double Engine::margin(const Pt& q) const { return margin_of(q.spectrum, pr_.stability_kind()); }

}  // namespace detail

}  // namespace rbcstab
