#include "rbcstab/sweep/zero_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void ZeroSetOptions::validate() const {
  require(seed_lines >= 0 && seed_lines <= 10000, "seed_lines", seed_lines, "an integer in [0, 10000]");
  require(samples >= 2 && samples <= 1000000, "samples", samples, "an integer in [2, 1000000]");
  require(bisections >= 1 && bisections <= 200, "bisections", bisections, "an integer in [1, 200]");
  require(std::isfinite(max_step) && max_step > 0 && max_step <= 0.5, "max_step", max_step, "in (0, 0.5]");
  require(std::isfinite(initial_step) && initial_step > 0 && initial_step <= max_step, "initial_step", initial_step,
          "in (0, max_step]");
  require(std::isfinite(newton_tol) && newton_tol > 0 && newton_tol < 1e-4, "newton_tol", newton_tol, "in (0, 1e-4)");
  require(std::isfinite(residual_tol) && residual_tol > 0, "residual_tol", residual_tol, "finite and > 0");
  require(std::isfinite(cover_tol) && cover_tol > 0 && cover_tol < 0.5, "cover_tol", cover_tol, "in (0, 0.5)");
  require(max_points >= 3 && max_points <= 10000000, "max_points", double(max_points), "an integer in [3, 1e7]");
  require(max_pieces >= 1 && max_pieces <= 100000, "max_pieces", max_pieces, "an integer in [1, 100000]");
}

namespace {

using Vec2 = std::array<double, 2>;  // (u, v) in the unit square

// The criteria on the unit square with a small cache: the engine evaluates the residual, the events
// and the stop predicate at the same corrected point, and the finite differences around it.
class Evaluator {
 public:
  Evaluator(const ModeCriteria& c, const PlaneBox& b) : c_(c), b_(b) {}
  double x(double u) const { return b_.x_min + (b_.x_max - b_.x_min) * u; }
  double y(double v) const { return b_.y_min + (b_.y_max - b_.y_min) * v; }
  const CriterionSample& at(double u, double v) {
    for (const Entry& e : cache_)
      if (e.valid && e.u == u && e.v == v) return e.s;
    Entry& e = cache_[next_];
    next_ = (next_ + 1) % cache_.size();
    e.valid = false;
    e.s = c_.at(x(u), y(v));
    ++evaluations;
    if (e.s.g.empty()) throw InvalidArgument("criteria", "the criterion returned no modes");
    for (double g : e.s.g)
      if (!std::isfinite(g))
        throw InvalidArgument(
            "criteria", "the criterion is not finite at (" + format_value(x(u)) + ", " + format_value(y(v)) + ")");
    e.u = u;
    e.v = v;
    e.valid = true;
    return e.s;
  }
  double g(double u, double v, std::size_t k) { return at(u, v).g[k]; }
  // Envelope max_k g_k and its argmax (ties to the lower mode).
  std::pair<double, std::size_t> envelope(double u, double v) {
    const std::vector<double>& g = at(u, v).g;
    std::size_t best = 0;
    for (std::size_t k = 1; k < g.size(); ++k)
      if (g[k] > g[best]) best = k;
    return {g[best], best};
  }
  // Gradient of g_k in (u, v) by central differences (step 1e-6: error ~1e-12 relative for smooth g).
  Vec2 gradient(double u, double v, std::size_t k) {
    constexpr double h = 1e-6;
    return {(g(u + h, v, k) - g(u - h, v, k)) / (2 * h), (g(u, v + h, k) - g(u, v - h, k)) / (2 * h)};
  }
  std::size_t evaluations = 0;
  std::size_t failures = 0;  // start-search samples outside the criterion's domain

