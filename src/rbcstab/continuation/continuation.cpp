#include "rbcstab/continuation/continuation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/core/error.hpp"

namespace rbcstab {

const SpecialPoint* find_special_point(const Branch& b, SpecialPointType type, int k) {
  for (const auto& sp : b.special_points)
    if (sp.type == type && --k == 0) return &sp;
  return nullptr;
}

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
  for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1 + static_cast<double>(i) / static_cast<double>(d.size()));
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
  if (std::isfinite(m)) c.margin_error = std::max(c.margin_error, std::abs(m - c.margin));
  c.stability = label(c.margin, c.margin_error);
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
  c.margin_error = known && std::isfinite(c.margin) ? std::max(hi - a, a - lo) : std::numeric_limits<double>::quiet_NaN();
  c.stability = label(c.margin, c.margin_error);
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


void ContinuationOptions::validate() const {
  require(std::isfinite(max_step) && max_step > 0, "max_step", max_step, "a finite number > 0");
  require(std::isfinite(initial_step) && initial_step > 0 && initial_step <= max_step, "initial_step", initial_step,
          "in (0, max_step] with max_step = " + format_value(max_step));
  require(std::isfinite(min_step) && min_step > 0 && min_step <= initial_step, "min_step", min_step,
          "a number in (0, initial_step]");
  require(step_growth >= 1 && step_growth <= 10, "step_growth", step_growth, "[1, 10]");
  require(step_shrink > 0 && step_shrink < 1, "step_shrink", step_shrink, "(0, 1)");
  require(easy_iterations >= 1, "easy_iterations", easy_iterations, "an integer >= 1");
  require(max_newton >= 2 && max_newton <= 100, "max_newton", max_newton, "an integer in [2, 100]");
  require(newton_tol > 0 && newton_tol < 1e-2, "newton_tol", newton_tol, "(0, 1e-2)");
  require(!std::isnan(p_min) && !std::isnan(p_max) && p_min < p_max, "p_min", p_min, "a number < p_max");
  require(max_points >= 2, "max_points", static_cast<double>(max_points), "an integer >= 2");
  require(location_tol > 0, "location_tol", location_tol, "a number > 0");
  require(max_location_iterations >= 1, "max_location_iterations", max_location_iterations, "an integer >= 1");
  require(stability_tol >= 0, "stability_tol", stability_tol, "a number >= 0");
  require(certificate_refine_margin >= 0, "certificate_refine_margin", certificate_refine_margin, "a number >= 0 (or inf)");
  for (const auto& e : events) {
    if (!e.g) throw InvalidArgument("events", "event '" + e.name + "' has no function");
  }
}

namespace {

constexpr int kSlots = 4;  // test function slots: 0 LP/LPC, 1 BP, 2 HB/NS, 3 PD (cycles only)

// A corrected point with what the detectors need.
struct Pt {
  Eigen::VectorXd X;  // (x, p)
  Eigen::VectorXd t;  // unit tangent, oriented along the continuation
  Eigen::VectorXcd spectrum;
  int n_unstable = 0;
  std::array<double, kSlots> tests{};
  std::vector<double> events;
  int iterations = 0;
};

// z / (1 + |z|): keeps the argument (hence the sign of a real product) and avoids overflow.
std::complex<double> squash(std::complex<double> z) { return z / (1 + std::abs(z)); }

class Engine {
 public:
  Engine(const ContinuationProblem& problem, const ContinuationOptions& options)
      : pr_(problem), o_(options), n_(problem.dimension()), N_(n_ + 1), cycles_(problem.stability_kind() == StabilityKind::multipliers) {}

  ContinuationCounters counters;

