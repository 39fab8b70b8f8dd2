// Full-model equilibria (continuation/full_equilibrium.hpp): the coordinates and the area identity,
// the analytic Jacobian, the ellipsoidal branch against the modal level and the closed form, a
// stress-free shape with l = 3 content against a closed form derived here (below), a long full-model
// simulation, the branch point of the unforced l = 4 and the rejection of rotating forcings.
//
// The closed form is derived in continuation/full_fixtures.hpp (and docs/theory.md).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "continuation/full_fixtures.hpp"
#include "continuation/full_model_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

using full_fixtures::closed_form;
using full_fixtures::ClosedForm;
using full_fixtures::drive;
using full_fixtures::forced_scene;
using full_fixtures::state_error;
using cd = std::complex<double>;

TEST(FullEquilibrium, CoordinatesAreRealShapesAndAreaIsTheSphere) {
  const Scene s = forced_scene(0.03, 5, 1e-3);
  const FullEquilibriumProblem pr(s, ContinuationParameter::C);
  EXPECT_EQ(pr.dimension(), 32);  // (L+1)^2 - 4
  const double p = s.parameters.C;
  std::mt19937 rng(11);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd x(pr.dimension());
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = N01(rng);
    x *= (0.5 + 0.2 * trial) / x.norm();  // on and off the sphere
    const std::vector<double> y = pr.to_full_state(x, p);
    const FullModel& m = pr.model(p);
    const ModeAmplitudes f = m.amplitudes(0, y);
    // Reality: f_{l,-m} = (-1)^m conj f_{l,m}, Im f_{l,0} = 0 (exact by construction).
    for (int l = 2; l <= s.L; ++l)
      for (int mm = 0; mm <= l; ++mm) EXPECT_EQ(f.at(l, -mm), (mm % 2 ? -1.0 : 1.0) * std::conj(f.at(l, mm)));
    // |x|^2 Delta is the total excess area (Eq. excess_f); round trip.
    EXPECT_NEAR(x.squaredNorm() * s.parameters.Delta, f.total_excess_area(), 1e-14);
    EXPECT_LT((pr.from_full_state(y, p) - x).lpNorm<Eigen::Infinity>(), 1e-15);
    // Area conservation x.F = 0 (the identity G = F + (|x|^2 - 1) x relies on), relative to |x||F|.
    Eigen::VectorXd F;
    pr.dynamics(x, p, F);
    EXPECT_LT(std::abs(x.dot(F)), 1e-13 * x.norm() * F.norm());
    EXPECT_GT(F.norm(), 1e-3);  // not vacuous
    // F is FullModel's rhs on the real shape (that rhs keeps real shapes real).
    std::vector<double> dydt(y.size());
    m.rhs(0, y, dydt);
    EXPECT_LT((pr.from_full_state(dydt, p) - F).lpNorm<Eigen::Infinity>(), 1e-13 * (1 + F.lpNorm<Eigen::Infinity>()));
    const ModeAmplitudes df = m.amplitudes(0, dydt);
    for (int l = 2; l <= s.L; ++l)
      for (int mm = 0; mm <= l; ++mm)
        EXPECT_LT(std::abs(df.at(l, -mm) - (mm % 2 ? -1.0 : 1.0) * std::conj(df.at(l, mm))),
                  1e-12 * (1 + std::abs(df.at(l, mm))));
  }
}

TEST(FullEquilibrium, AnalyticJacobianMatchesDifferences) {
  const Scene s = forced_scene(0.03, 4, 1e-3);
  const FullEquilibriumProblem pr(s, ContinuationParameter::lambda);
  std::mt19937 rng(5);
  std::normal_distribution<double> N01;
  Eigen::VectorXd x(pr.dimension());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = N01(rng);
  x *= 0.9 / x.norm();
  Eigen::MatrixXd Ja, Jd;
  pr.jacobian(x, 1.3, Ja);
  pr.ContinuationProblem::jacobian(x, 1.3, Jd);
  // Central differences with h ~ eps^(1/3): error ~ 1e-10 |J| (|J| ~ |Upsilon_4| ~ 10 here).
  EXPECT_LT((Ja - Jd).lpNorm<Eigen::Infinity>(), 1e-7 * (1 + Ja.lpNorm<Eigen::Infinity>()));
}

