// Pseudo-arclength continuation: its options, Newton at fixed parameter, and the engine's steps along a
// branch (predictor, corrector, landing on a bound) in one or both directions.
#include "rbcstab/continuation/continuation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/detail/continuation_engine.hpp"
#include "rbcstab/continuation/normal_form_analysis.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

const SpecialPoint* find_special_point(const Branch& b, SpecialPointType type, int k) {
  for (const auto& sp : b.special_points)
    if (sp.type == type && --k == 0) return &sp;
  return nullptr;
}

void ContinuationOptions::validate() const {
  // Each tunable option's domain (tunable_options.hpp), then how they relate.
  for (const TunableOption& o : tunable_options())
    if (!o.orbit) o.check(o.get(*this, OrbitOptions{}));
  require(initial_step <= max_step, "initial_step", initial_step,
          "in (0, max_step] with max_step = " + format_value(max_step));
  require(min_step <= initial_step, "min_step", min_step, "a number in (0, initial_step]");
  require(step_growth >= 1 && step_growth <= 10, "step_growth", step_growth, "[1, 10]");
  require(step_shrink > 0 && step_shrink < 1, "step_shrink", step_shrink, "(0, 1)");
  require(easy_iterations >= 1, "easy_iterations", easy_iterations, "an integer >= 1");
  require(!std::isnan(p_min) && !std::isnan(p_max) && p_min < p_max, "p_min", p_min, "a number < p_max");
  require(max_points >= 2 && max_points <= std::size_t(kMaxPointsLimit), "max_points", static_cast<double>(max_points),
          integer_range(2, kMaxPointsLimit));
  require(max_location_iterations >= 1, "max_location_iterations", max_location_iterations, "an integer >= 1");
  require(stability_tol >= 0, "stability_tol", stability_tol, "a number >= 0");
  require(certificate_refine_margin >= 0, "certificate_refine_margin", certificate_refine_margin,
          "a number >= 0 (or inf)");
  for (const auto& e : events) {
    if (!e.g) throw InvalidArgument("events", "event '" + e.name + "' has no function");
  }
}

namespace {

// z / (1 + |z|): keeps the argument (hence the sign of a real product) and avoids overflow.
std::complex<double> squash(std::complex<double> z) { return z / (1 + std::abs(z)); }

}  // namespace

