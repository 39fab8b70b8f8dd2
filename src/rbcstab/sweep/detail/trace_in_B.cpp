#include "rbcstab/sweep/detail/trace_in_B.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/verdict/asymptotic.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab::detail {

bool closed_form_in_B_applies(const Scene& base, const DiagramSpec& plane, const TraceOptions& options) {
  if (options.method != TraceMethod::automatic || plane.alpha != 0) return false;
  if (options.criterion == TraceCriterion::asymptotic &&
      (!options.orbit.enabled || is_out_of_plane(base, options.predictor)))
    return false;
  const bool b_on_x = plane.x.axis == Axis::lnB;
  if (b_on_x == (plane.y.axis == Axis::lnB)) return false;
  // independent() excludes the axes that move B (alpha, shear_rate); the rest leave every point's B at its ln B.
  return independent(Axis::lnB, b_on_x ? plane.y.axis : plane.x.axis);
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Brent's zeroin (Brent 1973, ch. 4) on [a, b] with f(a) f(b) <= 0, to 4 eps |b| + t.
template <class F>
double brent(F&& f, double a, double b, double fa, double fb, double t) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < 200; ++it) {
    if ((fb > 0) == (fc > 0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2 * kEps * std::abs(b) + 0.5 * t, m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p, q;
      if (a == c) {
        p = 2 * m * s;
        q = 1 - s;
      } else {
        const double r = fb / fc;
        q = fa / fc;
        p = s * (2 * m * q * (q - r) - (b - a) * (r - 1));
        q = (q - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q;
      p = std::abs(p);
      if (2 * p < std::min(3 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = e = m;
      }
    } else {
      d = e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

struct Unusable {
  std::string why;
};

// One value u of the other axis: its orbit (asymptotic) or transient (finite horizon) and, per mode,
// e_l(B) = a_l + m_l B and r_l = -m_l/a_l.
struct Flow {
  OrbitSigmaAverage orbit;
  ReducedTransient transient;
  std::vector<double> slope, rate;  // m_l, r_l (index l - 3)
  std::size_t best = 0;             // argmax r_l (ties to the lower mode)
};

enum class Side { below, inside, above };  // the boundary's ln B at u against the traced ln B range

struct Node {
  double u = 0, v = 0;  // v: the boundary's ln B (inside), else where it would be (+inf: none)
  Side side = Side::above;
  std::size_t left = 0, right = 0;  // active mode index towards lower and higher u (differ at a corner)
  bool corner() const { return left != right; }
};

class InB {
 public:
  InB(const Scene& base, const DiagramSpec& plane, const TraceOptions& options)
      : base_(base),
        plane_(plane),
        o_(options),
        b_on_x_(plane.x.axis == Axis::lnB),
        finite_(options.criterion == TraceCriterion::finite_horizon),
        T_(options.T > 0 ? options.T : base.T) {
    const AxisRange& U = b_on_x_ ? plane.y : plane.x;
    const AxisRange& V = b_on_x_ ? plane.x : plane.y;
    u0_ = std::min(U.min, U.max);  // sampled upwards whatever the axis's orientation (chains are oriented in x)
    u1_ = std::max(U.min, U.max);
    v_lo_ = std::min(V.min, V.max);
    v_hi_ = std::max(V.min, V.max);
    u_axis_ = U.axis;
  }

  TraceResult run(const std::string& criterion) {
    const int n = std::max(o_.samples, int(std::ceil(1 / o_.max_step)));
    Node a = node(u0_);
    if (a.side == Side::inside) append(a);
    for (int i = 1; i <= n; ++i) {
      const Node b = node(i == n ? u1_ : u0_ + (u1_ - u0_) * double(i) / n);
      segment(a, b, 0);
      a = b;
    }
    close();
    return result(criterion);
  }
  std::size_t evaluations = 0;

 private:
  Scene scene(double u, double v) const {
    Scene s = b_on_x_ ? plane_scene(base_, plane_, v, u) : plane_scene(base_, plane_, u, v);
    s.validate();
    return s;
  }
  double x(double u, double v) const { return b_on_x_ ? v : u; }
  double y(double u, double v) const { return b_on_x_ ? u : v; }
  // <sigma_R> on the orbit, or <sigma_R>_T over the transient, at the scene's B.
  double sigma_R(const Flow& f, const Scene& s) const {
    return finite_ ? finite_horizon_growth(s, transient_at_B(f.transient, s)).mean_sigma_R
                   : orbit_sigma_average_at_B(f.orbit, s).sigma_R;
  }
  double excess(const Flow& f, double u, double v, std::size_t k) const {
    const Scene s = scene(u, v);
    return sigma_R(f, s) - sigma_c(int(k) + 3, s.parameters.alpha());
  }

  const Flow& flow(double u) {
    if (auto it = flows_.find(u); it != flows_.end()) return it->second;
    const Scene lo = scene(u, v_lo_), hi = scene(u, v_hi_);
    const std::string at = parameter_label(u_axis_) + " = " + format_value(u);
    Flow f;
    if (finite_) {
      f.transient = reduced_transient(lo, T_, 1, o_.predictor);
      ++evaluations;
      if (o_.on_progress) o_.on_progress(double(evaluations), 0);
      const ModePrediction p = finite_horizon_prediction(lo, finite_horizon_growth(lo, f.transient));
      if (p.status != DomainStatus::ok) throw Unusable{"no reduced transient to T at " + at + ": " + p.reason};
    } else {
      // Out of plane the verdict takes the equilibrium; checked at every sample (beta near 0 or pi only).
      if (is_out_of_plane(lo, o_.predictor)) throw Unusable{"the scene at " + at + " is out of plane"};
      f.orbit = orbit_sigma_average(lo, o_.orbit);
      ++evaluations;
      if (o_.on_progress) o_.on_progress(double(evaluations), 0);
      if (!f.orbit.ok) throw Unusable{"no attracting periodic orbit at " + at + ": " + f.orbit.reason};
    }
    // e_l at the two ends of the ln B range: slope and intercept of the affine law.
    const double B_lo = lo.parameters.B, B_hi = hi.parameters.B;
    for (int l = 3; l <= base_.L; ++l) {
      const double e_lo = sigma_R(f, lo) - sigma_c(l, lo.parameters.alpha());
      const double e_hi = sigma_R(f, hi) - sigma_c(l, hi.parameters.alpha());
      const double m = (e_hi - e_lo) / (B_hi - B_lo), a = e_lo - m * B_lo;
      if (!(a > 0)) throw Unusable{"the criterion of mode " + std::to_string(l) + " is not affine in B at " + at};
      f.slope.push_back(m);
      f.rate.push_back(-m / a);
      if (f.rate.back() > f.rate[f.best]) f.best = f.rate.size() - 1;
    }
    return flows_.emplace(u, std::move(f)).first->second;
  }

  // Mode k's boundary ln B at u by Newton on e_k (affine in B: one step reaches roundoff from the fit's root).
  double polish(const Flow& f, double u, std::size_t k) const {
    double v = -std::log(f.rate[k]), e = excess(f, u, v, k);
    for (int it = 0; it < 4 && e != 0; ++it) {
      const double w = v - e / (f.slope[k] * std::exp(v)), ew = excess(f, u, w, k);
      if (!(std::abs(ew) < std::abs(e))) break;
      v = w;
      e = ew;
    }
    return v;
  }

  Node node(double u) {
    const Flow& f = flow(u);
    Node n;
    n.u = u;
    n.left = n.right = f.best;
    const double r = f.rate[f.best];
    n.v = r > 0 ? -std::log(r) : std::numeric_limits<double>::infinity();
    n.side = n.v < v_lo_ ? Side::below : n.v > v_hi_ ? Side::above : Side::inside;
    if (n.side == Side::inside) n.v = std::clamp(polish(f, u, f.best), v_lo_, v_hi_);
    return n;
  }

  double root(auto&& g, double a, double b) {
    const double ga = g(a), gb = g(b);
    if ((ga > 0) == (gb > 0) && ga != 0 && gb != 0) return std::abs(ga) <= std::abs(gb) ? a : b;  // roundoff tie
    return brent(g, a, b, ga, gb, 1e-14 * std::abs(u1_ - u0_));
  }

  // Where the boundary crosses the edge ln B = v between a and b: the verdict's margin there changes sign.
  Node exit(const Node& a, const Node& b, double v) {
    auto margin = [&](double u) {
      const Flow& f = flow(u);
      const Scene s = scene(u, v);
      return asymptotic_verdict(s, sigma_R(f, s)).margin;
    };
    Node n;
    n.u = root(margin, a.u, b.u);
    n.v = v;
    n.side = Side::inside;
    n.left = n.right = flow(n.u).best;
    return n;
  }

  // Where mode a.right hands over to b.left (r equal): a corner, unless a third mode or the box's edge
  // intervenes there (then an ordinary sample that splits the interval).
  Node corner(const Node& a, const Node& b) {
    const std::size_t ka = a.right, kb = b.left;
    auto diff = [&](double u) {
      const Flow& f = flow(u);
      return f.rate[ka] - f.rate[kb];
    };
    const double u = root(diff, a.u, b.u);
    Node n = node(u);
    const Flow& f = flow(u);
    const double top = std::max(f.rate[ka], f.rate[kb]);
    bool third = false;
    for (std::size_t j = 0; j < f.rate.size(); ++j) third = third || (j != ka && j != kb && f.rate[j] > top);
    if (n.side != Side::inside || third) return n;
    n.left = ka;
    n.right = kb;
    n.v = std::clamp(polish(f, u, ka), v_lo_, v_hi_);
    return n;
  }

  double distance(const Node& a, const Node& b) const {
    return std::hypot((b.u - a.u) / (u1_ - u0_), (b.v - a.v) / (v_hi_ - v_lo_));
  }

  void append(const Node& n) {
    if (!chain_.empty() && chain_.back().u == n.u) {
      chain_.back().right = n.right;
      return;
    }
    chain_.push_back(n);
  }
  void close() {
    if (chain_.size() >= 2) chains_.push_back(chain_);
    chain_.clear();
  }

  // The boundary over (a.u, b.u]: appended to the open chain (which ends with a when a is inside), chains
  // closed where it leaves the box.
  void segment(const Node& a, const Node& b, int depth) {
    if (depth > 200) {
      notes_.push_back("refinement stopped at " + parameter_label(u_axis_) + " = " + format_value(b.u));
      if (a.side == Side::inside && b.side == Side::inside) append(b);
      return;
    }
    const auto edge = [&](Side s) { return s == Side::below ? v_lo_ : v_hi_; };
    if (a.side == Side::inside && b.side == Side::inside) {
      if (a.right != b.left) {
        const Node c = corner(a, b);
        if (c.u <= a.u) {  // the hand-over at a (a tie to roundoff): a becomes the corner
          Node a2 = a;
          a2.right = b.left;
          append(a2);
          segment(a2, b, depth + 1);
        } else if (c.u >= b.u) {  // at b
          Node b2 = b;
          b2.left = a.right;
          segment(a, b2, depth + 1);
        } else {
          segment(a, c, depth + 1);  // ends with c
          segment(c, b, depth + 1);
        }
        return;
      }
      if (distance(a, b) > o_.max_step && b.u - a.u > 1e-12 * std::abs(u1_ - u0_)) {
        const Node m = node(0.5 * (a.u + b.u));
        segment(a, m, depth + 1);
        segment(m, b, depth + 1);
        return;
      }
      append(b);
      return;
    }
    if (a.side == Side::inside) {
      segment(a, exit(a, b, edge(b.side)), depth + 1);
      close();
      return;
    }
    if (b.side == Side::inside || a.side != b.side) {  // enters the box (and may cross it to the other edge)
      close();
      const Node e = exit(a, b, edge(a.side));
      append(e);
      segment(e, b, depth + 1);
    }
  }

  TracePoint point(double u, double v, std::size_t k) {
    const Flow& f = flow(u);
    const Scene s = scene(u, v);
    const int l = int(k) + 3;
    if (finite_) {  // the residual G_l(T), as the continuation tracer's
      const FiniteHorizon h = finite_horizon_growth(s, transient_at_B(f.transient, s));
      return {x(u, v), y(u, v), l, h.mean_sigma_R, sigma_c(l, s.parameters.alpha()), h.G[std::size_t(l - 2)]};
    }
    const double sigma = sigma_R(f, s);
    return {x(u, v), y(u, v), l, sigma, sigma_c(l, s.parameters.alpha()), Upsilon_l(s.parameters, l, sigma)};
  }

  TraceResult result(const std::string& criterion) {
    TraceResult res;
    res.criterion = o_.criterion;
    for (std::vector<Node>& nodes : chains_) {
      if (x(nodes.back().u, nodes.back().v) < x(nodes.front().u, nodes.front().v)) {
        std::reverse(nodes.begin(), nodes.end());
        for (Node& n : nodes) std::swap(n.left, n.right);
      }
      const std::size_t id = res.chains++;
      auto piece = [&](std::size_t k) { return TraceCurve{int(k) + 3, criterion, {}, id}; };
      res.curves.push_back(piece(nodes.front().right));
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Node& n = nodes[i];
        const bool turn = n.corner() && i > 0 && i + 1 < nodes.size();
        res.curves.back().points.push_back(point(n.u, n.v, i == 0 ? n.right : n.left));
        if (!turn) continue;
        res.corners.push_back({x(n.u, n.v), y(n.u, n.v), int(n.left) + 3, int(n.right) + 3});
        res.curves.push_back(piece(n.right));
        res.curves.back().points.push_back(point(n.u, n.v, n.right));
      }
    }
    res.starts = res.chains;
    res.evaluations = evaluations;
    res.notes = notes_;
    res.method = "in closed form in B";
    return res;
  }

  const Scene& base_;
  const DiagramSpec& plane_;
  const TraceOptions& o_;
  bool b_on_x_;
  bool finite_;  // the finite-horizon criterion
  double T_;     // its horizon
  double u0_ = 0, u1_ = 1, v_lo_ = 0, v_hi_ = 1;
  Axis u_axis_ = Axis::lnC;
  std::map<double, Flow> flows_;
  std::vector<Node> chain_;
  std::vector<std::vector<Node>> chains_;
  std::vector<std::string> notes_;
};

}  // namespace

InBTrace trace_in_B(const Scene& base, const DiagramSpec& plane, const TraceOptions& options,
                    const std::string& criterion) {
  InB tracer(base, plane, options);
  InBTrace out;
  try {
    out.result = tracer.run(criterion);
  } catch (const Unusable& u) {
    out.why = u.why;
  }
  out.evaluations = tracer.evaluations;
  return out;
}

}  // namespace rbcstab::detail
