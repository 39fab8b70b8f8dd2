#include "rbcstab/sweep/agreement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <thread>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/parallel.hpp"
#include "rbcstab/verdict/asymptotic.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab {

void AgreementOptions::validate() const {
  require(threads >= 0 && threads <= 4096, "threads", threads, "an integer in [0, 4096] (0: all cores)");
  trace_options.validate();
}

namespace {

struct PointVerdict {
  bool classified = false;
  bool unstable = false;
  int l = 2;
};

using Polyline = std::vector<std::pair<double, double>>;

// Distances in grid steps to a set of polylines.
class BoundaryDistance {
 public:
  BoundaryDistance(const DiagramSpec& spec, std::vector<Polyline> lines) : lines_(std::move(lines)) {
    dx_ = spec.x.count > 1 ? (spec.x.max - spec.x.min) / (spec.x.count - 1) : 1.0;
    dy_ = spec.y.count > 1 ? (spec.y.max - spec.y.min) / (spec.y.count - 1) : 1.0;
  }
  double operator()(double x, double y) const {
    double best = std::numeric_limits<double>::infinity();
    for (const Polyline& c : lines_)
      for (std::size_t k = 0; k < c.size(); ++k) {
        const double px = (x - c[k].first) / dx_, py = (y - c[k].second) / dy_;
        if (k == 0) {
          best = std::min(best, std::hypot(px, py));
          continue;
        }
        const double sx = (c[k - 1].first - c[k].first) / dx_, sy = (c[k - 1].second - c[k].second) / dy_;
        const double len2 = sx * sx + sy * sy;
        const double t = len2 > 0 ? std::clamp((px * sx + py * sy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(px - t * sx, py - t * sy));
      }
    return best;
  }

 private:
  std::vector<Polyline> lines_;
  double dx_ = 1, dy_ = 1;
};

std::vector<Polyline> polylines(const TraceResult& t) {
  std::vector<Polyline> out;
  for (const TraceCurve& c : t.curves) {
    Polyline p;
    for (const TracePoint& q : c.points) p.emplace_back(q.x, q.y);
    out.push_back(std::move(p));
  }
  return out;
}

// Overlay samples as polylines, broken where samples were left out (outside the formula's domain).
std::vector<Polyline> polylines(const std::vector<Overlay>& overlays, const std::vector<std::string>& names,
                                const DiagramSpec& spec, int n) {
  std::vector<Polyline> out;
  const double step = std::abs(spec.x.max - spec.x.min) / (n - 1);
  for (const Overlay& o : overlays) {
    if (std::find(names.begin(), names.end(), o.name) == names.end()) continue;
    Polyline p;
    for (std::size_t k = 0; k < o.x.size(); ++k) {
      if (!p.empty() && std::abs(o.x[k] - p.back().first) > 1.5 * step) {
        out.push_back(std::move(p));
        p.clear();
      }
      p.emplace_back(o.x[k], o.y[k]);
    }
    if (!p.empty()) out.push_back(std::move(p));
  }
  return out;
}

int nearest_mode(double alpha, int L) { return std::clamp(int(std::lround(l_star(alpha))), 3, L); }

// Per-point verdicts of one predictor, in parallel over the points.
std::vector<PointVerdict> verdicts(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                                   int threads, const std::function<PointVerdict(const Scene&)>& f) {
  std::vector<PointVerdict> out(points.size());
  parallel_for(points.size(), threads, [&](std::size_t i) {
    if (points[i].verdict == Verdict::failed) return;
    try {
      out[i] = f(point_scene(base, spec, points[i].index));
    } catch (const InvalidArgument&) {
      out[i] = {};  // outside the predictor's domain: not classified
    }
  });
  return out;
}

// One value per reduced flow (ReducedTransient::flow) of the points, each computed once at the base scene's B, so
// that a point's value does not depend on which other points the diagram (or its shard) holds; the points map it
// to their B (transient_at_B, orbit_sigma_average_at_B). A flow whose computation refuses its scene has none.
template <class T>
class FlowValues {
 public:
  // compute(s) for one scene of each flow with B = the base's; wanted(s): the point needs its flow's value.
  FlowValues(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points, int threads,
             const std::function<bool(const Scene&)>& wanted, const std::function<T(const Scene&)>& compute) {
    std::vector<Scene> flows;
    for (const PointResult& p : points) {
      if (p.verdict == Verdict::failed) continue;
      Scene s = point_scene(base, spec, p.index);
      if (!wanted(s) || !index_.emplace(ReducedTransient::flow(s.parameters, s.beta), flows.size()).second) continue;
      s.parameters.B = base.parameters.B;
      flows.push_back(std::move(s));
    }
    values_.resize(flows.size());
    parallel_for(flows.size(), threads, [&](std::size_t k) {
      try {
        values_[k] = compute(flows[k]);
      } catch (const InvalidArgument&) {
        values_[k].reset();
      }
    });
  }
  // The value of the point scene s's flow; nullptr where it has none.
  const T* find(const Scene& s) const {
    const auto it = index_.find(ReducedTransient::flow(s.parameters, s.beta));
    return it == index_.end() || !values_[it->second] ? nullptr : &*values_[it->second];
  }

