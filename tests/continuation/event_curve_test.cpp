// Event curves (event_curve.hpp): the generic system [F; G] = 0 on a closed-form problem, the orbit's
// passage event (exact Jacobian, smoothness), the same curve from the one-parameter UZ function, and the
// swinging <-> tumbling curve of Fig. 2's in-plane orbit (continue_curve, --curve UZ) against two
// independent computations of the transition: the UZ of one-parameter branches at fixed second
// parameter, and the winding number of long direct simulations of the reduced model (bisection).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <span>
#include <vector>

#include "continuation/fig2_fixture.hpp"
#include "continuation/invalid_argument_fixture.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/event_curve.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/reduced_model.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;
using test::invalid_parameter;

// ---- the generic mechanism on a closed form

// F = (u^3 + u - p1, v - p1 p2), event g = u^2 + p2^2 - 1: the curve is u = cos(theta), p2 = sin(theta),
// p1 = u^3 + u, v = p1 p2, with folds in p2 at p2 = +-1 (u = 0).
class Cubic final : public TwoParameterProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& x, double p1, double p2, Eigen::VectorXd& F) const override {
    F.resize(2);
    F << x[0] * x[0] * x[0] + x[0] - p1, x[1] - p1 * p2;
  }
};

TEST(EventCurve, ScalarEventFollowsTheClosedFormCurveThroughItsFold) {
  const Cubic base;
  const auto g = [](const Eigen::VectorXd& x, double, double p2) { return x[0] * x[0] + p2 * p2 - 1; };
  // The one-parameter branch in p1 at p2 = 0 meets the event at u = 1, p1 = 2.
  const SliceProblem slice(base, 0.0);
  ContinuationOptions o;
  o.p_max = 3;
  o.events.push_back({"circle", [&](const Eigen::VectorXd& x, double p1) { return g(x, p1, 0.0); }});
  const Branch b = continue_branch(slice, Eigen::Vector2d(0.5, 0), 0.625, o);
  const SpecialPoint* uz = find_special_point(b, SpecialPointType::UZ);
  ASSERT_NE(uz, nullptr);
  EXPECT_NEAR(uz->p, 2.0, 1e-10);

  const ScalarCurveEvent event("circle", g);
  const EventCurveProblem curve(base, event, *uz, 0.0);
  EXPECT_EQ(curve.dimension(), 3);
  EXPECT_EQ(curve.parameter_names(), (std::vector<std::string>{"p1", "p2"}));
  ContinuationOptions co;
  co.direction = Direction::forward;
  co.p_min = -2;
  co.p_max = 2;
  co.max_step = 0.1;
  co.max_points = 45;  // past the fold at p2 = 1 onto the u < 0 half
  const Branch c = continue_branch(curve, curve.start(), 0.0, co);
  ASSERT_EQ(c.points.size(), 45u) << c.message;
  double u_min = 1;
  for (const BranchPoint& pt : c.points) {
    const double u = pt.x[0], p1 = pt.x[2], p2 = pt.p;
    u_min = std::min(u_min, u);
    // Newton to 1e-12: every point on the closed form to 1e-10.
    EXPECT_NEAR(u * u + p2 * p2, 1.0, 1e-10);
    EXPECT_NEAR(p1, u * u * u + u, 1e-10);
    EXPECT_NEAR(pt.x[1], p1 * p2, 1e-10);
    EXPECT_EQ(pt.parameters, (std::vector<double>{p1, p2}));
  }
  EXPECT_LT(u_min, -0.2);  // continued around the fold
  const SpecialPoint* lp = find_special_point(c, SpecialPointType::LP);
  ASSERT_NE(lp, nullptr);
  EXPECT_NEAR(lp->p, 1.0, 1e-8);  // the fold of the curve in p2
  EXPECT_NEAR(lp->x[0], 0.0, 1e-4);
}

