#include "rbcstab/analysis/truncation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

void TruncationOptions::validate() const {
  require(std::isfinite(tolerance) && tolerance > 0 && tolerance < 1, "tolerance", tolerance, "in (0, 1)");
  require_L(L_max, 3, kMaxL, {}, "L_max");
  require(checkpoints >= 1 && checkpoints <= 10000, "checkpoints", checkpoints, "an integer in [1, 10000]");
  predictor.validate();
}

namespace {
constexpr double kNoGain = -1e300;  // log_gain of a mode that never gains area (finite, never -inf)

// Three significant digits: the reason is read by a person.
std::string short_value(double v) {
  std::ostringstream ss;
  ss << std::setprecision(3) << v;
  return ss.str();
}

// ln(d (exp(2 G) - 1)) for G > 0, d > 0, without overflow for large G.
double log_area_gain(double d, double G) { return std::log(d) + 2 * G + std::log1p(-std::exp(-2 * G)); }
}  // namespace

ReducedTransient truncation_transient(const Scene& scene, const TruncationOptions& options) {
  return truncation_transient(validated(scene), options);
}

ReducedTransient truncation_transient(const ValidScene& valid, const TruncationOptions& options) {
  options.validate();
  return reduced_transient(valid, valid->T, options.checkpoints, options.predictor);
}

namespace {
TruncationChoice choose_from_transient(const ValidScene& valid, const ReducedTransient& transient,
                                       const TruncationOptions& options);
}  // namespace

TruncationChoice choose_truncation(const Scene& scene, const TruncationOptions& options) {
  options.validate();
  const ValidScene valid = validated(scene);
  return choose_from_transient(valid, reduced_transient(valid, scene.T, options.checkpoints, options.predictor),
                               options);
}

TruncationChoice choose_truncation(const Scene& scene, const ReducedTransient& transient,
                                   const TruncationOptions& options) {
  options.validate();
  return choose_from_transient(validated(scene), transient, options);
}