TEST(FullEquilibrium, EllipsoidalBranchEqualsModalLevelAndClosedForm) {
  const Scene s = forced_scene(0.08, 4, 0.0);
  const FullEquilibriumProblem pr(s, ContinuationParameter::lambda);
  const ModalEquilibriumProblem modal(s, ContinuationParameter::lambda);
  ContinuationOptions o;
  o.p_min = 0;
  o.p_max = 20;
  o.direction = Direction::both;
  const Branch b = continue_branch(pr, pr.ellipsoidal_state(1.0), 1.0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_DOUBLE_EQ(b.points.front().p, 0);
  EXPECT_DOUBLE_EQ(b.points.back().p, 20);
  ASSERT_GE(b.points.size(), 10u);
  for (const BranchPoint& pt : b.points) {
    // The closed form (analysis/steady_states) to 1e-10, the required accuracy (Newton stops at 1e-12).
    EXPECT_LT((pt.x - pr.ellipsoidal_state(pt.p)).lpNorm<Eigen::Infinity>(), 1e-10) << "lambda = " << pt.p;
    // The modal level's Newton solution: x_{2,2} = z, x_{2,0} = -w, x_{2,1} = v, l >= 3 zero.
    const NewtonResult nr = solve_fixed_parameter(modal, modal.ellipsoidal_state(pt.p), pt.p);
    ASSERT_TRUE(nr.converged);
    const Eigen::Index i22 = FullEquilibriumProblem::index(2, 2), i21 = FullEquilibriumProblem::index(2, 1);
    EXPECT_NEAR(pt.x[i22], nr.x[0], 1e-10);
    EXPECT_NEAR(pt.x[i22 + 1], nr.x[1], 1e-10);
    EXPECT_NEAR(pt.x[0], -nr.x[2], 1e-10);
    EXPECT_NEAR(pt.x[i21], nr.x[3], 1e-10);
    EXPECT_NEAR(pt.x[i21 + 1], nr.x[4], 1e-10);
    EXPECT_EQ(pt.x.tail(pt.x.size() - 5).lpNorm<Eigen::Infinity>(), 0.0);  // invariant under Newton
    const FullEquilibriumState st = pr.observe(pt.x, pt.p);
    const ModalState ms = modal.observe(nr.x, pt.p);
    EXPECT_NEAR(st.sigma, ms.sigma, 1e-9 * (1 + std::abs(ms.sigma)));
    EXPECT_NEAR(st.r, ms.r, 1e-10);
    // Spectrum: the modal one (reduced pair, Upsilon_2 +- i/2, Upsilon_l for the a_l = m = 0 directions)
    // plus Upsilon_l(sigma) +- i m/2 for l >= 3, m = 1..l; 1e-9 relative (dense QR, |J| ~ 10).
    const Parameters q = with_parameter(s.parameters, ContinuationParameter::lambda, pt.p);
    const Eigen::VectorXcd ms_spec = modal.spectrum(nr.x, pt.p);
    std::vector<cd> want(ms_spec.data(), ms_spec.data() + ms_spec.size());
    for (int l = 3; l <= s.L; ++l)
      for (int m = 1; m <= l; ++m) {
        want.emplace_back(Upsilon_l(q, l, ms.sigma), 0.5 * m);
        want.emplace_back(Upsilon_l(q, l, ms.sigma), -0.5 * m);
      }
    const std::vector<cd> got(pt.spectrum.data(), pt.spectrum.data() + pt.spectrum.size());
    ASSERT_EQ(got.size(), want.size());
    EXPECT_LT(test::multiset_distance(got, want), 1e-9) << "lambda = " << pt.p;
  }
}

// The branch in C from 0.08 down to 0.012 with a stress-free l = 3 content (L = 5).
struct ForcedRun {
  Scene s;
  FullEquilibriumProblem pr;
  Eigen::VectorXd x0;
  Branch branch;
  explicit ForcedRun(double rest3 = 1e-3, int L = 5, double C_min = 0.012)
      : s(forced_scene(0.08, L, rest3)), pr(s, ContinuationParameter::C) {
    const NewtonResult nr = solve_fixed_parameter(pr, pr.ellipsoidal_state(0.08), 0.08);
    x0 = nr.x;
    ContinuationOptions o;
    o.p_min = C_min;
    o.p_max = 0.08;
    o.max_step = 0.05;
    o.direction = Direction::backward;
    if (nr.converged) branch = continue_branch(pr, x0, 0.08, o);
  }
};

TEST(FullEquilibrium, ForcedBranchEqualsClosedForm) {
  const ForcedRun run;
  ASSERT_TRUE(run.x0.size() > 0);
  ASSERT_EQ(run.branch.status, ContinuationStatus::completed) << run.branch.message;
  EXPECT_DOUBLE_EQ(run.branch.points.front().p, 0.08);  // backward from the start
  EXPECT_DOUBLE_EQ(run.branch.points.back().p, 0.012);
  ASSERT_GE(run.branch.points.size(), 20u);
  double worst = 0;
  for (const BranchPoint& pt : run.branch.points) {
    const Parameters q = with_parameter(run.s.parameters, ContinuationParameter::C, pt.p);
    const ClosedForm c = closed_form(run.s, q);
    const FullEquilibriumState st = run.pr.observe(pt.x, pt.p);
    // 1e-10, the required accuracy: Newton stops at |dX| <= 1e-12 (1e-12 (1 + |x|)), and the closed form's
    // bisection is exact to the last bit of sigma; |f| <= 1.
    const double e = state_error(run.pr, pt.x, pt.p, c);
    worst = std::max(worst, e);
    EXPECT_LT(e, 1e-10) << "C = " << pt.p;
    EXPECT_NEAR(st.sigma, c.sigma, 1e-10 * std::abs(c.sigma)) << "C = " << pt.p;
    for (std::size_t k = 0; k < c.Delta_l.size(); ++k) EXPECT_NEAR(st.Delta_l[k], c.Delta_l[k], 1e-10);
    // The unforced modes hold nothing (invariant subspace of Newton), the forced l = 3 does.
    EXPECT_EQ(st.Delta_l[2], 0.0);
    EXPECT_EQ(st.Delta_l[3], 0.0);
    EXPECT_GT(st.Delta_l[1], 5e-4);
  }
  std::printf("forced branch: %zu points, max |f - closed form| = %.2e\n", run.branch.points.size(), worst);
  // The forcing unfolds the l = 3 pitchfork of the modal branch (C = 0.0362 there): no special point
  // before the unforced l = 4 crossing near C = 0.0153; Delta_3 grows smoothly to 0.92 instead.
  for (const auto& sp : run.branch.special_points) EXPECT_LT(sp.p, 0.016) << to_string(sp.type);
  EXPECT_GT(run.pr.observe(run.branch.points.back().x, 0.012).Delta_l[1], 0.9);
}

// C where the closed-form sigma(C) reaches sigma_4^c(B/C): the unforced l = 4 becomes neutral.
double l4_threshold(const Scene& s, double lo, double hi) {
  auto margin = [&](double C) {
    const Parameters q = with_parameter(s.parameters, ContinuationParameter::C, C);
    return closed_form(s, q).sigma - sigma_c(4, q.alpha());
  };
  const double mlo = margin(lo);
  EXPECT_LT(mlo * margin(hi), 0);
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((margin(mid) > 0) == (mlo > 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(FullEquilibrium, ForcedBranchesInEveryParameterEqualClosedForm) {
  // The same closed form along branches in the other parameters (the composites Lambda, S move Delta,
  // C underneath), each from the stable state at C = 0.03 (Delta_3 = 0.55), both directions, L = 4.
  struct Case {
    ContinuationParameter q;
    double lo, hi;
  };
  const Case cases[] = {{ContinuationParameter::lambda, 0.2, 5},     {ContinuationParameter::Delta, 0.5, 2},
                        {ContinuationParameter::Delta0, 1e-3, 0.05}, {ContinuationParameter::B, 0.7, 1.5},
                        {ContinuationParameter::Lambda, 0.3, 1.5},   {ContinuationParameter::S, 0.5, 2}};
  const ForcedRun at_C(1e-3, 4, 0.03);
  ASSERT_EQ(at_C.branch.status, ContinuationStatus::completed) << at_C.branch.message;
  const Eigen::VectorXd x0 = at_C.branch.points.back().x;
  for (const Case& c : cases) {
    const Scene s = forced_scene(0.03, 4, 1e-3);
    const FullEquilibriumProblem pr(s, c.q);
    const double p0 = pr.start_parameter();
    ASSERT_GT(p0, c.lo);
    ASSERT_LT(p0, c.hi);
    ContinuationOptions o;
    o.p_min = c.lo;
    o.p_max = c.hi;
    o.direction = Direction::both;
    o.detect_bifurcations = false;
    const Branch b = continue_branch(pr, x0, p0, o);
    // Ends on a bound, or (outside_domain) where a scene validation refuses the parameter.
    EXPECT_TRUE(b.status == ContinuationStatus::completed) << to_string(c.q) << ": " << b.message;
    EXPECT_GE(b.points.size(), 5u) << to_string(c.q);
    for (const BranchPoint& pt : b.points) {
      const Parameters q = with_parameter(s.parameters, c.q, pt.p);
      EXPECT_LT(state_error(pr, pt.x, pt.p, closed_form(s, q)), 1e-10) << to_string(c.q) << " = " << pt.p;
    }
  }
}

TEST(FullEquilibrium, UnforcedModeCrossingIsLocatedAsBranchPointWithCoincidentHopfPairs) {
  const ForcedRun run;
  ASSERT_EQ(run.branch.status, ContinuationStatus::completed) << run.branch.message;
  const SpecialPoint* bp = find_special_point(run.branch, SpecialPointType::BP);
  const SpecialPoint* hb = find_special_point(run.branch, SpecialPointType::HB);
  ASSERT_NE(bp, nullptr);
  ASSERT_NE(hb, nullptr);
  const double C4 = l4_threshold(run.s, 0.014, 0.017);
  // Located to 1e-8 against the nested closed-form root (the engine's bracket is < 1e-11).
  EXPECT_EQ(bp->status, LocationStatus::located);
  EXPECT_NEAR(bp->p, C4, 1e-8);
  const FullEquilibriumState st = run.pr.observe(bp->x, bp->p);
  const Parameters q = with_parameter(run.s.parameters, ContinuationParameter::C, bp->p);
  EXPECT_NEAR(Upsilon_l(q, 4, st.sigma), 0.0, 1e-8);
  // Coincident crossings: at Upsilon_4 = 0 the m = 0 real eigenvalue (the Z2 pitchfork f_{4,0} -> -f_{4,0})
  // and the four pairs Upsilon_4 +- i m/2 (m = 1..4, rotating l = 4 waves) cross together. det[J F_p; t^T]
  // changes sign once (BP); the Hopf product changes sign four times (no net change), so the engine
  // bisects for the unexplained change of the unstable count 0 -> 9 (= 1 + 2 * 4) to a bracket below
  // location_tol, reads from its ends' spectra what crossed and reports each at the BP (where the pairs' real
  // parts equal the BP's eigenvalue): the BP carries the real eigenvalue (0 -> 1), one HB per pair omega = m/2,
  // m = 1..4, carries 2 (1 -> 3 -> 5 -> 7 -> 9). Before: the BP carried 0 -> 0 and one HB the whole 0 -> 9.
  EXPECT_EQ(bp->unstable_before, 0);
  EXPECT_EQ(bp->unstable_after, 1);
  int count = 1, pairs = 0;
  for (const SpecialPoint& h : run.branch.special_points) {
    if (h.type != SpecialPointType::HB) continue;
    ++pairs;
    EXPECT_EQ(h.status, LocationStatus::located);
    EXPECT_EQ(h.p, bp->p);
    EXPECT_EQ(h.unstable_before, count);
    EXPECT_EQ(h.unstable_after, count += 2);
    EXPECT_NEAR(h.eigenvalue.imag(), 0.5 * pairs, 1e-9);
  }
  EXPECT_EQ(pairs, 4);
  EXPECT_EQ(run.branch.special_points.size(), 5u);
  // The crossing spectrum itself: at the BP, 9 eigenvalues on the imaginary axis (|Re| < 1e-7, the
  // location bracket times |dUpsilon_4/dC|), at 0 and +- i m/2, m = 1..4.
  const Eigen::VectorXcd ev = run.pr.spectrum(bp->x, bp->p);
  std::vector<cd> neutral;
  for (Eigen::Index i = 0; i < ev.size(); ++i)
    if (std::abs(ev[i].real()) < 1e-7) neutral.push_back(ev[i]);
  ASSERT_EQ(neutral.size(), 9u);
  std::vector<cd> want = {cd(0, 0)};
  for (int m = 1; m <= 4; ++m) want.insert(want.end(), {cd(0, 0.5 * m), cd(0, -0.5 * m)});
  EXPECT_LT(test::multiset_distance(neutral, want), 1e-7);
  // Why the problem uses independent real-shape coordinates: FullModel's stored state (both halves of
  // every m) also carries i times a real shape, a copy of the same linear spectrum, so there the m = 0
  // eigenvalue Upsilon_4 = 0 is double (Re and Im f_{4,0}), besides the area direction's trivial 0.
  {
    const std::vector<double> y = run.pr.to_full_state(bp->x, bp->p);
    StructuredJacobian J;
    std::vector<double> dfdt(y.size());
    run.pr.model(bp->p).jacobian(0, y, J, dfdt);
    const Eigen::VectorXcd all = Eigen::EigenSolver<Eigen::MatrixXd>(test::dense(J), false).eigenvalues();
    int zeros = 0, zeros_here = 0;
    for (Eigen::Index i = 0; i < all.size(); ++i) zeros += std::abs(all[i]) < 1e-7 ? 1 : 0;
    for (Eigen::Index i = 0; i < ev.size(); ++i) zeros_here += std::abs(ev[i]) < 1e-7 ? 1 : 0;
    EXPECT_EQ(zeros, 3);
    EXPECT_EQ(zeros_here, 1);
  }
  const double omega = std::abs(hb->eigenvalue.imag());
  std::printf("l = 4 crossing: BP C = %.12f (%s, %d -> %d, vs closed form %.1e), HB C = %.12f (omega %.6f, %d -> %d)\n",
              bp->p, to_string(bp->status).c_str(), bp->unstable_before, bp->unstable_after, std::abs(bp->p - C4),
              hb->p, omega, hb->unstable_before, hb->unstable_after);
}

TEST(FullEquilibrium, BranchSwitchAtTheL4CrossingHasSigmaPinnedAtItsCriticalValue) {
  // On the branch born at the l = 4 pitchfork f_{4,0} != 0 is unforced, so f_{4,0}' = Upsilon_4 f_{4,0}
  // = 0 pins sigma = sigma_4^c(B/C); every other mode is f = -S/(i m/2 + Upsilon_l(sigma_4^c)) (the
  // closed form above at that sigma) and Delta_4 = Delta minus their area. Tolerance 1e-10 as above.
  const ForcedRun run;
  const SpecialPoint* bp = find_special_point(run.branch, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  BranchSwitchOptions o;
  o.continuation.p_min = 0.012;
  o.continuation.p_max = 0.08;
  o.continuation.max_step = 0.05;
  const BranchSwitchResult sw = switch_branch(run.pr, run.branch, *bp, o);
  ASSERT_TRUE(sw.switched) << sw.message;
  EXPECT_LT(sw.singular_values[1], 1e-7 * sw.singular_values[2]);  // a 2-D kernel: one real crossing
  ASSERT_EQ(sw.branch.status, ContinuationStatus::completed) << sw.branch.message;
  ASSERT_GE(sw.branch.points.size(), 5u);
  EXPECT_DOUBLE_EQ(sw.branch.points.back().p, 0.012);
  for (const BranchPoint& pt : sw.branch.points) {
    const Parameters q = with_parameter(run.s.parameters, ContinuationParameter::C, pt.p);
    const double sigma4 = sigma_c(4, q.alpha());
    const FullEquilibriumState st = run.pr.observe(pt.x, pt.p);
    EXPECT_NEAR(st.sigma, sigma4, 1e-10 * std::abs(sigma4)) << "C = " << pt.p;
    double rest = 0;
    for (int l = 2; l <= run.s.L; ++l) {
      if (l == 4) continue;
      double Dl = 0;
      for (int m = -l; m <= l; ++m)
        Dl += a_l(l) * std::norm(drive(run.s, q, l, m)) / (0.25 * m * m + std::pow(Upsilon_l(q, l, sigma4), 2));
      EXPECT_NEAR(st.Delta_l[static_cast<std::size_t>(l - 2)], Dl, 1e-10) << "C = " << pt.p << ", l = " << l;
      rest += Dl;
    }
    EXPECT_NEAR(st.Delta_l[2], q.Delta - rest, 1e-10) << "C = " << pt.p;
    for (int m = 1; m <= 4; ++m) EXPECT_EQ(pt.x.segment(FullEquilibriumProblem::index(4, m), 2).norm(), 0.0);
  }
  EXPECT_GT(run.pr.observe(sw.branch.points.back().x, 0.012).Delta_l[2], 0.05);  // l = 4 takes area
}

TEST(FullEquilibrium, L4CrossingContinuedInTwoParametersByTheGenericBranchPointCurve) {
  // The l = 4 BP persists in (C, B) (the Z2 symmetry f_{4,0} -> -f_{4,0} of the unforced mode), so the
  // generic BP-curve system (branch_point_curve.hpp) over the full problem continues it. Oracle at
  // every curve point: the closed form's sigma(C, B) equals sigma_4^c(B/C) (1e-9 relative: the curve's
  // Newton tolerance 1e-12 on C times d(sigma - sigma_4^c)/dC ~ 1e3), mu = 0 and the state is the
  // closed form (1e-9).
  const ForcedRun run;
  const SpecialPoint* bp = find_special_point(run.branch, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  Scene scene = run.s;
  scene.parameters.C = bp->p;
  const SceneTwoParameterProblem<FullEquilibriumProblem> base(scene, ContinuationParameter::C,
                                                              ContinuationParameter::B);
  const BranchPointCurveProblem curve(base, *bp, 1.0);
  ContinuationOptions o;
  o.p_min = 0.8;
  o.p_max = 1.25;
  o.direction = Direction::both;
  o.max_step = 0.05;
  o.detect_bifurcations = false;
  const Branch c = continue_branch(curve, curve.start(), 1.0, o);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_DOUBLE_EQ(c.points.front().p, 0.8);
  EXPECT_DOUBLE_EQ(c.points.back().p, 1.25);
  ASSERT_GE(c.points.size(), 5u);
  const Eigen::Index n = base.dimension();
  double worst_sigma = 0;
  for (const BranchPoint& pt : c.points) {
    const double C = pt.parameters[0], B = pt.p;
    Scene sB = run.s;
    sB.parameters.B = B;
    const Parameters q = with_parameter(sB.parameters, ContinuationParameter::C, C);
    const ClosedForm cf = closed_form(sB, q);
    EXPECT_NEAR(cf.sigma, sigma_c(4, q.alpha()), 1e-9 * std::abs(cf.sigma)) << "B = " << B;
    worst_sigma = std::max(worst_sigma, std::abs(cf.sigma - sigma_c(4, q.alpha())) / std::abs(cf.sigma));
    EXPECT_LT(std::abs(curve.mu(pt.x)), 1e-10);
    EXPECT_LT(state_error(base.at(B), pt.x.head(n), C, cf), 1e-9) << "B = " << B;
  }
  std::printf("l = 4 BP curve in (C, B): %zu points, C from %.6f to %.6f, max relative |sigma - sigma_4^c| %.1e\n",
              c.points.size(), c.points.front().parameters[0], c.points.back().parameters[0], worst_sigma);
}

TEST(FullEquilibrium, LongFullSimulationRelaxesOntoTheForcedEquilibrium) {
  // C = 0.03: Delta_3 = 0.55 (far from the ellipsoid), stable (l = 4 crosses only at C = 0.0153).
  const double C = 0.03;
  Scene sim_scene = forced_scene(C, 4, 1e-3);
  sim_scene.model = ModelLevel::full;
  sim_scene.T = 400;
  sim_scene.dt = 100;
  SimulationOptions so;
  so.integrator.rtol = 1e-11;
  so.integrator.atol = 1e-14;
  so.record_trajectory = false;
  const SimulationResult sim = simulate(sim_scene, so);
  ASSERT_EQ(sim.status, IntegrationStatus::success) << sim.reason;
  ASSERT_EQ(sim.level.level, ModelLevel::full);
  // delta = 0: the run's area is Delta exactly, so the problem's sphere is the run's.
  ASSERT_NEAR(sim.Delta_total_initial, sim_scene.parameters.Delta, 1e-14);
  // The equilibrium continued from the stable ellipsoid at C = 0.08 (Newton straight from the
  // ellipsoid at C = 0.03 lands on an unstable member of the unfolded pitchfork instead).
  const ForcedRun run(1e-3, 4, C);
  ASSERT_EQ(run.branch.status, ContinuationStatus::completed) << run.branch.message;
  const FullEquilibriumProblem& pr = run.pr;
  NewtonResult nr;
  nr.x = run.branch.points.back().x;
  ASSERT_DOUBLE_EQ(run.branch.points.back().p, C);
  const FullEquilibriumState st = pr.observe(nr.x, C);
  // Tolerance: the slowest transient decays like exp(max Re lambda t); require it to be below e^-30
  // at T, so the remaining distance is set by the integrator (rtol 1e-11) -> bar 1e-8.
  const Eigen::VectorXcd ev = pr.spectrum(nr.x, C);
  const double slowest = ev.real().maxCoeff();
  ASSERT_LT(slowest, -30.0 / sim_scene.T);
  for (std::size_t k = 0; k < st.Delta_l.size(); ++k)
    EXPECT_NEAR(sim.Delta_final[k], st.Delta_l[k], 1e-8) << "l = " << k + 2;
  EXPECT_NEAR(sim.sigma_final, st.sigma, 1e-8 * std::abs(st.sigma));
  EXPECT_NEAR(sim.r_final, st.r, 1e-8);
  EXPECT_GT(st.Delta_l[1], 0.5);
  // relaxed_state() is the same path inside the problem: Newton from it lands on the same state.
  const FullEquilibriumProblem pr_C(sim_scene, ContinuationParameter::C);
  const NewtonResult nr2 = solve_fixed_parameter(pr_C, pr_C.relaxed_state(400), C);
  ASSERT_TRUE(nr2.converged);
  EXPECT_LT((nr2.x - nr.x).lpNorm<Eigen::Infinity>(), 1e-10);
  std::printf("simulation vs equilibrium: dDelta_3 = %.2e, dsigma = %.2e, slowest eigenvalue %.4f\n",
              std::abs(sim.Delta_final[1] - st.Delta_l[1]), std::abs(sim.sigma_final - st.sigma), slowest);
}

TEST(FullEquilibrium, BlockSpectrumEqualsDenseTangentSpectrum) {
  // spectrum() solves only the blocks that hold x densely; the dense tangent-plane spectrum of the
  // whole DF is the oracle (1e-9 relative: dense QR error ~ eps |DF|, |DF| ~ |Upsilon_6| ~ 50).
  const ForcedRun run(1e-3, 6, 0.02);
  ASSERT_EQ(run.branch.status, ContinuationStatus::completed) << run.branch.message;
  std::mt19937 rng(3);
  std::normal_distribution<double> N01;
  std::vector<Eigen::VectorXd> states = {run.branch.points.front().x, run.branch.points.back().x};
  Eigen::VectorXd random(run.pr.dimension());
  for (Eigen::Index i = 0; i < random.size(); ++i) random[i] = N01(rng);
  states.push_back(random / random.norm());  // every block active: the dense path alone
  for (const Eigen::VectorXd& x : states) {
    Eigen::MatrixXd DF;
    run.pr.dynamics_jacobian(x, 0.03, DF);
    const Eigen::VectorXcd dense = detail::tangent_spectrum(DF, x), blocks = run.pr.spectrum(x, 0.03);
    ASSERT_EQ(blocks.size(), run.pr.dimension() - 1);
    EXPECT_LT(test::multiset_distance(std::vector<cd>(blocks.data(), blocks.data() + blocks.size()),
                                      std::vector<cd>(dense.data(), dense.data() + dense.size())),
              1e-9);
  }
}

TEST(FullEquilibrium, AtTheLargestLTheBranchStillEqualsClosedForm) {
  // L = max_L (n = 285): a few points from C = 0.08 against the closed form (1e-10) and the spectrum's
  // inactive blocks (every l >= 4) against Upsilon_l +- i m/2.
  const Scene s = forced_scene(0.08, FullEquilibriumProblem::max_L, 1e-3);
  const FullEquilibriumProblem pr(s, ContinuationParameter::C);
  ASSERT_EQ(pr.dimension(), 285);
  const NewtonResult start = solve_fixed_parameter(pr, pr.ellipsoidal_state(0.08), 0.08);
  ASSERT_TRUE(start.converged);
  ContinuationOptions o;
  o.p_min = 0.05;
  o.p_max = 0.08;
  o.direction = Direction::backward;
  o.max_points = 4;
  const Branch b = continue_branch(pr, start.x, 0.08, o);
  ASSERT_EQ(b.points.size(), 4u) << b.message;
  for (const BranchPoint& pt : b.points) {
    const Parameters q = with_parameter(s.parameters, ContinuationParameter::C, pt.p);
    const ClosedForm c = closed_form(s, q);
    EXPECT_LT(state_error(pr, pt.x, pt.p, c), 1e-10) << "C = " << pt.p;
    std::vector<cd> want;
    for (int m = -16; m <= 16; ++m) want.emplace_back(Upsilon_l(q, 16, c.sigma), 0.5 * m);
    std::vector<cd> got;
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i)
      if (std::abs(pt.spectrum[i].real() - Upsilon_l(q, 16, c.sigma)) < 1e-6 * std::abs(Upsilon_l(q, 16, c.sigma)))
        got.push_back(pt.spectrum[i]);
    ASSERT_EQ(got.size(), want.size());  // l = 16's 2l + 1 eigenvalues, none else there
    EXPECT_LT(test::multiset_distance(got, want), 1e-12);
    EXPECT_TRUE(pt.stable);
  }
}

TEST(FullEquilibrium, RotatingForcingAndLargeLAreRejected) {
  Scene s = forced_scene(0.03, 4, 1e-3);
  s.beta = 0.3;  // Delta0 > 0, finite C: g has m != 0 content that rotates
  try {
    FullEquilibriumProblem pr(s, ContinuationParameter::C);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "beta");
  }
  s.parameters.Delta0 = 0;  // the l = 3 rest content still rotates
  EXPECT_THROW(FullEquilibriumProblem(s, ContinuationParameter::C), InvalidArgument);
  s.rest_delta_l.clear();  // no elastic memory left: autonomous
  EXPECT_NO_THROW(FullEquilibriumProblem(s, ContinuationParameter::C));
  Scene t = forced_scene(0.03, 4, 1e-3);
  t.beta = 0.3;
  t.parameters.C = std::numeric_limits<double>::infinity();  // C = inf: no rest-shape drive at all
  EXPECT_NO_THROW(FullEquilibriumProblem(t, ContinuationParameter::lambda));
  Scene u = forced_scene(0.03, FullEquilibriumProblem::max_L + 1, 1e-3);
  try {
    FullEquilibriumProblem pr(u, ContinuationParameter::C);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "L");
  }
}

// The lower levels cannot hold a stress-free shape with l >= 3 content: their problems refuse it by
// name instead of continuing the cell without it.
TEST(FullEquilibrium, LowerLevelProblemsRefuseRestContent) {
  const Scene s = forced_scene(0.03, 4, 1e-3);
  const auto names_rest = [](auto&& make) {
    try {
      make();
      ADD_FAILURE() << "no exception";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "rest_delta_l");
    }
  };
  names_rest([&] { ReducedEquilibriumProblem pr(s, ContinuationParameter::C); });
  names_rest([&] { ModalEquilibriumProblem pr(s, ContinuationParameter::C); });
  Scene in_plane = s;
  in_plane.beta = M_PI / 2;
  names_rest([&] { ReducedForcedSystem f(in_plane, ContinuationParameter::C); });
  names_rest([&] { ModalForcedSystem f(in_plane, ContinuationParameter::C); });
  Scene without = s;
  without.rest_delta_l.clear();
  EXPECT_NO_THROW(ReducedEquilibriumProblem(without, ContinuationParameter::C));
  EXPECT_NO_THROW(ModalEquilibriumProblem(without, ContinuationParameter::C));
}

}  // namespace
}  // namespace rbcstab