 private:
  struct Entry {
    bool valid = false;
    double u = 0, v = 0;
    CriterionSample s;
  };
  const ModeCriteria& c_;
  const PlaneBox& b_;
  std::array<Entry, 8> cache_{};
  std::size_t next_ = 0;
};

// g_k(u, v) = 0 with unknown q and parameter p: (u, v) = (p, q), or (q, p) when swapped.
class ModeCurve final : public ContinuationProblem {
 public:
  ModeCurve(Evaluator& ev, std::size_t k, bool swapped) : ev_(ev), k_(k), swapped_(swapped) {}
  Vec2 uv(double q, double p) const { return swapped_ ? Vec2{q, p} : Vec2{p, q}; }
  Eigen::Index dimension() const override { return 1; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override {
    const Vec2 w = uv(x[0], p);
    F.resize(1);
    F[0] = ev_.g(w[0], w[1], k_);
  }
  // Forward differences from the (cached) centre: 2 new evaluations for both derivatives instead of 4;
  // a relative error ~1e-8 in the Jacobian leaves Newton's convergence effectively quadratic.
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override {
    J.resize(1, 1);
    J(0, 0) = derivatives(x[0], p)[0];
  }
  void parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const override {
    Fp.resize(1);
    Fp[0] = derivatives(x[0], p)[1];
  }
  std::string parameter_name() const override { return swapped_ ? "v" : "u"; }

 private:
  Vec2 derivatives(double q, double p) const {
    if (have_ && q == q_ && p == p_) return d_;
    const double hq = 1e-7 * (1 + std::abs(q)), hp = 1e-7 * (1 + std::abs(p));
    const Vec2 c = uv(q, p), a = uv(q + hq, p), b = uv(q, p + hp);
    const double g0 = ev_.g(c[0], c[1], k_);
    d_ = {(ev_.g(a[0], a[1], k_) - g0) / hq, (ev_.g(b[0], b[1], k_) - g0) / hp};
    q_ = q;
    p_ = p;
    have_ = true;
    return d_;
  }
  Evaluator& ev_;
  std::size_t k_;
  bool swapped_;
  mutable bool have_ = false;
  mutable double q_ = 0, p_ = 0;
  mutable Vec2 d_{};
};

struct Root {
  Vec2 w{};
  Vec2 inward{};  // into the square (edges); (0, 0) for interior seed lines
};

// Sign changes of the envelope along w(s) = a + s (b - a), s in [0, 1], refined by bisection.
void roots_on_segment(Evaluator& ev, Vec2 a, Vec2 b, Vec2 inward, int samples, int bisections, std::vector<Root>& out) {
  auto at = [&](double s) { return Vec2{a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])}; };
  // NaN where the criterion is outside its domain (e.g. an unconverged time average): no bracket there.
  auto env = [&](double s) {
    const Vec2 w = at(s);
    try {
      return ev.envelope(w[0], w[1]).first;
    } catch (const InvalidArgument&) {
      ++ev.failures;
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
  double s0 = 0, f0 = env(0);
  for (int k = 1; k <= samples; ++k) {
    const double s1 = k == samples ? 1.0 : double(k) / samples;
    const double f1 = env(s1);
    if (!std::isnan(f0) && !std::isnan(f1) && (f0 < 0) != (f1 < 0)) {
      double lo = s0, hi = s1, flo = f0;
      for (int it = 0; it < bisections; ++it) {
        const double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi) break;
        const double fm = env(m);
        if (std::isnan(fm)) break;
        if ((fm < 0) == (flo < 0)) {
          lo = m;
          flo = fm;
        } else {
          hi = m;
        }
      }
      out.push_back({at(0.5 * (lo + hi)), inward});
    }
    s0 = s1;
    f0 = f1;
  }
}

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double sx = b[0] - a[0], sy = b[1] - a[1];
  const double len2 = sx * sx + sy * sy;
  const double t = len2 > 0 ? std::clamp(((p[0] - a[0]) * sx + (p[1] - a[1]) * sy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p[0] - a[0] - t * sx, p[1] - a[1] - t * sy);
}

enum class End { edge, corner, closed, other };

struct UPoint {
  Vec2 w{};
  std::size_t k = 0;
};
struct HalfPiece {
  std::size_t k = 0;
  std::vector<Vec2> w;
};
struct HalfCorner {
  Vec2 w{};
  std::size_t from = 0, to = 0;
  LocationStatus status = LocationStatus::guess;
  double precision = 0;
};
struct Half {
  std::vector<HalfPiece> pieces;
  std::vector<HalfCorner> corners;
  End end = End::other;
};

class Tracer {
 public:
  Tracer(Evaluator& ev, const ZeroSetOptions& o, ZeroSetResult& res) : ev_(ev), o_(o), res_(res) {}