namespace {
TruncationChoice choose_from_transient(const ValidScene& valid, const ReducedTransient& transient,
                                       const TruncationOptions& options) {
  const Scene& scene = *valid;
  if (!transient.of(scene) || transient.T != scene.T || transient.checkpoints != options.checkpoints)
    throw InvalidArgument(
        "transient", "the reduced transient must be the scene's over [0, T = " + format_value(scene.T) + "] with " +
                         std::to_string(options.checkpoints) + " checkpoints");
  Scene s = scene;
  // Every explicitly set mode must exist; L_max covers the candidates of the rule.
  int L_explicit = 2;
  for (const auto& [l, d] : scene.delta_l) L_explicit = std::max(L_explicit, l);
  for (const auto& [l, d] : scene.rest_delta_l) L_explicit = std::max(L_explicit, l);
  s.L = std::max(options.L_max, L_explicit);
  const Parameters& p = s.parameters;
  const double Delta = p.Delta;

  TruncationChoice c;
  c.G_max.assign(std::size_t(options.L_max - 2), -std::numeric_limits<double>::max());
  // G_l(t) at every checkpoint the run reached, so that a mode that grows and decays again before T counts.
  for (std::size_t k = 0; k < transient.t.size(); ++k) {
    const double t = transient.t[k];
    if (t <= 0) continue;
    const double mean_sigma = transient.integral[k] / t;
    for (int l = 3; l <= options.L_max; ++l) {
      double& G = c.G_max[std::size_t(l - 3)];
      G = std::max(G, t * Upsilon_l(p, l, mean_sigma));
    }
  }
  c.counters = transient.counters;

  std::ostringstream why;
  const double floor = std::log(options.tolerance * Delta);
  int L_needed = 2;
  c.log_gain.assign(c.G_max.size(), kNoGain);
  for (int l = 3; l <= options.L_max; ++l) {
    const double d = s.perturbation(l);
    const double G = c.G_max[std::size_t(l - 3)];
    if (d > 0 && G > 0) c.log_gain[std::size_t(l - 3)] = log_area_gain(d, G) - std::log(Delta);
    if (c.log_gain[std::size_t(l - 3)] + std::log(Delta) > floor) L_needed = l;
  }
  if (transient.status != IntegrationStatus::success) {
    c.status = DomainStatus::outside_domain;
    c.L = std::max(options.L_max, L_explicit);
    why << "L = " << c.L << " (conservative): the reduced run for the finite-horizon predictor stopped at t = "
        << format_value(transient.t_end) << " (" << transient.reason << ")";
    c.reason = why.str();
    return c;
  }
  // The lowest seeded mode stays even when nothing grows: the scene is perturbed, and the verdict needs a
  // candidate l >= 3 (it costs one mode).
  const int L_floor = s.perturbation(3) > 0 ? 3 : 2;
  c.L = std::max({L_needed, L_explicit, L_floor});
  for (int l = c.L + 1; l <= options.L_max; ++l) c.dropped_seeded_area += s.perturbation(l);

  why << "L = " << c.L << ": the smallest L keeping every mode whose linear area gain delta_l (exp(2 max_t G_l) - 1)"
      << " by T = " << format_value(s.T) << " exceeds " << short_value(options.tolerance)
      << " Delta (finite-horizon predictor)";
  if (L_needed >= 3) {
    why << "; l = " << L_needed << " grows (max_t G = " << short_value(c.G_max[std::size_t(L_needed - 3)]) << ")";
  } else {
    why << "; no mode gains";
  }
  if (c.L < options.L_max)
    why << ", l = " << c.L + 1 << " does not (max_t G = " << short_value(c.G_max[std::size_t(c.L + 1 - 3)]) << ")";
  if (L_explicit > L_needed && L_explicit == c.L) why << "; raised to the highest mode the scene sets explicitly";
  if (c.L == options.L_max && L_needed == options.L_max)
    why << "; capped at L_max: the linear predictor ignores saturation, so this is conservative";
  if (c.dropped_seeded_area > 0)
    why << "; l = " << c.L + 1 << ".." << options.L_max << " (seeded area " << short_value(c.dropped_seeded_area)
        << ") may be dropped only if a check after the run confirms it";
  c.reason = why.str();
  return c;
}

TruncationDecision resolve_valid(const ValidScene& valid, Origin L_origin, TruncationUse use,
                                 const TruncationOptions& options, const ReducedTransient* transient,
                                 const TransientRunner& transient_run = {}) {
  const Scene& scene = *valid;
  TruncationDecision d;
  d.L = scene.L;
  const std::string L = "L = " + std::to_string(scene.L);
  const std::string given = L_origin == Origin::flag   ? "given by --L"
                            : L_origin == Origin::file ? "given by the scene file's run.L"
                                                       : "the default";
  if (use == TruncationUse::reduced) {
    d.reason = L + " (" + given + ") is not used: the reduced system holds the l = 2 modes only";
    return d;
  }
  if (L_origin != Origin::default_value) {
    d.reason = L + ": " + given;
    return d;
  }
  const std::string unset = L + ": the default (neither --L nor run.L); ";
  switch (use) {
    case TruncationUse::simulation: {
      if (scene.L <= 3) {
        d.reason = unset + "no candidate below it keeps a perturbed mode";
        return d;
      }
      // Never above the scene's L: a larger L would seed more modes, i.e. another scene.
      TruncationOptions o = options;
      o.L_max = scene.L;
      o.validate();
      std::optional<ReducedTransient> own;
      if (!transient) own = transient_run ? transient_run(valid, o) : truncation_transient(valid, o);
      const TruncationChoice c = choose_from_transient(valid, transient ? *transient : *own, o);
      d.L = c.L;
      d.reason = c.reason;
      d.check = c.L < scene.L;
      return d;
    }
    case TruncationUse::grid:
      d.reason = unset + "one L serves every scene of the grid, while the automatic choice is made per scene";
      break;
    case TruncationUse::analysis:
      d.reason = unset +
                 "the automatic choice bounds the truncation error of a simulation over [0, T], and this "
                 "computation has no such horizon";
      break;
    case TruncationUse::measurement:
      d.reason = unset + "a benchmark measures at the L it is given";
      break;
    case TruncationUse::reduced:
      break;
  }
  return d;
}
}  // namespace

