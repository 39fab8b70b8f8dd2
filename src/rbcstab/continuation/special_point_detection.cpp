// The engine's special points between two accepted points of a branch: sign changes of the test functions
// (LP, BP, HB; LPC, PD, NS) and of the user events, located by a safeguarded secant on the arclength, and
// the crossings the test functions cannot see.
#include "rbcstab/continuation/detail/continuation_engine.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace rbcstab::detail {

namespace {
constexpr double kVerticalTangent = 1e-12;  // |t_p| of a unit tangent below this: the branch is at fixed p
}  // namespace

double Engine::test_value(const Pt& q, int slot, int event) const {
  return event >= 0 ? q.events[static_cast<std::size_t>(event)] : q.tests[static_cast<std::size_t>(slot)];
}

// Whether the eigenvalue/multiplier that test slot k watches is within stability_tol of critical.
bool Engine::neutral(const Pt& q, int slot) const {
  const Eigen::VectorXcd& s = q.spectrum;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    double d = 0;
    if (!cycles_)
      d = s[i].imag() != 0 ? std::abs(s[i].real()) : std::numeric_limits<double>::infinity();
    else if (slot == 2)
      d = s[i].imag() != 0 ? std::abs(std::abs(s[i]) - 1) : std::numeric_limits<double>::infinity();
    else
      d = std::abs(s[i] + 1.0);
    if (d <= o_.stability_tol) return true;
  }
  return false;
}

SpecialPointType Engine::slot_type(int slot) const {
  switch (slot) {
    case 0:
      return cycles_ ? SpecialPointType::LPC : SpecialPointType::LP;
    case 1:
      return SpecialPointType::BP;
    case 2:
      return cycles_ ? SpecialPointType::NS : SpecialPointType::HB;
    default:
      return SpecialPointType::PD;
  }
}