  // Follows the envelope's zero set from `start` on mode k, first along the tangent closest to `want`,
  // through corners, until an edge, a closure (back at `origin`) or a failure.
  Half run(Vec2 start, std::size_t k, Vec2 want, Vec2 origin) {
    Half h;
    try {
      follow(h, start, k, want, origin);
    } catch (const InvalidArgument& e) {
      // A gradient at a start or corner left the criterion's domain: keep what was traced.
      res_.notes.push_back(std::string("a piece stopped: ") + e.what());
      h.end = End::other;
    }
    return h;
  }

 private:
  void follow(Half& h, Vec2 start, std::size_t k, Vec2 want, Vec2 origin) {
    const std::size_t nmodes = ev_.at(start[0], start[1]).g.size();
    for (int piece = 0; piece < o_.max_pieces; ++piece) {
      const Vec2 grad = ev_.gradient(start[0], start[1], k);
      const bool swapped = std::abs(grad[1]) < std::abs(grad[0]);  // p = the coordinate the curve extends along
      Vec2 t{-grad[1], grad[0]};
      if (t[0] * want[0] + t[1] * want[1] < 0) t = {-t[0], -t[1]};
      const double tp = swapped ? t[1] : t[0];
      ModeCurve problem(ev_, k, swapped);
      ContinuationOptions co;
      co.initial_step = o_.initial_step;
      co.max_step = o_.max_step;
      co.min_step = 1e-12;
      co.newton_tol = o_.newton_tol;
      co.p_min = 0;
      co.p_max = 1;
      co.max_points = o_.max_points;
      co.direction = tp >= 0 ? Direction::forward : Direction::backward;
      co.detect_bifurcations = false;
      co.compute_stability = false;
      for (std::size_t j = 0; j < nmodes; ++j)
        if (j != k)
          co.events.push_back({"mode " + std::to_string(j), [this, &problem, k, j](const Eigen::VectorXd& x, double p) {
                                 const Vec2 w = problem.uv(x[0], p);
                                 const std::vector<double>& g = ev_.at(w[0], w[1]).g;
                                 return g[j] - g[k];
                               }});
      std::size_t steps = 0;
      bool closed = false;
      const bool may_close = origin[0] >= 0;
      co.stop = [&, k](const Eigen::VectorXd& x, double p) {
        ++steps;
        if (x[0] < 0 || x[0] > 1) return true;
        const Vec2 w = problem.uv(x[0], p);
        const std::vector<double>& g = ev_.at(w[0], w[1]).g;
        for (std::size_t j = 0; j < g.size(); ++j)
          if (j != k && g[j] > g[k]) return true;
        if (may_close && steps > 3 && std::hypot(w[0] - origin[0], w[1] - origin[1]) < 0.6 * o_.max_step) {
          closed = true;
          return true;
        }
        return false;
      };
      const Vec2 q0 = swapped ? Vec2{start[0], start[1]} : Vec2{start[1], start[0]};  // (unknown, parameter)
      const Branch br = continue_branch(problem, Eigen::VectorXd::Constant(1, q0[0]), q0[1], co);
      add(res_.counters, br.counters);
      if (br.points.empty()) {
        res_.notes.push_back("a piece of mode index " + std::to_string(k) + " did not start: " + br.message);
        h.end = End::other;
        return;
      }
      // The first located event away from the start ends the piece.
      const SpecialPoint* stop_at = nullptr;
      for (const SpecialPoint& sp : br.special_points) {
        if (sp.type != SpecialPointType::UZ) continue;
        if (std::abs(sp.x[0] - br.points[0].x[0]) + std::abs(sp.p - br.points[0].p) < 1e-9) continue;
        stop_at = &sp;
        break;
      }
      HalfPiece hp{k, {}};
      const std::size_t last = stop_at ? stop_at->after_index : br.points.size() - 1;
      for (std::size_t i = 0; i <= last && i < br.points.size(); ++i)
        hp.w.push_back(problem.uv(br.points[i].x[0], br.points[i].p));
      if (stop_at) hp.w.push_back(problem.uv(stop_at->x[0], stop_at->p));
      // Turning points in the plane: the parameter coordinate reverses.
      for (std::size_t i = 2; i < hp.w.size(); ++i) {
        const int c = swapped ? 1 : 0;
        if ((hp.w[i][c] - hp.w[i - 1][c]) * (hp.w[i - 1][c] - hp.w[i - 2][c]) < 0) ++res_.turning_points;
      }
      const Vec2 end = hp.w.back();
      h.pieces.push_back(std::move(hp));
      if (stop_at && stop_at->name.rfind("mode ", 0) == 0) {
        const std::size_t j = std::stoul(stop_at->name.substr(5));
        h.corners.push_back({end, k, j, stop_at->status, stop_at->precision});
        // Continue on mode j into the region where it dominates: along -grad g_k.
        const Vec2 gk = ev_.gradient(end[0], end[1], k);
        want = {-gk[0], -gk[1]};
        start = end;
        k = j;
        continue;
      }
      const Eigen::VectorXd& xl = br.points.back().x;
      if (!stop_at && br.points.size() >= 2 && (xl[0] < 0 || xl[0] > 1)) {
        // Left through an edge of the unknown coordinate: replace the point outside by the crossing.
        h.pieces.back().w.back() = edge_crossing(k, h.pieces.back().w, swapped, xl[0] < 0 ? 0.0 : 1.0);
        h.end = End::edge;
      } else if (br.message.rfind("reached the parameter bound", 0) == 0) {  // also "... at a fold"
        h.end = End::edge;
      } else if (closed) {
        h.pieces.back().w.push_back(origin);
        h.end = End::closed;
      } else {
        res_.notes.push_back("a piece ended inside the plane near (" + format_value(end[0]) + ", " +
                             format_value(end[1]) + ") (unit square): " + to_string(br.status) + ": " + br.message);
        h.end = End::other;
      }
      return;
    }
    res_.notes.push_back("stopped after max_pieces pieces");
  }