TEST(EventCurve, RefusesAStartThatIsNotALocatedUZ) {
  const Cubic base;
  const ScalarCurveEvent event("circle", [](const Eigen::VectorXd& x, double, double) { return x[0] - 1; });
  SpecialPoint sp;
  sp.type = SpecialPointType::LP;
  sp.status = LocationStatus::located;
  sp.x = Eigen::Vector2d(1, 0);
  sp.p = 2;
  EXPECT_EQ(invalid_parameter([&] { EventCurveProblem(base, event, sp, 0.0); }), "uz");
  sp.type = SpecialPointType::UZ;
  sp.status = LocationStatus::guess;
  EXPECT_EQ(invalid_parameter([&] { EventCurveProblem(base, event, sp, 0.0); }), "uz");
  EXPECT_EQ(invalid_parameter([] { ScalarCurveEvent("none", nullptr); }), "event");
}

// ---- the orbit's passage through z = 0

// Fig. 2's in-plane orbit continued in Delta at lambda = 5 (4 segments): its swing_tumble UZ.
struct Fig2Transition {
  Scene scene = test::fig2_in_plane(0.3);
  SpecialPoint uz;
};

Fig2Transition fig2_transition() {
  Fig2Transition f;
  OrbitOptions oo;
  oo.segments = 4;
  const ReducedForcedSystem sys(f.scene, P::Delta);
  const PeriodicOrbitProblem pr(sys, oo);
  const NewtonResult st = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(200), 0.3), 0.3);
  ContinuationOptions o;
  o.direction = Direction::forward;
  o.p_max = 0.45;
  o.max_step = 0.05;
  o.events.push_back(pr.transition_event());
  const Branch b = continue_branch(pr, st.x, 0.3, o);
  if (const SpecialPoint* uz = find_special_point(b, SpecialPointType::UZ)) f.uz = *uz;
  return f;
}

OrbitOptions four_segments() {
  OrbitOptions oo;
  oo.segments = 4;
  return oo;
}

// The curve system's Jacobian (the shooting Jacobian from the variational equations, the passage rows
// from point_at) against central differences of its residual, on the curve and off it; and the passage
// event is smooth: its directional difference quotients converge to the exact derivative as h^2 from
// h = 1e-2 down to the rounding floor (no kinks, no jumps between segments or samples).
TEST(OrbitPassageEvent, JacobianIsExactAndTheEventIsSmooth) {
  const Fig2Transition f = fig2_transition();
  ASSERT_EQ(f.uz.type, SpecialPointType::UZ);
  const ReducedForcedSystem2 sys2(f.scene, P::Delta, P::lambda);
  const OrbitTwoParameterProblem base(sys2, four_segments());
  const OrbitPassageEvent event(base);
  const EventCurveProblem curve(base, event, f.uz, 5.0);
  ASSERT_EQ(curve.dimension(), 12 + 2);
  const Eigen::VectorXd X0 = curve.start();
  // At the start the orbit passes through z = 0 to the UZ's precision (r_min ~ 1e-12).
  Eigen::VectorXd R;
  curve.residual(X0, 5.0, R);
  EXPECT_LT(R.lpNorm<Eigen::Infinity>(), 1e-10);
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(X0.size(), 0.3, -0.7);
  v.normalize();
  for (const Eigen::VectorXd& X : {X0, Eigen::VectorXd(X0 + 1e-2 * v)}) {
    Eigen::MatrixXd J;
    curve.jacobian(X, 5.0, J);
    // Central differences, step 1e-6: truncation ~1e-12 |R'''|, rounding and integration noise
    // ~1e-13 / 1e-6 = 1e-7; the entries are O(1).
    for (Eigen::Index j = 0; j < X.size(); ++j) {
      Eigen::VectorXd Xp = X, Xm = X, Rp, Rm;
      Xp[j] += 1e-6;
      Xm[j] -= 1e-6;
      curve.residual(Xp, 5.0, Rp);
      curve.residual(Xm, 5.0, Rm);
      EXPECT_LT(((Rp - Rm) / 2e-6 - J.col(j)).lpNorm<Eigen::Infinity>(), 1e-6) << j;
    }
  }
  // Smoothness along v through the start, in the event rows only.
  Eigen::MatrixXd J;
  curve.jacobian(X0, 5.0, J);
  const Eigen::Vector2d exact = J.bottomRows(2) * v;
  double previous = 0;
  for (double h : {1e-2, 1e-3, 1e-4, 1e-5}) {
    Eigen::VectorXd Rp, Rm;
    curve.residual(X0 + h * v, 5.0, Rp);
    curve.residual(X0 - h * v, 5.0, Rm);
    const double err = ((Rp - Rm).tail(2) / (2 * h) - exact).lpNorm<Eigen::Infinity>();
    std::printf("h = %.0e: |difference quotient - exact| = %.2e\n", h, err);
    if (h == 1e-3) {
      EXPECT_LT(err, 0.02 * previous);  // second order: 100x smaller for 10x smaller h
    }
    if (h <= 1e-4) {
      EXPECT_LT(err, 1e-7);
    }
    previous = err;
  }
  // Across a segment end the state is continuous at a solution (the segments join to Newton's tolerance).
  const OrbitPoint before = base.point_at(f.uz.x, f.uz.p, 5.0, kTwoPi / 4 - 1e-13);
  const OrbitPoint after = base.point_at(f.uz.x, f.uz.p, 5.0, kTwoPi / 4);
  EXPECT_EQ(before.segment, 0);
  EXPECT_EQ(after.segment, 1);
  EXPECT_LT((before.x - after.x).norm(), 1e-10);
  // The start's passage time is the summary's time of r_min.
  EXPECT_EQ(curve.auxiliary(X0)[0], base.summary(f.uz.x, f.uz.p, 5.0).t_r_min);
}

