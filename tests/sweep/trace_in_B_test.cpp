// The in-plane asymptotic boundary in closed form in B (TraceMethod::automatic) on the App. E planes,
// against the direct verdict at every point and against the continuation tracer; its fallbacks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {
namespace {

constexpr double kMaxStep = 0.04;  // twice the default: the contract is the same, the tests cheaper

struct Panel {
  Scene scene;
  DiagramSpec plane;
  TraceResult exact;
};

TraceOptions options(bool exact) {
  TraceOptions o;
  o.max_step = kMaxStep;
  o.method = exact ? TraceMethod::automatic : TraceMethod::continuation;
  return o;
}

// App. E (a), (b), (c) in plane, each traced once per test process.
const Panel& panel(char p) {
  static std::map<char, Panel> panels;
  if (auto it = panels.find(p); it != panels.end()) return it->second;
  const SceneFile f = load_scene(std::string(RBCSTAB_SCENES_DIR) + "/appE_" + p + "_ip.toml");
  Panel x{f.scene, diagram_spec(f), {}};
  x.exact = trace_boundary(x.scene, x.plane, options(true));
  std::cout << "appE_" << p << ": exact " << x.exact.evaluations << " orbits, " << x.exact.seconds << " s\n";
  return panels.emplace(p, std::move(x)).first->second;
}

using Vec2 = std::array<double, 2>;
// A point in the unit square of the traced box.
Vec2 unit(const DiagramSpec& d, double x, double y) {
  return {(x - d.x.min) / (d.x.max - d.x.min), (y - d.y.min) / (d.y.max - d.y.min)};
}
double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double sx = b[0] - a[0], sy = b[1] - a[1], len2 = sx * sx + sy * sy;
  const double t = len2 > 0 ? std::clamp(((p[0] - a[0]) * sx + (p[1] - a[1]) * sy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p[0] - a[0] - t * sx, p[1] - a[1] - t * sy);
}
// Distance from p to the polylines of t's curves (unit square).
double distance_to(const TraceResult& t, const DiagramSpec& d, Vec2 p) {
  double best = INFINITY;
  for (const TraceCurve& c : t.curves)
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      const Vec2 a = unit(d, c.points[i].x, c.points[i].y);
      const Vec2 b = i + 1 < c.points.size() ? unit(d, c.points[i + 1].x, c.points[i + 1].y) : a;
      best = std::min(best, segment_distance(p, a, b));
    }
  return best;
}
// The largest curvature over consecutive point triples of one piece (circumscribed circle), unit square.
double max_curvature(const TraceResult& t, const DiagramSpec& d) {
  double k = 0;
  for (const TraceCurve& c : t.curves)
    for (std::size_t i = 2; i < c.points.size(); ++i) {
      const Vec2 a = unit(d, c.points[i - 2].x, c.points[i - 2].y), b = unit(d, c.points[i - 1].x, c.points[i - 1].y),
                 e = unit(d, c.points[i].x, c.points[i].y);
      const double cross = (b[0] - a[0]) * (e[1] - a[1]) - (b[1] - a[1]) * (e[0] - a[0]);
      const double ab = std::hypot(b[0] - a[0], b[1] - a[1]), be = std::hypot(e[0] - b[0], e[1] - b[1]),
                   ae = std::hypot(e[0] - a[0], e[1] - a[1]);
      if (ab > 0 && be > 0 && ae > 0) k = std::max(k, 2 * std::abs(cross) / (ab * be * ae));
    }
  return k;
}

// Corners: where the boundary's mode changes between l and l + 1 (either way along the chain), e_l = e_{l+1} = 0, so
// sigma_l^c = sigma_{l+1}^c: alpha = Pi(l) Pi(l+1)/4 (alpha_mode_change, an independent closed form). The corner's u is
// Brent's root to ~1e-14 of the axis and its ln B a Newton step: alpha to ~1e-13 relative; 1e-11 leaves margin.
void expect_corners_on_mode_change_lines(const Scene& base, const DiagramSpec& plane, const TraceResult& t) {
  for (const TraceCorner& k : t.corners) {
    EXPECT_EQ(std::abs(k.l_to - k.l_from), 1);
    const double alpha = plane_scene(base, plane, k.x, k.y).parameters.alpha();
    EXPECT_NEAR(alpha / alpha_mode_change(std::min(k.l_from, k.l_to)), 1.0, 1e-11)
        << "corner " << k.l_from << "->" << k.l_to;
  }
}

