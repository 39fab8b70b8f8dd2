#include "rbcstab/sweep/trace.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/sweep/detail/trace_in_B.hpp"
#include "rbcstab/verdict/asymptotic.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab {

namespace {
const char* kAsymptoticExact =
    "mu_l = Upsilon_l(sigma_R^eq) = 0 (exact out-of-plane equilibrium, envelope over l = 3..L)";
const char* kAsymptoticAverage =
    "mu_l = Upsilon_l(<sigma_R>) = 0 (time average on the reduced attractor, envelope over l = 3..L)";
const char* kAsymptoticOrbit =
    "mu_l = Upsilon_l(<sigma_R>) = 0 (period average on the attracting periodic orbit, else time average; envelope "
    "over l = 3..L)";
const char* kFiniteHorizon =
    "G_l(T) = int_0^T Upsilon_l(sigma_R(t)) dt = 0 (reduced transient, envelope over l = 3..L)";
}  // namespace

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
    c.description = is_out_of_plane(base, options.predictor) ? kAsymptoticExact
                    : options.orbit.enabled                  ? kAsymptoticOrbit
                                                             : kAsymptoticAverage;
    // Evaluations that share a flow (e.g. along a line of constant C) share its in-plane orbit.
    c.at = [&base, &plane, memo = std::make_shared<AsymptoticSigmaMemo>(options.predictor, options.orbit)](double x,
                                                                                                           double y) {
      const Scene s = plane_scene(base, plane, x, y);
      s.validate();
      CriterionSample out;
      out.sigma_R = memo->verdict(s).sigma_R;
      out.alpha = s.parameters.alpha();
      for (int l = 3; l <= s.L; ++l) out.g.push_back(Upsilon_l(s.parameters, l, out.sigma_R));
      return out;
    };
  } else {
    c.description = kFiniteHorizon;
    c.at = [&base, &plane, &options](double x, double y) {
      const Scene s = plane_scene(base, plane, x, y);
      const FiniteHorizon h = finite_horizon_growth(s, options.T > 0 ? options.T : s.T, options.predictor);
      const ModePrediction verdict = finite_horizon_prediction(s, h);
      if (verdict.status != DomainStatus::ok) throw InvalidArgument("criterion", verdict.reason);
      CriterionSample out;
      out.sigma_R = h.mean_sigma_R;
      out.alpha = s.parameters.alpha();
      out.g.assign(h.G.begin() + 1, h.G.end());  // G is indexed l - 2
      return out;
    };
  }
  return c;
}

namespace {
TraceResult trace_by_continuation(const Scene& base, const DiagramSpec& plane_spec, const TraceOptions& options,
                                  std::chrono::steady_clock::time_point t0) {
  ModeCriteria criteria = plane_criteria(base, plane_spec, options);
  std::size_t evaluations = 0;  // the zero set is traced on this thread
  if (options.on_progress)
    criteria.at = [at = criteria.at, &evaluations, &options](double x, double y) {
      options.on_progress(double(++evaluations), 0);
      return at(x, y);
    };
  // A geometric axis (shear_rate, spanning decades) is traced in ln of its value, so the curve's resolution
  // (max_step of the unit square) is even in ln, as the diagram's grid is.
  const bool gx = parameter_row(plane_spec.x.axis).scale == AxisScale::geometric;
  const bool gy = parameter_row(plane_spec.y.axis).scale == AxisScale::geometric;
  auto traced = [](bool g, double v) { return g ? std::log(v) : v; };
  auto value = [](bool g, double v) { return g ? std::exp(v) : v; };
  if (gx || gy)
    criteria.at = [at = criteria.at, gx, gy, value](double x, double y) { return at(value(gx, x), value(gy, y)); };
  const PlaneBox box{traced(gx, plane_spec.x.min), traced(gx, plane_spec.x.max), traced(gy, plane_spec.y.min),
                     traced(gy, plane_spec.y.max)};
  const ZeroSetResult z = trace_zero_set(criteria, box, options.zero_set());
  TraceResult res;
  res.criterion = options.criterion;
  for (const ZeroSetPiece& p : z.pieces) {
    TraceCurve c;
    c.l = p.l;
    c.criterion = criteria.description;
    c.chain = p.chain;
    for (const ZeroSetPoint& q : p.points)
      c.points.push_back({value(gx, q.x), value(gy, q.y), q.l, q.sigma_R, sigma_c(q.l, q.alpha), q.g});
    res.curves.push_back(std::move(c));
  }
  for (const ZeroSetCorner& k : z.corners) res.corners.push_back({value(gx, k.x), value(gy, k.y), k.l_from, k.l_to});
  res.evaluations = z.evaluations;
  res.chains = z.chains;
  res.starts = z.starts;
  res.turning_points = z.turning_points;
  res.counters = z.counters;
  res.notes = z.notes;
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}
}  // namespace

TraceResult trace_boundary(const Scene& base, const DiagramSpec& plane_spec, const TraceOptions& options) {
  options.validate();
  validate_plane(base, plane_spec);
  require_L(base.L, 3, kMaxL, "a boundary needs a mode l >= 3");
  const auto t0 = std::chrono::steady_clock::now();
  if (!detail::closed_form_in_B_applies(base, plane_spec, options))
    return trace_by_continuation(base, plane_spec, options, t0);
  detail::InBTrace exact =
      detail::trace_in_B(base, plane_spec, options,
                         options.criterion == TraceCriterion::finite_horizon ? kFiniteHorizon : kAsymptoticOrbit);
  if (exact.result) {
    exact.result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return *exact.result;
  }
  TraceResult res = trace_by_continuation(base, plane_spec, options, t0);
  res.evaluations += exact.evaluations;
  std::vector<std::string> notes(1, "closed form in B not used (traced by continuation): " + exact.why);
  notes.insert(notes.end(), res.notes.begin(), res.notes.end());
  res.notes = std::move(notes);
  return res;
}

std::vector<Overlay> analytic_overlays(const Scene& base, const DiagramSpec& plane, int n) {
  require(n >= 2 && n <= 1'000'000, "n", n, "an integer in [2, 1000000]");
  std::vector<Overlay> out;
  const AxisRange& X = plane.x;
  const AxisRange& Y = plane.y;
  auto xs = [&](int k) { return X.min + (X.max - X.min) * double(k) / double(n - 1); };
  auto inside = [&](double y) {
    return std::isfinite(y) && y >= std::min(Y.min, Y.max) && y <= std::max(Y.min, Y.max);
  };
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
      if (const Quantity q = C_star_plus(p, stress_free_r0(base));
          q.valid() && q.value > 0 && inside(std::log(q.value)))
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