  // Newton on [F(x, p); border.(X - X0) - s] = 0 (pseudo-arclength, or p = bound with border = e_p).
  bool correct(Eigen::VectorXd& X, const Eigen::VectorXd& border, const Eigen::VectorXd& X0, double s, int& iterations) {
    iterations = 0;
    for (int it = 0; it < o_.max_newton; ++it) {
      assemble(X, border);
      Eigen::VectorXd R(N_);
      R.head(n_) = F_;
      R[n_] = border.dot(X - X0) - s;
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(A_);
      const Eigen::VectorXd dX = lu.solve(-R);
      ++iterations;
      ++counters.newton_iterations;
      if (!dX.allFinite()) return false;
      X += dX;
      if (dX.lpNorm<Eigen::Infinity>() <= o_.newton_tol * (1 + X.lpNorm<Eigen::Infinity>())) {
        // Quadratic convergence: the error after this update is ~ |dX|^2; confirm with the residual.
        eval_F(X);
        return F_.allFinite() && F_.lpNorm<Eigen::Infinity>() <= std::sqrt(o_.newton_tol) * 1e-3;
      }
      if (dX.lpNorm<Eigen::Infinity>() > 1e3 * (1 + X.lpNorm<Eigen::Infinity>())) return false;  // diverging
    }
    return false;
  }

  // Tangent at X oriented by t_prev (t_prev . t > 0), spectrum, test functions and events.
  Pt finish(const Eigen::VectorXd& X, const Eigen::VectorXd& t_prev, int iterations) {
    Pt q;
    q.X = X;
    q.iterations = iterations;
    assemble(X, t_prev);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(A_);
    Eigen::VectorXd e = Eigen::VectorXd::Zero(N_);
    e[n_] = 1;
    q.t = lu.solve(e);
    q.t.normalize();
    if (q.t.dot(t_prev) < 0) q.t = -q.t;
    const double p = X[n_];
    const Eigen::VectorXd x = X.head(n_);
    q.tests.fill(std::nan(""));
    if (o_.compute_stability) {
      q.spectrum = pr_.spectrum(x, p);
      ++counters.spectra;
      q.n_unstable = count_unstable(q.spectrum, pr_.stability_kind(), o_.stability_tol);
    }
    if (o_.detect_bifurcations) {
      q.tests[0] = q.t[n_];
      // BP: det of the bordered Jacobian with the point's own tangent changes sign at a branch point
      // (and not at a fold, where the tangent turns with it).
      assemble(X, q.t);
      q.tests[1] = Eigen::PartialPivLU<Eigen::MatrixXd>(A_).determinant();
      if (o_.compute_stability) {
        const Eigen::VectorXcd& s = q.spectrum;
        std::complex<double> prod = 1;
        if (!cycles_) {
          // HB: prod_{i<j} (l_i + l_j) (bialternate-product determinant) vanishes when a pair l, conj(l)
          // has Re = 0; its sign changes when one pair crosses. Neutral saddles are filtered on location.
          for (Eigen::Index i = 0; i < s.size(); ++i)
            for (Eigen::Index j = i + 1; j < s.size(); ++j) prod *= squash(s[i] + s[j]);
          q.tests[2] = prod.real();
        } else {
          // NS: prod_{i<j} (mu_i mu_j - 1); PD: prod (1 + mu_i).
          for (Eigen::Index i = 0; i < s.size(); ++i)
            for (Eigen::Index j = i + 1; j < s.size(); ++j) prod *= squash(s[i] * s[j] - 1.0);
          q.tests[2] = prod.real();
          std::complex<double> pd = 1;
          for (Eigen::Index i = 0; i < s.size(); ++i) pd *= squash(1.0 + s[i]);
          q.tests[3] = pd.real();
        }
      }
    }
    q.events.resize(o_.events.size());
    for (std::size_t k = 0; k < o_.events.size(); ++k) q.events[k] = o_.events[k].g(x, p);
    return q;
  }

  // The point at arclength s along a's tangent (corrected), or nullopt-like failure.
  bool probe(const Pt& a, double s, Pt& out) {
    Eigen::VectorXd X = a.X + s * a.t;
    int it = 0;
    if (!correct(X, a.t, a.X, s, it)) return false;
    out = finish(X, a.t, it);
    return true;
  }

  double test_value(const Pt& q, int slot, int event) const {
    return event >= 0 ? q.events[static_cast<std::size_t>(event)] : q.tests[static_cast<std::size_t>(slot)];
  }