// Illinois-safeguarded secant on the arclength between a (s = 0) and b (s = sb) for a zero of one
// test function (slot) or user event (event >= 0).
bool Engine::locate(const Pt& a, const Pt& b, int slot, int event, std::size_t after, SpecialPoint& sp) {
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
    if (!std::isfinite(s) || std::abs(s - s_lo) < 1e-3 * std::abs(w) || std::abs(s_hi - s) < 1e-3 * std::abs(w) ||
        it % 3 == 2)
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
      if (!cycles_)
        d = std::abs(s[i].real()) + (s[i].imag() > 0 ? 0.0 : 1e300);
      else if (slot == 2)
        d = std::abs(std::abs(s[i]) - 1) + (s[i].imag() > 0 ? 0.0 : 1e300);
      else
        d = std::abs(s[i] + 1.0);
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
int Engine::crossings(SpecialPointType type) {
  return type == SpecialPointType::HB || type == SpecialPointType::NS ? 2 : 1;
}

// Type of a crossing the test functions could not see (they cancel when two eigenvalues cross
// together): from which part of the spectrum the change of the unstable count comes.
SpecialPointType Engine::unresolved_type(const Pt& a, const Pt& b) const {
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
void Engine::detect(const Pt& a, const Pt& b, std::size_t after, int depth, std::vector<SpecialPoint>& out) {
  std::vector<SpecialPoint> found;
  int explained = 0;
  if (o_.detect_bifurcations) {
    for (int k = 0; k < kSlots; ++k) {
      const double ga = a.tests[static_cast<std::size_t>(k)], gb = b.tests[static_cast<std::size_t>(k)];
      if (std::isnan(ga) || std::isnan(gb) || !(ga * gb < 0)) continue;
      // A neutral spectrum on both sides (a centre, e.g. the conservative S = inf reduced system)
      // makes the spectral products pure rounding noise: no crossing can be read from them.
      if (k >= 2 && a.n_unstable == b.n_unstable && neutral(a, k) && neutral(b, k)) continue;
      // Likewise the tangent's p component on a branch at fixed p (a vertical bifurcating set): rounding noise
      // at both ends; a fold inside a step has |t_p| of the order of the step at its ends.
      if (k == 0 && std::max(std::abs(ga), std::abs(gb)) <= kVerticalTangent) continue;
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
      const std::size_t before = out.size();
      detect(a, m, after, depth + 1, out);
      detect(m, b, after, depth + 1, out);
      if (depth == 0) merge_coincident(out, before);
      // A count change the test functions did not see, within location_tol in p of a step end on a bound:
      // the branch stopped within rounding of the crossing (the test function is ~0 there, the count flips
      // where the eigenvalue passes stability_tol, measured 5.8e-12 short of a BP), so it is that end.
      const double pb = b.X[n_];
      if (depth == 0 && (pb == o_.p_max || pb == o_.p_min))
        for (std::size_t k = before; k < out.size(); ++k)
          if (SpecialPoint& q = out[k]; std::abs(q.p - pb) <= o_.location_tol && q.p != pb) {
            q.precision =
                std::max(q.precision, std::max((q.x - b.X.head(n_)).lpNorm<Eigen::Infinity>(), std::abs(q.p - pb)));
            q.x = b.X.head(n_);
            q.p = pb;
            q.parameters = pr_.parameter_values(q.x, q.p);
            q.p_lo = std::min(q.p_lo, pb);
            q.p_hi = std::max(q.p_hi, pb);
          }
      return;  // the halves find the test-function zeros and the user events again
    }
    const std::vector<SpecialPoint> parts = unresolved_crossings(a, b, after);
    found.insert(found.end(), parts.begin(), parts.end());
  }
  for (std::size_t e = 0; e < o_.events.size(); ++e) {
    if (!(a.events[e] * b.events[e] < 0) && !(b.events[e] == 0 && a.events[e] != 0)) continue;
    SpecialPoint sp;
    if (locate(a, b, -1, static_cast<int>(e), after, sp)) found.push_back(sp);
  }
  // Sort along the step by arclength rather than p (p may turn at an LP inside the step).
  std::stable_sort(found.begin(), found.end(), [&](const SpecialPoint& u, const SpecialPoint& v) {
    Eigen::VectorXd Xu(N_), Xv(N_);
    Xu << u.x, u.p;
    Xv << v.x, v.p;
    return a.t.dot(Xu - a.X) < a.t.dot(Xv - a.X);
  });
  out.insert(out.end(), found.begin(), found.end());
}

// The crossings between a and b (a bracket within location_tol) that the test functions did not resolve: one
// point per real eigenvalue (BP) and per pair (HB) that changed side, BPs first, then pairs by frequency, the
// unstable count chained through them. Several eigenvalues crossing at one parameter (the full model's
// Upsilon_l + i m/2, m = 0..l, at sigma_l^c) are as many special points, each with its own eigenvalue, instead of
// one HB carrying the real eigenvalue's change too. The test value is NaN: no test function saw them (what
// merge_coincident reads). Cycles (multipliers), and a split that does not add up to the count change, keep one
// point of unresolved_type carrying the whole change.
std::vector<SpecialPoint> Engine::unresolved_crossings(const Pt& a, const Pt& b, std::size_t after) {
  SpecialPoint sp;
  sp.type = unresolved_type(a, b);
  sp.x = b.X.head(n_);
  sp.p = b.X[n_];
  sp.parameters = pr_.parameter_values(sp.x, sp.p);
  sp.p_lo = std::min(a.X[n_], b.X[n_]);
  sp.p_hi = std::max(a.X[n_], b.X[n_]);
  sp.precision = (b.X - a.X).lpNorm<Eigen::Infinity>();
  sp.status = sp.precision <= o_.location_tol ? LocationStatus::located : LocationStatus::guess;
  sp.unstable_before = a.n_unstable;
  sp.unstable_after = b.n_unstable;
  sp.test_value = std::numeric_limits<double>::quiet_NaN();
  sp.after_index = after;
  const double ma = margin(a), mb = margin(b);
  auto finish_point = [&](SpecialPoint q) {
    q.name = to_string(q.type);
    set_certificate(q, b, ma, mb);
    return q;
  };
  // The unstable real eigenvalues and the frequencies (Im > 0) of the unstable pairs of q.
  auto unstable = [&](const Pt& q, std::vector<double>& omega) {
    int real = 0;
    for (Eigen::Index i = 0; i < q.spectrum.size(); ++i) {
      const std::complex<double> z = q.spectrum[i];
      if (z.real() <= o_.stability_tol) continue;
      if (z.imag() == 0) ++real;
      if (z.imag() > 0) omega.push_back(z.imag());
    }
    return real;
  };
  std::vector<double> wa, wb;
  const int dr = cycles_ ? 0 : unstable(b, wb) - unstable(a, wa);
  // A pair unstable at both ends is one pair: its frequency moves far less than 1e-6 across the bracket.
  for (auto i = wa.begin(); i != wa.end();) {
    const auto j = std::find_if(wb.begin(), wb.end(), [&](double w) { return std::abs(w - *i) <= 1e-6 * (1 + *i); });
    if (j == wb.end()) {
      ++i;
      continue;
    }
    wb.erase(j);
    i = wa.erase(i);
  }
  const int sign = b.n_unstable > a.n_unstable ? 1 : -1;
  std::vector<double> pairs = sign > 0 ? wb : wa;
  std::sort(pairs.begin(), pairs.end());
  const bool adds_up = !cycles_ && (sign > 0 ? wa.empty() : wb.empty()) && dr * sign >= 0 &&
                       a.n_unstable + dr + sign * 2 * static_cast<int>(pairs.size()) == b.n_unstable;
  if (!adds_up) {
    if (sp.type == SpecialPointType::HB || sp.type == SpecialPointType::NS) sp.eigenvalue = critical_value(b, sp.type);
    return {finish_point(sp)};
  }
  std::vector<SpecialPoint> out;
  int count = a.n_unstable;
  for (int k = 0; k < std::abs(dr); ++k) {
    SpecialPoint q = sp;
    q.type = SpecialPointType::BP;
    q.unstable_before = count;
    q.unstable_after = count += sign;
    out.push_back(finish_point(q));
  }
  for (const double w : pairs) {
    SpecialPoint q = sp;
    q.type = SpecialPointType::HB;
    q.unstable_before = count;
    q.unstable_after = count += 2 * sign;
    // The pair's value at b: of those at this frequency (other l share it: Upsilon_l + i m/2) the one nearest the
    // axis.
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < b.spectrum.size(); ++i)
      if (const std::complex<double> z = b.spectrum[i];
          z.imag() > 0 && std::abs(z.imag() - w) <= 1e-6 * (1 + w) && std::abs(z.real()) < best)
        best = std::abs(z.real()), q.eigenvalue = z;
    out.push_back(finish_point(q));
  }
  return out;
}

// Coincident crossings seen twice in one step: a located BP (a zero of the determinant) that carries no count
// change, and unresolved points of one bracket of the same step (the count flips where the eigenvalues pass
// stability_tol, outside the determinant's bracket: 2e-12 in C from it on the full model's l = 4 crossing).
// They are one crossing when, at the BP, every one of them has its eigenvalue (pair) as near the axis as the BP's
// own real eigenvalue, to stability_tol (the full model: all are Upsilon_l + i m/2, equal real parts). Then the BP
// takes the unresolved BP's count change and the pairs move to it (located with it); a located HB with no count
// change whose pair is one of theirs (an odd number of pairs changes the product's sign) is the same pair and goes.
void Engine::merge_coincident(std::vector<SpecialPoint>& out, std::size_t first) {
  if (cycles_) return;
  auto unresolved = [](const SpecialPoint& q) { return std::isnan(q.test_value); };
  for (std::size_t k = first; k < out.size(); ++k) {
    const SpecialPoint v = out[k];
    if (v.type != SpecialPointType::BP || unresolved(v) || v.status != LocationStatus::located ||
        v.unstable_before != v.unstable_after)
      continue;
    std::size_t j = out.size();
    for (std::size_t i = first; i < out.size(); ++i)
      if (out[i].type == SpecialPointType::BP && unresolved(out[i]) &&
          (j == out.size() || std::abs(out[i].p - v.p) < std::abs(out[j].p - v.p)))
        j = i;
    if (j == out.size()) continue;
    const Eigen::VectorXd ux = out[j].x;
    const double up = out[j].p;
    const Eigen::VectorXcd ev = pr_.spectrum(v.x, v.p);
    ++counters.spectra;
    double real = std::numeric_limits<double>::infinity();  // the BP's own eigenvalue: the real one nearest 0
    for (Eigen::Index i = 0; i < ev.size(); ++i)
      if (ev[i].imag() == 0) real = std::min(real, std::abs(ev[i].real()));
    auto with_bp = [&](const SpecialPoint& q) {
      if (q.type == SpecialPointType::BP) return true;
      for (Eigen::Index i = 0; i < ev.size(); ++i)
        if (std::abs(ev[i].imag() - q.eigenvalue.imag()) <= 1e-6 * (1 + std::abs(q.eigenvalue.imag())) &&
            std::abs(std::abs(ev[i].real()) - real) <= o_.stability_tol)
          return true;
      return false;
    };
    bool coincident = std::isfinite(real);
    for (std::size_t i = first; i < out.size() && coincident; ++i)
      if (unresolved(out[i]) && out[i].p == up && out[i].x == ux) coincident = with_bp(out[i]);
    if (!coincident) continue;
    for (std::size_t i = first; i < out.size(); ++i) {
      SpecialPoint& q = out[i];
      if (!unresolved(q) || q.p != up || q.x != ux) continue;
      q.x = v.x;
      q.p = v.p;
      q.parameters = v.parameters;
      q.precision = v.precision;
      q.p_lo = v.p_lo;
      q.p_hi = v.p_hi;
      q.status = v.status;
    }
    SpecialPoint merged = v;
    merged.unstable_before = out[j].unstable_before;
    merged.unstable_after = out[j].unstable_after;
    out[j] = merged;
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
    k = first - 1;  // the indices moved: start over (each pass removes one point)
  }
  for (std::size_t k = first; k < out.size();) {
    const SpecialPoint& h = out[k];
    const bool same_pair =
        h.type == SpecialPointType::HB && !unresolved(h) && h.unstable_before == h.unstable_after &&
        std::any_of(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), [&](const SpecialPoint& q) {
          return q.type == SpecialPointType::HB && unresolved(q) &&
                 std::abs(q.eigenvalue.imag() - h.eigenvalue.imag()) <= 1e-6 * (1 + std::abs(h.eigenvalue.imag()));
        });
    if (same_pair)
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
    else
      ++k;
  }
}

