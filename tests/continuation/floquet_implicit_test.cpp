// The implicit (Rosenbrock) variational integration behind the monodromy action: its block-triangular
// shifted solve against a finite-difference Jacobian of the variational system, and its actions against
// the rk8pd action and the exact monodromy of the in-plane orbit (test::ExactInPlaneMonodromy: l = 2
// block dense, closed form (-1)^m exp(2 pi Upsilon_l(sigma_bar)) for l >= 3). L = 60 is in
// floquet_slow_test.cpp (label slow).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "continuation/in_plane_orbit.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

std::size_t full_dimension(int L) { return 2 * ModeAmplitudes::count(L); }

double rel_error(std::span<const double> a, std::span<const double> b) {
  double d = 0, n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d += (a[i] - b[i]) * (a[i] - b[i]);
    n += b[i] * b[i];
  }
  return std::sqrt(d / n);
}

MonodromyOptions rosenbrock_options(double rtol) {
  MonodromyOptions mo;
  mo.integrator = {Stepper::rosenbrock, rtol, 1e-2 * rtol};
  return mo;
}

// (I - c J_aug) x = b from the variational system's solver, checked against J_aug by central differences
// of its right-hand side (which never uses the solver's K = F''[., v]); dF_aug/dt likewise. A generic
// state: l = 3 content in f and in the rest shape (so the drive depends on t and K couples all modes).
TEST(FloquetImplicit, ShiftedSolveMatchesFiniteDifferenceJacobian) {
  Scene s = test::ellipsoidal_scene(3, 1.0);
  s.delta = 0.05;
  s.rest_delta_l[3] = 2e-3;
  const InitialState init = initial_state(s);
  const FullModel full(s.parameters, init);
  const auto aug = make_variational_system(full);
  const std::size_t n = full.dimension(), N = aug->dimension();
  ASSERT_EQ(N, 2 * n);
  std::vector<double> y = full.initial_state();
  const std::vector<double> v = test::test_vector(n);
  y.insert(y.end(), v.begin(), v.end());
  const double t = 0.7;
  // Central differences, step 1e-6 (|y| ~ 0.3): truncation ~1e-12 |F'''|, rounding ~1e-10 |F|.
  const double h = 1e-6;
  Eigen::MatrixXd J(static_cast<Eigen::Index>(N), static_cast<Eigen::Index>(N));
  std::vector<double> yp(y), fp(N), fm(N);
  for (std::size_t j = 0; j < N; ++j) {
    yp[j] = y[j] + h;
    aug->rhs(t, yp, fp);
    yp[j] = y[j] - h;
    aug->rhs(t, yp, fm);
    yp[j] = y[j];
    for (std::size_t i = 0; i < N; ++i) J(Eigen::Index(i), Eigen::Index(j)) = (fp[i] - fm[i]) / (2 * h);
  }
  aug->rhs(t + h, y, fp);
  aug->rhs(t - h, y, fm);
  const auto solver = aug->make_shifted_solver();
  std::vector<double> dfdt(N);
  solver->linearize(t, y, dfdt);
  double dt_err = 0, dt_scale = 0;
  for (std::size_t i = 0; i < N; ++i) {
    dt_err = std::max(dt_err, std::abs(dfdt[i] - (fp[i] - fm[i]) / (2 * h)));
    dt_scale = std::max(dt_scale, std::abs(dfdt[i]));
  }
  EXPECT_GT(dt_scale, 1e-3);  // the rest shape's l = 3 content makes F depend on t
  EXPECT_LT(dt_err, 1e-7 * dt_scale);
  const Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(test::test_vector(N).data(), Eigen::Index(N));
  for (double c : {0.01, 0.3, 5.0}) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(N));
    ASSERT_TRUE(solver->solve(c, {b.data(), N}, {x.data(), N}));
    const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(Eigen::Index(N), Eigen::Index(N)) - c * J;
    // FD Jacobian entries carry ~1e-9 relative error: the residual is bounded by that times c |J| |x|.
    EXPECT_LT((A * x - b).norm(), 1e-7 * (b.norm() + c * J.norm() * x.norm())) << "c = " << c;
    // The K block matters: dropping it (a block-diagonal solve) misses the residual by far more.
    Eigen::VectorXd x_diag(x);
    const auto base_solver = full.make_shifted_solver();
    std::vector<double> dfdt_base(n);
    base_solver->linearize(t, std::span<const double>(y).first(n), dfdt_base);
    ASSERT_TRUE(base_solver->solve(c, {b.data() + n, n}, {x_diag.data() + n, n}));
    EXPECT_GT((A * x_diag - b).norm(), 1e-4 * b.norm()) << "c = " << c;
  }
}