  // Whether the eigenvalue/multiplier that test slot k watches is within stability_tol of critical.
  bool neutral(const Pt& q, int slot) const {
    const Eigen::VectorXcd& s = q.spectrum;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
      double d = 0;
      if (!cycles_) d = s[i].imag() != 0 ? std::abs(s[i].real()) : std::numeric_limits<double>::infinity();
      else if (slot == 2) d = s[i].imag() != 0 ? std::abs(std::abs(s[i]) - 1) : std::numeric_limits<double>::infinity();
      else d = std::abs(s[i] + 1.0);
      if (d <= o_.stability_tol) return true;
    }
    return false;
  }

  SpecialPointType slot_type(int slot) const {
    switch (slot) {
      case 0: return cycles_ ? SpecialPointType::LPC : SpecialPointType::LP;
      case 1: return SpecialPointType::BP;
      case 2: return cycles_ ? SpecialPointType::NS : SpecialPointType::HB;
      default: return SpecialPointType::PD;
    }
  }

  // Illinois-safeguarded secant on the arclength between a (s = 0) and b (s = sb) for a zero of one
  // test function (slot) or user event (event >= 0).
  bool locate(const Pt& a, const Pt& b, int slot, int event, std::size_t after, SpecialPoint& sp) {
    double s_lo = 0, s_hi = a.t.dot(b.X - a.X);
    double g_lo = test_value(a, slot, event), g_hi = test_value(b, slot, event);
    Eigen::VectorXd X_lo = a.X, X_hi = b.X;
    double m_lo = margin(a), m_hi = margin(b);
    Pt best = std::abs(g_lo) < std::abs(g_hi) ? a : b;
    double g_best = std::min(std::abs(g_lo), std::abs(g_hi));
    int side = 0;
    bool converged = false;
    for (int it = 0; it < o_.max_location_iterations; ++it) {
      if ((X_hi - X_lo).lpNorm<Eigen::Infinity>() < o_.location_tol) {
        converged = true;
        break;
      }
      ++counters.location_iterations;
      double s = s_lo - g_lo * (s_hi - s_lo) / (g_hi - g_lo);
      const double w = s_hi - s_lo;
      // Safeguard: stay inside the bracket and away from its ends; bisect every third step.
      if (!std::isfinite(s) || std::abs(s - s_lo) < 1e-3 * std::abs(w) || std::abs(s_hi - s) < 1e-3 * std::abs(w) || it % 3 == 2)
        s = 0.5 * (s_lo + s_hi);
      Pt q;
      if (!probe(a, s, q)) break;
      const double g = test_value(q, slot, event);
      if (std::abs(g) < g_best) {
        g_best = std::abs(g);
        best = q;
      }
      if (g == 0) {
        X_lo = X_hi = q.X;
        m_lo = m_hi = margin(q);
        converged = true;
        break;
      }
      if ((g > 0) == (g_lo > 0)) {
        s_lo = s, g_lo = g, X_lo = q.X, m_lo = margin(q);
        if (side == -1) g_hi *= 0.5;  // Illinois
        side = -1;
      } else {
        s_hi = s, g_hi = g, X_hi = q.X, m_hi = margin(q);
        if (side == 1) g_lo *= 0.5;
        side = 1;
      }
    }
    sp.type = event >= 0 ? SpecialPointType::UZ : slot_type(slot);
    sp.name = event >= 0 ? o_.events[static_cast<std::size_t>(event)].name : to_string(sp.type);
    sp.x = best.X.head(n_);
    sp.p = best.X[n_];
    sp.parameters = pr_.parameter_values(sp.x, sp.p);
    sp.p_lo = std::min(X_lo[n_], X_hi[n_]);
    sp.p_hi = std::max(X_lo[n_], X_hi[n_]);
    sp.precision = (X_hi - X_lo).lpNorm<Eigen::Infinity>();
    sp.status = converged ? LocationStatus::located : LocationStatus::guess;
    sp.unstable_before = a.n_unstable;
    sp.unstable_after = b.n_unstable;
    sp.test_value = test_value(best, slot, event);
    sp.after_index = after;
    if (event < 0 && (slot == 2 || slot == 3) && best.spectrum.size() > 0) {
      // The critical eigenvalue/multiplier; reject neutral saddles (a real pair summing to zero).
      const Eigen::VectorXcd& s = best.spectrum;
      Eigen::Index k = 0;
      double dist = std::numeric_limits<double>::infinity();
      for (Eigen::Index i = 0; i < s.size(); ++i) {
        double d = 0;
        if (!cycles_) d = std::abs(s[i].real()) + (s[i].imag() > 0 ? 0.0 : 1e300);
        else if (slot == 2) d = std::abs(std::abs(s[i]) - 1) + (s[i].imag() > 0 ? 0.0 : 1e300);
        else d = std::abs(s[i] + 1.0);
        if (d < dist) dist = d, k = i;
      }
      if (!(dist < 1e-4 * (1 + std::abs(s[k])))) return false;
      sp.eigenvalue = s[k];
    }
    set_certificate(sp, best, m_lo, m_hi);
    return true;
  }