TEST(OrbitPassageEvent, RefusesAStartAwayFromTheTransition) {
  const Fig2Transition f = fig2_transition();
  const ReducedForcedSystem2 sys2(f.scene, P::Delta, P::lambda);
  const OrbitTwoParameterProblem base(sys2, four_segments());
  const OrbitPassageEvent event(base);
  // The orbit at Delta = 0.3 swings with r >= 0.6: not a passage through z = 0.
  const ReducedForcedSystem sys(f.scene, P::Delta);
  const PeriodicOrbitProblem pr(sys, four_segments());
  const NewtonResult st = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(200), 0.3), 0.3);
  ASSERT_TRUE(st.converged);
  std::string m;
  EXPECT_EQ(invalid_parameter([&] { (void)event.auxiliary_start(st.x, 0.3, 5.0); }, &m), "event");
  EXPECT_NE(m.find("does not pass through z = 0"), std::string::npos) << m;
}

// The same mechanism with the one-parameter UZ function itself (transition_event, +-r_min from the dense
// summary) as a scalar event gives the same curve: near the transition it is smooth to about the
// integration tolerance (measured at the UZ: its difference quotients along a direction in X agree to
// 2e-9 relative for h from 1e-4 to 1e-7), but every evaluation is a dense pass over the period and its
// Jacobian row 2 (3 N + 1) of them (measured: 25x the passage event's CPU time on the curve below).
TEST(OrbitPassageEvent, TheUZFunctionAsAScalarEventGivesTheSameCurve) {
  const Fig2Transition f = fig2_transition();
  const ReducedForcedSystem2 sys2(f.scene, P::Delta, P::lambda);
  const OrbitTwoParameterProblem base(sys2, four_segments());
  const OrbitPassageEvent passage(base);
  const ScalarCurveEvent scalar(std::string(kTransitionEventName), [&](const Eigen::VectorXd& X, double p1, double p2) {
    return base.summary(X, p1, p2).transition_function;
  });
  ContinuationOptions co;
  co.p_min = 4.8;
  co.p_max = 5.2;
  co.direction = Direction::both;
  const EventCurveProblem a(base, passage, f.uz, 5.0), b(base, scalar, f.uz, 5.0);
  const Branch ca = continue_branch(a, a.start(), 5.0, co), cb = continue_branch(b, b.start(), 5.0, co);
  ASSERT_EQ(ca.status, ContinuationStatus::completed) << ca.message;
  ASSERT_EQ(cb.status, ContinuationStatus::completed) << cb.message;
  ASSERT_EQ(ca.points.size(), cb.points.size());
  ASSERT_GE(ca.points.size(), 5u);
  for (std::size_t k = 0; k < ca.points.size(); ++k) {
    // Both converged to 1e-12 on the same curve; the step sequences coincide as long as the Newton
    // iteration counts do.
    EXPECT_NEAR(ca.points[k].p, cb.points[k].p, 1e-9) << k;
    EXPECT_NEAR(ca.points[k].parameters[0], cb.points[k].parameters[0], 1e-9) << k;
  }
}