// L = 6: the rosenbrock dense monodromy equals the rk8pd one and the exact multipliers.
// Tolerance: rosenbrock at rtol 1e-8 gives a measured action error ~1e-9 relative (BM_FloquetAction),
// rk8pd at its default rtol 1e-11 ~1e-12; 1e-7 relative to max|Phi| leaves a factor 100.
TEST(FloquetImplicit, RosenbrockDenseMonodromyMatchesRk8pdAndClosedFormAtL6) {
  const int L = 6;
  const test::InPlaneOrbit o = test::in_plane_orbit(L);
  ASSERT_TRUE(o.ok);
  const FullModel full(o.p, o.init);
  bool ok_r = false, ok_e = false;
  const MonodromyAction implicit_action(full, full.initial_state(), o.t0, rosenbrock_options(1e-8));
  const Eigen::MatrixXd Mr = implicit_action.dense(&ok_r);
  const Eigen::MatrixXd Me = MonodromyAction(full, full.initial_state(), o.t0, {}).dense(&ok_e);
  ASSERT_TRUE(ok_r && ok_e);
  EXPECT_LT((Mr - Me).cwiseAbs().maxCoeff(), 1e-7 * Me.cwiseAbs().maxCoeff());
  EXPECT_GT(implicit_action.counters().jacobian_evaluations, 0u);  // the implicit path really ran
  const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(Mr, false).eigenvalues();
  const auto exact = test::exact_in_plane_monodromy(o, L).multipliers();
  EXPECT_LT(test::multiset_distance({e.data(), e.data() + e.size()}, exact), 1e-7);
}

// ARPACK on the rosenbrock action at L = 6 finds the 12 leading multipliers (+-695 = +-exp(2 pi
// Upsilon_4(sigma_bar)), l = 4 unstable) to the closed form (1e-7 as above).
TEST(FloquetImplicit, ArpackOnRosenbrockActionMatchesClosedFormAtL6) {
  const int L = 6;
  const test::InPlaneOrbit o = test::in_plane_orbit(L);
  const FullModel full(o.p, o.init);
  ArpackOptions ao;
  ao.k = 12;
  ao.tol = 1e-10;
  const FloquetResult fr = leading_floquet_multipliers(full, full.initial_state(), o.t0, rosenbrock_options(1e-8), ao);
  ASSERT_EQ(fr.arpack.status, ArpackStatus::converged) << fr.arpack.message;
  const auto& e = fr.arpack.eigenvalues;
  const auto exact = test::exact_in_plane_monodromy(o, L).multipliers();
  EXPECT_LT(test::multiset_distance({e.data(), e.data() + e.size()}, exact), 1e-7);
  EXPECT_NEAR(std::abs(e(0)), std::abs(exact[0]), 1e-7 * std::abs(exact[0]));
}

// L = 30 (n = 1914), default suite: one action on a generic vector, rosenbrock and rk8pd, against the
// exact Phi v (1e-7, as above); and the linearised area is conserved: with g(y) = grad Delta(y) =
// 2 a_l y, g(y(T)) . Phi v = g(y0) . v for every v (the trivial multiplier 1 with left eigenvector g
// on a periodic orbit). Tolerance 1e-9 |g| |v|: g lives on l = 2, where Phi v is O(|v|) and
// accurate to the action error (~1e-9 relative, measured) — Cauchy-Schwarz.
TEST(FloquetImplicit, ActionAtL30MatchesExactMonodromyAndConservesArea) {
  const int L = 30;
  const test::InPlaneOrbit o = test::in_plane_orbit(L);
  ASSERT_TRUE(o.ok);
  const FullModel full(o.p, o.init);
  const auto exact = test::exact_in_plane_monodromy(o, L);
  const std::vector<double> v = test::test_vector(full.dimension());
  std::vector<double> want(v.size()), got_r(v.size()), got_e(v.size());
  exact.apply(v, want);
  const MonodromyAction implicit_action(full, full.initial_state(), o.t0, rosenbrock_options(1e-8));
  ASSERT_TRUE(implicit_action.apply(v, got_r)) << implicit_action.failure_reason();
  ASSERT_TRUE(MonodromyAction(full, full.initial_state(), o.t0, {}).apply(v, got_e));
  EXPECT_LT(rel_error(got_r, want), 1e-7);
  EXPECT_LT(rel_error(got_e, want), 1e-7);
  // Accuracy-bound, not stability-bound: fewer steps than |Upsilon_30| T ~ 1000 would allow rk8pd.
  EXPECT_LT(implicit_action.counters().steps, 4000u);
  const double grid[1] = {o.t0 + kTwoPi};
  IntegratorOptions io;
  io.rtol = 1e-12;
  io.atol = 1e-14;
  const IntegrationResult yT = integrate(full, full.initial_state(), o.t0, grid, io, {});
  ASSERT_EQ(yT.status, IntegrationStatus::success);
  auto grad_dot = [&](std::span<const double> y, std::span<const double> x) {
    double s = 0, gn = 0;
    for (int l = 2; l <= L; ++l)
      for (int m = -l; m <= l; ++m)
        for (std::size_t i = 2 * ModeAmplitudes::index(l, m), j = i; j < i + 2; ++j) {
          s += 2 * a_l(l) * y[j] * x[j];
          gn += std::pow(2 * a_l(l) * y[j], 2);
        }
    return std::pair{s, std::sqrt(gn)};
  };
  const auto [g0v, g0n] = grad_dot(full.initial_state(), v);
  const auto [gTu, gTn] = grad_dot(yT.y, got_r);
  EXPECT_LT(std::abs(gTu - g0v), 1e-9 * g0n);
  EXPECT_GT(std::abs(g0v), 1e-3 * g0n);  // the identity is not trivially 0 = 0
  (void)gTn;
}

