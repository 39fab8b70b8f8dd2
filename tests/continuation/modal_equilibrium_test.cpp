// Modal-model equilibria in regular coordinates (continuation/modal_equilibrium.hpp): the equations
// against ModalModel::rhs, the ellipsoidal branch against the reduced problem and the closed form,
// the branch points where Upsilon_l(sigma) crosses 0 against the closed-form threshold, branch
// switching to the post-instability state against its exact form, post_instability() and a long
// modal simulation, and the two-parameter BP curve against the asymptotic boundary of trace.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "continuation/modal_fixtures.hpp"
#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab {
namespace {
using namespace modal_fixtures;

TEST(ModalEquilibrium, EquationsMatchModalModelRhs) {
  // sigma and every derivative at random states (off the sphere too) against ModalModel::rhs after
  // the change of coordinates; 1e-12 relative: both are O(10) sums of O(100) terms in double.
  for (double Delta : {1.0, 0.37}) {
    Scene s = scene(0.03, 7);
    s.parameters.Delta = Delta;
    s.parameters.Delta0 = 0.02;
    s.parameters.lambda = 2.5;
    const InitialState init = initial_state(s);
    const ModalModel model(s.parameters, init);
    ASSERT_EQ(model.active_modes().size(), 5u);
    const ModalEquilibriumProblem pr(s, ContinuationParameter::C);
    const double p = s.parameters.C;
    const ModalCoefficients& c = pr.coefficients(p);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd x(pr.dimension());
      for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = u(rng);
      const std::vector<double> y = pr.to_modal_model_state(x, p);
      std::vector<double> dy(y.size());
      model.rhs(0, y, dy);
      const double sigma = ModalEquilibriumProblem::sigma(c, x);
      EXPECT_NEAR(sigma, model.sigma(0, y), 1e-12 * (1 + std::abs(sigma)));
      Eigen::VectorXd F;
      ModalEquilibriumProblem::dynamics(c, x, F);
      const double fz = std::sqrt(Delta / 4), fw = -std::sqrt(Delta / 2);
      const double expect[5] = {dy[3] / fz, dy[4] / fz, dy[0] / fw, dy[1] / fz, dy[2] / fz};
      for (int i = 0; i < 5; ++i) EXPECT_NEAR(F[i], expect[i], 1e-12 * (1 + std::abs(expect[i]))) << i;
      for (int l = 3; l <= s.L; ++l) {
        const Eigen::Index i = ModalEquilibriumProblem::index_of_mode(l);
        // u_l' = (ln Delta_l)' = 2 a_l'/a_l = 2 Upsilon_l.
        EXPECT_NEAR(2 * F[i] / x[i], dy[static_cast<std::size_t>(5 + l - 3)], 1e-11 * (1 + std::abs(dy[5 + l - 3])));
        EXPECT_NEAR(F[i] / x[i], Upsilon_l(s.parameters, l, sigma), 1e-11 * (1 + std::abs(F[i] / x[i])));
      }
    }
  }
}

TEST(ModalEquilibrium, AnalyticJacobianMatchesFiniteDifferences) {
  const Scene s = scene(0.03, 6);
  const ModalEquilibriumProblem pr(s, ContinuationParameter::lambda);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd x(pr.dimension());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = u(rng);
  Eigen::MatrixXd J, Jfd;
  pr.jacobian(x, 1.0, J);
  pr.ContinuationProblem::jacobian(x, 1.0, Jfd);  // central differences, error ~ 1e-10 relative
  EXPECT_LT((J - Jfd).lpNorm<Eigen::Infinity>(), 1e-7 * (1 + J.lpNorm<Eigen::Infinity>()));
}

TEST(ModalEquilibrium, ForcedSceneIsRejected) {
  Scene s = scene();
  s.beta = 0.3;
  EXPECT_THROW(ModalEquilibriumProblem(s, ContinuationParameter::lambda), InvalidArgument);
  s.parameters.Delta0 = 0;  // no elastic memory: autonomous again
  EXPECT_NO_THROW(ModalEquilibriumProblem(s, ContinuationParameter::lambda));
}