// ---- the swinging <-> tumbling curve from a scene (continue_curve, --curve UZ)

// Fig. 2's in-plane orbit continued in Delta at lambda = 5 (UZ at Delta = 0.38478), its transition
// continued in lambda over [2.5, 6].
SceneCurve lambda_curve() {
  return continue_curve(test::orbit_spec(), test::curve_of(CurveKind::UZ, P::lambda, 2.5, 6));
}

TEST(TransitionCurve, IsTheEventSystemWithOrbitMeasures) {
  const SceneCurve c = lambda_curve();
  ASSERT_TRUE(c.started) << c.message;
  EXPECT_EQ(c.system, CurveSystem::event);
  EXPECT_EQ(to_string(c.system), "event");
  EXPECT_EQ(to_string(c.spec.type), "UZ");
  EXPECT_EQ(c.start.name, "swing_tumble");
  EXPECT_NEAR(c.start.p, 0.38478125, 1e-6);
  EXPECT_EQ(c.start_p2, 5.0);
  EXPECT_EQ(c.curve.measure_names, (std::vector<std::string>{"r", "Psi", "t_passage"}));
  EXPECT_EQ(c.curve.branch.parameter_names, (std::vector<std::string>{"Delta", "lambda"}));
  ASSERT_EQ(c.curve.branch.status, ContinuationStatus::completed) << c.curve.branch.message;
  const auto& pts = c.curve.branch.points;
  ASSERT_GE(pts.size(), 10u);
  EXPECT_EQ(pts.front().p, 2.5);
  EXPECT_EQ(pts.back().p, 6.0);
  // The reduced system depends on (lambda, Delta) only through Lambda (S does not involve them): the
  // transition curve is the level set Lambda(lambda, Delta) = Lambda*, every point the same orbit.
  const auto Lambda_at = [&](std::size_t k) {
    return get_parameter(
        with_parameter(with_parameter(c.one.problem_scene, P::lambda, pts[k].p), P::Delta, pts[k].parameters[0]),
        P::Lambda);
  };
  for (std::size_t k = 0; k < pts.size(); ++k) {
    EXPECT_TRUE(pts[k].stable) << k;
    // Certified from the orbit's multipliers (the curve system's own Jacobian has none): margin ~0.95,
    // its error far below it (certified from the curve Jacobian instead, every point was uncertain, no bound).
    EXPECT_EQ(pts[k].stability, Stability::stable) << k << " " << to_string(pts[k].uncertain_because);
    EXPECT_GT(pts[k].margin, 0.5) << k;
    EXPECT_LT(pts[k].margin_error, 1e-6) << k;
    const double t = c.curve.number(k, "t_passage");
    EXPECT_TRUE(t > -kTwoPi && t < 2 * kTwoPi) << t;
    EXPECT_NEAR(Lambda_at(k), Lambda_at(0), 1e-11) << k;  // measured 1e-15
    EXPECT_NEAR(t, c.curve.number(0, "t_passage"), 1e-9) << k;
    EXPECT_NEAR(c.curve.number(k, "r"), c.curve.number(0, "r"), 1e-9) << k;
    if (k > 0) {
      EXPECT_LT(pts[k].parameters[0], pts[k - 1].parameters[0]);  // Delta*(lambda) decreasing
    }
  }
}