namespace detail {

// Newton on [F(x, p); border.(X - X0) - s] = 0 (pseudo-arclength, or p = bound with border = e_p).
bool Engine::correct(Eigen::VectorXd& X, const Eigen::VectorXd& border, const Eigen::VectorXd& X0, double s,
                     int& iterations) {
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
Pt Engine::finish(const Eigen::VectorXd& X, const Eigen::VectorXd& t_prev, int iterations) {
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

// The point at arclength s along a's tangent (corrected), or false. A corrector that wanders out of the
// problem's domain is a failed probe like any other: the detection around it goes on (its special points
// stay guesses, which the branch-jump guard sees) instead of being abandoned.
bool Engine::probe(const Pt& a, double s, Pt& out) {
  try {
    Eigen::VectorXd X = a.X + s * a.t;
    int it = 0;
    if (!correct(X, a.t, a.X, s, it)) return false;
    out = finish(X, a.t, it);
    return true;
  } catch (const InvalidArgument&) {
    return false;
  }
}

BranchPoint Engine::to_branch_point(const Pt& q, double arclength) {
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
  bp.uncertain_because = c.uncertain_because;
  bp.arclength = arclength;
  bp.newton_iterations = q.iterations;
  return bp;
}

// One direction from the corrected start point.
Branch Engine::run(const Eigen::VectorXd& x0, double p0, double sign) {
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
  std::string unconfirmed;  // why the branch-jump guard rejected a step since the last accepted point
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
    std::vector<SpecialPoint> found;
    const std::size_t after = br.points.size() - 1;
    if (ok) {
      bool detected = true;
      try {
        detect(a, b, after, 0, found);
        if (at_bound) detect_at_bound(a, b, after, found);
      } catch (const InvalidArgument&) {
        detected = false;  // a user event left the domain: the bracketing endpoints are still valid points
      }
      if (o_.confirm_special_points) {
        std::string why = unconfirmed_change(a, b, found);
        if (!detected && why.empty() && a.n_unstable != b.n_unstable)
          why = "changed the unstable count (" + std::to_string(a.n_unstable) + " -> " + std::to_string(b.n_unstable) +
                ") where detection could not run";
        if (!why.empty()) {
          ok = false;
          unconfirmed = why;
          ++counters.unconfirmed_steps;
        }
      }
    }
    if (!ok) {
      ++counters.rejected_steps;
      ds *= o_.step_shrink;
      if (ds < o_.min_step) {
        if (!unconfirmed.empty()) {
          br.status = ContinuationStatus::branch_lost;
          br.message = "lost the branch after point " + std::to_string(after) + " from the start (" +
                       pr_.parameter_name() + " = " + format_value(a.X[n_]) +
                       "): every step down to min_step = " + format_value(o_.min_step) + " " + unconfirmed +
                       " (a nearby branch?)";
        } else {
          br.status =
              last_domain_error.empty() ? ContinuationStatus::step_too_small : ContinuationStatus::outside_domain;
          br.message = last_domain_error.empty() ? "the corrector failed down to min_step" : last_domain_error;
        }
        break;
      }
      continue;
    }
    last_domain_error.clear();
    unconfirmed.clear();
    const std::size_t known = br.special_points.size();
    br.special_points.insert(br.special_points.end(), found.begin(), found.end());
    const std::string stopped = stop_event(br.special_points, known, a, b);  // b: the stop's point, if any
    const bool fold_end = stopped.empty() && !at_bound && fold_at_bound(br.special_points, known, a, b);
    arclength += sign * std::abs(a.t.dot(b.X - a.X));
    br.points.push_back(to_branch_point(b, arclength));
    if (o_.on_progress) o_.on_progress(double(br.points.size()), double(o_.max_points));
    const int iters = b.iterations;
    a = std::move(b);
    if (!stopped.empty()) {
      br.message = "stopped at " + stopped;
      break;
    }
    if (at_bound || fold_end) {
      br.message = fold_end ? "reached the parameter bound at a fold (turning within location_tol of it)"
                            : "reached the parameter bound";
      break;
    }
    if (o_.stop && o_.stop(a.X.head(n_), a.X[n_])) {
      br.message = "user stop";
      break;
    }
    if (iters <= o_.easy_iterations)
      ds = std::min(ds * o_.step_growth, o_.max_step);
    else if (iters > o_.max_newton / 2)
      ds = std::max(ds * o_.step_shrink, o_.min_step);
  }
  if (br.points.size() >= o_.max_points && br.message.empty()) br.message = "reached max_points";
  return br;
}

void Engine::eval_F(const Eigen::VectorXd& X) {
  F_.resize(n_);
  pr_.residual(X.head(n_), X[n_], F_);
  ++counters.residual_evaluations;
}

// A = [J Fp; border^T] and F at X.
void Engine::assemble(const Eigen::VectorXd& X, const Eigen::VectorXd& border) {
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

}  // namespace detail

namespace {

using detail::Engine;

void add_counters(ContinuationCounters& a, const ContinuationCounters& b) {
  a.steps += b.steps;
  a.rejected_steps += b.rejected_steps;
  a.unconfirmed_steps += b.unconfirmed_steps;
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
    // A given state that already solves F = 0 to 1e-2 tol (a labelled point, stored as computed) is kept as
    // it is: at a fold or BP the Jacobian is singular there and a Newton step would throw it off.
    if (it == 0 && F.allFinite() && F.lpNorm<Eigen::Infinity>() <= 1e-2 * tol * (1 + r.x.lpNorm<Eigen::Infinity>())) {
      r.residual_norm = F.lpNorm<Eigen::Infinity>();
      r.converged = true;
      return r;
    }
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
  auto with_normal_forms = [&](Branch b) {
    if (options.normal_forms) attach_normal_forms(problem, b);  // equilibria's LP, BP, HB; forced orbits' PD
    return b;
  };
  if (options.direction != Direction::both)
    return with_normal_forms([&] {
      Branch b = run(options.direction == Direction::forward ? 1.0 : -1.0);
      b.counters = out.counters;
      return b;
    }());
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
  return with_normal_forms(std::move(out));
}

}  // namespace rbcstab