TEST(ModalEquilibrium, EllipsoidalBranchReproducesReducedBranchAndClosedForm) {
  // lambda in [0, 20] at C = 0.08 (stable throughout? not needed: BPs are crossed, a = 0 is invariant).
  const Scene s = scene(0.08, 6);
  const ModalEquilibriumProblem pr(s, ContinuationParameter::lambda);
  const ReducedEquilibriumProblem red(s, ContinuationParameter::lambda);
  ContinuationOptions o;
  o.p_min = 0;
  o.p_max = 20;
  o.direction = Direction::both;
  const Branch b = continue_branch(pr, pr.ellipsoidal_state(1.0), 1.0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_DOUBLE_EQ(b.points.front().p, 0);
  EXPECT_DOUBLE_EQ(b.points.back().p, 20);
  for (const BranchPoint& pt : b.points) {
    // The closed form (1e-10, the required accuracy; Newton stops at |dX| <= 1e-12).
    const Eigen::VectorXd e = pr.ellipsoidal_state(pt.p);
    EXPECT_LT((pt.x - e).lpNorm<Eigen::Infinity>(), 1e-10) << "lambda = " << pt.p;
    // The reduced problem's own Newton solution at the same lambda.
    const NewtonResult nr = solve_fixed_parameter(red, pt.x.head(3), pt.p);
    ASSERT_TRUE(nr.converged);
    EXPECT_LT((pt.x.head(3) - nr.x).lpNorm<Eigen::Infinity>(), 1e-10);
    // a = 0 and v = 0 exactly (invariant subspaces of Newton's iteration).
    EXPECT_EQ(pt.x.tail(pt.x.size() - 3).lpNorm<Eigen::Infinity>(), 0.0);
    // Spectrum: the reduced pair, Upsilon_2 +- i/2 (the f21 block) and Upsilon_l(sigma) for l >= 3.
    const double sigma = pr.observe(pt.x, pt.p).sigma;
    const Parameters q = with_parameter(s.parameters, ContinuationParameter::lambda, pt.p);
    const Eigen::VectorXcd rs = red.spectrum(nr.x, pt.p);
    std::vector<std::complex<double>> expected(rs.data(), rs.data() + rs.size());
    expected.emplace_back(Upsilon_l(q, 2, sigma), 0.5);
    expected.emplace_back(Upsilon_l(q, 2, sigma), -0.5);
    for (int l = 3; l <= s.L; ++l) expected.emplace_back(Upsilon_l(q, l, sigma), 0.0);
    ASSERT_EQ(static_cast<std::size_t>(pt.spectrum.size()), expected.size());
    for (const auto& ev : expected) {
      double best = 1e300;
      for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) best = std::min(best, std::abs(pt.spectrum[i] - ev));
      EXPECT_LT(best, 1e-9 * (1 + std::abs(ev))) << "lambda = " << pt.p << " eigenvalue " << ev;
    }
  }
}

// The ellipsoidal branch in C from 0.08 down to 0.015: BPs of l = 3, 4 (in that order).
struct CRun {
  Scene s;
  ModalEquilibriumProblem pr;
  Branch branch;
  explicit CRun(int L = 6) : s(scene(0.08, L)), pr(s, ContinuationParameter::C) {
    ContinuationOptions o;
    o.p_min = 0.015;
    o.p_max = 0.08;
    o.max_step = 0.05;
    o.direction = Direction::backward;
    branch = continue_branch(pr, pr.ellipsoidal_state(0.08), 0.08, o);
  }
};

TEST(ModalEquilibrium, BranchPointsWhereUpsilonCrossesZero) {
  const CRun run;
  ASSERT_EQ(run.branch.status, ContinuationStatus::completed) << run.branch.message;
  std::vector<const SpecialPoint*> bps;
  for (const auto& sp : run.branch.special_points)
    if (sp.type == SpecialPointType::BP) bps.push_back(&sp);
  ASSERT_GE(bps.size(), 2u);
  int expected_l = 3;
  for (const SpecialPoint* sp : bps) {
    EXPECT_EQ(sp->status, LocationStatus::located);
    const int l = critical_mode(run.pr, sp->x, sp->p);
    EXPECT_EQ(l, expected_l++);
    // Located to 1e-8 against the closed form: sigma_eq(C) = sigma_l^c(B/C) solved by bisection.
    const double C_star =
        threshold_root(run.s.parameters, ContinuationParameter::C, l, sp->p_lo - 1e-3, sp->p_hi + 1e-3);
    EXPECT_NEAR(sp->p, C_star, 1e-8) << "l = " << l;
    EXPECT_EQ(sp->unstable_after, sp->unstable_before + 1);  // one real eigenvalue (Upsilon_l) crosses
  }
}

