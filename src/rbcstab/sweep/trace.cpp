#include "rbcstab/sweep/trace.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

namespace {
const char* kCriterion = "mu_l = Upsilon_l(sigma_R^eq) = 0 (exact out-of-plane equilibrium, envelope over l = 3..L)";

AsymptoticVerdict verdict_of(const Parameters& p, int L) {
  AsymptoticVerdict v;
  const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(p);
  v.sigma_R = eq.sigma_R;
  v.active_mode = surviving_mode(p.alpha(), L);
  v.margin = v.sigma_R - sigma_critical(v.active_mode, p.alpha());
  v.unstable = v.margin < 0;
  v.l = v.unstable ? v.active_mode : 2;
  return v;
}

struct Plane {
  const Scene& base;
  const DiagramSpec& spec;
  std::size_t evaluations = 0;
  AsymptoticVerdict at(double x, double y) {
    ++evaluations;
    return verdict_of(plane_scene(base, spec, x, y).parameters, base.L);
  }
  double margin(double x, double y) { return at(x, y).margin; }
};

// Root of margin(x, .) in [a, b] with a sign change, bisected to the last bit.
double bisect_y(Plane& plane, double x, double a, double b, double fa, int iterations) {
  for (int k = 0; k < iterations; ++k) {
    const double m = 0.5 * (a + b);
    if (m <= std::min(a, b) || m >= std::max(a, b)) break;
    const double fm = plane.margin(x, m);
    if (fm == 0) return m;
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

std::vector<double> roots_on_line(Plane& plane, double x, double y0, double y1, int samples, int bisections) {
  std::vector<double> roots;
  double ya = y0, fa = plane.margin(x, ya);
  for (int k = 1; k <= samples; ++k) {
    const double yb = k == samples ? y1 : y0 + (y1 - y0) * double(k) / samples;
    const double fb = plane.margin(x, yb);
    if (fa == 0) roots.push_back(ya);
    else if ((fa < 0) != (fb < 0) && fb != 0) roots.push_back(bisect_y(plane, x, ya, yb, fa, bisections));
    ya = yb;
    fa = fb;
  }
  if (fa == 0) roots.push_back(ya);
  return roots;
}

TracePoint point_at(Plane& plane, double x, double y) {
  const AsymptoticVerdict v = plane.at(x, y);
  const Parameters p = plane_scene(plane.base, plane.spec, x, y).parameters;
  TracePoint t{x, y, v.active_mode, v.sigma_R, sigma_critical(v.active_mode, p.alpha()), 0};
  t.mu = Upsilon(p, t.l, v.sigma_R);
  return t;
}
}  // namespace

AsymptoticVerdict asymptotic_verdict(const Scene& scene) {
  const double r0 = stress_free_r0(scene);
  const double limit = PredictorOptions{}.out_of_plane_r0;
  if (!(r0 < limit))
    throw InvalidArgument("beta", "the asymptotic criterion with the exact equilibrium needs an out-of-plane scene: "
                                  "stress-free r0 = " + format_value(r0) + " must be < " + format_value(limit) +
                                  " (beta near 0 or pi)");
  return verdict_of(scene.parameters, scene.L);
}

void TraceOptions::validate() const {
  require(lines >= 2 && lines <= 100000, "lines", lines, "an integer in [2, 100000]");
  require(samples >= 2 && samples <= 100000, "samples", samples, "an integer in [2, 100000]");
  require(bisections >= 1 && bisections <= 200, "bisections", bisections, "an integer in [1, 200]");
}

TraceResult trace_boundary(const Scene& base, const DiagramSpec& plane_spec, const TraceOptions& options) {
  options.validate();
  plane_spec.validate();
  base.validate();
  (void)asymptotic_verdict(base);  // out-of-plane check
  const auto t0 = std::chrono::steady_clock::now();
  Plane plane{base, plane_spec};
  TraceResult res;
  const AxisRange& X = plane_spec.x;
  const AxisRange& Y = plane_spec.y;

  // Roots on each line, linked into curves while the number of roots per line stays the same.
  std::vector<std::vector<TracePoint>> raw;  // curves before the split by mode
  std::vector<std::size_t> open;             // raw indices continued by the current line
  for (int k = 0; k < options.lines; ++k) {
    const double x = X.min + (X.max - X.min) * double(k) / double(options.lines - 1);
    const std::vector<double> ys = roots_on_line(plane, x, Y.min, Y.max, options.samples, options.bisections);
    if (ys.size() != open.size()) open.clear();
    const bool extend = !open.empty();
    for (std::size_t r = 0; r < ys.size(); ++r) {
      const TracePoint tp = point_at(plane, x, ys[r]);
      if (extend) {
        raw[open[r]].push_back(tp);
      } else {
        raw.push_back({tp});
        open.push_back(raw.size() - 1);
      }
    }
  }

  // Split by active mode; locate each corner by bisection in x, re-solving the root near the curve.
  const double dy_sample = (Y.max - Y.min) / options.samples;
  for (const auto& curve : raw) {
    TraceCurve piece;
    piece.criterion = kCriterion;
    piece.l = curve.front().l;
    piece.points.push_back(curve.front());
    for (std::size_t k = 1; k < curve.size(); ++k) {
      const TracePoint& a = curve[k - 1];
      const TracePoint& b = curve[k];
      if (b.l != a.l) {
        double xa = a.x, xb = b.x, ya = a.y, yb = b.y;
        TracePoint corner = a;
        for (int it = 0; it < 60 && xb - xa > 0; ++it) {
          const double xm = 0.5 * (xa + xb);
          if (xm <= xa || xm >= xb) break;
          const double guess = 0.5 * (ya + yb);
          const double half = std::abs(yb - ya) + 2 * dy_sample;
          const double lo = std::max(Y.min, guess - half), hi = std::min(Y.max, guess + half);
          const std::vector<double> ys = roots_on_line(plane, xm, lo, hi, 16, options.bisections);
          if (ys.empty()) break;
          const double ym = *std::min_element(ys.begin(), ys.end(), [&](double u, double v) {
            return std::abs(u - guess) < std::abs(v - guess);
          });
          corner = point_at(plane, xm, ym);
          if (corner.l == a.l) {
            xa = xm;
            ya = ym;
          } else {
            xb = xm;
            yb = ym;
          }
        }
        res.corners.push_back({corner.x, corner.y, a.l, b.l});
        TracePoint end = corner;  // the corner closes this piece with its own mode
        end.l = a.l;
        const Parameters p = plane_scene(base, plane_spec, end.x, end.y).parameters;
        end.sigma_c = sigma_critical(end.l, p.alpha());
        end.mu = Upsilon(p, end.l, end.sigma_R);
        piece.points.push_back(end);
        res.curves.push_back(piece);
        piece.points.clear();
        piece.l = b.l;
        TracePoint start = end;
        start.l = b.l;
        start.sigma_c = sigma_critical(start.l, p.alpha());
        start.mu = Upsilon(p, start.l, start.sigma_R);
        piece.points.push_back(start);
      }
      piece.points.push_back(b);
    }
    res.curves.push_back(piece);
  }
  res.evaluations = plane.evaluations;
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

Agreement asymptotic_agreement(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                               const TraceResult& boundary) {
  Agreement a;
  const double dx = spec.x.count > 1 ? (spec.x.max - spec.x.min) / (spec.x.count - 1) : 1.0;
  const double dy = spec.y.count > 1 ? (spec.y.max - spec.y.min) / (spec.y.count - 1) : 1.0;
  auto distance = [&](double x, double y) {
    double best = std::numeric_limits<double>::infinity();
    for (const TraceCurve& c : boundary.curves)
      for (std::size_t k = 0; k < c.points.size(); ++k) {
        // Distance to the segment (k-1, k) in grid steps (one point: to the point).
        const double px = (x - c.points[k].x) / dx, py = (y - c.points[k].y) / dy;
        if (k == 0) {
          best = std::min(best, std::hypot(px, py));
          continue;
        }
        const double sx = (c.points[k - 1].x - c.points[k].x) / dx, sy = (c.points[k - 1].y - c.points[k].y) / dy;
        const double len2 = sx * sx + sy * sy;
        const double t = len2 > 0 ? std::clamp((px * sx + py * sy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(px - t * sx, py - t * sy));
      }
    return best;
  };
  for (const PointResult& p : points) {
    if (p.verdict == Verdict::failed) continue;
    const Scene s = point_scene(base, spec, p.index);
    const AsymptoticVerdict v = asymptotic_verdict(s);
    ++a.points;
    const bool sim_unstable = p.verdict == Verdict::unstable;
    if (sim_unstable == v.unstable) {
      ++a.verdict_matches;
      if (!v.unstable || v.l == p.l_Delta) ++a.mode_matches;
      continue;
    }
    Disagreement d;
    d.index = p.index;
    d.simulated = p.verdict;
    d.l_simulated = p.l_Delta;
    d.predicted_unstable = v.unstable;
    d.l_predicted = v.l;
    d.distance_steps = distance(p.x, p.y);
    d.S = s.parameters.S();
    const Quantity ai = alpha_init(s.parameters);
    d.alpha_over_alpha_init = ai.valid() && ai.value > 0 ? s.parameters.alpha() / ai.value : 0.0;
    if (d.distance_steps > 1) ++a.beyond_one_step;
    a.verdict_disagreements.push_back(d);
  }
  return a;
}

}  // namespace rbcstab
