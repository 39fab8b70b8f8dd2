#include "rbcstab/sweep/threshold_precision.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab {

void ThresholdPrecisionOptions::validate() const {
  require(std::isfinite(ln_C_lo) && std::isfinite(ln_C_hi) && ln_C_lo < ln_C_hi, "ln_C_lo", ln_C_lo,
          "finite and below ln_C_hi = " + format_value(ln_C_hi));
  require(ln_C_hi - ln_C_lo <= 100, "ln_C_hi", ln_C_hi, "within 100 of ln_C_lo");
  for (int k : bisections) require(k >= 1 && k <= 60, "bisections", k, "each in [1, 60]");
  for (double r : rtols) require(std::isfinite(r) && r >= 1e-14 && r <= 0.1, "rtols", r, "each in [1e-14, 0.1]");
  for (int n : grid_points) require(n >= 2 && n <= 100000, "grid_points", n, "each in [2, 100000]");
  require(std::isfinite(grid_rtol) && grid_rtol >= 1e-14 && grid_rtol <= 0.1, "grid_rtol", grid_rtol,
          "in [1e-14, 0.1]");
  require(std::isfinite(reference_rtol) && reference_rtol >= 1e-14 && reference_rtol <= 1e-9, "reference_rtol",
          reference_rtol, "in [1e-14, 1e-9]");
  require(reference_bisections >= 10 && reference_bisections <= 60, "reference_bisections", reference_bisections,
          "an integer in [10, 60]");
  for (double h : trace_max_steps)
    require(std::isfinite(h) && h > 0 && h <= 0.5, "trace_max_steps", h, "each in (0, 0.5]");
  require(std::isfinite(trace_half_width) && trace_half_width > 0 && trace_half_width <= 10, "trace_half_width",
          trace_half_width, "in (0, 10]");
  for (const auto& name : predictors)
    if (name != "asymptotic" && name != "finite_horizon" && name != "simulation")
      throw InvalidArgument("predictors",
                            "predictors: '" + name + "' is not one of asymptotic, finite_horizon, simulation");
}