TEST(ModalEquilibrium, BranchSwitchingGivesThePostInstabilityState) {
  const CRun run;
  const SpecialPoint* bp = find_special_point(run.branch, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  BranchSwitchOptions o;
  o.continuation.p_min = 0.015;
  o.continuation.p_max = 0.08;
  o.continuation.max_step = 0.05;
  const BranchSwitchResult sw = switch_branch(run.pr, run.branch, *bp, o);
  ASSERT_TRUE(sw.switched) << sw.message;
  EXPECT_LT(sw.singular_values[1], 1e-7 * sw.singular_values[2]);  // a 2-D kernel
  const Branch& nb = sw.branch;
  ASSERT_EQ(nb.status, ContinuationStatus::completed) << nb.message;
  ASSERT_GE(nb.points.size(), 5u);
  EXPECT_LT(nb.points.back().p, bp->p);  // supercritical: the new branch lives where the ellipsoid is unstable
  EXPECT_DOUBLE_EQ(nb.points.back().p, 0.015);
  const Eigen::Index i3 = ModalEquilibriumProblem::index_of_mode(3);
  for (const BranchPoint& pt : nb.points) {
    const Parameters q = with_parameter(run.s.parameters, ContinuationParameter::C, pt.p);
    const ModalState st = run.pr.observe(pt.x, pt.p);
    const PostState ex = exact_post_state(q, 3);
    // 1e-10 (absolute, O(1) quantities): Newton's tolerance 1e-12 times the condition of sigma(x).
    EXPECT_NEAR(st.sigma, ex.sigma, 1e-9 * (1 + std::abs(ex.sigma))) << "C = " << pt.p;
    EXPECT_NEAR(st.Delta_l[0], ex.Delta2, 1e-10) << "C = " << pt.p;
    EXPECT_NEAR(st.Delta_l[1], ex.Delta_l, 1e-10) << "C = " << pt.p;
    EXPECT_GT(std::abs(pt.x[i3]), 0);
    for (int l = 4; l <= run.s.L; ++l) EXPECT_EQ(pt.x[ModalEquilibriumProblem::index_of_mode(l)], 0.0);
    // Stable iff every other mode decays at sigma_3^c, i.e. sigma_3^c is the largest critical tension:
    // alpha < 60 (sigma_3^c = sigma_4^c at 12 + 4 alpha/12 = 20 + 4 alpha/20), C > 1/60 here.
    const bool l3_survives = q.alpha() < 60;
    EXPECT_EQ(pt.stable, l3_survives) << "C = " << pt.p << " n_unstable = " << pt.n_unstable;
    // post_instability's integer-mode Delta~2 (Eq. ss with Eq. subs_ss, exact out of plane).
    const PostInstability post = post_instability(q, run.s.L);
    if (!l3_survives) continue;
    ASSERT_EQ(post.surviving_mode, 3);
    ASSERT_TRUE(post.integer_mode.Delta2_tilde.valid()) << post.integer_mode.Delta2_tilde.reason;
    EXPECT_NEAR(st.Delta_l[0], post.integer_mode.Delta2_tilde.value, 1e-10) << "C = " << pt.p;
  }
  // The secondary BP where the l = 3 state loses stability to l = 4: Upsilon_4(sigma_3^c) = 0 at
  // alpha = 60, C = B/60 exactly.
  const SpecialPoint* bp2 = find_special_point(nb, SpecialPointType::BP);
  ASSERT_NE(bp2, nullptr);
  EXPECT_NEAR(bp2->p, run.s.parameters.B / 60, 1e-8);
  EXPECT_EQ(critical_mode(run.pr, bp2->x, bp2->p), 4);
}

TEST(ModalEquilibrium, BranchSwitchedStateIsTheLongTimeStateOfTheModalSimulation) {
  const CRun run;
  const SpecialPoint* bp = find_special_point(run.branch, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  const double C = 0.025;  // past the l = 3 threshold (C ~ 0.037); l = 4 is unstable on the ellipsoid too
  Scene sim_scene = scene(C, run.s.L);
  sim_scene.model = ModelLevel::modal;
  sim_scene.delta = 1e-6;
  sim_scene.T = 150;
  sim_scene.dt = 50;
  SimulationOptions so;
  so.integrator.rtol = 1e-11;
  so.integrator.atol = 1e-14;
  so.record_trajectory = false;
  const SimulationResult sim = simulate(sim_scene, so);
  ASSERT_EQ(sim.status, IntegrationStatus::success) << sim.reason;
  // The simulation holds Delta + (L - 2) delta of area: continue with that Delta (the modal model's
  // area is its state's, and Lambda, kappa scale accordingly).
  Scene s = run.s;
  s.parameters.Delta = sim.Delta_total_initial;
  const ModalEquilibriumProblem pr(s, ContinuationParameter::C);
  ContinuationOptions co;
  co.p_min = 0.015;
  co.p_max = 0.08;
  co.direction = Direction::backward;
  const Branch eb = continue_branch(pr, pr.ellipsoidal_state(0.08), 0.08, co);
  const SpecialPoint* bp2 = find_special_point(eb, SpecialPointType::BP);
  ASSERT_NE(bp2, nullptr);
  BranchSwitchOptions o;
  o.continuation.p_min = C;
  o.continuation.p_max = 0.08;
  const BranchSwitchResult sw = switch_branch(pr, eb, *bp2, o);
  ASSERT_TRUE(sw.switched) << sw.message;
  const BranchPoint& end = sw.branch.points.back();
  ASSERT_DOUBLE_EQ(end.p, C);
  const ModalState st = pr.observe(end.x, end.p);
  // The transients decay like exp(Upsilon t) with the slowest rate |Re| ~ 0.3 here (the f21 block and
  // the l = 2 pair at sigma_3^c): e^{-0.3 * 100} ~ 1e-13 after the ~50 time units of growth from 1e-6,
  // so the simulation's own tolerance (1e-11 relative) bounds the difference: 1e-8 leaves a margin.
  EXPECT_NEAR(sim.Delta_final[0], st.Delta_l[0], 1e-8);
  EXPECT_NEAR(sim.Delta_final[1], st.Delta_l[1], 1e-8);
  for (int l = 4; l <= s.L; ++l) EXPECT_LT(sim.Delta_final[static_cast<std::size_t>(l - 2)], 1e-12);
  EXPECT_NEAR(sim.sigma_final, st.sigma, 1e-7);
  EXPECT_TRUE(end.stable);
}

TEST(ModalEquilibrium, BranchPointCurveIsTheAsymptoticBoundary) {
  const CRun run;
  const SpecialPoint* bp = find_special_point(run.branch, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  const int l = critical_mode(run.pr, bp->x, bp->p);
  const ModalBranchPointCurve curve(run.s, ContinuationParameter::C, ContinuationParameter::B, l);
  ContinuationOptions o;
  o.p_min = 0.6;
  o.p_max = 1.6;
  o.direction = Direction::both;
  o.max_step = 0.05;
  o.detect_bifurcations = false;
  const Branch b = continue_branch(curve, curve.start(bp->x, bp->p), curve.start_parameter(), o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_GE(b.points.size(), 10u);
  for (const BranchPoint& pt : b.points) {
    const double B = pt.p, C = pt.x[5];
    Parameters q = run.s.parameters;
    q.B = B;
    // The root in C of mu_l = Upsilon_l(sigma_R^eq) = 0 at this B (trace.hpp's criterion): 1e-9.
    const double C_star = threshold_root(q, ContinuationParameter::C, l, C * 0.9, C * 1.1);
    EXPECT_NEAR(C, C_star, 1e-9) << "B = " << B;
    // And trace.hpp's own verdict flips across the curve (l is the active mode there).
    Scene s = run.s;
    s.parameters = q;
    s.parameters.C = C * (1 + 1e-6);
    const AsymptoticVerdict above = asymptotic_verdict(s);
    s.parameters.C = C * (1 - 1e-6);
    const AsymptoticVerdict below = asymptotic_verdict(s);
    EXPECT_FALSE(above.unstable);
    EXPECT_TRUE(below.unstable);
    EXPECT_EQ(below.l, l);
  }
  // trace.hpp's own traced boundary on the (ln B, ln C) plane: at each traced B, Newton on the curve
  // problem (from the nearest curve point) gives the traced C to 1e-9 relative (trace bisects to the
  // last bit of ln C).
  DiagramSpec plane;
  plane.x = {Axis::lnB, std::log(0.65), std::log(1.55), 8};
  plane.y = {Axis::lnC, std::log(0.012), std::log(0.07), 8};
  TraceOptions to;
  to.lines = 8;
  to.samples = 64;
  const TraceResult tr = trace_boundary(run.s, plane, to);
  std::size_t compared = 0;
  for (const TraceCurve& tc : tr.curves) {
    if (tc.l != l) continue;
    for (const TracePoint& tp : tc.points) {
      const double B = std::exp(tp.x);
      const BranchPoint* near = &b.points.front();
      for (const BranchPoint& pt : b.points)
        if (std::abs(pt.p - B) < std::abs(near->p - B)) near = &pt;
      const NewtonResult nr = solve_fixed_parameter(curve, near->x, B);
      ASSERT_TRUE(nr.converged);
      EXPECT_NEAR(nr.x[5] / std::exp(tp.y), 1.0, 1e-9) << "B = " << B;
      ++compared;
    }
  }
  EXPECT_GE(compared, 5u);
}

}  // namespace
}  // namespace rbcstab