// Every point against the direct verdict at its scene (a fresh periodic-orbit solve, not the tracer's
// mapped one): the margin <sigma_R> - max_l sigma_l^c vanishes to roundoff, the active mode is the point's
// (either mode at a corner), and ln B -+ 1e-6 (a margin change ~1e-6 |d margin/d ln B| = O(1e-6), far above
// roundoff) gives stable below, unstable above. Roundoff: sigma_R = <mu> B/Gamma_2 + sigma_2^c sums terms of
// size |sigma_l^c| (up to ~1e2 at the boundary), each exact to an ulp: 1e-13 (1 + |sigma_c|) is ~50 ulps;
// points located by Brent in ln C (edge exits, corners) add |d margin/d ln C| 1e-14 of the axis, below that.
// Consecutive points are at most max_step apart (the resolution contract).
TEST(TraceInB, PointsAreOnTheDirectBoundary) {
  for (char p : {'a', 'b', 'c'}) {
    const Panel& P = panel(p);
    const TraceResult& t = P.exact;
    ASSERT_FALSE(t.curves.empty());
    EXPECT_TRUE(t.notes.empty()) << t.notes.front();  // the method is t.method, not a note
    EXPECT_EQ(t.method, "in closed form in B");
    const TraceOptions o = options(true);
    AsymptoticSigmaMemo memo(o.predictor, o.orbit);
    std::vector<std::pair<double, double>> corners;
    for (const TraceCorner& k : t.corners) corners.emplace_back(k.x, k.y);
    double worst = 0;
    std::size_t n = 0;
    for (const TraceCurve& c : t.curves) {
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        const TracePoint& q = c.points[i];
        ASSERT_EQ(q.l, c.l);
        const Scene s = plane_scene(P.scene, P.plane, q.x, q.y);
        const AsymptoticVerdict v = asymptotic_verdict(s, o.predictor, o.orbit);
        EXPECT_LE(std::abs(v.margin), 1e-13 * (1 + std::abs(q.sigma_c))) << p << " at " << q.x << ", " << q.y;
        worst = std::max(worst, std::abs(v.margin) / (1 + std::abs(q.sigma_c)));
        EXPECT_EQ(q.sigma_R, v.sigma_R);
        EXPECT_EQ(q.sigma_c, sigma_c(q.l, s.parameters.alpha()));
        EXPECT_LE(std::abs(q.mu), 1e-13 * (1 + std::abs(q.sigma_c)));
        const bool at_corner = std::count(corners.begin(), corners.end(), std::pair{q.x, q.y}) > 0;
        if (!at_corner) {
          EXPECT_EQ(v.active_mode, q.l) << p << " at " << q.x << ", " << q.y;
        }
        if (q.x - 1e-6 > P.plane.x.min && q.x + 1e-6 < P.plane.x.max) {
          EXPECT_FALSE(memo.verdict(plane_scene(P.scene, P.plane, q.x - 1e-6, q.y)).unstable);
          EXPECT_TRUE(memo.verdict(plane_scene(P.scene, P.plane, q.x + 1e-6, q.y)).unstable);
        }
        if (i > 0) {
          const Vec2 a = unit(P.plane, c.points[i - 1].x, c.points[i - 1].y), b = unit(P.plane, q.x, q.y);
          EXPECT_LE(std::hypot(b[0] - a[0], b[1] - a[1]), kMaxStep * (1 + 1e-12));
        }
        ++n;
      }
    }
    EXPECT_GT(n, 30u);
    std::cout << "appE_" << p << ": " << n << " points, max |margin|/(1 + |sigma_c|) = " << worst << "\n";
    expect_corners_on_mode_change_lines(P.scene, P.plane, t);
  }
}

