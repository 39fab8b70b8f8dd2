// The shear rate at which a physical cell first becomes unstable (verdict/shear_rate.hpp), against the
// (ln B, ln C) boundary traced the usual way (sweep/trace.hpp): raising the shear rate at a fixed cell moves
// the scene along ln B - ln C = ln alpha, so the threshold is where that line meets the traced boundary.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/physical.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/shear_rate.hpp"

namespace rbcstab {
namespace {

constexpr double kInPlane = std::numbers::pi / 2;

// R = 3 um, kappa = 2e-19 J, mu = 2.5 uN/m, eta = 1 mPa s (the paper's Sec. VI estimate), lambda = 5,
// Delta = 1, Delta0 = 0.5: in plane it turns unstable near 600/s (measured), out of plane it stays stable.
Scene physical_scene() {
  Scene s;
  PhysicalCell c;
  c.shear_rate = 1000;
  c.viscosity = 1e-3;
  c.radius = 3e-6;
  c.bending_modulus = 2e-19;
  c.shear_modulus = 2.5e-6;
  s.physical = c;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.5;
  s.parameters = physical_parameters(c, s.parameters);
  s.T = 200;
  return s;
}

TEST(ShearRate, PathMovesBAndCAtFixedAlpha) {
  const Scene s = physical_scene();
  const Parameters p = at_shear_rate(*s.physical, s.parameters, 250);
  EXPECT_NEAR(p.B, s.parameters.B / 4, 1e-15 * s.parameters.B);
  EXPECT_NEAR(p.C, s.parameters.C / 4, 1e-15 * s.parameters.C);
  EXPECT_NEAR(p.alpha(), s.parameters.alpha(), 1e-14 * s.parameters.alpha());
  // The same as the cell at 250/s converted afresh.
  PhysicalCell c = *s.physical;
  c.shear_rate = 250;
  EXPECT_NEAR(p.B, physical_parameters(c, s.parameters).B, 1e-14 * p.B);
  EXPECT_THROW(shear_rate_threshold(Scene{}, kInPlane), InvalidArgument);
}

// The traced boundary's polyline crosses ln B - ln C = ln alpha at x*; the threshold's B must be e^x*.
// Tolerance 1e-4 relative in gamma: the traced points solve the criterion to ~1e-10 and are at most
// max_step = 0.02 of the unit square apart (0.012 in ln B here), so the chord between them is off the curve by
// ~h^2/8 ~ 2e-5 in ln units for an O(1) curvature; the bisection's bracket is 1e-6.
TEST(ShearRate, ThresholdIsWhereTheTracedBoundaryMeetsTheAlphaLine) {
  const Scene s = physical_scene();
  const ShearRateThreshold t = shear_rate_threshold(s, kInPlane);
  ASSERT_TRUE(t.found) << t.reason;
  EXPECT_EQ(t.side, "");
  EXPECT_LE(t.hi / t.lo - 1, 1e-6);
  EXPECT_GE(t.l, 3);
  // Independently of the search: the verdict flips across the bracket.
  Scene lo = s, hi = s;
  lo.beta = hi.beta = kInPlane;
  lo.parameters = at_shear_rate(*s.physical, s.parameters, t.lo);
  hi.parameters = at_shear_rate(*s.physical, s.parameters, t.hi);
  EXPECT_FALSE(asymptotic_verdict(lo).unstable);
  EXPECT_TRUE(asymptotic_verdict(hi).unstable);
  // This window stays open to the search's end (measured), and says so.
  EXPECT_FALSE(t.end_found);
  EXPECT_NE(t.end_reason.find("unstable up to max_rate"), std::string::npos) << t.end_reason;
  hi.parameters = at_shear_rate(*s.physical, s.parameters, ShearRateSearchOptions{}.max_rate);
  EXPECT_TRUE(asymptotic_verdict(hi).unstable);

  Scene base = s;
  base.beta = kInPlane;
  DiagramSpec plane;
  plane.x = {Axis::lnB, std::log(t.B) - 0.3, std::log(t.B) + 0.3, 16};
  plane.y = {Axis::lnC, std::log(t.C) - 0.3, std::log(t.C) + 0.3, 16};
  TraceOptions o;
  o.lines = 2;
  o.samples = 16;
  const TraceResult r = trace_boundary(base, plane, o);
  ASSERT_FALSE(r.curves.empty());
  const double ln_alpha = std::log(t.alpha);
  std::optional<double> x_cross;
  for (const TraceCurve& c : r.curves)
    for (std::size_t k = 1; k < c.points.size(); ++k) {
      const TracePoint &p = c.points[k - 1], &q = c.points[k];
      const double fp = p.x - p.y - ln_alpha, fq = q.x - q.y - ln_alpha;
      if ((fp <= 0) != (fq <= 0) && !x_cross) x_cross = p.x + (q.x - p.x) * fp / (fp - fq);
    }
  ASSERT_TRUE(x_cross.has_value()) << "the traced boundary does not cross the alpha line";
  const double b = s.parameters.B / s.physical->shear_rate;  // B = b gamma
  const double gamma_traced = std::exp(*x_cross) / b;
  EXPECT_NEAR(gamma_traced / t.shear_rate, 1, 1e-4) << "traced " << gamma_traced << ", searched " << t.shear_rate;
}

// The unstable window's upper end: R = 3 um, kappa = 2e-19 J, mu = 2.5 uN/m, eta = 1 mPa s, lambda = 1, Delta = 0.5,
// Delta0 = 0.01 out of plane is unstable from the search's lower end (1/s) up to ~68/s (measured). The end's
// bracket is checked independently of the search: the verdict is unstable at its lower and stable at its upper end.
TEST(ShearRate, WindowEndIsWhereTheVerdictTurnsStableAgain) {
  Scene s = physical_scene();
  s.physical->shear_rate = 100;
  s.parameters.lambda = 1;
  s.parameters.Delta = 0.5;
  s.parameters.Delta0 = 0.01;
  s.parameters = physical_parameters(*s.physical, s.parameters);
  const ShearRateThreshold t = shear_rate_threshold(s, 1e-3);
  EXPECT_FALSE(t.found);
  EXPECT_NE(t.reason.find("unstable already at min_rate"), std::string::npos) << t.reason;
  EXPECT_EQ(t.side, "below");
  ASSERT_TRUE(t.end_found) << t.end_reason;
  EXPECT_EQ(t.end_shear_rate, t.end_bracket[1]);
  EXPECT_LE(t.end_bracket[1] / t.end_bracket[0] - 1, 1e-6);
  EXPECT_GT(t.end_shear_rate, 10);
  EXPECT_LT(t.end_shear_rate, 1000);
  Scene below = s, above = s;
  below.beta = above.beta = 1e-3;
  below.parameters = at_shear_rate(*s.physical, s.parameters, t.end_bracket[0]);
  above.parameters = at_shear_rate(*s.physical, s.parameters, t.end_bracket[1]);
  EXPECT_TRUE(asymptotic_verdict(below).unstable);
  EXPECT_FALSE(asymptotic_verdict(above).unstable);
}

// The side of a crossing outside the searched range is a field set where the search decides, not read from the
// reason's text: the Sec. VI cell out of plane stays stable over the default range (measured) -> "above"; the
// same cell in plane with the range starting past its crossing -> "below" (verdicts checked at the range's ends).
TEST(ShearRate, SideOfACrossingOutsideTheRange) {
  const Scene s = physical_scene();
  const ShearRateThreshold op = shear_rate_threshold(s, 1e-3);
  ASSERT_FALSE(op.found);
  EXPECT_EQ(op.side, "above") << op.reason;
  const ShearRateThreshold ip = shear_rate_threshold(s, kInPlane);
  ASSERT_TRUE(ip.found) << ip.reason;
  ShearRateSearchOptions past;
  past.min_rate = 2 * ip.shear_rate;
  past.max_rate = 4 * ip.shear_rate;
  const ShearRateThreshold below = shear_rate_threshold(s, kInPlane, past);
  EXPECT_FALSE(below.found);
  EXPECT_EQ(below.side, "below") << below.reason;
  Scene at = s;
  at.beta = kInPlane;
  at.parameters = at_shear_rate(*s.physical, s.parameters, past.min_rate);
  EXPECT_TRUE(asymptotic_verdict(at).unstable);
  // A range wholly under the crossing: "above".
  past.min_rate = ip.shear_rate / 4;
  past.max_rate = ip.shear_rate / 2;
  EXPECT_EQ(shear_rate_threshold(s, kInPlane, past).side, "above");
}

// A diagram with a shear_rate axis: its grid is geometric, and every point's result is that of the plain scene
// (no cell) at the cell converted afresh at the point's rate (physical_parameters), run as its own one-point
// diagram. Equal to 1e-12 relative: both runs integrate the same system from the same state, the parameters a
// few ulps apart; the verdict and l_Delta exactly.
TEST(ShearRate, DiagramAxisPointsAreThePlainSceneAtTheConvertedRate) {
  Scene base = physical_scene();
  base.L = 5;
  base.T = 40;
  base.dt = 40;
  DiagramSpec spec;
  spec.x = {SceneParameter::shear_rate, 10, 1000, 3};
  spec.y = {SceneParameter::lambda, 1, 5, 2};
  validate_plane(base, spec);
  EXPECT_EQ(spec.x.value(0), 10);
  EXPECT_NEAR(spec.x.value(1), 100, 1e-12 * 100);
  EXPECT_EQ(spec.x.value(2), 1000);
  SimulationOptions options;
  options.record_trajectory = false;
  for (std::size_t k = 0; k < spec.size(); ++k) {
    const PointResult on_path = run_point(base, options, spec, k);
    Scene plain = point_scene(base, spec, k);
    PhysicalCell c = *base.physical;
    c.shear_rate = on_path.x;
    plain.physical.reset();
    plain.parameters = physical_parameters(c, plain.parameters);
    DiagramSpec one;
    one.x = {SceneParameter::lambda, plain.parameters.lambda, plain.parameters.lambda, 1};
    one.y = {SceneParameter::Delta, plain.parameters.Delta, plain.parameters.Delta, 1};
    const PointResult direct = run_point(plain, options, one, 0);
    EXPECT_EQ(on_path.verdict, direct.verdict) << k;
    EXPECT_EQ(on_path.l_Delta, direct.l_Delta) << k;
    EXPECT_NEAR(on_path.growth, direct.growth, 1e-12 * (1 + std::abs(direct.growth))) << k;
    EXPECT_NEAR(on_path.sigma_final, direct.sigma_final, 1e-9 * (1 + std::abs(direct.sigma_final))) << k;
  }
  // Axes that move each other are refused: shear_rate moves B and C.
  spec.y = {SceneParameter::lnC, -2, 0, 2};
  EXPECT_THROW(validate_plane(base, spec), InvalidArgument);
  // A plain scene cannot take the axis.
  spec.y = {SceneParameter::lambda, 1, 5, 2};
  try {
    validate_plane(Scene{}, spec);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "shear_rate");
  }
}

// A shear_rate plane is traced in ln of the rate (the axis is geometric): successive points of a piece are at
// most max_step apart in the unit square of (ln rate, lambda), i.e. their rates differ by at most a factor
// (max/min)^max_step, also where the boundary runs at low rates; each point solves the criterion at the plain
// scene converted from its rate (|mu_l| <= 1e-8: Newton's residual 1e-10 in the reduced units of the tracer).
TEST(ShearRate, TracedInLnOfTheRate) {
  Scene base = physical_scene();
  base.parameters.Delta0 = 0.01;
  base.parameters = physical_parameters(*base.physical, base.parameters);
  base.beta = 0.001;
  DiagramSpec plane;
  plane.x = {SceneParameter::shear_rate, 10, 1e4, 2};
  plane.y = {SceneParameter::lambda, 1, 5, 2};
  TraceOptions o;
  const TraceResult r = trace_boundary(base, plane, o);
  ASSERT_FALSE(r.curves.empty());
  const double factor = std::pow(1e3, o.max_step) * (1 + 1e-9);
  std::size_t points = 0;
  for (const TraceCurve& c : r.curves) {
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      const TracePoint& q = c.points[k];
      ASSERT_GE(q.x, 10 * (1 - 1e-12));
      ASSERT_LE(q.x, 1e4 * (1 + 1e-12));
      if (k > 0) {
        const double ratio = q.x / c.points[k - 1].x;
        EXPECT_LE(std::max(ratio, 1 / ratio), factor) << "at rate " << q.x;
      }
      PhysicalCell cell = *base.physical;
      Scene plain = base;
      plain.physical.reset();
      plain.parameters.lambda = q.y;
      plain.parameters = at_shear_rate(cell, plain.parameters, q.x);
      const AsymptoticVerdict v = asymptotic_verdict(plain);
      EXPECT_LE(std::abs(Upsilon_l(plain.parameters, q.l, v.sigma_R)), 1e-8) << q.x << ", " << q.y;
      ++points;
    }
  }
  EXPECT_GE(points, 10u);
}

}  // namespace
}  // namespace rbcstab