TruncationDecision resolve_truncation(const Scene& scene, Origin L_origin, TruncationUse use,
                                      const TruncationOptions& options, const ReducedTransient* transient) {
  return resolve_valid(validated(scene), L_origin, use, options, transient);
}

namespace {

// The candidate run's state at one accepted step, reduced to what the check reads.
struct StepRecord {
  double t = 0, sigma = 0;
  double J = 0;  // int_0^t sigma dt'
  bool J_exact = false;
  double D = 0;  // sum over the kept modes of dUpsilon_l/dsigma Delta_l (< 0)
  double W = 0;  // the work term of the area balance: sum_l Upsilon_l(sigma) Delta_l + W = 0 (tension.hpp)
  double Delta2 = 0;
};

// Records the candidate run step by step. int_0^t sigma comes exactly (to the integration error) from a kept
// seeded mode r without rest content: ln(Delta_r(t)/Delta_r(0)) = 2 slope_r (int_0^t sigma - sigma_r^c t). The
// largest such mode is used, if it is above a floor where its relative accuracy is still ~1e-6 at the full level
// (amplitudes carry the absolute tolerance atol); otherwise the trapezoid rule from the previous step (filled in
// by finish(), once t = 0 is known).
class StepRecorder {
 public:
  StepRecorder(const ValidScene& candidate, double atol) : floor_(std::max(1e6 * atol * 1e6 * atol, 1e-300)) {
    const InitialState init = initial_state(candidate);
    for (int l = 2; l <= candidate->L; ++l) {
      U_.push_back(Upsilon_l(candidate->parameters, l));
      Delta0_.push_back(init.f.excess_area(l));
      reference_.push_back(l >= 3 && Delta0_.back() > 0 && candidate->rest_perturbation(l) == 0);
    }
  }
  void add(double t, const std::vector<double>& Delta_l, double sigma) {
    StepRecord r;
    r.t = t;
    r.sigma = sigma;
    double best = 0;
    int ref = -1;
    for (std::size_t j = 0; j < Delta_l.size() && j < U_.size(); ++j) {
      r.D += U_[j].slope * Delta_l[j];
      r.W -= U_[j](sigma) * Delta_l[j];
      if (reference_[j] && Delta_l[j] >= floor_ && Delta_l[j] > best) {
        best = Delta_l[j];
        ref = int(j);
      }
    }
    r.Delta2 = Delta_l.empty() ? 0.0 : Delta_l[0];
    if (ref >= 0) {
      const GrowthRate& U = U_[std::size_t(ref)];
      r.J = std::log(best / Delta0_[std::size_t(ref)]) / (2 * U.slope) + U.sigma_c * t;
      r.J_exact = true;
    }
    steps.push_back(r);
  }
  // Puts the t = 0 state first and fills the integrals no reference mode gave; across a certified skip (the
  // steps at terminated_at and resumed_at) the integral is the orbit's, early.sigma_integral.
  void finish(const std::vector<double>& Delta_initial, double sigma_initial, const EarlyTermination& early) {
    std::vector<StepRecord> accepted = std::move(steps);
    steps.clear();
    add(0.0, Delta_initial, sigma_initial);
    steps.front().J = 0;
    steps.front().J_exact = true;
    for (const StepRecord& r : accepted) {
      if (r.t <= steps.back().t) continue;
      steps.push_back(r);
      StepRecord& cur = steps.back();
      const StepRecord& prev = steps[steps.size() - 2];
      const bool skip = early.terminated && prev.t == early.terminated_at && cur.t == early.resumed_at;
      if (!cur.J_exact)
        cur.J = prev.J + (skip ? early.sigma_integral : 0.5 * (cur.t - prev.t) * (prev.sigma + cur.sigma));
    }
  }
  std::vector<StepRecord> steps;

