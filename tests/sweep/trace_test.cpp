// Boundary tracing (asymptotic criterion, exact out-of-plane equilibrium) and its agreement with
// simulated diagrams.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/trace.hpp"

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
        EXPECT_LE(std::abs(Upsilon(q, c.l, sigma_R)), 1e-10) << "lambda " << lambda << " at " << p.x << ", " << p.y;
        EXPECT_LE(std::abs(sigma_R - sigma_critical(c.l, q.alpha())), 1e-10 * (1 + std::abs(sigma_R)));
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

TEST(Trace, RejectsInPlaneScenes) {
  Scene s = op_scene(5, 1);
  s.beta = 1.5707963267948966;
  EXPECT_THROW(asymptotic_verdict(s), InvalidArgument);
  EXPECT_THROW(trace_boundary(s, fig4_plane()), InvalidArgument);
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
              << (d.predicted_unstable ? "unstable" : "stable") << ", " << d.distance_steps << " grid steps from the boundary, S = "
              << d.S << "\n";
  EXPECT_EQ(a.beyond_one_step, 0u);
  EXPECT_GE(a.verdict_matches, a.points - 3);
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
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
