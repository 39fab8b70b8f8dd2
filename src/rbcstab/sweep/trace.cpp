#include "rbcstab/sweep/trace.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/continuation/parameters.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

namespace {
const char* kAsymptoticExact = "mu_l = Upsilon_l(sigma_R^eq) = 0 (exact out-of-plane equilibrium, envelope over l = 3..L)";
const char* kAsymptoticAverage = "mu_l = Upsilon_l(<sigma_R>) = 0 (time average on the reduced attractor, envelope over l = 3..L)";
const char* kAsymptoticOrbit =
    "mu_l = Upsilon_l(<sigma_R>) = 0 (period average on the attracting periodic orbit, else time average; envelope over l = 3..L)";
const char* kFiniteHorizon = "G_l(T) = int_0^T Upsilon_l(sigma_R(t)) dt = 0 (reduced transient, envelope over l = 3..L)";

bool out_of_plane(const Scene& scene, const PredictorOptions& o) { return stress_free_r0(scene) < o.out_of_plane_r0; }
}  // namespace

void OrbitAverageOptions::validate() const {
  require(relaxation_periods >= 0 && relaxation_periods <= 100000, "relaxation_periods", relaxation_periods,
          "an integer in [0, 100000]");
  require(samples >= 4 && samples <= 1000000, "samples", samples, "an integer in [4, 1000000]");
  require(std::isfinite(max_multiplier) && max_multiplier > 0 && max_multiplier <= 1, "max_multiplier",
          max_multiplier, "(0, 1]");
  require(std::isfinite(newton_tol) && newton_tol >= 1e-15 && newton_tol <= 1e-6, "newton_tol", newton_tol,
          "[1e-15, 1e-6]");
  require(max_iterations >= 1 && max_iterations <= 1000, "max_iterations", max_iterations, "an integer in [1, 1000]");
  shooting.validate();
}

OrbitSigmaAverage orbit_sigma_average(const Scene& scene, const OrbitAverageOptions& o) {
  o.validate();
  scene.validate();
  constexpr double kTwoPi = 2 * std::numbers::pi;
  OrbitSigmaAverage a;
  // The free parameter is irrelevant at fixed p; B is defined for every valid scene.
  const ReducedForcedSystem sys(scene, ContinuationParameter::B);
  const PeriodicOrbitProblem orbit(sys, o.shooting);
  const double p = sys.start_parameter();
  const ReducedModel& model = sys.model(p);
  Eigen::VectorXd x0;
  if (o.relaxation_periods > 0) {
    x0 = sys.relaxed_state(kTwoPi * o.relaxation_periods);
  } else {
    const std::vector<double> y0 = model.initial_state();
    x0 = Eigen::Map<const Eigen::VectorXd>(y0.data(), 3);
  }
  if (!x0.allFinite()) {
    a.reason = "relaxation run failed";
    return a;
  }
  const NewtonResult nr = solve_fixed_parameter(orbit, orbit.shooting_guess(x0, p), p, o.newton_tol, o.max_iterations);
  a.newton_iterations = nr.iterations;
  a.newton_residual = nr.residual_norm;
  if (!nr.converged) {
    a.integrations = orbit.integrations();
    a.reason = "periodic-orbit Newton did not converge in " + std::to_string(nr.iterations) + " iterations (residual " +
               format_value(nr.residual_norm) + ")";
    return a;
  }
  const Floquet fl = orbit.floquet(nr.x, p);
  a.max_multiplier = fl.multipliers.size() > 0 ? fl.multipliers.cwiseAbs().maxCoeff() : 0.0;
  a.x0 = orbit.state_at_zero(nr.x);
  if (!(a.max_multiplier < o.max_multiplier)) {
    a.integrations = orbit.integrations();
    a.reason = "the periodic orbit is not attracting (largest nontrivial Floquet multiplier modulus " +
               format_value(a.max_multiplier) + ")";
    return a;
  }
  // Periodic trapezoid rule on t_k = 2 pi k / K: sigma_R(t) from the model's own observation.
  const int K = o.samples;
  std::vector<double> grid;
  grid.reserve(static_cast<std::size_t>(K));
  for (int k = 1; k < K; ++k) grid.push_back(kTwoPi * k / K);
  double sum = model.observe(0.0, std::span<const double>(a.x0.data(), 3)).sigma;
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = o.shooting.rtol;
  io.atol = o.shooting.atol;
  const IntegrationResult r = integrate(model, std::span<const double>(a.x0.data(), 3), 0.0, grid, io,
                                        [&](double t, std::span<const double> y) { sum += model.observe(t, y).sigma; });
  a.integrations = orbit.integrations() + 1;
  if (r.status != IntegrationStatus::success) {
    a.reason = "one-period run failed: " + r.reason;
    return a;
  }
  a.sigma_R = sum / K;
  a.ok = std::isfinite(a.sigma_R);
  if (!a.ok) a.reason = "non-finite period average";
  return a;
}

