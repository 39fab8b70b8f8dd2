// Boundary tracing (asymptotic criterion, exact out-of-plane equilibrium) and its agreement with
// simulated diagrams.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab {
namespace {

Scene op_scene(double lambda, double Delta) {
  Scene s;  // beta = 0.001, Delta0 = 0.01, L = 10
  s.parameters.lambda = lambda;
  s.parameters.Delta = Delta;
  return s;
}
DiagramSpec fig4_plane() {
  DiagramSpec d;  // ln B in [-1, 6], ln C in [-5.5, 2]
  d.classifier = Classifier::final;
  return d;
}

// Every traced point solves mu_l = Upsilon_l(sigma_R^eq) = 0 for its mode. Tolerance 1e-10: the roots are
// bisected to the last bit of y, so |mu| ~ |d mu/dy| ulp(y) ~ 1e-14; 1e-10 leaves room for the scale of mu.
// Independent of the tracer: sigma_R^eq is recomputed from the analysis module at the point, and the
// verdict must flip across the point (a bracket of +-1e-7 of the y range).
TEST(Trace, PointsSatisfyTheCriterionAndSeparateVerdicts) {
  for (auto [lambda, Delta] : {std::pair{1.0, 1.0}, std::pair{5.0, 1.0}, std::pair{5.0, 0.1}}) {
    const Scene base = op_scene(lambda, Delta);
    const DiagramSpec plane = fig4_plane();
    TraceOptions o;
    o.lines = 40;
    o.samples = 64;
    const TraceResult t = trace_boundary(base, plane, o);
    ASSERT_FALSE(t.curves.empty());
    std::size_t n = 0;
    for (const TraceCurve& c : t.curves)
      for (const TracePoint& p : c.points) {
        ASSERT_EQ(p.l, c.l);
        const Parameters q = plane_scene(base, plane, p.x, p.y).parameters;
        const double sigma_R = out_of_plane_equilibrium(q).sigma_R;
        EXPECT_LE(std::abs(Upsilon_l(q, c.l, sigma_R)), 1e-10) << "lambda " << lambda << " at " << p.x << ", " << p.y;
        EXPECT_LE(std::abs(sigma_R - sigma_c(c.l, q.alpha())), 1e-10 * (1 + std::abs(sigma_R)));
        const double eps = 1e-7 * (plane.y.max - plane.y.min);
        if (p.y - eps > plane.y.min && p.y + eps < plane.y.max) {
          Scene lo = plane_scene(base, plane, p.x, p.y - eps), hi = plane_scene(base, plane, p.x, p.y + eps);
          EXPECT_NE(asymptotic_verdict(lo).unstable, asymptotic_verdict(hi).unstable);
        }
        ++n;
      }
    EXPECT_GT(n, 20u);
  }
}

// Corners: where the active mode changes from l to l + 1 on the boundary, sigma_l^c = sigma_{l+1}^c, i.e.
// alpha = Pi(l) Pi(l+1)/4 (analysis::alpha_mode_change, an independent closed form); the bisection in x
// stops at ~1e-15 of the x range, so alpha agrees to ~1e-12 relative; 1e-9 leaves margin.
TEST(Trace, CornersSitOnTheModeChangeLines) {
  const Scene base = op_scene(1.0, 1.0);  // Fig. 4(a): the boundary climbs through l = 3..9
  const DiagramSpec plane = fig4_plane();
  TraceOptions o;
  o.lines = 60;
  o.samples = 64;
  const TraceResult t = trace_boundary(base, plane, o);
  ASSERT_GE(t.corners.size(), 3u);
  for (const TraceCorner& k : t.corners) {
    EXPECT_EQ(k.l_to, k.l_from + 1);
    const double alpha = plane_scene(base, plane, k.x, k.y).parameters.alpha();
    EXPECT_NEAR(alpha / alpha_mode_change(k.l_from), 1.0, 1e-9) << "corner " << k.l_from << "->" << k.l_to;
  }
}

// The root-solve oracle (the tracer this module had before continuation): on the line x = const, the sign
// changes of the envelope margin m(y) = sigma_R^eq - max_{3<=l<=L} sigma_l^c bracketed on `samples` intervals
// and bisected to the last bit of y.
std::vector<double> oracle_roots(const Scene& base, const DiagramSpec& plane, double x, double y0, double y1,
                                 int samples) {
  auto margin = [&](double y) { return asymptotic_verdict(plane_scene(base, plane, x, y)).margin; };
  std::vector<double> roots;
  double ya = y0, fa = margin(ya);
  for (int k = 1; k <= samples; ++k) {
    const double yb = k == samples ? y1 : y0 + (y1 - y0) * double(k) / samples;
    const double fb = margin(yb);
    if ((fa < 0) != (fb < 0)) {
      double a = ya, b = yb, fa2 = fa;
      for (int it = 0; it < 200; ++it) {
        const double m = 0.5 * (a + b);
        if (m <= std::min(a, b) || m >= std::max(a, b)) break;
        const double fm = margin(m);
        if ((fm < 0) == (fa2 < 0))
          a = m, fa2 = fm;
        else
          b = m;
      }
      roots.push_back(0.5 * (a + b));
    }
    ya = yb;
    fa = fb;
  }
  return roots;
}

// Continuation against the oracle on the three Fig. 4 planes: (i) on 25 lines x = const the traced curves cross
// the line exactly as often as the oracle finds roots (no piece missed or doubled); (ii) every traced point is
// the oracle's root on its own line x = p.x, bracketed within +-1% of the y range, to 1e-9 of the y range
// (both are converged to ~1e-15; the margin's slope makes 1e-9 generous).
TEST(Trace, ContinuationAgreesWithTheRootSolveOracle) {
  for (auto [lambda, Delta] : {std::pair{1.0, 1.0}, std::pair{5.0, 1.0}, std::pair{5.0, 0.1}}) {
    const Scene base = op_scene(lambda, Delta);
    const DiagramSpec plane = fig4_plane();
    const TraceResult t = trace_boundary(base, plane);
    const double ry = plane.y.max - plane.y.min;
    for (int k = 1; k <= 25; ++k) {
      const double x = plane.x.min + (plane.x.max - plane.x.min) * (k + 0.37) / 26.0;
      const std::size_t expected = oracle_roots(base, plane, x, plane.y.min, plane.y.max, 512).size();
      std::size_t crossings = 0;
      for (const TraceCurve& c : t.curves)
        for (std::size_t i = 1; i < c.points.size(); ++i)
          if ((c.points[i - 1].x - x) * (c.points[i].x - x) < 0) ++crossings;
      EXPECT_EQ(crossings, expected) << "lambda " << lambda << " Delta " << Delta << " x " << x;
    }
    for (const TraceCurve& c : t.curves)
      for (const TracePoint& p : c.points) {
        const double lo = std::max(plane.y.min, p.y - 0.01 * ry), hi = std::min(plane.y.max, p.y + 0.01 * ry);
        if (hi - lo < 0.015 * ry) continue;  // on the y edges the bracket is one-sided: covered by (i)
        const std::vector<double> r = oracle_roots(base, plane, p.x, lo, hi, 4);
        ASSERT_EQ(r.size(), 1u) << p.x << ", " << p.y;
        EXPECT_NEAR(r[0], p.y, 1e-9 * ry);
      }
    std::cout << "lambda " << lambda << ", Delta " << Delta << ": " << t.curves.size() << " pieces, "
              << t.corners.size() << " corners, " << t.evaluations << " evaluations, " << t.seconds << " s\n";
  }
}

// Finite horizon: traced points satisfy G_l(T) = 0 to 1e-10, with G recomputed by analysis
// finite_horizon_growth (the same deterministic reduced run; Newton leaves |G| ~ 1e-13 and polishing
// guarantees 1e-12). Corners: on the boundary max_l G_l = 0 and G_l = T Upsilon_l(<sigma_R>_T) is affine in
// <sigma_R>_T, so the active mode changes where sigma_l^c = sigma_{l+1}^c, alpha = Pi(l)Pi(l+1)/4, as for
// the asymptotic criterion (an independent closed form; tolerance as in CornersSitOnTheModeChangeLines).
TEST(Trace, FiniteHorizonPointsSatisfyGlOfTAndCornersOnModeChangeLines) {
  const Scene base = op_scene(1.0, 1.0);
  DiagramSpec plane = fig4_plane();
  plane.x = {Axis::lnB, 2, 4.5, 64};  // holds the corners 3 -> 4 -> 5
  plane.y = {Axis::lnC, -3, 0, 64};
  TraceOptions o;
  o.criterion = TraceCriterion::finite_horizon;
  o.lines = 0;
  o.samples = 32;
  o.max_step = 0.05;
  const TraceResult t = trace_boundary(base, plane, o);
  ASSERT_FALSE(t.curves.empty()) << (t.notes.empty() ? "" : t.notes.front());
  EXPECT_TRUE(t.notes.empty()) << t.notes.front();
  for (const TraceCurve& c : t.curves) {
    EXPECT_NE(c.criterion.find("G_l(T)"), std::string::npos);
    for (const TracePoint& p : c.points) {
      const FiniteHorizon h = finite_horizon_growth(plane_scene(base, plane, p.x, p.y), base.T, o.predictor);
      EXPECT_LE(std::abs(h.G[std::size_t(c.l - 2)]), 1e-10) << p.x << ", " << p.y;
      for (int l = 3; l <= base.L; ++l) EXPECT_LE(h.G[std::size_t(l - 2)], 1e-8);  // the envelope
    }
  }
  ASSERT_GE(t.corners.size(), 1u);
  for (const TraceCorner& k : t.corners) {
    EXPECT_EQ(k.l_to, k.l_from + 1);
    const double alpha = plane_scene(base, plane, k.x, k.y).parameters.alpha();
    EXPECT_NEAR(alpha / alpha_mode_change(k.l_from), 1.0, 1e-9) << "corner " << k.l_from << "->" << k.l_to;
  }
  std::cout << "finite horizon: " << t.curves.size() << " pieces, " << t.corners.size() << " corners, " << t.evaluations
            << " evaluations, " << t.seconds << " s\n";
}

// In-plane scenes: the asymptotic criterion is mu_l = Upsilon_l(<sigma_R>) with a time average (cheap options:
// transient 100, window 200 on a small lambda - ln C plane). The traced points satisfy the criterion as
// recomputed by asymptotic_sigma_R (the same deterministic function) to 1e-10, and the verdict flips across.
TEST(Trace, InPlaneAsymptoticByTimeAverage) {
  Scene s = op_scene(1, 1);  // Appendix E(a): lambda = 1, Delta = 1
  s.beta = 1.5707963267948966;
  s.L = 5;
  DiagramSpec plane;
  plane.x = {Axis::lnB, 3, 5, 5};
  plane.y = {Axis::lnC, -3, 0, 5};
  TraceOptions o;
  o.lines = 0;
  o.samples = 8;
  o.bisections = 30;
  o.max_step = 0.1;
  o.predictor.transient = 100;
  o.predictor.window = 200;
  o.predictor.average_tolerance = 1e-2;
  const TraceResult t = trace_boundary(s, plane, o);
  ASSERT_FALSE(t.curves.empty()) << (t.notes.empty() ? "" : t.notes.front());
  EXPECT_NE(t.curves.front().criterion.find("time average"), std::string::npos);
  for (const TraceCurve& c : t.curves)
    for (const TracePoint& p : c.points) {
      const Scene q = plane_scene(s, plane, p.x, p.y);
      const double sigma = asymptotic_sigma_R(q, o.predictor).sigma_R;
      EXPECT_FALSE(asymptotic_sigma_R(q, o.predictor).exact);
      // Since the periodic-orbit average (OrbitAverageOptions on by default): every point of this plane from it.
      EXPECT_EQ(asymptotic_sigma_R(q, o.predictor, o.orbit).source, SigmaSource::periodic_orbit);
      EXPECT_LE(std::abs(Upsilon_l(q.parameters, c.l, sigma)), 1e-10) << p.x << ", " << p.y;
    }
  std::cout << "in-plane trace: " << t.curves.size() << " pieces, " << t.evaluations << " evaluations, "
            << t.counters.steps << " steps, " << t.counters.rejected_steps << " rejected, "
            << t.counters.newton_iterations << " newton, " << t.counters.location_iterations << " location, "
            << t.seconds << " s\n";
}

// On a small simulated grid (Fig. 4(b) plane, 7 x 6 points, T = 500, L = 10: the paper's setting) the traced
// boundary separates the simulated verdicts except within one grid step of it; exceptions are printed.
TEST(Trace, BoundarySeparatesSimulatedVerdictsOnASmallGrid) {
  const Scene base = op_scene(5.0, 1.0);
  DiagramSpec spec = fig4_plane();
  spec.x.count = 7;
  spec.y = {Axis::lnC, -4, 2, 6};  // ln C >= -4 keeps the explicit runs cheap
  DiagramOptions ro;
  ro.threads = 2;
  Scene sim = base;
  sim.dt = sim.T;
  const DiagramRun run = run_diagram(sim, {}, spec, ro);
  ASSERT_TRUE(run.complete);
  TraceOptions o;
  o.lines = 80;
  o.samples = 128;
  DiagramSpec plane = spec;
  const TraceResult t = trace_boundary(base, plane, o);
  const Agreement a = asymptotic_agreement(sim, spec, run.points, t);
  EXPECT_EQ(a.points, spec.size());
  for (const Disagreement& d : a.verdict_disagreements)
    std::cout << "disagreement at point " << d.index << ": simulated l = " << d.l_simulated << ", predicted "
              << (d.predicted_unstable ? "unstable" : "stable") << ", " << d.distance_steps
              << " grid steps from the boundary, S = " << d.S << "\n";
  EXPECT_EQ(a.beyond_one_step, 0u);
  EXPECT_GE(a.verdict_matches, a.points - 3);

  // Every predictor: one entry each, in order; the asymptotic one equals asymptotic_agreement; every finished
  // point is either classified or not; the l_* entry against its closed form alpha = e^(x - y) >= (35/8)^2
  // counted here independently.
  AgreementOptions ao;
  ao.threads = 2;
  const std::vector<Agreement> all = predictor_agreements(sim, spec, run.points, ao);
  ASSERT_EQ(all.size(), 5u);
  const char* names[] = {"asymptotic", "finite_horizon", "l_star", "alpha_init", "large_S"};
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_EQ(all[k].predictor, names[k]);
    EXPECT_EQ(all[k].points + all[k].not_classified, spec.size());
    EXPECT_LE(all[k].mode_matches, all[k].verdict_matches);
    EXPECT_EQ(all[k].verdict_matches + all[k].verdict_disagreements.size(), all[k].points);
    std::cout << all[k].predictor << ": verdict " << all[k].verdict_matches << "/" << all[k].points << ", mode "
              << all[k].mode_matches << ", beyond one step " << all[k].beyond_one_step << ", not classified "
              << all[k].not_classified << " (" << all[k].boundary << ")\n";
  }
  EXPECT_EQ(all[0].verdict_matches, a.verdict_matches);
  EXPECT_EQ(all[0].mode_matches, a.mode_matches);
  EXPECT_EQ(all[0].beyond_one_step, a.beyond_one_step);
  EXPECT_EQ(all[1].boundary_pieces, all[0].boundary_pieces);  // distances to the asymptotic boundary by default
  std::size_t lstar_matches = 0, lstar_unstable = 0, lstar_unstable_mode = 0;
  for (const PointResult& p : run.points) {
    const double alpha = std::exp(p.x - p.y);
    const bool u = alpha >= 35.0 * 35.0 / 64.0, unstable = p.verdict == Verdict::unstable;
    lstar_matches += u == unstable;
    lstar_unstable += u && unstable;
    lstar_unstable_mode += u && unstable && std::clamp(int(std::lround(l_star(alpha))), 3, sim.L) == p.l_Delta;
  }
  EXPECT_EQ(all[2].verdict_matches, lstar_matches);
  EXPECT_EQ(all[2].unstable_matches, lstar_unstable);
  EXPECT_EQ(all[2].unstable_mode_matches, lstar_unstable_mode);
  for (const Agreement& g : all) EXPECT_LE(g.unstable_mode_matches, g.unstable_matches);
  // The finite-horizon predictor integrates the same reduced transient over the same T as the simulation
  // starts from: on this grid it misses at most the points the asymptotic one misses plus one.
  EXPECT_GE(all[1].verdict_matches + 1, all[0].verdict_matches);
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
// The finite-horizon agreement integrates one reduced transient per flow and maps it across B (transient_at_B):
// on 16 x 16 grids of the Fig. 4(b) plane, out of plane and in plane, its verdict and mode at every point equal
// those of a direct reduced run there. With every point simulated stable, the disagreements list exactly the
// points predicted unstable, with their mode.
TEST(Trace, FiniteHorizonAgreementReusesTransientsAcrossB) {
  for (double beta : {0.001, 1.5707963267948966}) {
    Scene base = op_scene(5.0, 1.0);
    base.beta = beta;
    DiagramSpec spec = fig4_plane();
    spec.x.count = spec.y.count = 16;
    std::vector<PointResult> points(spec.size());
    for (std::size_t i = 0; i < points.size(); ++i) points[i].index = i;
    AgreementOptions ao;
    ao.threads = 2;
    ao.trace = false;
    const std::vector<Agreement> all = predictor_agreements(base, spec, points, ao);
    ASSERT_EQ(all[1].predictor, "finite_horizon");
    std::vector<int> reused(points.size(), 2), direct(points.size(), 2);  // 2: stable, else the mode
    for (const Disagreement& d : all[1].verdict_disagreements) reused[d.index] = d.l_predicted;
    std::size_t unstable = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Scene s = point_scene(base, spec, i);
      const ModePrediction m = finite_horizon_prediction(s, finite_horizon_growth(s, s.T));
      ASSERT_EQ(m.status, DomainStatus::ok) << i;
      direct[i] = m.unstable.empty() ? 2 : m.l_Delta;
      unstable += !m.unstable.empty();
    }
    EXPECT_EQ(reused, direct) << "beta " << beta;
    EXPECT_GT(unstable, 0u);
    EXPECT_LT(unstable, points.size());
  }
}