 private:
  double floor_;
  std::vector<GrowthRate> U_;   // index l - 2
  std::vector<double> Delta0_;  // the run's Delta_l(0)
  std::vector<char> reference_;
};

std::string mode_range(int a, int b) {
  return a == b ? std::to_string(a) : std::to_string(a) + ".." + std::to_string(b);
}

// The check of the dropped modes l = Lc+1..scene.L along the recorded run.
TruncationCheck check_run(const Scene& scene, int Lc, const SimulationResult& run, const std::vector<StepRecord>& steps,
                          const TruncationOptions& options) {
  const Parameters& p = scene.parameters;
  TruncationCheck c;
  c.L_scene = scene.L;
  c.L_candidate = Lc;
  c.threshold = options.tolerance * p.Delta;
  c.samples = steps.size();
  struct Mode {
    GrowthRate U;
    double delta, u0;  // seed and its log (u0 unused when delta = 0)
    double u_max = -std::numeric_limits<double>::infinity();
    double t_max = 0;
  };
  std::vector<Mode> modes;
  std::vector<int> rest;
  for (int l = Lc + 1; l <= scene.L; ++l) {
    const double d = scene.perturbation(l);
    modes.push_back({Upsilon_l(p, l), d, d > 0 ? std::log(d) : 0.0});
    if (scene.rest_perturbation(l) > 0) rest.push_back(l);
  }
  const GrowthRate U2 = Upsilon_l(p, 2);
  std::ostringstream failed;
  if (!rest.empty()) failed << "l = " << rest.front() << " has stress-free content: its growth is not the linear law; ";
  if (run.status != IntegrationStatus::success)
    failed << "the candidate run stopped at t = " << format_value(run.t_reached) << " (" << run.reason << "); ";
  if (steps.size() < 2) failed << "the candidate run has no accepted step; ";
  if (run.early.terminated && !std::isfinite(run.early.sigma_integral))
    failed << "the candidate run skipped periods on an attractor without the integral of sigma over them; ";

  auto u_at = [](const Mode& m, const StepRecord& r) { return m.u0 + 2 * m.U.slope * (r.J - m.U.sigma_c * r.t); };
  double sigma_scale = 0;
  for (const StepRecord& r : steps) sigma_scale = std::max(sigma_scale, std::abs(r.sigma));
  c.sigma_tolerance = options.tolerance * sigma_scale;

  // Interval k = [t_k, t_k+1]: sigma there lies in [lo, hi], the endpoints widened by their difference (the
  // integrator's step resolves sigma, so it does not move further than that inside a step) and by the curvature
  // the step's mean shows: with both integrals exact the mean is (J_k+1 - J_k)/h, and a parabola through the
  // endpoints with that mean leaves them by at most 1.5 |mean - (a + b)/2|.
  struct Interval {
    double lo, hi;
    std::vector<double> ub;  // per dropped mode: a bound on ln Delta_l over the interval (-inf without area)
  };
  // A certified skip (steps at terminated_at and resumed_at): sigma follows the attracting orbit there, so it
  // stays in the range the run shows over a period before the skip and after it (widened by half that range on
  // each side, as the endpoints' difference widens a step), and ln Delta_l departs from the line through its
  // ends by at most 2 |slope| P (hi - lo): the integral of sigma's periodic part over any span is below P (hi - lo).
  const EarlyTermination& early = run.early;
  double gap_lo = std::numeric_limits<double>::infinity(), gap_hi = -gap_lo;
  if (early.terminated) {
    for (const StepRecord& r : steps)
      if ((r.t >= early.terminated_at - early.period && r.t <= early.terminated_at) ||
          (r.t >= early.resumed_at && r.t <= early.resumed_at + early.period)) {
        gap_lo = std::min(gap_lo, r.sigma);
        gap_hi = std::max(gap_hi, r.sigma);
      }
    const double widen = 0.5 * (gap_hi - gap_lo);
    gap_lo -= widen;
    gap_hi += widen;
    if (!(gap_hi >= gap_lo)) {  // no step near the skip: nothing bounds sigma there, and the check fails
      gap_lo = -std::numeric_limits<double>::infinity();
      gap_hi = std::numeric_limits<double>::infinity();
    }
  }
  auto skip_interval = [&](const StepRecord& r, const StepRecord& n) {
    Interval in{gap_lo, gap_hi, std::vector<double>(modes.size(), -std::numeric_limits<double>::infinity())};
    for (std::size_t i = 0; i < modes.size(); ++i) {
      Mode& m = modes[i];
      if (m.delta <= 0) continue;
      const double uk = u_at(m, r), un = u_at(m, n);
      in.ub[i] = std::max(uk, un) + 2 * std::abs(m.U.slope) * early.period * (gap_hi - gap_lo);
      if (!(in.ub[i] <= m.u_max)) {
        m.u_max = in.ub[i];
        m.t_max = uk >= un ? r.t : n.t;
      }
    }
    return in;
  };
  auto interval = [&](std::size_t k) {
    const StepRecord &r = steps[k], &n = steps[k + 1];
    if (early.terminated && r.t == early.terminated_at && n.t == early.resumed_at) return skip_interval(r, n);
    const double h = n.t - r.t;
    double margin = std::abs(n.sigma - r.sigma);
    if (r.J_exact && n.J_exact && h > 0) margin += 1.5 * std::abs((n.J - r.J) / h - 0.5 * (r.sigma + n.sigma));
    Interval in{std::min(r.sigma, n.sigma) - margin, std::max(r.sigma, n.sigma) + margin,
                std::vector<double>(modes.size(), -std::numeric_limits<double>::infinity())};
    for (std::size_t i = 0; i < modes.size(); ++i) {
      Mode& m = modes[i];
      if (m.delta <= 0) continue;  // no area: stays at zero exactly
      const double uk = u_at(m, r), un = u_at(m, n);
      // d ln Delta_l/dt = 2 |slope| (sigma_c - sigma) lies in [-g, f]: f = 2 |slope| (sigma_c - lo) and
      // g = 2 |slope| (hi - sigma_c), so u(t) <= min(uk + f tau, un + g (h - tau)), tau = t - t_k. That minimum
      // is concave: its largest value is at tau = 0, h or where the two lines meet.
      const double f = 2 * std::abs(m.U.slope) * (m.U.sigma_c - in.lo),
                   g = 2 * std::abs(m.U.slope) * (in.hi - m.U.sigma_c);
      auto line_min = [&](double tau) { return std::min(uk + f * tau, un + g * (h - tau)); };
      double bound = std::max({line_min(0), line_min(h), uk, un});
      if (f + g > 0) bound = std::max(bound, line_min(std::clamp((un - uk + g * h) / (f + g), 0.0, h)));
      in.ub[i] = bound;
      if (bound > m.u_max) {
        m.u_max = bound;
        m.t_max = uk >= un ? r.t : n.t;
      }
    }
    return in;
  };
  // The tension the scene would have at step k: the run's kept shape, the dropped modes at their bounds over the
  // adjacent intervals, and the area they released (or took), a, in l = 2 (f_2 scaled by s):
  //   sigma' - sigma = -[sum_dropped Upsilon_l(sigma) Delta_l + Upsilon_2(sigma) a + (s - 1) W] / D',
  // with |a| <= R = sum_dropped max(delta_l, Delta_l - delta_l), |s - 1| <= |a| / Delta_2 and
  // |D'| >= |D| - |slope_2| R (every slope is negative); each |Upsilon_l| is bounded over the sigma range.
  auto shift_at = [&](const StepRecord& r, const std::vector<const Interval*>& adjacent) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Interval* in : adjacent) {
      lo = std::min(lo, in->lo);
      hi = std::max(hi, in->hi);
    }
    auto rate_bound = [&](const GrowthRate& U) {
      return std::abs(U.slope) * std::max(std::abs(lo - U.sigma_c), std::abs(hi - U.sigma_c));
    };
    double direct = 0, R = 0;
    for (std::size_t i = 0; i < modes.size(); ++i) {
      if (modes[i].delta <= 0) continue;
      double u = -std::numeric_limits<double>::infinity();
      for (const Interval* in : adjacent) u = std::max(u, in->ub[i]);
      const double Dl = std::exp(u);
      direct += rate_bound(modes[i].U) * Dl;
      R += std::max(modes[i].delta, Dl - modes[i].delta);
    }
    const double den = std::abs(r.D) - std::abs(U2.slope) * R;
    if (!(den > 0 && R < r.Delta2)) return std::numeric_limits<double>::infinity();
    return (direct + rate_bound(U2) * R + std::abs(r.W) * R / r.Delta2) / den;
  };
  std::optional<Interval> before;  // the interval ending at step k
  for (std::size_t k = 0; steps.size() >= 2 && k < steps.size(); ++k) {
    std::optional<Interval> after;
    if (k + 1 < steps.size()) after = interval(k);
    std::vector<const Interval*> adjacent;
    if (before) adjacent.push_back(&*before);
    if (after) adjacent.push_back(&*after);
    const double shift = shift_at(steps[k], adjacent);
    if (!(shift <= c.sigma_shift)) {
      c.sigma_shift = shift;
      c.t_sigma_shift = steps[k].t;
    }
    before = std::move(after);
  }

  int worst = -1;
  double worst_excess = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const Mode& m = modes[i];
    TruncationCheck::DroppedMode d{Lc + 1 + int(i), m.delta, m.delta > 0 ? std::exp(m.u_max) : 0.0, m.t_max};
    c.dropped.push_back(d);
    const double excess = d.Delta_max - d.delta;
    if (m.delta > 0 && !(excess <= worst_excess)) {
      worst_excess = excess;
      worst = int(i);
    }
  }
  for (const auto& d : c.dropped)
    if (!(d.Delta_max <= d.delta + c.threshold))
      failed << "l = " << d.l << " reaches Delta_" << d.l << " = " << short_value(d.Delta_max) << " > delta_l + "
             << short_value(c.threshold) << " = " << short_value(d.delta + c.threshold)
             << " (t = " << short_value(d.t_max) << "); ";
  if (!(c.sigma_shift <= c.sigma_tolerance))
    failed << "their area moves sigma by up to " << short_value(c.sigma_shift) << " > "
           << short_value(c.sigma_tolerance) << " (t = " << short_value(c.t_sigma_shift) << ")";
  std::string f = failed.str();
  if (f.size() >= 2 && f.compare(f.size() - 2, 2, "; ") == 0) f.resize(f.size() - 2);
  c.passed = f.empty();
  c.L_run = c.passed ? Lc : scene.L;
  std::ostringstream v;
  if (c.passed) {
    v << "every dropped Delta_l stays below delta_l + " << short_value(c.threshold);
    if (worst >= 0) {
      const auto& d = c.dropped[std::size_t(worst)];
      v << " (closest: l = " << d.l << ", " << short_value(d.delta) << " -> " << short_value(d.Delta_max)
        << " at t = " << short_value(d.t_max) << ")";
    }
    v << ", and their area moves sigma by at most " << short_value(c.sigma_shift)
      << " <= " << short_value(c.sigma_tolerance) << " (" << short_value(options.tolerance) << " max |sigma|)";
  } else {
    v << f;
  }
  c.verdict = v.str();
  return c;
}