AsymptoticSigma asymptotic_sigma_R(const Scene& scene, const PredictorOptions& options, const OrbitAverageOptions& orbit) {
  AsymptoticSigma out;
  if (out_of_plane(scene, options)) {
    const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(scene.parameters);
    if (eq.stable) {
      out.sigma_R = eq.sigma_R;
      out.exact = true;
      out.source = SigmaSource::equilibrium;
      return out;
    }
  } else if (orbit.enabled) {
    // In plane the attractor is (mostly) a 2 pi-periodic orbit of the forced reduced system.
    const OrbitSigmaAverage a = orbit_sigma_average(scene, orbit);
    out.max_multiplier = a.max_multiplier;
    out.newton_iterations = a.newton_iterations;
    if (a.ok) {
      out.sigma_R = a.sigma_R;
      out.source = SigmaSource::periodic_orbit;
      return out;
    }
    out.note = a.reason;
  }
  // The time average (the needed sigma_R integral at three times only: no dense regime sampling, 10x cheaper).
  PredictorOptions o = options;
  o.regime_sample_dt = 0.5 * o.window;
  const SigmaAverage avg = time_averaged_sigma_R(scene, o);
  if (!avg.mean.valid())
    throw InvalidArgument("criterion", out.note.empty() ? avg.mean.reason : avg.mean.reason + " (" + out.note + ")");
  out.sigma_R = avg.mean.value;
  out.source = SigmaSource::time_average;
  return out;
}

AsymptoticVerdict asymptotic_verdict(const Scene& scene, const PredictorOptions& options,
                                     const OrbitAverageOptions& orbit) {
  AsymptoticVerdict v;
  v.sigma_R = asymptotic_sigma_R(scene, options, orbit).sigma_R;
  const double alpha = scene.parameters.alpha();
  v.active_mode = surviving_mode(alpha, scene.L);
  v.margin = v.sigma_R - sigma_critical(v.active_mode, alpha);
  v.unstable = v.margin < 0;
  v.l = v.unstable ? v.active_mode : 2;
  return v;
}

void TraceOptions::validate() const {
  require(std::isfinite(T) && T >= 0, "T", T, "finite and >= 0 (0: the scene's T)");
  predictor.validate();
  orbit.validate();
  zero_set().validate();
}

PredictorOptions TraceOptions::tracing_predictor() {
  PredictorOptions o;
  o.integrator.rtol = 1e-12;
  o.integrator.atol = 1e-14;
  return o;
}

ZeroSetOptions TraceOptions::zero_set() const {
  ZeroSetOptions z;
  z.seed_lines = lines;
  z.samples = samples;
  z.bisections = bisections;
  z.max_step = max_step;
  z.initial_step = std::min(z.initial_step, max_step);
  return z;
}

ModeCriteria plane_criteria(const Scene& base, const DiagramSpec& plane, const TraceOptions& options) {
  ModeCriteria c;
  c.l_min = 3;
  if (options.criterion == TraceCriterion::asymptotic) {
    c.description = out_of_plane(base, options.predictor) ? kAsymptoticExact
                    : options.orbit.enabled                ? kAsymptoticOrbit
                                                           : kAsymptoticAverage;
    c.at = [&base, &plane, po = options.predictor, oo = options.orbit](double x, double y) {
      const Scene s = plane_scene(base, plane, x, y);
      s.validate();
      CriterionSample out;
      out.sigma_R = asymptotic_sigma_R(s, po, oo).sigma_R;
      out.alpha = s.parameters.alpha();
      for (int l = 3; l <= s.L; ++l) out.g.push_back(Upsilon(s.parameters, l, out.sigma_R));
      return out;
    };
  } else {
    c.description = kFiniteHorizon;
    c.at = [&base, &plane, &options](double x, double y) {
      const Scene s = plane_scene(base, plane, x, y);
      const FiniteHorizon h = finite_horizon_growth(s, options.T > 0 ? options.T : s.T, options.predictor);
      if (h.status != IntegrationStatus::success)
        throw InvalidArgument("criterion", "reduced run stopped at t = " + format_value(h.T) + ": " + h.reason);
      CriterionSample out;
      out.sigma_R = h.mean_sigma_R;
      out.alpha = s.parameters.alpha();
      out.g.assign(h.G.begin() + 1, h.G.end());  // G is indexed l - 2
      return out;
    };
  }
  return c;
}