  // How many eigenvalues (multipliers) a special point moves across the stability boundary: a complex
  // pair for HB/NS, one real one otherwise.
  static int crossings(SpecialPointType type) {
    return type == SpecialPointType::HB || type == SpecialPointType::NS ? 2 : 1;
  }

  // Type of a crossing the test functions could not see (they cancel when two eigenvalues cross
  // together): from which part of the spectrum the change of the unstable count comes.
  SpecialPointType unresolved_type(const Pt& a, const Pt& b) const {
    auto counts = [&](const Pt& q, bool want_complex, bool want_negative) {
      int c = 0;
      for (Eigen::Index i = 0; i < q.spectrum.size(); ++i) {
        const std::complex<double> z = q.spectrum[i];
        const bool unstable = cycles_ ? std::abs(z) > 1 + o_.stability_tol : z.real() > o_.stability_tol;
        const bool is_complex = z.imag() != 0;
        if (unstable && is_complex == want_complex && (!cycles_ || want_complex || (z.real() < 0) == want_negative)) ++c;
      }
      return c;
    };
    if (counts(a, true, false) != counts(b, true, false)) return cycles_ ? SpecialPointType::NS : SpecialPointType::HB;
    if (cycles_ && counts(a, false, true) != counts(b, false, true)) return SpecialPointType::PD;
    return SpecialPointType::BP;
  }

  // All special points between consecutive accepted points a, b. The test functions' sign changes are
  // located; when they do not account for the change of the unstable count (two crossings that cancel
  // in a product, or a located change rejected as a neutral saddle), the step is split until they do.
  // Crossings that coincide to within location_tol are reported as one located point of that bracket.
  void detect(const Pt& a, const Pt& b, std::size_t after, int depth, std::vector<SpecialPoint>& out) {
    std::vector<SpecialPoint> found;
    int explained = 0;
    if (o_.detect_bifurcations) {
      for (int k = 0; k < kSlots; ++k) {
        const double ga = a.tests[static_cast<std::size_t>(k)], gb = b.tests[static_cast<std::size_t>(k)];
        if (std::isnan(ga) || std::isnan(gb) || !(ga * gb < 0)) continue;
        // A neutral spectrum on both sides (a centre, e.g. the conservative S = inf reduced system)
        // makes the spectral products pure rounding noise: no crossing can be read from them.
        if (k >= 2 && a.n_unstable == b.n_unstable && neutral(a, k) && neutral(b, k)) continue;
        SpecialPoint sp;
        if (locate(a, b, k, -1, after, sp)) {
          explained += crossings(sp.type);
          found.push_back(sp);
        }
      }
    }
    const int change = std::abs(a.n_unstable - b.n_unstable);
    if (o_.detect_bifurcations && o_.compute_stability && change > explained) {
      const double s = a.t.dot(b.X - a.X);
      Pt m;
      if (depth < 60 && std::abs(s) > o_.location_tol && probe(a, 0.5 * s, m)) {
        detect(a, m, after, depth + 1, out);
        detect(m, b, after, depth + 1, out);
        return;  // the halves find the test-function zeros and the user events again
      }
      SpecialPoint sp;
      sp.type = unresolved_type(a, b);
      sp.name = to_string(sp.type);
      sp.x = b.X.head(n_);
      sp.p = b.X[n_];
      sp.parameters = pr_.parameter_values(sp.x, sp.p);
      sp.p_lo = std::min(a.X[n_], b.X[n_]);
      sp.p_hi = std::max(a.X[n_], b.X[n_]);
      sp.precision = (b.X - a.X).lpNorm<Eigen::Infinity>();
      sp.status = sp.precision <= o_.location_tol ? LocationStatus::located : LocationStatus::guess;
      sp.unstable_before = a.n_unstable;
      sp.unstable_after = b.n_unstable;
      sp.after_index = after;
      set_certificate(sp, b, margin(a), margin(b));
      found.push_back(sp);
    }
    for (std::size_t e = 0; e < o_.events.size(); ++e) {
      if (!(a.events[e] * b.events[e] < 0) && !(b.events[e] == 0 && a.events[e] != 0)) continue;
      SpecialPoint sp;
      if (locate(a, b, -1, static_cast<int>(e), after, sp)) found.push_back(sp);
    }
    // Sort along the step by arclength rather than p (p may turn at an LP inside the step).
    std::sort(found.begin(), found.end(), [&](const SpecialPoint& u, const SpecialPoint& v) {
      Eigen::VectorXd Xu(N_), Xv(N_);
      Xu << u.x, u.p;
      Xv << v.x, v.p;
      return a.t.dot(Xu - a.X) < a.t.dot(Xv - a.X);
    });
    out.insert(out.end(), found.begin(), found.end());
  }