TEST(FloquetImplicit, OptionsChooseTheStepperByLevelAndL) {
  const MonodromyOptions mo;
  auto model = [](int L, ModelLevel level) {
    const Scene s = test::ellipsoidal_scene(L, std::numbers::pi / 2);
    return make_system(s.parameters, initial_state(s), level);
  };
  EXPECT_EQ(mo.integrator_for(*model(mo.implicit_from_L - 1, ModelLevel::full)).stepper, Stepper::rk8pd);
  EXPECT_EQ(mo.integrator_for(*model(mo.implicit_from_L, ModelLevel::full)).stepper, Stepper::rosenbrock);
  EXPECT_EQ(mo.integrator_for(*model(mo.implicit_from_L, ModelLevel::modal)).stepper, Stepper::rk8pd);
  MonodromyOptions never = mo;
  never.implicit_from_L = 0;
  EXPECT_EQ(never.integrator_for(*model(60, ModelLevel::full)).stepper, Stepper::rk8pd);
  MonodromyOptions bad = mo;
  bad.implicit.stepper = Stepper::msbdf;
  try {
    bad.validate();
    ADD_FAILURE() << "msbdf accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("msbdf"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rosenbrock"), std::string::npos) << e.what();
  }
  bad = mo;
  bad.implicit_from_L = -1;
  EXPECT_THROW(bad.validate(), InvalidArgument);
}

// The scene-level entry point (relax at the scene's own level, embed in the full model, ARPACK): for
// the in-plane ellipsoidal scene it must reproduce the exact multipliers of the same relaxed orbit
// (1e-7 as above; rk8pd at L = 6).
TEST(SceneFloquet, InPlaneSceneMatchesExactMultipliers) {
  const int L = 6;
  const Scene s = test::ellipsoidal_scene(L, std::numbers::pi / 2);
  const SceneFloquetResult r = scene_floquet_multipliers(s, {});
  ASSERT_EQ(r.status, SceneFloquetStatus::converged) << r.message;
  EXPECT_DOUBLE_EQ(r.period, kTwoPi);  // in-plane rest shape: only even m
  EXPECT_DOUBLE_EQ(r.t0, 30 * kTwoPi);
  EXPECT_EQ(r.dimension, full_dimension(L));
  EXPECT_EQ(r.stepper, Stepper::rk8pd);
  EXPECT_LT(r.periodicity_defect, 1e-6);  // 30 periods relax onto the attracting orbit
  const auto exact = test::exact_in_plane_monodromy(test::in_plane_orbit(L), L).multipliers();
  const auto& e = r.floquet.arpack.eigenvalues;
  ASSERT_EQ(e.size(), 12);
  EXPECT_LT(test::multiset_distance({e.data(), e.data() + e.size()}, exact), 1e-7);
}

TEST(SceneFloquet, OddMRestShapeDoublesThePeriodAndBadInputIsRefused) {
  Scene s = test::ellipsoidal_scene(3, 1.0);  // tilted rest shape: g_{2,+-1} != 0, period 4 pi
  SceneFloquetOptions o;
  o.relax_periods = 0;  // the initial shape: not on the orbit
  o.arpack.k = 4;
  const SceneFloquetResult off = scene_floquet_multipliers(s, o);
  EXPECT_EQ(off.status, SceneFloquetStatus::not_periodic) << off.periodicity_defect;
  EXPECT_GT(off.periodicity_defect, o.max_periodicity_defect);
  EXPECT_EQ(off.floquet.integrations, 0u);  // no monodromy of a non-orbit unless asked for
  o.max_periodicity_defect = std::numeric_limits<double>::infinity();
  const SceneFloquetResult r = scene_floquet_multipliers(s, o);
  ASSERT_EQ(r.status, SceneFloquetStatus::converged) << r.message;
  EXPECT_DOUBLE_EQ(r.period, 2 * kTwoPi);
  o.relax_periods = -1;
  EXPECT_THROW(scene_floquet_multipliers(s, o), InvalidArgument);
  o.relax_periods = 0;
  o.max_periodicity_defect = 0;
  EXPECT_THROW(scene_floquet_multipliers(s, o), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