// Independent computation 1: at fixed lambda, the one-parameter branch in Delta from a fresh scene
// (its own relaxation and shooting start, 8 segments) with the UZ function transition_event (+-r_min),
// located by the engine's secant. Both are converged to 1e-12 and located to 1e-11: 1e-10 (measured
// 1e-14 .. 6e-14).
TEST(TransitionCurve, MatchesTheUZOfOneParameterBranchesAtFixedLambda) {
  const SceneCurve c = lambda_curve();
  ASSERT_TRUE(c.started) << c.message;
  const auto& pts = c.curve.branch.points;
  for (std::size_t k : {std::size_t{0}, pts.size() / 4, pts.size() / 2, pts.size() - 1}) {
    const double Delta_c = pts[k].parameters[0], lambda = pts[k].p;
    const double Delta_0 = Delta_c - 0.02;
    const Scene s = with_parameter(test::fig2_in_plane(Delta_0), P::lambda, lambda);
    const ReducedForcedSystem sys(s, P::Delta);
    const PeriodicOrbitProblem pr(sys);
    const NewtonResult st = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(200), Delta_0), Delta_0);
    ASSERT_TRUE(st.converged);
    ContinuationOptions o;
    o.direction = Direction::forward;
    o.p_max = Delta_c + 0.02;
    o.max_step = 0.01;
    o.events.push_back(pr.transition_event());
    const Branch b = continue_branch(pr, st.x, Delta_0, o);
    const SpecialPoint* uz = find_special_point(b, SpecialPointType::UZ);
    ASSERT_NE(uz, nullptr) << lambda;
    std::printf("lambda = %.10f: curve Delta = %.13f, one-parameter UZ %.13f, difference %.1e\n", lambda, Delta_c,
                uz->p, uz->p - Delta_c);
    EXPECT_NEAR(uz->p, Delta_c, 1e-10) << lambda;
    // The same orbit certified the same way: the same label, and margins (1 - max |mu| of the same
    // multipliers, from 4 and 8 shooting segments) within the sum of their errors plus the margin's change
    // over the 1e-10 between the two parameter values (|d margin / d Delta| = O(1)).
    const BranchPoint& q = pts[k];
    std::printf("  margins: curve %.12f +- %.1e, branch UZ %.12f +- %.1e\n", q.margin, q.margin_error, uz->margin,
                uz->margin_error);
    EXPECT_EQ(q.stability, uz->stability) << lambda;
    EXPECT_EQ(q.stability, Stability::stable) << lambda;
    EXPECT_NEAR(q.margin, uz->margin, q.margin_error + uz->margin_error + 1e-9) << lambda;
  }
}