// The eigenvalue (multiplier) of q nearest the crossing of a special point of this type: a pair with Im > 0
// nearest the imaginary axis (HB) or the unit circle (NS), a real one nearest 0 (BP, LP; 1 for cycles) or -1 (PD).
std::complex<double> Engine::critical_value(const Pt& q, SpecialPointType type) const {
  const bool pair = type == SpecialPointType::HB || type == SpecialPointType::NS;
  std::complex<double> best{};
  double dist = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < q.spectrum.size(); ++i) {
    const std::complex<double> z = q.spectrum[i];
    if (pair ? !(z.imag() > 0) : z.imag() != 0) continue;
    double d = 0;
    if (!cycles_)
      d = std::abs(z.real());
    else if (pair)
      d = std::abs(std::abs(z) - 1);
    else
      d = std::abs(z - (type == SpecialPointType::PD ? -1.0 : 1.0));
    if (d < dist) dist = d, best = z;
  }
  return best;
}

// A special point within rounding of a bound the step b landed on: the branch stops there before the test
// function changes sign (or the critical eigenvalue passes stability_tol), e.g. continued to a label's own
// value. Reported at b, located, when the secant of a test function through a and b has its zero at most
// location_tol beyond b (the distance is the precision); a type already found at b is not repeated.
void Engine::detect_at_bound(const Pt& a, const Pt& b, std::size_t after, std::vector<SpecialPoint>& out) {
  if (!o_.detect_bifurcations) return;
  const double pa = a.X[n_], pb = b.X[n_];
  if (pa == pb) return;
  for (int k = 0; k < kSlots; ++k) {
    const double ga = a.tests[static_cast<std::size_t>(k)], gb = b.tests[static_cast<std::size_t>(k)];
    if (!std::isfinite(ga) || !std::isfinite(gb) || ga == 0 || ga * gb < 0) continue;
    if (k >= 2 && (!o_.compute_stability || (neutral(a, k) && neutral(b, k)))) continue;
    if (k == 0 && std::max(std::abs(ga), std::abs(gb)) <= kVerticalTangent) continue;
    // The secant's zero beyond b along the step, in (x, p) max norm like location_tol (not in p alone: p is
    // quadratic in the arclength at a fold).
    const double f = gb == 0 ? 0.0 : gb / (ga - gb);
    const double beyond = f * (b.X - a.X).lpNorm<Eigen::Infinity>();
    if (!(f >= 0 && beyond <= o_.location_tol)) continue;
    const SpecialPointType type = slot_type(k);
    if (std::any_of(out.begin(), out.end(),
                    [&](const SpecialPoint& q) { return q.type == type && std::abs(q.p - pb) <= o_.location_tol; }))
      continue;
    SpecialPoint sp;
    sp.type = type;
    sp.name = to_string(type);
    sp.x = b.X.head(n_);
    sp.p = pb;
    sp.parameters = pr_.parameter_values(sp.x, sp.p);
    sp.p_lo = std::min(pb, pb + f * (pb - pa));
    sp.p_hi = std::max(pb, pb + f * (pb - pa));
    sp.precision = beyond;
    sp.status = LocationStatus::located;
    sp.unstable_before = a.n_unstable;
    sp.unstable_after = b.n_unstable;
    sp.test_value = gb;
    sp.after_index = after;
    if (k >= 2) sp.eigenvalue = critical_value(b, type);
    set_certificate(sp, b, margin(a), margin(b));
    out.push_back(sp);
  }
}