TraceResult trace_boundary(const Scene& base, const DiagramSpec& plane_spec, const TraceOptions& options) {
  options.validate();
  plane_spec.validate();
  base.validate();
  require(base.L >= 3, "L", base.L, ">= 3 (a boundary needs a mode l >= 3)");
  const auto t0 = std::chrono::steady_clock::now();
  const ModeCriteria criteria = plane_criteria(base, plane_spec, options);
  const PlaneBox box{plane_spec.x.min, plane_spec.x.max, plane_spec.y.min, plane_spec.y.max};
  const ZeroSetResult z = trace_zero_set(criteria, box, options.zero_set());
  TraceResult res;
  res.criterion = options.criterion;
  for (const ZeroSetPiece& p : z.pieces) {
    TraceCurve c;
    c.l = p.l;
    c.criterion = criteria.description;
    c.chain = p.chain;
    for (const ZeroSetPoint& q : p.points)
      c.points.push_back({q.x, q.y, q.l, q.sigma_R, sigma_critical(q.l, q.alpha), q.g});
    res.curves.push_back(std::move(c));
  }
  for (const ZeroSetCorner& k : z.corners) res.corners.push_back({k.x, k.y, k.l_from, k.l_to});
  res.evaluations = z.evaluations;
  res.chains = z.chains;
  res.starts = z.starts;
  res.turning_points = z.turning_points;
  res.counters = z.counters;
  res.notes = z.notes;
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

std::vector<Overlay> analytic_overlays(const Scene& base, const DiagramSpec& plane, int n) {
  require(n >= 2 && n <= 1'000'000, "n", n, "an integer in [2, 1000000]");
  std::vector<Overlay> out;
  const AxisRange& X = plane.x;
  const AxisRange& Y = plane.y;
  auto xs = [&](int k) { return X.min + (X.max - X.min) * double(k) / double(n - 1); };
  auto inside = [&](double y) { return std::isfinite(y) && y >= std::min(Y.min, Y.max) && y <= std::max(Y.min, Y.max); };
  if (X.axis == Axis::lnB && Y.axis == Axis::lnC && plane.alpha == 0) {
    auto alpha_line = [&](const std::string& name, double alpha) {
      Overlay o{name, {}, {}};
      for (int k = 0; k < n; ++k)
        if (const double y = xs(k) - std::log(alpha); inside(y)) o.x.push_back(xs(k)), o.y.push_back(y);
      out.push_back(o);
    };
    alpha_line("l_star=2.5", alpha_for_l_star(2.5));
    for (int l = 3; l < base.L; ++l) alpha_line("l_star=" + std::to_string(l) + ".5", alpha_for_l_star(l + 0.5));
    if (const Quantity ai = alpha_init(base.parameters); ai.valid()) alpha_line("alpha_init", ai.value);
    Overlay cm{"C_star_minus", {}, {}}, cp{"C_star_plus", {}, {}};
    for (int k = 0; k < n; ++k) {
      const Parameters p = plane_scene(base, plane, xs(k), 0.5 * (Y.min + Y.max)).parameters;
      if (const Quantity q = C_star_minus(p); q.valid() && q.value > 0 && inside(std::log(q.value)))
        cm.x.push_back(xs(k)), cm.y.push_back(std::log(q.value));
      if (const Quantity q = C_star_plus(p, stress_free_r0(base)); q.valid() && q.value > 0 && inside(std::log(q.value)))
        cp.x.push_back(xs(k)), cp.y.push_back(std::log(q.value));
    }
    out.push_back(cm);
    out.push_back(cp);
  } else if (X.axis == Axis::lnC && Y.axis == Axis::lambda && plane.alpha > 0) {
    Overlay o{"lambda_star_minus", {}, {}};
    for (int k = 0; k < n; ++k)
      if (const Quantity q = lambda_star_minus(plane.alpha, std::exp(xs(k)), base.parameters.Delta);
          q.valid() && inside(q.value))
        o.x.push_back(xs(k)), o.y.push_back(q.value);
    out.push_back(o);
  }
  return out;
}

}  // namespace rbcstab