 private:
  std::map<std::array<double, 5>, std::size_t> index_;
  std::vector<std::optional<T>> values_;
};

Agreement compare(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                  const std::vector<PointVerdict>& v, const BoundaryDistance& distance) {
  Agreement a;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PointResult& p = points[i];
    if (p.verdict == Verdict::failed) continue;
    if (!v[i].classified) {
      ++a.not_classified;
      continue;
    }
    ++a.points;
    const bool sim_unstable = p.verdict == Verdict::unstable;
    if (sim_unstable == v[i].unstable) {
      ++a.verdict_matches;
      if (!v[i].unstable || v[i].l == p.l_Delta) ++a.mode_matches;
      if (v[i].unstable) {
        ++a.unstable_matches;
        if (v[i].l == p.l_Delta) ++a.unstable_mode_matches;
      }
      continue;
    }
    const Scene s = point_scene(base, spec, p.index);
    Disagreement d;
    d.index = p.index;
    d.simulated = p.verdict;
    d.l_simulated = p.l_Delta;
    d.predicted_unstable = v[i].unstable;
    d.l_predicted = v[i].l;
    d.distance_steps = distance(p.x, p.y);
    d.S = s.parameters.S();
    const Quantity ai = alpha_init(s.parameters);
    d.alpha_over_alpha_init = ai.valid() && ai.value > 0 ? s.parameters.alpha() / ai.value : 0.0;
    if (d.distance_steps > 1) ++a.beyond_one_step;
    if (d.S < 10) ++a.small_S;
    if (d.alpha_over_alpha_init > 0 && std::abs(d.alpha_over_alpha_init - 1) < 0.25) ++a.near_alpha_init;
    a.verdict_disagreements.push_back(d);
  }
  return a;
}

// The asymptotic verdicts. In plane one periodic orbit per flow (it holds no B), mapped to each point's B
// (bit-identical to solving it there: verdict/asymptotic.hpp).
std::vector<PointVerdict> asymptotic_verdicts(const Scene& base, const DiagramSpec& spec,
                                              const std::vector<PointResult>& points, int threads,
                                              const PredictorOptions& po, const OrbitAverageOptions& oo) {
  const FlowValues<OrbitSigmaAverage> orbits(
      base, spec, points, threads, [&](const Scene& s) { return oo.enabled && !is_out_of_plane(s, po); },
      [&](const Scene& s) { return orbit_sigma_average(s, oo); });
  return verdicts(base, spec, points, threads, [&](const Scene& s) {
    const OrbitSigmaAverage* orbit = orbits.find(s);
    const AsymptoticVerdict v = orbit ? asymptotic_verdict(s, *orbit, po, oo) : asymptotic_verdict(s, po, oo);
    return PointVerdict{true, v.unstable, v.l};
  });
}

}  // namespace

Agreement asymptotic_agreement(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                               const TraceResult& boundary) {
  const std::vector<PointVerdict> v = asymptotic_verdicts(base, spec, points, 1, {}, {});
  Agreement a = compare(base, spec, points, v, BoundaryDistance(spec, polylines(boundary)));
  a.predictor = "asymptotic";
  a.boundary = "the given traced boundary";
  a.boundary_pieces = boundary.curves.size();
  a.boundary_corners = boundary.corners.size();
  return a;
}