  // The zero of g_k on the edge (coordinate c = value) between the last two points of w (the last one
  // outside): secant along the edge from the linear interpolation (the engine's events would spend ~20
  // corrected secant steps on what is a 1-D root on a known line).
  Vec2 edge_crossing(std::size_t k, const std::vector<Vec2>& w, bool swapped, double value) {
    const int c = swapped ? 0 : 1, f = 1 - c;  // c: the unknown (edge) coordinate, f: along the edge
    const Vec2 a = w[w.size() - 2], b = w.back();
    const double t = (value - a[c]) / (b[c] - a[c]);
    Vec2 e;
    e[c] = value;
    auto g = [&](double s) {
      Vec2 q;
      q[c] = value;
      q[f] = s;
      return ev_.g(q[0], q[1], k);
    };
    double s0 = a[f] + t * (b[f] - a[f]), s1 = s0 + 1e-6;
    double g0 = g(s0), g1 = g(s1);
    for (int it = 0; it < 30 && std::abs(g1) > o_.residual_tol && g1 != g0; ++it) {
      const double s2 = s1 - g1 * (s1 - s0) / (g1 - g0);
      s0 = s1;
      g0 = g1;
      s1 = s2;
      g1 = g(s1);
    }
    e[f] = std::abs(g1) <= std::abs(g0) ? s1 : s0;
    return e;
  }
  static void add(ContinuationCounters& a, const ContinuationCounters& b) {
    a.steps += b.steps;
    a.rejected_steps += b.rejected_steps;
    a.unconfirmed_steps += b.unconfirmed_steps;
    a.newton_iterations += b.newton_iterations;
    a.residual_evaluations += b.residual_evaluations;
    a.jacobian_evaluations += b.jacobian_evaluations;
    a.location_iterations += b.location_iterations;
  }
  Evaluator& ev_;
  const ZeroSetOptions& o_;
  ZeroSetResult& res_;
};

// Newton along the gradient when the corrector left |g| above residual_tol (the engine's acceptance test
// is |F| <= sqrt(newton_tol) 1e-3). A point on an edge moves along the edge only.
Vec2 polish(Evaluator& ev, Vec2 w, std::size_t k, double tol) {
  const bool u_fixed = w[0] == 0 || w[0] == 1, v_fixed = w[1] == 0 || w[1] == 1;
  for (int it = 0; it < 6; ++it) {
    const double g = ev.g(w[0], w[1], k);
    if (std::abs(g) <= tol) break;
    Vec2 d = ev.gradient(w[0], w[1], k);
    if (u_fixed) d[0] = 0;
    if (v_fixed) d[1] = 0;
    const double n2 = d[0] * d[0] + d[1] * d[1];
    if (!(n2 > 0)) break;
    w = {w[0] - g * d[0] / n2, w[1] - g * d[1] / n2};
  }
  return w;
}

}  // namespace