// Against the continuation tracer on the same planes: the same chains and corners (same modes in order), the
// corners within 1e-8 (both are located to ~1e-13 of the axes), and each tracer's points within the other's
// polyline's interpolation error. Both polylines have their vertices on the curve (to roundoff) at most h =
// max_step apart, so a chord is within k h^2/8 of the curve (k its curvature in the unit square) and each vertex
// of one within k h^2/8 of the other's chords; k is estimated from the exact points' circles through three
// neighbours, and doubled (the curvature between vertices may exceed the sampled one).
TEST(TraceInB, AgreesWithContinuation) {
  for (char p : {'a', 'b', 'c'}) {
    const Panel& P = panel(p);
    const TraceResult& e = P.exact;
    const TraceResult c = trace_boundary(P.scene, P.plane, options(false));
    std::cout << "appE_" << p << ": continuation " << c.evaluations << " evaluations, " << c.seconds << " s\n";
    EXPECT_EQ(e.chains, c.chains) << p;
    ASSERT_EQ(e.corners.size(), c.corners.size()) << p;
    for (std::size_t i = 0; i < e.corners.size(); ++i) {
      EXPECT_EQ(e.corners[i].l_from, c.corners[i].l_from);
      EXPECT_EQ(e.corners[i].l_to, c.corners[i].l_to);
      EXPECT_NEAR(e.corners[i].x, c.corners[i].x, 1e-8) << p << " corner " << i;
      EXPECT_NEAR(e.corners[i].y, c.corners[i].y, 1e-8) << p << " corner " << i;
    }
    ASSERT_EQ(e.curves.size(), c.curves.size());
    for (std::size_t i = 0; i < e.curves.size(); ++i) EXPECT_EQ(e.curves[i].l, c.curves[i].l);
    const double k = max_curvature(e, P.plane), bound = 2 * k * kMaxStep * kMaxStep / 8 + 1e-12;
    double e_to_c = 0, c_to_e = 0;
    for (const TraceCurve& curve : e.curves)
      for (const TracePoint& q : curve.points)
        e_to_c = std::max(e_to_c, distance_to(c, P.plane, unit(P.plane, q.x, q.y)));
    for (const TraceCurve& curve : c.curves)
      for (const TracePoint& q : curve.points)
        c_to_e = std::max(c_to_e, distance_to(e, P.plane, unit(P.plane, q.x, q.y)));
    EXPECT_LE(e_to_c, bound) << p;
    EXPECT_LE(c_to_e, bound) << p;
    const double grid = 1.0 / (P.plane.x.count - 1);
    std::cout << "appE_" << p << ": curvature " << k << ", bound " << bound / grid
              << " grid steps; exact to continuation " << e_to_c / grid << ", continuation to exact " << c_to_e / grid
              << " grid steps\n";
  }
}

// A reversed axis: the same boundary (the same orbits and roots: bit for bit).
TEST(TraceInB, ReversedAxesGiveTheSameBoundary) {
  const Panel& P = panel('a');
  for (int axis = 0; axis < 2; ++axis) {
    DiagramSpec reversed = P.plane;
    AxisRange& r = axis == 0 ? reversed.x : reversed.y;
    std::swap(r.min, r.max);
    const TraceResult t = trace_boundary(P.scene, reversed, options(true));
    ASSERT_EQ(t.corners.size(), P.exact.corners.size());
    for (std::size_t i = 0; i < t.corners.size(); ++i) {
      EXPECT_EQ(t.corners[i].x, P.exact.corners[i].x);
      EXPECT_EQ(t.corners[i].y, P.exact.corners[i].y);
    }
    ASSERT_EQ(t.curves.size(), P.exact.curves.size());
    for (std::size_t i = 0; i < t.curves.size(); ++i)
      EXPECT_EQ(t.curves[i].points.size(), P.exact.curves[i].points.size());
  }
}

// ln B on the y axis: the same boundary, transposed (the corners to roundoff: the same orbits and roots), and
// each chain runs towards increasing x.
TEST(TraceInB, LnBOnTheYAxisGivesTheTransposedBoundary) {
  const Panel& P = panel('a');
  DiagramSpec swapped = P.plane;
  std::swap(swapped.x, swapped.y);
  const TraceResult t = trace_boundary(P.scene, swapped, options(true));
  EXPECT_EQ(t.method, "in closed form in B");
  EXPECT_EQ(t.evaluations, P.exact.evaluations);
  ASSERT_EQ(t.corners.size(), P.exact.corners.size());
  for (std::size_t i = 0; i < t.corners.size(); ++i) {
    // Chains run towards increasing ln C here, towards increasing ln B there: along the curve in the same sense
    // (ln B increases with ln C on this boundary).
    EXPECT_NEAR(t.corners[i].x, P.exact.corners[i].y, 1e-12);
    EXPECT_NEAR(t.corners[i].y, P.exact.corners[i].x, 1e-12);
    EXPECT_EQ(t.corners[i].l_from, P.exact.corners[i].l_from);
  }
  for (const TraceCurve& c : t.curves) {
    std::size_t chain_first = 0;
    while (t.curves[chain_first].chain != c.chain) ++chain_first;
    std::size_t chain_last = t.curves.size() - 1;
    while (t.curves[chain_last].chain != c.chain) --chain_last;
    EXPECT_LT(t.curves[chain_first].points.front().x, t.curves[chain_last].points.back().x);
    for (const TracePoint& q : c.points) EXPECT_LE(distance_to(P.exact, P.plane, unit(P.plane, q.y, q.x)), 1e-12);
  }
}