// Independent computation 2: the winding number of z over one forcing period of a long direct
// simulation of the reduced model (model/, not continuation/), from the scene's shape: 0 swinging,
// 1 tumbling. The simulation runs 14 periods (the multipliers are 0.05, so the transient is < 1e-18)
// at rtol 1e-12; the winding is the sum of the angles between successive samples, 256 per period and
// 4000 across the two intervals around the closest approach. A sample pair is misread only when the
// chord between them passes on the other side of 0 than the orbit: the chord's distance from the
// orbit is ~ dt^2 |z''| / 8 ~ 1e-10 there, and r_min ~ 2 |Delta - Delta*|, so the classification is
// right to ~1e-10 in Delta. Bisection in Delta at the curve's lambda to a 1e-12 bracket: 1e-9
// (measured 3e-12 .. 1e-11).
int simulated_winding(double Delta, double lambda) {
  const Scene s = with_parameter(test::fig2_in_plane(Delta), P::lambda, lambda);
  const ReducedModel m(s.parameters, initial_state(s));
  IntegratorOptions io;
  io.rtol = 1e-12;
  io.atol = 1e-14;
  const double T0 = 14 * kTwoPi;
  const double end[1] = {T0};
  const IntegrationResult relaxed = integrate(m, m.initial_state(), 0.0, end, io, {});
  if (relaxed.status != IntegrationStatus::success) return -1;
  constexpr int kCoarse = 256, kFine = 4000;
  std::vector<double> grid;
  for (int k = 1; k <= kCoarse; ++k) grid.push_back(T0 + kTwoPi * k / kCoarse);
  std::vector<std::vector<double>> ys{relaxed.y};
  integrate(m, relaxed.y, T0, grid, io,
            [&](double, std::span<const double> y) { ys.emplace_back(y.begin(), y.end()); });
  if (ys.size() != kCoarse + 1) return -1;
  const auto angle = [](const std::vector<double>& a, const std::vector<double>& b) {
    return std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
  };
  // The closest sample k* (indices mod kCoarse: the state after a period is the state at its start).
  std::size_t kmin = 0;
  for (std::size_t k = 1; k < kCoarse; ++k)
    if (std::hypot(ys[k][0], ys[k][1]) < std::hypot(ys[kmin][0], ys[kmin][1])) kmin = k;
  const std::size_t before = (kmin + kCoarse - 1) % kCoarse;
  double total = 0;
  for (std::size_t k = 0; k < kCoarse; ++k)
    if (k != before && k != kmin) total += angle(ys[k], ys[k + 1]);
  // [t_{k*-1}, t_{k*+1}] finely.
  const double ta = T0 + kTwoPi * static_cast<double>(before) / kCoarse;
  std::vector<double> fine;
  for (int k = 1; k <= kFine; ++k) fine.push_back(ta + 2 * kTwoPi / kCoarse * k / kFine);
  std::vector<double> prev = ys[before];
  integrate(m, ys[before], ta, fine, io, [&](double, std::span<const double> y) {
    std::vector<double> cur(y.begin(), y.end());
    total += angle(prev, cur);
    prev = cur;
  });
  return static_cast<int>(std::lround(total / kTwoPi));
}

TEST(TransitionCurve, MatchesTheWindingOfLongSimulations) {
  const SceneCurve c = lambda_curve();
  ASSERT_TRUE(c.started) << c.message;
  const auto& pts = c.curve.branch.points;
  for (std::size_t k : {std::size_t{0}, pts.size() / 2, pts.size() - 1}) {
    const double Delta_c = pts[k].parameters[0], lambda = pts[k].p;
    double lo = Delta_c - 1e-4, hi = Delta_c + 1e-4;
    ASSERT_EQ(simulated_winding(lo, lambda), 0) << lambda;  // swinging below the curve
    ASSERT_EQ(simulated_winding(hi, lambda), 1) << lambda;  // tumbling above
    while (hi - lo > 1e-12) {
      const double mid = 0.5 * (lo + hi);
      (simulated_winding(mid, lambda) == 0 ? lo : hi) = mid;
    }
    std::printf("lambda = %.10f: curve Delta = %.13f, simulated winding changes at %.13f, difference %.1e\n", lambda,
                Delta_c, 0.5 * (lo + hi), 0.5 * (lo + hi) - Delta_c);
    EXPECT_NEAR(0.5 * (lo + hi), Delta_c, 1e-9) << lambda;
  }
}

// The transition curve in (Delta, beta) from the in-plane UZ meets Delta = 1 (a UZ event on the curve)
// at the beta where beta_test.cpp's one-parameter continuation in beta at Delta = 1 locates its UZ,
// 0.647737957609 (docs/continuation.md): two different paths, both located to 1e-11: 1e-9.
TEST(TransitionCurve, InBetaMeetsTheBetaContinuationsTransitionAtDeltaOne) {
  const Fig2Transition f = fig2_transition();
  const ReducedForcedSystem2 sys2(f.scene, P::Delta, P::beta);
  const OrbitTwoParameterProblem base(sys2, four_segments());
  const OrbitPassageEvent event(base);
  const EventCurveProblem curve(base, event, f.uz, M_PI / 2);
  ContinuationOptions co;
  co.direction = Direction::backward;
  co.p_min = 0.5;
  co.max_step = 0.1;
  co.events.push_back({"Delta_1", [&](const Eigen::VectorXd& X, double) { return X[base.dimension()] - 1.0; }});
  const Branch c = continue_branch(curve, curve.start(), M_PI / 2, co);
  const SpecialPoint* at1 = find_special_point(c, SpecialPointType::UZ);
  ASSERT_NE(at1, nullptr) << c.message;
  EXPECT_EQ(at1->status, LocationStatus::located);
  std::printf("transition curve at Delta = 1: beta = %.14f (beta continuation: 0.647737957609)\n", at1->p);
  EXPECT_NEAR(at1->p, 0.647737957609, 1e-9);
}

