// The Z2-reduced BP curve of the in-plane ellipsoidal orbit (modal_orbit_bp_curve.hpp), against
//  - a 1-D bisection of sigma_bar(C) = sigma_3^c(B/C) with sigma_bar from a long direct simulation of
//    the reduced model (time average, no shooting, no quadrature state);
//  - the modal orbit's own Floquet multipliers (variational equations of ModalForcedSystem at L = 4):
//    the a_3 multiplier is 1 on the curve;
//  - the generic BP system (BranchPointCurveProblem over the modal shooting problem, L = 4);
//  - the in-plane asymptotic criterion of verdict/asymptotic (orbit_sigma_average: trapezoid of sigma_R on
//    ReducedModel::observe samples): mu_3 = Upsilon_3(<sigma_R>) = 0 on the curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "continuation/ellipsoidal_orbit_bp_fixture.hpp"
#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab {
namespace {

using test::curve_point;

// <sigma> on the reduced attractor by brute force: relax 150 forcing periods from the scene's own state,
// then average sigma over 20 periods by the trapezoid rule on 128 samples per period (spectrally accurate
// for a periodic integrand). Independent of the curve's shooting and quadrature.
double simulated_sigma_bar(const Scene& s) {
  const ReducedModel m(s.parameters, oriented_initial_state(s));
  const int relax = 150, periods = 20, per = 128;
  std::vector<double> grid;
  grid.push_back(relax * kTwoPi);
  for (int k = 1; k <= periods * per; ++k) grid.push_back(relax * kTwoPi + kTwoPi * k / per);
  IntegratorOptions o;
  o.stepper = Stepper::rk8pd;
  o.rtol = 1e-12;
  o.atol = 1e-13;
  double sum = 0;
  bool first = true;
  const IntegrationResult r = integrate(m, m.initial_state(), 0.0, grid, o, [&](double t, std::span<const double> y) {
    if (first) {  // the sample at the end of the relaxation equals the last one of the window (periodic)
      first = false;
      return;
    }
    sum += m.sigma_from_mu(m.mu(t, y));
  });
  EXPECT_EQ(r.status, IntegrationStatus::success);
  return sum / (periods * per);
}

// The root in C of simulated_sigma_bar - sigma_3^c(B/C) by bisection on [lo, hi].
double bisect_C(double lambda, double B, double lo, double hi) {
  auto h = [&](double C) { return simulated_sigma_bar(test::in_plane_modal(lambda, B, C, 4)) - sigma_c(3, B / C); };
  double hlo = h(lo);
  EXPECT_LT(hlo * h(hi), 0) << "no sign change in [" << lo << ", " << hi << "]";
  for (int i = 0; i < 45 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi), hm = h(mid);
    if (hm * hlo > 0) {
      lo = mid;
      hlo = hm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// Newton from a guess 20 % off lands on the bisection root of the brute-force average, and the curve
// continued in B over [1.5, 2.5] matches the bisection at its ends and middle. Tolerance 1e-8 relative
// in C: the time average is exact to ~1e-11 (rtol 1e-12, relaxation e^{-150 * 2 pi * decay} negligible:
// measured multipliers < 0.5), and dh/dC ~ 300 turns that into ~1e-13 in C; the curve's residual
// is 1e-12.
TEST(ModalOrbitBranchPointCurve, MatchesBisectionOfLongSimulationAverage) {
  const double lambda = 1;
  const Scene s = test::in_plane_modal(lambda, 2, 0.08, 4);
  const ModalOrbitBranchPointCurve curve(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  const NewtonResult n = curve_point(curve, s, 0.08, 2.0);
  ASSERT_TRUE(n.converged);
  const Eigen::Index k = curve.dimension() - 1;
  const double C_bisect = bisect_C(lambda, 2.0, 0.05, 0.1);
  std::printf("B = 2: curve C = %.15f, bisection C = %.15f (Newton %d iterations)\n", n.x[k], C_bisect, n.iterations);
  EXPECT_NEAR(n.x[k], C_bisect, 1e-8 * C_bisect);

  ContinuationOptions o;
  o.p_min = 1.5;
  o.p_max = 2.5;
  o.direction = Direction::both;
  o.initial_step = 0.05;
  o.max_step = 0.1;
  const Branch b = continue_branch(curve, n.x, 2.0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_GE(b.points.size(), 5u);
  EXPECT_NEAR(b.points.front().p, 1.5, 1e-12);
  EXPECT_NEAR(b.points.back().p, 2.5, 1e-12);
  for (const std::size_t i : {std::size_t{0}, b.points.size() / 2, b.points.size() - 1}) {
    const auto& pt = b.points[i];
    const double C = pt.parameters[0], B = pt.parameters[1];
    const double Cb = bisect_C(lambda, B, 0.8 * C, 1.25 * C);
    std::printf("B = %.6f: curve C = %.15f, bisection C = %.15f\n", B, C, Cb);
    EXPECT_NEAR(C, Cb, 1e-8 * Cb) << "B = " << B;
  }
  // Every point: the orbits are stable apart from the critical multiplier 1 (mode 3), which the engine
  // counts as neutral (|mu| - 1 < stability_tol).
  for (const auto& pt : b.points) EXPECT_EQ(pt.n_unstable, 0) << "B = " << pt.p;
}

// The modal orbit's Floquet multipliers (ModalForcedSystem variational equations, L = 4) at curve
// points: the orbit embedded with a_l = 0, v~ = 0 solves the modal shooting system, and its multipliers
// contain 1 (mode 3's) to 1e-8 (shooting at rtol 1e-12 over 8 segments; the tests of modal_orbit.hpp
// measure the decoupled multipliers to 1e-7 relative, ~1e-9 here).
TEST(ModalOrbitBranchPointCurve, ModalMultiplierOfModeLIsOneOnTheCurve) {
  for (double lambda : {1.0, 5.0}) {
    const Scene s = test::in_plane_modal(lambda, 2, 0.08, 4);
    const ModalOrbitBranchPointCurve curve(s, ContinuationParameter::C, ContinuationParameter::B, 3);
    for (double B : {1.6, 2.4}) {
      const NewtonResult n = curve_point(curve, s, lambda == 1 ? 0.05 * B : 0.048 * B, B);
      ASSERT_TRUE(n.converged) << "lambda " << lambda << " B " << B;
      const Eigen::Index k = curve.dimension() - 1;
      const double C = n.x[k];
      const Scene at = with_parameter(with_parameter(s, ContinuationParameter::B, B), ContinuationParameter::C, C);
      const ModalForcedSystem sys(at, ContinuationParameter::C);
      const PeriodicOrbitProblem mp(sys);
      const Eigen::Index nm = sys.dimension();
      Eigen::VectorXd Xm = Eigen::VectorXd::Zero(nm * mp.segments());
      for (int j = 0; j < mp.segments(); ++j) Xm.segment<3>(nm * j) = n.x.segment<3>(3 * j);
      Eigen::VectorXd F;
      mp.residual(Xm, C, F);
      EXPECT_LT(F.norm(), 1e-10) << "the embedded orbit solves the modal shooting system";
      const Floquet f = mp.floquet(Xm, C);
      double closest = 1e300;
      for (Eigen::Index i = 0; i < f.multipliers.size(); ++i)
        closest = std::min(closest, std::abs(f.multipliers[i] - 1.0));
      std::printf("lambda %g B %g C %.12f: closest modal multiplier to 1 at %.2e\n", lambda, B, C, closest);
      EXPECT_LT(closest, 1e-8);
      // The curve's own spectrum (closed-form decoupled multipliers) matches the modal Floquet set.
      const Eigen::VectorXcd mine = curve.spectrum(n.x, B);
      ASSERT_EQ(mine.size(), f.multipliers.size());
      for (Eigen::Index i = 0; i < mine.size(); ++i) {
        double d = 1e300;
        for (Eigen::Index j = 0; j < mine.size(); ++j) d = std::min(d, std::abs(mine[i] - f.multipliers[j]));
        EXPECT_LT(d, 1e-7 * std::max(1.0, std::abs(mine[i]))) << "multiplier " << mine[i];
      }
    }
  }
}

// The in-plane asymptotic criterion that sweep/trace traces (mu_3 = Upsilon_3(<sigma_R>), <sigma_R> the
// trapezoid average over the attracting orbit, orbit_sigma_average) vanishes on the curve: |<sigma_R> -
// sigma_3^c| < 1e-8 (both period means are accurate to ~1e-11 at rtol 1e-12), and asymptotic_verdict
// flips from stable to unstable (l = 3) across the curve (C * (1 +- 1e-4)).
TEST(ModalOrbitBranchPointCurve, IsTheInPlaneAsymptoticBoundaryOfTrace) {
  const double lambda = 5;
  const Scene s = test::in_plane_modal(lambda, 2, 0.1, 4);
  const ModalOrbitBranchPointCurve curve(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  for (double B : {1.5, 2.0, 3.0}) {
    const NewtonResult n = curve_point(curve, s, 0.05 * B, B);
    ASSERT_TRUE(n.converged) << "B " << B;
    const double C = n.x[curve.dimension() - 1];
    const Scene at = with_parameter(with_parameter(s, ContinuationParameter::B, B), ContinuationParameter::C, C);
    const OrbitSigmaAverage avg = orbit_sigma_average(at);
    ASSERT_TRUE(avg.ok) << avg.reason;
    std::printf("B %g: C %.12f, trace <sigma_R> - sigma_3^c = %.2e\n", B, C, avg.sigma_R - sigma_c(3, B / C));
    EXPECT_NEAR(avg.sigma_R, sigma_c(3, B / C), 1e-8);
    const AsymptoticVerdict above = asymptotic_verdict(with_parameter(at, ContinuationParameter::C, C * (1 + 1e-4)));
    const AsymptoticVerdict below = asymptotic_verdict(with_parameter(at, ContinuationParameter::C, C * (1 - 1e-4)));
    EXPECT_FALSE(above.unstable);
    EXPECT_TRUE(below.unstable);
    EXPECT_EQ(below.l, 3);
  }
}

// The generic BP system (BranchPointCurveProblem over the modal shooting problem, L = 4, 2 segments:
// 2 n + 2 = 30 unknowns, its own psi/mu unfolding) continues the same curve: the one-parameter modal
// orbit run in C from the embedded ellipsoidal orbit locates the a_3 -> -a_3 BP, the generic curve is
// continued a few steps in B, and at each of its points the reduced curve's Newton (8 segments) gives the
// same C to 1e-8 relative (both solve to residual 1e-12 with rtol 1e-12 shooting; measured ~1e-12).
TEST(ModalOrbitBranchPointCurve, MatchesGenericBranchPointSystemAtL4) {
  const double lambda = 1, C0 = 0.07, B0 = 2;
  const Scene s = test::in_plane_modal(lambda, B0, C0, 4);
  OrbitOptions oo;
  oo.segments = 2;
  const ModalForcedSystem2 sys2(s, ContinuationParameter::C, ContinuationParameter::B);
  const OrbitTwoParameterProblem base(sys2, oo);
  const ModalOrbitBranchPointCurve mine(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  const test::EllipsoidalOrbitBP located = test::locate_ellipsoidal_orbit_bp(sys2, s, 0.055, oo);
  ASSERT_TRUE(located.start_converged);
  ASSERT_TRUE(located.bp.has_value()) << "no located BP on the modal ellipsoidal orbit branch";
  const SpecialPoint* bp = &*located.bp;
  // The BP's state is the ellipsoidal orbit (a_3 = a_4 = 0, v~ = 0) and its mode is 3.
  EXPECT_LT(bp->x.segment(3, 4).norm(), 1e-10);
  const BranchPointCurveProblem generic(base, *bp, B0);
  ContinuationOptions oc;
  oc.p_min = 1.9;
  oc.p_max = 2.1;
  oc.direction = Direction::both;
  oc.initial_step = 0.05;
  oc.max_step = 0.05;
  oc.max_points = 4;
  const Branch g = continue_branch(generic, generic.start(), B0, oc);
  ASSERT_GE(g.points.size(), 5u);
  int compared = 0;
  for (const auto& pt : g.points) {
    const double C = pt.parameters[0], B = pt.parameters[1];
    const NewtonResult n = curve_point(mine, s, C, B);
    ASSERT_TRUE(n.converged);
    const double Cm = n.x[mine.dimension() - 1];
    EXPECT_NEAR(Cm, C, 1e-8 * C) << "B = " << B;
    ++compared;
  }
  EXPECT_GE(compared, 5);
  // The critical mode read from sigma_bar at the BP (the CLI's choice): 3.
  const Eigen::Index n = mine.dimension() - 1;
  const NewtonResult n0 = curve_point(mine, s, bp->p, B0);
  ASSERT_TRUE(n0.converged);
  EXPECT_EQ(ellipsoidal_orbit_critical_mode(mine.parameters(bp->p, B0), 4, mine.sigma_bar(n0.x.head(n), bp->p, B0)), 3);
}

// sweep/trace's traced in-plane asymptotic boundary (trace_boundary, the whole pipeline: starts, arclength
// tracing of mu_l = 0 on the (ln B, ln C) plane) lies on the curve where l = 3 is the active mode: at each
// traced point's B the curve's C equals the traced one to 1e-8 in ln C (trace solves its criterion to
// 1e-10 in Upsilon_3, |dUpsilon_3/d ln C| ~ 10 here, so ~1e-11; the curve's residual is 1e-12).
TEST(ModalOrbitBranchPointCurve, ContainsTheTracedInPlaneBoundary) {
  const Scene s = test::in_plane_modal(5, 2, 0.1, 4);
  DiagramSpec plane;
  plane.x = {Axis::lnB, std::log(1.5), std::log(3.0), 3};
  plane.y = {Axis::lnC, std::log(0.05), std::log(0.2), 3};
  TraceOptions o;
  o.lines = 0;
  o.samples = 8;
  o.bisections = 30;
  o.max_step = 0.2;
  const TraceResult t = trace_boundary(s, plane, o);
  ASSERT_FALSE(t.curves.empty()) << (t.notes.empty() ? "" : t.notes.front());
  const ModalOrbitBranchPointCurve curve(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  int compared = 0;
  double worst = 0;
  for (const TraceCurve& c : t.curves) {
    if (c.l != 3) continue;
    for (const TracePoint& p : c.points) {
      const double B = std::exp(p.x);
      const NewtonResult n = curve_point(curve, s, std::exp(p.y), B);
      ASSERT_TRUE(n.converged) << "B " << B;
      const double lnC = std::log(n.x[curve.dimension() - 1]);
      EXPECT_NEAR(lnC, p.y, 1e-8) << "B = " << B;
      worst = std::max(worst, std::abs(lnC - p.y));
      ++compared;
    }
  }
  std::printf("compared %d traced points (%zu evaluations, %.2f s): max |ln C - traced| = %.2e\n", compared,
              t.evaluations, t.seconds, worst);
  EXPECT_GE(compared, 3);
}

// Bad input names the parameter.
TEST(ModalOrbitBranchPointCurve, RejectsCoupledPairsModesAndTiltedRestShapes) {
  const Scene s = test::in_plane_modal(1, 2, 0.08, 4);
  EXPECT_THROW(ModalOrbitBranchPointCurve(s, ContinuationParameter::C, ContinuationParameter::S, 3), InvalidArgument);
  EXPECT_THROW(ModalOrbitBranchPointCurve(s, ContinuationParameter::C, ContinuationParameter::B, 5), InvalidArgument);
  EXPECT_THROW(ModalOrbitBranchPointCurve(s, ContinuationParameter::C, ContinuationParameter::B, 2), InvalidArgument);
  Scene tilted = s;
  tilted.beta = 1.0;
  EXPECT_THROW(ModalOrbitBranchPointCurve(tilted, ContinuationParameter::C, ContinuationParameter::B, 3),
               InvalidArgument);
  EXPECT_THROW(ModalOrbitBranchPointCurve(s, ContinuationParameter::C, ContinuationParameter::beta, 3),
               InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