// The branch-jump guard: why the step a -> b is not one piece of a branch, or "" when it is. A step that jumps
// to a nearby branch changes the unstable count or a test function's sign with no zero in between: the
// bracket of the change cannot shrink below the distance between the branches, so the special point that
// detect reports for it stays a guess. Located points (and UZ events, which may jump by themselves) pass.
std::string Engine::unconfirmed_change(const Pt& a, const Pt& b, const std::vector<SpecialPoint>& found) const {
  for (const auto& sp : found) {
    if (sp.type == SpecialPointType::UZ || sp.status == LocationStatus::located) continue;
    std::ostringstream os;
    os << "changed the unstable count (" << a.n_unstable << " -> " << b.n_unstable << ") or a test function's sign ("
       << to_string(sp.type) << ") with no located special point between (bracket " << sp.precision << " in (x, "
       << pr_.parameter_name() << "))";
    return os.str();
  }
  return "";
}

// A fold (LP, LPC) located within location_tol of a bound: the branch turns back within rounding of the range
// end (e.g. continued to an LP label's own value), so the fold is that end. The branch ends on it: end is the
// fold's state with p on the bound (the fold's precision covers the shift), the points found after it dropped.
bool Engine::fold_at_bound(std::vector<SpecialPoint>& special, std::size_t first, const Pt& a, Pt& end) {
  for (std::size_t k = first; k < special.size(); ++k) {
    SpecialPoint& sp = special[k];
    if ((sp.type != SpecialPointType::LP && sp.type != SpecialPointType::LPC) || sp.status != LocationStatus::located)
      continue;
    const double bound = std::abs(sp.p - o_.p_max) <= std::abs(sp.p - o_.p_min) ? o_.p_max : o_.p_min;
    if (!(std::abs(sp.p - bound) <= o_.location_tol)) continue;
    sp.precision = std::max(sp.precision, std::abs(sp.p - bound));
    sp.p_lo = std::min(sp.p_lo, bound);
    sp.p_hi = std::max(sp.p_hi, bound);
    sp.p = bound;
    sp.parameters = pr_.parameter_values(sp.x, sp.p);
    Eigen::VectorXd X(N_);
    X << sp.x, bound;
    end = finish(X, a.t, 0);
    special.erase(special.begin() + static_cast<std::ptrdiff_t>(k) + 1, special.end());
    return true;
  }
  return false;
}

std::string Engine::stop_event(std::vector<SpecialPoint>& special, std::size_t first, const Pt& a, Pt& end) {
  for (std::size_t k = first; k < special.size(); ++k) {
    const SpecialPoint& sp = special[k];
    if (sp.type != SpecialPointType::UZ) continue;
    const auto e =
        std::find_if(o_.events.begin(), o_.events.end(), [&](const UserEvent& u) { return u.name == sp.name; });
    if (e == o_.events.end() || !e->stop) continue;
    Eigen::VectorXd X(N_);
    X << sp.x, sp.p;
    end = finish(X, a.t, 0);
    const std::string name = sp.name + (sp.status == LocationStatus::located ? "" : " (not located: a guess)");
    special.erase(special.begin() + static_cast<std::ptrdiff_t>(k) + 1, special.end());
    return name;
  }
  return {};
}

}  // namespace rbcstab::detail