ZeroSetResult trace_zero_set(const ModeCriteria& criteria, const PlaneBox& box, const ZeroSetOptions& options) {
  options.validate();
  if (!criteria.at) throw InvalidArgument("criteria", "no criterion function");
  require(std::isfinite(box.x_min) && std::isfinite(box.x_max) && box.x_min != box.x_max, "x range", box.x_max,
          "finite with x_min != x_max");
  require(std::isfinite(box.y_min) && std::isfinite(box.y_max) && box.y_min != box.y_max, "y range", box.y_max,
          "finite with y_min != y_max");
  ZeroSetResult res;
  Evaluator ev(criteria, box);

  // Start roots: the four edges (with their inward normals), then interior lines u = const.
  std::vector<Root> roots;
  const int n = options.samples, b = options.bisections;
  roots_on_segment(ev, {0, 0}, {0, 1}, {1, 0}, n, b, roots);
  roots_on_segment(ev, {0, 0}, {1, 0}, {0, 1}, n, b, roots);
  roots_on_segment(ev, {1, 0}, {1, 1}, {-1, 0}, n, b, roots);
  roots_on_segment(ev, {0, 1}, {1, 1}, {0, -1}, n, b, roots);
  for (int s = 1; s <= options.seed_lines; ++s) {
    const double u = double(s) / (options.seed_lines + 1);
    roots_on_segment(ev, {u, 0}, {u, 1}, {0, 0}, n, b, roots);
  }
  res.starts = roots.size();

  std::vector<std::vector<Vec2>> traced;  // polylines traced so far (unit square)
  auto covered = [&](Vec2 w) {
    for (const auto& line : traced)
      for (std::size_t i = 0; i < line.size(); ++i)
        if ((i == 0 ? std::hypot(w[0] - line[0][0], w[1] - line[0][1]) : segment_distance(w, line[i - 1], line[i])) <
            options.cover_tol)
          return true;
    return false;
  };
  Tracer tracer(ev, options, res);
  for (const Root& r : roots) {
    if (covered(r.w)) continue;
    std::size_t k = 0;
    Vec2 g{0, 0};
    try {
      k = ev.envelope(r.w[0], r.w[1]).second;
      if (r.inward[0] == 0 && r.inward[1] == 0) g = ev.gradient(r.w[0], r.w[1], k);
    } catch (const InvalidArgument& e) {
      res.notes.push_back(std::string("a start was skipped: ") + e.what());
      continue;
    }
    Half chain;
    if (r.inward[0] != 0 || r.inward[1] != 0) {
      chain = tracer.run(r.w, k, r.inward, {-1, -1});
    } else {
      // Interior seed: both ways along the curve, unless the first closes a loop.
      const Vec2 t{-g[1], g[0]};
      chain = tracer.run(r.w, k, t, r.w);
      if (chain.end != End::closed) {
        Half back = tracer.run(r.w, k, {-t[0], -t[1]}, {-1, -1});
        // back reversed, then chain; the two first pieces share the seed and the mode.
        Half joined;
        for (std::size_t i = back.pieces.size(); i-- > 0;) {
          HalfPiece p = back.pieces[i];
          std::reverse(p.w.begin(), p.w.end());
          joined.pieces.push_back(std::move(p));
        }
        for (std::size_t i = back.corners.size(); i-- > 0;) {
          HalfCorner c = back.corners[i];
          std::swap(c.from, c.to);
          joined.corners.push_back(c);
        }
        if (!joined.pieces.empty() && !chain.pieces.empty()) {
          HalfPiece& tail = joined.pieces.back();
          tail.w.insert(tail.w.end(), chain.pieces.front().w.begin() + 1, chain.pieces.front().w.end());
          joined.pieces.insert(joined.pieces.end(), chain.pieces.begin() + 1, chain.pieces.end());
        } else {
          joined.pieces.insert(joined.pieces.end(), chain.pieces.begin(), chain.pieces.end());
        }
        joined.corners.insert(joined.corners.end(), chain.corners.begin(), chain.corners.end());
        chain = std::move(joined);
      }
    }
    if (chain.pieces.empty()) continue;
    // Orient the chain so that x increases from its first to its last point.
    const double x_first = ev.x(chain.pieces.front().w.front()[0]), x_last = ev.x(chain.pieces.back().w.back()[0]);
    if (x_last < x_first) {
      std::reverse(chain.pieces.begin(), chain.pieces.end());
      for (HalfPiece& p : chain.pieces) std::reverse(p.w.begin(), p.w.end());
      std::reverse(chain.corners.begin(), chain.corners.end());
      for (HalfCorner& c : chain.corners) std::swap(c.from, c.to);
    }
    const std::size_t id = res.chains++;
    std::vector<Vec2> line;
    for (const HalfPiece& p : chain.pieces) {
      ZeroSetPiece piece;
      piece.l = criteria.l_min + int(p.k);
      piece.chain = id;
      for (const Vec2& w0 : p.w) {
        Vec2 w = w0;
        try {
          w = polish(ev, w0, p.k, options.residual_tol);
        } catch (const InvalidArgument&) {
          // the gradient left the domain: keep the corrector's point
        }
        const CriterionSample& s = ev.at(w[0], w[1]);
        piece.points.push_back({ev.x(w[0]), ev.y(w[1]), piece.l, s.g[p.k], s.sigma_R, s.alpha});
        line.push_back(w);
      }
      res.pieces.push_back(std::move(piece));
    }
    for (const HalfCorner& c : chain.corners)
      res.corners.push_back({ev.x(c.w[0]), ev.y(c.w[1]), criteria.l_min + int(c.from), criteria.l_min + int(c.to), id,
                             c.status, c.precision});
    traced.push_back(std::move(line));
  }
  res.evaluations = ev.evaluations;
  if (ev.failures > 0)
    res.notes.push_back(std::to_string(ev.failures) +
                        " start-search samples were outside the criterion's domain (no start bracketed there)");
  return res;
}

}  // namespace rbcstab