// run_and_check on a scene already validated: the candidate copy is validated once, for its run and its recorder.
CheckedRun check_candidate(const ValidScene& valid, int L_candidate, const SimulationOptions& options,
                           const TruncationOptions& truncation, const SceneRunner& runner = {}) {
  const Scene& scene = *valid;
  options.validate();
  truncation.validate();
  int L_explicit = 2;
  for (const auto& [l, d] : scene.delta_l) L_explicit = std::max(L_explicit, l);
  for (const auto& [l, d] : scene.rest_delta_l) L_explicit = std::max(L_explicit, l);
  require(L_candidate >= L_explicit && L_candidate < scene.L, "L_candidate", L_candidate,
          "an integer in [" + std::to_string(L_explicit) + ", " + std::to_string(scene.L - 1) +
              "]: below the scene's L and keeping every mode the scene sets explicitly");
  Scene candidate;
  const ValidScene valid_candidate = validated_at_L(valid, candidate, L_candidate);
  StepRecorder recorder(valid_candidate, options.integrator.atol);
  SimulationOptions o = options;
  o.on_step = [&recorder, &options](double t, const Observation& ob) {
    recorder.add(t, ob.Delta_l, ob.sigma);
    if (options.on_step) options.on_step(t, ob);
  };
  CheckedRun out;
  out.run = runner ? runner(valid_candidate, o) : simulate(valid_candidate, o);
  recorder.finish(out.run.Delta_initial, out.run.sigma_initial, out.run.early);
  out.check = check_run(scene, L_candidate, out.run, recorder.steps, truncation);
  return out;
}