  // The certificate of corrected point q: the problem's cheap one; near the boundary (special points:
  // always) the refined one, widened by the margin's change when the state moves by its error (one
  // more corrector step, at least newton_tol: state_perturbation).
  StabilityCertificate certificate(const Pt& q, bool special) {
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
  void set_certificate(SpecialPoint& sp, const Pt& q, double m_lo, double m_hi) {
    const StabilityCertificate c = certificate(q, true);
    sp.margin = c.margin;
    sp.margin_error = c.margin_error + std::abs(m_hi - m_lo);
    sp.stability = label(sp.margin, sp.margin_error);
  }
  double margin(const Pt& q) const { return margin_of(q.spectrum, pr_.stability_kind()); }

  BranchPoint to_branch_point(const Pt& q, double arclength) {
    BranchPoint bp;
    bp.x = q.X.head(n_);
    bp.p = q.X[n_];
    bp.parameters = pr_.parameter_values(bp.x, bp.p);
    bp.spectrum = q.spectrum;
    bp.n_unstable = q.n_unstable;
    bp.stable = q.n_unstable == 0;
    const StabilityCertificate c = certificate(q, false);
    bp.stability = c.stability;
    bp.margin = c.margin;
    bp.margin_error = c.margin_error;
    bp.arclength = arclength;
    bp.newton_iterations = q.iterations;
    return bp;
  }

  // One direction from the corrected start point.
  Branch run(const Eigen::VectorXd& x0, double p0, double sign) {
    Branch br;
    br.parameter_names = pr_.parameter_names();
    Eigen::VectorXd X0(N_);
    X0 << x0, p0;
    Eigen::VectorXd ep = Eigen::VectorXd::Zero(N_);
    ep[n_] = sign;
    Pt a;
    try {
      a = finish(X0, ep, 0);
    } catch (const InvalidArgument& e) {
      br.status = ContinuationStatus::outside_domain;
      br.message = e.what();
      return br;
    }
    // Orient by the requested direction in p (at a fold start, |t_p| ~ 0: then along the null vector).
    if (a.t[n_] * sign < 0) a.t = -a.t;
    double arclength = 0;
    br.points.push_back(to_branch_point(a, 0));
    if ((sign > 0 && X0[n_] >= o_.p_max) || (sign < 0 && X0[n_] <= o_.p_min)) {
      br.message = "started on the parameter bound";
      return br;
    }
    double ds = o_.initial_step;
    std::string last_domain_error;
    while (br.points.size() < o_.max_points) {
      ++counters.steps;
      Pt b;
      bool ok = false;
      bool at_bound = false;
      try {
        Eigen::VectorXd X = a.X + ds * a.t;
        int it = 0;
        // A predictor beyond a bound goes straight to the landing below (no residual outside the range).
        const bool beyond = X[n_] > o_.p_max || X[n_] < o_.p_min;
        ok = beyond || correct(X, a.t, a.X, ds, it);
        if (ok && (X[n_] > o_.p_max || X[n_] < o_.p_min)) {
          // Land exactly on the bound: natural-parameter corrector from the interpolated predictor.
          const double bound = X[n_] > o_.p_max ? o_.p_max : o_.p_min;
          const double f = (bound - a.X[n_]) / (X[n_] - a.X[n_]);
          Eigen::VectorXd Xb = a.X + f * (X - a.X);
          Xb[n_] = bound;
          Eigen::VectorXd e = Eigen::VectorXd::Zero(N_);
          e[n_] = 1;
          ok = correct(Xb, e, Eigen::VectorXd::Zero(N_), bound, it);
          X = Xb;
          at_bound = ok;
        }
        if (ok) b = finish(X, a.t, it);
        if (ok && b.t.dot(a.t) < 0.5) ok = false;  // the tangent turned too far: likely a branch jump
      } catch (const InvalidArgument& e) {
        ok = false;
        last_domain_error = e.what();
      }
      if (!ok) {
        ++counters.rejected_steps;
        ds *= o_.step_shrink;
        if (ds < o_.min_step) {
          br.status = last_domain_error.empty() ? ContinuationStatus::step_too_small : ContinuationStatus::outside_domain;
          br.message = last_domain_error.empty() ? "the corrector failed down to min_step" : last_domain_error;
          break;
        }
        continue;
      }
      last_domain_error.clear();
      const std::size_t after = br.points.size() - 1;
      try {
        detect(a, b, after, 0, br.special_points);
      } catch (const InvalidArgument&) {
        // A probe left the domain inside the step: the bracketing endpoints are still valid points.
      }
      arclength += sign * std::abs(a.t.dot(b.X - a.X));
      br.points.push_back(to_branch_point(b, arclength));
      if (o_.on_progress) o_.on_progress(double(br.points.size()), double(o_.max_points));
      const int iters = b.iterations;
      a = std::move(b);
      if (at_bound) {
        br.message = "reached the parameter bound";
        break;
      }
      if (o_.stop && o_.stop(a.X.head(n_), a.X[n_])) {
        br.message = "user stop";
        break;
      }
      if (iters <= o_.easy_iterations) ds = std::min(ds * o_.step_growth, o_.max_step);
      else if (iters > o_.max_newton / 2) ds = std::max(ds * o_.step_shrink, o_.min_step);
    }
    if (br.points.size() >= o_.max_points && br.message.empty()) br.message = "reached max_points";
    return br;
  }

 private:
  void eval_F(const Eigen::VectorXd& X) {
    F_.resize(n_);
    pr_.residual(X.head(n_), X[n_], F_);
    ++counters.residual_evaluations;
  }
  // A = [J Fp; border^T] and F at X.
  void assemble(const Eigen::VectorXd& X, const Eigen::VectorXd& border) {
    const Eigen::VectorXd x = X.head(n_);
    const double p = X[n_];
    eval_F(X);
    pr_.jacobian(x, p, J_);
    pr_.parameter_derivative(x, p, Fp_);
    ++counters.jacobian_evaluations;
    A_.resize(N_, N_);
    A_.topLeftCorner(n_, n_) = J_;
    A_.topRightCorner(n_, 1) = Fp_;
    A_.bottomRows(1) = border.transpose();
  }

  const ContinuationProblem& pr_;
  const ContinuationOptions& o_;
  Eigen::Index n_, N_;
  bool cycles_;
  Eigen::VectorXd F_, Fp_;
  Eigen::MatrixXd J_, A_;
};

void add_counters(ContinuationCounters& a, const ContinuationCounters& b) {
  a.steps += b.steps;
  a.rejected_steps += b.rejected_steps;
  a.newton_iterations += b.newton_iterations;
  a.residual_evaluations += b.residual_evaluations;
  a.jacobian_evaluations += b.jacobian_evaluations;
  a.spectra += b.spectra;
  a.location_iterations += b.location_iterations;
}

}  // namespace