// The overlay alpha lines are where l_* (analysis::l_star, the forward formula) takes its value.
TEST(Trace, AnalyticOverlaysLieOnTheirDefiningLines) {
  const Scene base = op_scene(1.0, 1.0);
  const DiagramSpec plane = fig4_plane();
  const std::vector<Overlay> lines = analytic_overlays(base, plane, 50);
  bool saw_l25 = false, saw_cminus = false;
  for (const Overlay& o : lines) {
    ASSERT_EQ(o.x.size(), o.y.size());
    if (o.name == "l_star=2.5") {
      saw_l25 = true;
      ASSERT_FALSE(o.x.empty());
      for (std::size_t k = 0; k < o.x.size(); ++k)
        EXPECT_NEAR(l_star(plane_scene(base, plane, o.x[k], o.y[k]).parameters.alpha()), 2.5, 1e-12);
    }
    if (o.name == "C_star_minus") saw_cminus = !o.x.empty();  // Lambda ~ 0.7 < 1: C_*^- exists
  }
  EXPECT_TRUE(saw_l25);
  EXPECT_TRUE(saw_cminus);
  DiagramSpec other = plane;
  other.x.axis = Axis::Delta;
  EXPECT_TRUE(analytic_overlays(base, other, 10).empty());
}
}  // namespace
}  // namespace rbcstab