std::vector<Agreement> predictor_agreements(const Scene& base, const DiagramSpec& spec,
                                            const std::vector<PointResult>& points, const AgreementOptions& options) {
  options.validate();
  const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  const PredictorOptions& po = options.predictor;
  std::vector<Agreement> out;

  auto traced = [&](TraceCriterion c, Agreement& a) {
    if (!options.trace) return BoundaryDistance(spec, {});
    if (!options.trace_in_plane && !is_out_of_plane(base, options.predictor)) {
      a.note = "boundary not traced: in-plane scene (AgreementOptions::trace_in_plane, or rbcstab trace --diagram)";
      return BoundaryDistance(spec, {});
    }
    TraceOptions to = options.trace_options;
    to.criterion = c;
    try {
      const bool given = c == TraceCriterion::asymptotic && options.asymptotic_boundary;
      const TraceResult t = given ? *options.asymptotic_boundary : trace_boundary(base, spec, to);
      a.boundary_pieces = t.curves.size();
      a.boundary_corners = t.corners.size();
      a.boundary = "the " + to_string(c) + " boundary traced " + t.method;
      if (!t.notes.empty()) a.note = t.notes.front();
      return BoundaryDistance(spec, polylines(t));
    } catch (const InvalidArgument& e) {
      a.note = std::string("boundary not traced: ") + e.what();
      return BoundaryDistance(spec, {});
    }
  };

  // A predictor's entry: its agreement, plus the traced boundary it was measured against.
  auto push = [&](Agreement a, const Agreement& boundary, const char* predictor, const char* description) {
    a.predictor = predictor;
    a.description = description;
    a.boundary = boundary.boundary;
    a.boundary_pieces = boundary.boundary_pieces;
    a.boundary_corners = boundary.boundary_corners;
    a.note = boundary.note;
    out.push_back(std::move(a));
  };
  Agreement asymptotic_boundary;
  const BoundaryDistance asymptotic_distance = traced(TraceCriterion::asymptotic, asymptotic_boundary);
  {  // asymptotic
    const auto v = asymptotic_verdicts(base, spec, points, threads, po, options.trace_options.orbit);
    push(compare(base, spec, points, v, asymptotic_distance), asymptotic_boundary, "asymptotic",
         "unstable iff mu_l = Upsilon_l(<sigma_R>) > 0 for some l in [3, L] (exact equilibrium out of "
         "plane, periodic-orbit average in plane, time average where no orbit attracts); mode: the surviving mode "
         "argmax_l sigma_l^c");
  }
  if (options.finite_horizon) {
    const FlowValues<ReducedTransient> transients(
        base, spec, points, threads, [](const Scene&) { return true; },
        [&](const Scene& s) { return reduced_transient(s, s.T, 1, po); });
    const auto v = verdicts(base, spec, points, threads, [&](const Scene& s) {
      const ReducedTransient* tr = transients.find(s);
      if (!tr) return PointVerdict{};  // the flow's run refused its scene: not classified
      const ModePrediction m = finite_horizon_prediction(s, finite_horizon_growth(s, transient_at_B(*tr, s)));
      if (m.status != DomainStatus::ok) return PointVerdict{};
      return PointVerdict{true, !m.unstable.empty(), m.unstable.empty() ? 2 : m.l_Delta};
    });
    Agreement tmp = asymptotic_boundary;
    const BoundaryDistance d =
        options.trace_finite_horizon ? traced(TraceCriterion::finite_horizon, tmp) : asymptotic_distance;
    push(compare(base, spec, points, v, d), tmp, "finite_horizon",
         "unstable iff G_l(T) > 0 for some l in [3, L] along the reduced transient; mode: argmax_l "
         "Delta_l(0)(exp(2 G_l(T)) - 1)");
  }
  constexpr int kOverlaySamples = 400;
  const std::vector<Overlay> overlays = analytic_overlays(base, spec, kOverlaySamples);
  auto analytic = [&](const std::string& name, const std::string& description, const std::vector<std::string>& lines,
                      const std::function<PointVerdict(const Scene&)>& f) {
    const auto v = verdicts(base, spec, points, threads, f);
    const std::vector<Polyline> pl = polylines(overlays, lines, spec, kOverlaySamples);
    Agreement a = compare(base, spec, points, v, BoundaryDistance(spec, pl));
    a.predictor = name;
    a.description = description;
    std::string joined;
    for (const std::string& s : lines) joined += (joined.empty() ? "" : ", ") + s;
    a.boundary = pl.empty() ? "no analytic line on this plane" : "the analytic line(s) " + joined;
    out.push_back(std::move(a));
  };
  analytic("l_star", "unstable iff l_* >= 2.5 (alpha >= (35/8)^2); mode: round(l_*)", {"l_star=2.5"},
           [](const Scene& s) {
             const double alpha = s.parameters.alpha();
             const bool u = l_star_criterion(alpha);
             return PointVerdict{true, u, u ? nearest_mode(alpha, s.L) : 2};
           });
  analytic("alpha_init", "unstable iff alpha > alpha_*^init (sigma_R(0) < sigma_*); mode: round(l_*)", {"alpha_init"},
           [](const Scene& s) {
             const Quantity ai = alpha_init(s.parameters);
             if (!ai.valid()) return PointVerdict{};
             const double alpha = s.parameters.alpha();
             const bool u = alpha > ai.value;
             return PointVerdict{true, u, u ? nearest_mode(alpha, s.L) : 2};
           });
  analytic("large_S",
           "unstable iff <sigma_R^-+> (S >> 1 closed form) < sigma_* and l_* >= 2.5, i.e. C < C_*^-+ or lambda > "
           "lambda_*^-; mode: round(l_*)",
           {"C_star_minus", "C_star_plus", "lambda_star_minus"}, [](const Scene& s) {
             const Parameters& p = s.parameters;
             const double Lambda = p.Lambda();
             const Quantity m = Lambda < 1   ? mean_sigma_R_minus(p)
                                : Lambda > 1 ? mean_sigma_R_plus(p, stress_free_r0(s))
                                             : Quantity::outside("Lambda = 1");
             if (!m.valid()) return PointVerdict{};
             const double alpha = p.alpha();
             const bool u = l_star_criterion(alpha) && m.value < sigma_star(alpha);
             return PointVerdict{true, u, u ? nearest_mode(alpha, s.L) : 2};
           });
  return out;
}

}  // namespace rbcstab