namespace {
using Clock = std::chrono::steady_clock;

struct Eval {
  bool unstable = false;
  bool ok = true;
  std::size_t rhs = 0;
  std::string why;
};
using VerdictFn = std::function<Eval(double ln_C, double rtol)>;

Scene at(const Scene& base, double ln_C) {
  Scene s = base;
  s.parameters.C = std::exp(ln_C);
  return s;
}

// A <sigma_R> outside its domain is a failed evaluation (a status), as a failed run is for the others.
Eval asymptotic(const Scene& base, double ln_C, double) {
  const Scene s = at(base, ln_C);
  const AsymptoticSigma a = asymptotic_sigma_R(s);
  if (!a.valid()) return {false, false, 0, a.reason};
  return {asymptotic_verdict(s, a.sigma_R).unstable, true, 0, {}};
}

Eval finite_horizon(const Scene& base, double ln_C, double rtol) {
  const Scene s = at(base, ln_C);
  PredictorOptions po;
  po.integrator.rtol = rtol;
  po.integrator.atol = rtol * 1e-4;  // as work-precision: the relative test governs the O(1) state
  const FiniteHorizon h = finite_horizon_growth(s, s.T, po);
  Eval e;
  e.rhs = h.counters.rhs_evaluations;
  e.ok = h.status == IntegrationStatus::success;
  e.why = h.reason;
  for (std::size_t k = 1; k < h.G.size(); ++k) e.unstable = e.unstable || h.G[k] > 0;  // l >= 3
  return e;
}

Eval simulation(const Scene& base, double ln_C, double rtol) {
  Scene s = at(base, ln_C);
  s.dt = s.T;
  SimulationOptions so;
  so.integrator.rtol = rtol;
  so.integrator.atol = rtol * 1e-4;
  so.record_trajectory = false;
  const SimulationResult r = simulate(s, so);
  return {r.l_Delta >= 3, r.status == IntegrationStatus::success, r.counters.rhs_evaluations, r.reason};
}

// Bisection on the verdict; estimates[k - 1] is the bracket midpoint after k halvings, with the cumulative cost.
struct Bisection {
  std::vector<double> estimate, width, seconds;
  std::vector<std::size_t> evaluations, rhs;
  std::string status = "ok";
};
Bisection bisect(const VerdictFn& f, double lo, double hi, double rtol, int halvings) {
  Bisection b;
  const auto t0 = Clock::now();
  std::size_t evals = 0, rhs = 0;
  auto eval = [&](double x) {
    const Eval e = f(x, rtol);
    ++evals;
    rhs += e.rhs;
    return e;
  };
  const Eval elo = eval(lo), ehi = eval(hi);
  if (!elo.ok || !ehi.ok) {
    b.status = "a run at the bracket ends failed: " + (elo.ok ? ehi.why : elo.why);
    return b;
  }
  if (elo.unstable == ehi.unstable) {
    b.status =
        std::string("no verdict change in the bracket (") + (elo.unstable ? "unstable" : "stable") + " at both ends)";
    return b;
  }
  double a = lo, c = hi;
  for (int k = 1; k <= halvings; ++k) {
    const double m = 0.5 * (a + c);
    const Eval e = eval(m);
    if (!e.ok) {
      b.status = "run failed at ln C = " + format_value(m) + ": " + e.why;
      return b;
    }
    (e.unstable == elo.unstable ? a : c) = m;
    b.estimate.push_back(0.5 * (a + c));
    b.width.push_back(c - a);
    b.evaluations.push_back(evals);
    b.rhs.push_back(rhs);
    b.seconds.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return b;
}

// The boundary by continuation: trace the strip ln B +- half_width, then interpolate the traced curve linearly
// at ln B (the points themselves are Newton-corrected onto the curve; the interpolation error is the method's).
ThresholdRow continuation(const Scene& base, const std::string& name, TraceCriterion criterion, double lo, double hi,
                          double half_width, double max_step) {
  ThresholdRow row{name, "continuation", 0, int(std::lround(1 / max_step)), 0, 0, 0, 0, 0, "ok"};
  const double x0 = std::log(base.parameters.B);
  DiagramSpec plane;
  plane.x = {Axis::lnB, x0 - half_width, x0 + half_width, 2};
  plane.y = {Axis::lnC, lo, hi, 2};
  TraceOptions to;
  to.criterion = criterion;
  to.max_step = max_step;
  const TraceResult tr = trace_boundary(base, plane, to);
  row.evaluations = tr.evaluations;
  row.seconds = tr.seconds;
  bool found = false;
  for (const TraceCurve& c : tr.curves)
    for (std::size_t k = 1; k < c.points.size() && !found; ++k) {
      const TracePoint &a = c.points[k - 1], &b = c.points[k];
      if ((a.x - x0) * (b.x - x0) > 0 || a.x == b.x) continue;
      row.ln_C = a.y + (b.y - a.y) * (x0 - a.x) / (b.x - a.x);
      found = true;
    }
  if (!found) row.status = "the traced curve does not cross ln B = " + format_value(x0);
  return row;
}

ThresholdRow grid(const std::string& name, const VerdictFn& f, double lo, double hi, double rtol, int n) {
  ThresholdRow row{name, "grid", rtol, n, 0, 0, 0, 0, 0, "ok"};
  const auto t0 = Clock::now();
  bool first = false, found = false;
  for (int i = 0; i < n; ++i) {
    const double x = lo + (hi - lo) * i / (n - 1);
    const Eval e = f(x, rtol);
    ++row.evaluations;
    row.rhs_evaluations += e.rhs;
    if (!e.ok) {
      row.status = "run failed at ln C = " + format_value(x) + ": " + e.why;
      break;
    }
    if (i == 0) first = e.unstable;
    if (!found && i > 0 && e.unstable != first) {
      row.ln_C = x - 0.5 * (hi - lo) / (n - 1);  // midpoint of the cell (as a diagram would draw it)
      found = true;
    }
  }
  if (row.status == "ok" && !found) row.status = "no verdict change on the grid";
  row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return row;
}
}  // namespace

ThresholdPrecision threshold_precision(const Scene& base, const ThresholdPrecisionOptions& options) {
  options.validate();
  base.validate();
  ThresholdPrecision out;
  out.B = base.parameters.B;
  const double lo = options.ln_C_lo, hi = options.ln_C_hi;
  struct Predictor {
    std::string name;
    VerdictFn f;
    bool integrates = false;
  };
  const std::vector<Predictor> predictors{
      {"asymptotic", [&](double x, double r) { return asymptotic(base, x, r); }, false},
      {"finite_horizon", [&](double x, double r) { return finite_horizon(base, x, r); }, true},
      {"simulation", [&](double x, double r) { return simulation(base, x, r); }, true}};
  int kmax = 1;
  for (int k : options.bisections) kmax = std::max(kmax, k);
  auto add = [&](const ThresholdRow& row) {
    out.rows.push_back(row);
    if (options.on_progress) options.on_progress(double(out.rows.size()), 0);
  };

  for (const Predictor& p : predictors) {
    if (std::find(options.predictors.begin(), options.predictors.end(), p.name) == options.predictors.end()) continue;
    const double ref_rtol = p.integrates ? options.reference_rtol : 0.0;
    const Bisection ref = bisect(p.f, lo, hi, ref_rtol, options.reference_bisections);
    ThresholdReference r{p.name, 0, 0, ref.status};
    if (ref.status == "ok") {
      r.ln_C = ref.estimate.back();
      r.bracket = ref.width.back();
    }
    out.references.push_back(r);
    // Without a reference the error is unknown: NaN, which the outputs show as a missing value with its reason.
    auto error_of = [&](double x) {
      return r.status == "ok" ? std::abs(x - r.ln_C) : std::numeric_limits<double>::quiet_NaN();
    };

    const std::vector<double> rtols = p.integrates ? options.rtols : std::vector<double>{0.0};
    for (double rtol : rtols) {
      const Bisection b = bisect(p.f, lo, hi, rtol, kmax);
      for (int k : options.bisections) {
        ThresholdRow row{p.name, "bisection", rtol, k, 0, 0, 0, 0, 0, b.status};
        if (b.status == "ok") {
          const std::size_t i = std::size_t(k - 1);
          row.ln_C = b.estimate[i];
          row.error = error_of(row.ln_C);
          row.evaluations = b.evaluations[i];
          row.rhs_evaluations = b.rhs[i];
          row.seconds = b.seconds[i];
        }
        add(row);
      }
    }
    for (int n : options.grid_points) {
      ThresholdRow row = grid(p.name, p.f, lo, hi, p.integrates ? options.grid_rtol : 0.0, n);
      if (row.status == "ok") row.error = error_of(row.ln_C);
      add(row);
    }
    if (p.name != "simulation")  // the simulated verdict has no smooth criterion to continue
      for (double h : options.trace_max_steps) {
        const TraceCriterion crit =
            p.name == "asymptotic" ? TraceCriterion::asymptotic : TraceCriterion::finite_horizon;
        ThresholdRow row = continuation(base, p.name, crit, lo, hi, options.trace_half_width, h);
        if (row.status == "ok") row.error = error_of(row.ln_C);
        add(row);
      }
    if (p.name == "asymptotic") {
      // The paper's closed form (S >> 1): a model approximation of this predictor, not a numerical method.
      const Parameters& par = base.parameters;
      const auto t0 = Clock::now();
      const Quantity C = par.Lambda() > 1 ? C_star_plus(par, stress_free_r0(base)) : C_star_minus(par);
      ThresholdRow row{p.name, "closed_form", 0, 1, 0, 0, 1, 0, 0, "ok"};
      row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      if (C.valid() && C.value > 0) {
        row.ln_C = std::log(C.value);
        row.error = error_of(row.ln_C);
      } else {
        row.status = "closed form outside its domain: " + C.reason;
      }
      add(row);
    }
  }
  return out;
}

}  // namespace rbcstab