NewtonResult solve_fixed_parameter(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p, double tol,
                                   int max_iterations) {
  NewtonResult r;
  r.x = x0;
  const Eigen::Index n = problem.dimension();
  Eigen::VectorXd F(n);
  Eigen::MatrixXd J;
  for (int it = 0; it < max_iterations; ++it) {
    problem.residual(r.x, p, F);
    problem.jacobian(r.x, p, J);
    const Eigen::VectorXd dx = J.partialPivLu().solve(-F);
    ++r.iterations;
    if (!dx.allFinite()) break;
    r.x += dx;
    if (dx.lpNorm<Eigen::Infinity>() <= tol * (1 + r.x.lpNorm<Eigen::Infinity>())) {
      problem.residual(r.x, p, F);
      r.residual_norm = F.lpNorm<Eigen::Infinity>();
      r.converged = F.allFinite() && r.residual_norm <= std::sqrt(tol) * 1e-3;
      return r;
    }
  }
  problem.residual(r.x, p, F);
  r.residual_norm = F.lpNorm<Eigen::Infinity>();
  return r;
}

Branch continue_branch(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                       const ContinuationOptions& options) {
  options.validate();
  require(x0.size() == problem.dimension(), "x0", static_cast<double>(x0.size()),
          "a state of the problem's dimension " + std::to_string(problem.dimension()));
  require(x0.allFinite(), "x0", x0.cwiseAbs().maxCoeff(), "finite values");
  require(p0 >= options.p_min && p0 <= options.p_max, "p0", p0,
          "[" + format_value(options.p_min) + ", " + format_value(options.p_max) + "] (p_min, p_max)");
  Branch out;
  out.parameter_names = problem.parameter_names();
  NewtonResult start;
  try {
    start = solve_fixed_parameter(problem, x0, p0, options.newton_tol);
  } catch (const InvalidArgument& e) {
    out.status = ContinuationStatus::outside_domain;
    out.message = e.what();
    return out;
  }
  if (!start.converged) {
    out.status = ContinuationStatus::start_failed;
    out.message = "Newton did not converge at the start point (|F| = " + format_value(start.residual_norm) + ")";
    return out;
  }
  auto run = [&](double sign) {
    Engine e(problem, options);
    Branch b = e.run(start.x, p0, sign);
    add_counters(out.counters, e.counters);
    return b;
  };
  if (options.direction != Direction::both) return [&] {
    Branch b = run(options.direction == Direction::forward ? 1.0 : -1.0);
    b.counters = out.counters;
    return b;
  }();
  Branch back = run(-1.0);
  Branch fwd = run(1.0);
  // Backward part reversed (without its start point), then the forward part.
  const std::size_t nb = back.points.empty() ? 0 : back.points.size() - 1;
  for (std::size_t k = back.points.size(); k-- > 1;) out.points.push_back(back.points[k]);
  for (auto it = back.special_points.rbegin(); it != back.special_points.rend(); ++it) {
    SpecialPoint sp = *it;
    std::swap(sp.unstable_before, sp.unstable_after);
    sp.after_index = nb - 1 - sp.after_index;
    out.special_points.push_back(sp);
  }
  out.points.insert(out.points.end(), fwd.points.begin(), fwd.points.end());
  for (SpecialPoint sp : fwd.special_points) {
    sp.after_index += nb;
    out.special_points.push_back(sp);
  }
  // A start on a special point (a restart from a located one) is seen by both halves, each locating it
  // to location_tol next to the start: one point, with the unstable counts of both sides.
  const std::size_t nsb = back.special_points.size();
  if (nsb > 0 && !fwd.special_points.empty()) {
    SpecialPoint& a = out.special_points[nsb - 1];
    const SpecialPoint& b = out.special_points[nsb];
    const double d = std::max((a.x - b.x).lpNorm<Eigen::Infinity>(), std::abs(a.p - b.p));
    if (a.type == b.type && a.name == b.name && a.after_index + 1 == nb && b.after_index == nb &&
        d <= 10 * options.location_tol) {
      a.unstable_after = b.unstable_after;
      out.special_points.erase(out.special_points.begin() + static_cast<std::ptrdiff_t>(nsb));
    }
  }
  out.status = fwd.status != ContinuationStatus::completed ? fwd.status : back.status;
  out.message = "backward: " + (back.message.empty() ? to_string(back.status) : back.message) +
                "; forward: " + (fwd.message.empty() ? to_string(fwd.status) : fwd.message);
  return out;
}

}  // namespace rbcstab