// Every field, bit for bit (tuples of doubles compare exactly).
void expect_identical(const TraceResult& a, const TraceResult& b) {
  const auto summary = [](const TraceResult& t) {
    return std::tuple{t.evaluations, t.chains, t.starts, t.notes, t.method, t.curves.size(), t.corners.size()};
  };
  ASSERT_EQ(summary(a), summary(b));
  for (std::size_t i = 0; i < a.curves.size(); ++i) {
    EXPECT_EQ(std::tie(a.curves[i].l, a.curves[i].criterion), std::tie(b.curves[i].l, b.curves[i].criterion));
    ASSERT_EQ(a.curves[i].points.size(), b.curves[i].points.size());
    for (std::size_t j = 0; j < a.curves[i].points.size(); ++j) {
      const TracePoint &p = a.curves[i].points[j], &q = b.curves[i].points[j];
      EXPECT_EQ(std::tie(p.x, p.y, p.l, p.sigma_R, p.sigma_c, p.mu),
                std::tie(q.x, q.y, q.l, q.sigma_R, q.sigma_c, q.mu));
    }
  }
  for (std::size_t i = 0; i < a.corners.size(); ++i) {
    const TraceCorner &p = a.corners[i], &q = b.corners[i];
    EXPECT_EQ(std::tie(p.x, p.y, p.l_from, p.l_to), std::tie(q.x, q.y, q.l_from, q.l_to));
  }
}