// The boundary Lambda*(S) itself (both composites: Lambda moved through Delta, S through C): the curve
// from the Lambda branch of Fig. 2's cell at Delta = 1 (UZ at Lambda* = 1.17408) in S over [1.9, 3],
// against the UZ of a one-parameter branch in Lambda at S = 3 (the curve's end, exact): 1e-10.
TEST(TransitionCurve, LambdaStarOfSMatchesTheUZOfABranchInLambdaAtFixedS) {
  BranchSpec spec = test::spec_of(test::fig2_in_plane(1.0), ProblemKind::orbit, P::Lambda, 1, 2, Direction::backward);
  spec.orbit.segments = 4;
  const SceneCurve c = continue_curve(spec, test::curve_of(CurveKind::UZ, P::S, 1.9, 3));
  ASSERT_TRUE(c.started) << c.message;
  EXPECT_NEAR(c.start.p, 1.174082827, 1e-8);
  const Branch& b = c.curve.branch;
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_EQ(b.parameter_names, (std::vector<std::string>{"Lambda", "S"}));
  ASSERT_EQ(b.points.back().p, 3.0);
  const double Lambda_c = b.points.back().parameters[0];
  BranchSpec at3 = spec;
  at3.scene = with_parameter(spec.scene, P::S, 3.0);
  at3.engine.max_step = 0.05;
  const SceneBranch one = continue_scene(at3);
  const SpecialPoint* uz = find_special_point(one.branch.branch, SpecialPointType::UZ);
  ASSERT_NE(uz, nullptr);
  std::printf("S = 3: curve Lambda* = %.13f, one-parameter UZ %.13f\n", Lambda_c, uz->p);
  EXPECT_NEAR(uz->p, Lambda_c, 1e-10);
  // Certified as the branch's UZ at the same parameters (see MatchesTheUZOfOneParameterBranchesAtFixedLambda).
  for (const BranchPoint& q : b.points) EXPECT_NE(q.stability, Stability::uncertain) << q.p;
  EXPECT_EQ(b.points.back().stability, uz->stability);
  EXPECT_NEAR(b.points.back().margin, uz->margin, b.points.back().margin_error + uz->margin_error + 1e-9);
}

TEST(TransitionCurve, NoUZOnTheBranchIsAReasonAndEquilibriaHaveNoEvents) {
  BranchSpec spec = test::orbit_spec();
  spec.engine.p_max = 0.35;  // swinging throughout
  const SceneCurve c = continue_curve(spec, test::curve_of(CurveKind::UZ, P::lambda, 4, 6));
  EXPECT_FALSE(c.started);
  EXPECT_NE(c.message.find("--curve UZ: no located UZ point number 1: the one-parameter branch has 0 UZ point(s)"),
            std::string::npos)
      << c.message;
  EXPECT_TRUE(c.curve.branch.points.empty());
  std::string m;
  EXPECT_EQ(invalid_parameter([&] { test::curve_of(CurveKind::UZ, P::B, 0, 1).validate(BranchSpec{}); }, &m), "curve");
  EXPECT_NE(m.find("curve = UZ is not available for --kind equilibrium: must be LP, BP or HB"), std::string::npos) << m;
  EXPECT_EQ(invalid_parameter([&] { test::curve_of(CurveKind::LP, P::B, 0, 1).validate(test::orbit_spec()); }, &m),
            "curve");
  EXPECT_NE(m.find("must be LPC, PD, NS, BP or UZ"), std::string::npos) << m;
  EXPECT_EQ(curve_kind_from_string("UZ"), CurveKind::UZ);
  EXPECT_EQ(special_point_type(CurveKind::UZ), SpecialPointType::UZ);
}

}  // namespace
}  // namespace rbcstab