// resolve_truncation for a simulation, then the candidate's run and check when it is below the scene's L: sets
// file.scene.L, L_reason and truncation_check. Returns the candidate's run when it passed (the run at file.scene.L).
std::optional<SimulationResult> decide_simulation(SceneFile& file, const ValidScene& valid,
                                                  const SimulationOptions& options, const ReducedTransient* transient,
                                                  const SceneRunner& run, const TransientRunner& transient_run) {
  // Without a check d.L is the scene's L, and with one the candidate (the scene at d.L) is validated_at_L for its
  // run, so neither outcome needs another check.
  const TruncationDecision d =
      resolve_valid(valid, file.origin("run.L"), TruncationUse::simulation, {}, transient, transient_run);
  file.truncation_check.reset();
  if (!d.check) {
    file.scene.L = d.L;
    file.L_reason = d.reason;
    return std::nullopt;
  }
  CheckedRun c = check_candidate(valid, d.L, options, {}, run);
  const std::string dropped = "l = " + mode_range(d.L + 1, file.scene.L);
  std::optional<SimulationResult> out;
  if (c.check.passed) {
    file.L_reason = "L = " + std::to_string(d.L) + ": the scene's L = " + std::to_string(file.scene.L) + " less " +
                    dropped + ", dropped after the check of this run (" + c.check.verdict + "); candidate: " + d.reason;
    file.scene.L = d.L;
    out = std::move(c.run);
  } else {
    file.L_reason = "L = " + std::to_string(file.scene.L) +
                    ": the scene's L, because the candidate L = " + std::to_string(d.L) +
                    " failed the check after its run (" + c.check.verdict + "); candidate: " + d.reason;
  }
  file.truncation_check = std::move(c.check);
  return out;
}

}  // namespace