// Where the closed form does not apply the result is the continuation's, bit for bit: an out-of-plane scene, a
// plane at fixed alpha (C moves with B), a plane without ln B. Small boxes and coarse options: every in-plane
// evaluation of these is a new flow.
TEST(TraceInB, OtherPlanesAreTracedByContinuationUnchanged) {
  const Panel& P = panel('a');
  TraceOptions o = options(true);
  o.lines = 0;
  o.samples = 8;
  o.max_step = 0.1;
  TraceOptions off = o;
  off.method = TraceMethod::continuation;
  Scene out_of_plane = P.scene;
  out_of_plane.beta = 0.001;
  DiagramSpec fixed_alpha;
  fixed_alpha.x = {Axis::lnB, 2, 4, 8};  // alpha = 100: the boundary near ln B = 2.8 at lambda = 1
  fixed_alpha.y = {Axis::lambda, 0.5, 2, 8};
  fixed_alpha.alpha = 100;
  DiagramSpec no_B;
  no_B.x = {Axis::lnC, -2.5, -1.5, 8};
  no_B.y = {Axis::lambda, 0.5, 1.5, 8};
  Scene at_B = P.scene;
  at_B.parameters.B = std::exp(3.0);  // the boundary near ln C = -1.9 at lambda = 1
  const std::vector<std::pair<Scene, DiagramSpec>> cases = {
      {out_of_plane, P.plane}, {P.scene, fixed_alpha}, {at_B, no_B}};
  for (const auto& [s, d] : cases) {
    const TraceResult a = trace_boundary(s, d, o), b = trace_boundary(s, d, off);
    EXPECT_FALSE(a.curves.empty());
    expect_identical(a, b);
  }
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
// A value whose orbit is not usable (here: one Newton iteration cannot converge the shooting) sends the whole
// plane to continuation, whose criterion then takes the time average there: the continuation's result, with the
// reason first in the notes and the failed orbit solve counted. Cheap time averages on a small plane, as in
// Trace.InPlaneAsymptoticByTimeAverage.
TEST(TraceInB, UnusableOrbitFallsBackToContinuation) {
  Scene s = load_scene(std::string(RBCSTAB_SCENES_DIR) + "/appE_a_ip.toml").scene;
  s.L = 5;
  DiagramSpec plane;
  plane.x = {Axis::lnB, 3.5, 4.5, 5};
  plane.y = {Axis::lnC, -2, -1.5, 5};
  TraceOptions o;
  o.lines = 0;
  o.samples = 4;
  o.bisections = 30;
  o.max_step = 0.25;
  o.predictor.transient = 100;
  o.predictor.window = 200;
  o.predictor.average_tolerance = 1e-2;
  o.orbit.max_iterations = 1;
  TraceOptions off = o;
  off.method = TraceMethod::continuation;
  TraceResult a = trace_boundary(s, plane, o);
  const TraceResult b = trace_boundary(s, plane, off);
  ASSERT_FALSE(a.curves.empty());
  ASSERT_FALSE(a.notes.empty());
  EXPECT_EQ(a.notes.front().rfind(
                "closed form in B not used (traced by continuation): no attracting periodic orbit at ln C = -2", 0),
            0u)
      << a.notes.front();
  EXPECT_EQ(a.evaluations, b.evaluations + 1);
  a.notes.erase(a.notes.begin());
  a.evaluations = b.evaluations;
  expect_identical(a, b);
}
}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
// Another axis beside ln B (lambda: it moves the flow, not B), with ln B on y: the note names it, every point's
// direct verdict has its margin at roundoff and flips across it, corners on the mode-change lines (the mode
// falls with lambda here: the chain runs towards increasing lambda, so its corners read 5 -> 4 -> 3).
TEST(TraceInB, LambdaAxis) {
  Scene s = load_scene(std::string(RBCSTAB_SCENES_DIR) + "/appE_a_ip.toml").scene;
  s.parameters.C = std::exp(-1.8);
  DiagramSpec plane;
  plane.x = {Axis::lambda, 0.5, 3, 8};
  plane.y = {Axis::lnB, 2, 5, 8};
  TraceOptions o = options(true);
  o.samples = 16;
  o.max_step = 0.1;
  const TraceResult t = trace_boundary(s, plane, o);
  EXPECT_EQ(t.method, "in closed form in B");
  ASSERT_FALSE(t.curves.empty());
  ASSERT_EQ(t.corners.size(), 2u);
  EXPECT_EQ(t.corners[0].l_from, 5);
  EXPECT_EQ(t.corners[1].l_to, 3);
  std::size_t n = 0;
  for (const TraceCurve& c : t.curves)
    for (const TracePoint& q : c.points) {
      const AsymptoticVerdict v = asymptotic_verdict(plane_scene(s, plane, q.x, q.y), o.predictor, o.orbit);
      EXPECT_LE(std::abs(v.margin), 1e-13 * (1 + std::abs(q.sigma_c))) << q.x << ", " << q.y;
      if (q.y - 1e-6 > plane.y.min && q.y + 1e-6 < plane.y.max) {
        EXPECT_FALSE(asymptotic_verdict(plane_scene(s, plane, q.x, q.y - 1e-6), o.predictor, o.orbit).unstable);
        EXPECT_TRUE(asymptotic_verdict(plane_scene(s, plane, q.x, q.y + 1e-6), o.predictor, o.orbit).unstable);
      }
      ++n;
    }
  expect_corners_on_mode_change_lines(s, plane, t);
  std::cout << "lambda x ln B: " << n << " points, " << t.corners.size() << " corners, " << t.evaluations << " orbits, "
            << t.seconds << " s\n";
}
}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {

// The finite-horizon boundary in closed form in B (G_l(T) = T Upsilon_l(<sigma_R>_T) with <sigma_R>_T affine in B
// at fixed ln C: transient_at_B) against continuation on an out-of-plane Fig. 4 plane holding the corners 3 -> 4 -> 5,
// and every point against a fresh reduced run at that scene (independent of the mapping; the mapped and the fresh
// transients differ by ~1e-11 in G_l, from the fresh run's step selection).
TEST(TraceInB, FiniteHorizonEqualsContinuationAndFreshRuns) {
  const SceneFile f = load_scene(std::string(RBCSTAB_SCENES_DIR) + "/fig4b_op.toml");
  Scene s = f.scene;
  s.parameters.lambda = 1.0;
  DiagramSpec plane = diagram_spec(f);
  plane.x = {Axis::lnB, 2, 4.5, 64};
  plane.y = {Axis::lnC, -3, 0, 64};
  TraceOptions o;
  o.criterion = TraceCriterion::finite_horizon;
  o.lines = 0;
  o.samples = 32;
  o.max_step = 0.05;
  const TraceResult exact = trace_boundary(s, plane, o);
  o.method = TraceMethod::continuation;
  const TraceResult cont = trace_boundary(s, plane, o);
  EXPECT_EQ(exact.method, "in closed form in B");
  EXPECT_EQ(cont.method, "by continuation");
  EXPECT_TRUE(exact.notes.empty()) << exact.notes.front();
  EXPECT_LT(exact.evaluations, cont.evaluations);
  ASSERT_FALSE(exact.curves.empty());
  ASSERT_EQ(exact.chains, cont.chains);
  ASSERT_EQ(exact.corners.size(), cont.corners.size());
  ASSERT_GE(exact.corners.size(), 1u);
  for (std::size_t k = 0; k < exact.corners.size(); ++k) {
    EXPECT_EQ(exact.corners[k].l_from, cont.corners[k].l_from);
    EXPECT_EQ(exact.corners[k].l_to, cont.corners[k].l_to);
    EXPECT_NEAR(exact.corners[k].x, cont.corners[k].x, 1e-8);
    EXPECT_NEAR(exact.corners[k].y, cont.corners[k].y, 1e-8);
  }
  for (const TraceCurve& c : exact.curves) {
    EXPECT_NE(c.criterion.find("G_l(T)"), std::string::npos);
    for (const TracePoint& p : c.points) {
      const FiniteHorizon h = finite_horizon_growth(plane_scene(s, plane, p.x, p.y), s.T, o.predictor);
      EXPECT_LE(std::abs(h.G[std::size_t(c.l - 2)]), 1e-10) << p.x << ", " << p.y;
      EXPECT_LE(std::abs(p.mu), 1e-10) << "the point's own residual G_l(T) = T Upsilon_l: roundoff of sigma times T";
      for (int l = 3; l <= s.L; ++l) EXPECT_LE(h.G[std::size_t(l - 2)], 1e-8);  // the envelope
    }
  }
  std::cout << "finite horizon: " << exact.evaluations << " transients (continuation " << cont.evaluations
            << " evaluations), " << exact.seconds << " s (continuation " << cont.seconds << " s)\n";
}

// In plane (App. E(a)) the finite-horizon boundary in closed form in B: every point is a zero of G_l(T) of a fresh
// reduced run, and the verdict flips across it.
TEST(TraceInB, InPlaneFiniteHorizonPointsAreZerosOfFreshRuns) {
  const SceneFile f = load_scene(std::string(RBCSTAB_SCENES_DIR) + "/appE_a_ip.toml");
  const DiagramSpec plane = diagram_spec(f);
  TraceOptions o;
  o.criterion = TraceCriterion::finite_horizon;
  o.samples = 16;
  o.max_step = 0.1;
  const TraceResult t = trace_boundary(f.scene, plane, o);
  EXPECT_EQ(t.method, "in closed form in B");
  ASSERT_FALSE(t.curves.empty());
  for (const TraceCurve& c : t.curves)
    for (std::size_t i = 0; i < c.points.size(); i += 3) {
      const TracePoint& p = c.points[i];
      const FiniteHorizon h = finite_horizon_growth(plane_scene(f.scene, plane, p.x, p.y), f.scene.T, o.predictor);
      EXPECT_LE(std::abs(h.G[std::size_t(c.l - 2)]), 1e-9) << p.x << ", " << p.y;
      if (p.x - 1e-4 < plane.x.min || p.x + 1e-4 > plane.x.max) continue;
      auto grows = [&](double x) {
        const FiniteHorizon g = finite_horizon_growth(plane_scene(f.scene, plane, x, p.y), f.scene.T, o.predictor);
        return *std::max_element(g.G.begin() + 1, g.G.end()) > 0;
      };
      EXPECT_NE(grows(p.x - 1e-4), grows(p.x + 1e-4)) << p.x << ", " << p.y;
    }
}

}  // namespace
}  // namespace rbcstab