CheckedRun run_and_check(const Scene& scene, int L_candidate, const SimulationOptions& options,
                         const TruncationOptions& truncation) {
  return check_candidate(validated(scene), L_candidate, options, truncation);
}

SimulationResult simulate_truncated(SceneFile& file, const SimulationOptions& options,
                                    const ReducedTransient* transient, const SceneRunner& run_full,
                                    const TransientRunner& transient_run) {
  return simulate_truncated(file, validated(file), options, transient, run_full, transient_run);
}

SimulationResult simulate_truncated(SceneFile& file, const ValidScene& valid, const SimulationOptions& options,
                                    const ReducedTransient* transient, const SceneRunner& run_full,
                                    const TransientRunner& transient_run) {
  if (&*valid != &file.scene) throw InvalidArgument("valid", "valid must prove this file's own scene: validated(file)");
  std::optional<SimulationResult> run = decide_simulation(file, valid, options, transient, run_full, transient_run);
  if (run) return std::move(*run);
  return run_full ? run_full(valid, options) : simulate(valid, options);
}

void apply_truncation(SceneFile& file, TruncationUse use, const ReducedTransient* transient,
                      const SceneRunner& run_candidate, const TransientRunner& transient_run) {
  apply_truncation(file, validated(file), use, transient, run_candidate, transient_run);
}

void apply_truncation(SceneFile& file, const ValidScene& valid, TruncationUse use, const ReducedTransient* transient,
                      const SceneRunner& run_candidate, const TransientRunner& transient_run) {
  if (&*valid != &file.scene) throw InvalidArgument("valid", "valid must prove this file's own scene: validated(file)");
  if (use == TruncationUse::simulation) {
    SimulationOptions o = file.options;
    o.record_trajectory = false;
    (void)decide_simulation(file, valid, o, transient, run_candidate, transient_run);
    return;
  }
  const TruncationDecision d = resolve_valid(valid, file.origin("run.L"), use, {}, transient);
  Scene at_L;
  (void)validated_at_L(valid, at_L, d.L);  // the L set: checked alone, so valid stays valid
  file.scene.L = d.L;
  file.L_reason = d.reason;
  file.truncation_check.reset();
}

}  // namespace rbcstab
