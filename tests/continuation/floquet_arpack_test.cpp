// Leading Floquet multipliers of the full model around an in-plane ellipsoidal orbit, matrix-free
// (ARPACK on the monodromy action), against the dense monodromy (n integrations) and against the
// closed form of the decoupled l >= 3 block.
//
// Closed form: along a trajectory with f_{l>=3} = 0 each (l, m), l >= 3, obeys
// f' = (Upsilon_l(sigma(t)) + i m/2) f alone, so over one period T = 2 pi it is multiplied by
// exp(int_0^T Upsilon_l dt) e^{i pi m}; the real 2x2 block has that real value twice:
// (-1)^m exp(T Upsilon_l(sigma_bar)), Upsilon_l being affine in sigma (sigma_bar the period mean of sigma).
// The l = 2 block (10 x 10) is the L = 2 model's monodromy, computed densely.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "continuation/full_model_fixture.hpp"
#include "rbcstab/continuation/monodromy.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// An in-plane orbit state at t0 = 2 pi k: the reduced model (exact for ellipsoidal states) relaxed over
// 30 forcing periods, embedded with f_{l>=3} = 0.
struct InPlaneOrbit {
  Parameters p;
  InitialState init;
  double t0 = 0;
};

InPlaneOrbit in_plane_orbit(int L) {
  InPlaneOrbit o;
  const Scene s = test::ellipsoidal_scene(L, std::numbers::pi / 2);
  o.p = s.parameters;
  o.init = initial_state(s);
  const ReducedModel red(o.p, o.init);
  o.t0 = 30 * kTwoPi;
  const double grid[1] = {o.t0};
  IntegratorOptions io;
  io.rtol = 1e-11;
  io.atol = 1e-13;
  const IntegrationResult r = integrate(red, red.initial_state(), 0.0, grid, io, {});
  EXPECT_EQ(r.status, IntegrationStatus::success);
  o.init.f = red.amplitudes(o.t0, r.y);
  return o;
}

// Mean of sigma over one period along the full-model trajectory (composite Simpson, 4000 intervals:
// error ~ h^4 |sigma''''| ~ 1e-12 relative for this smooth periodic sigma).
double mean_sigma(const FullModel& full, std::span<const double> y0, double t0) {
  const int N = 4000;
  std::vector<double> grid(N + 1), sig;
  for (int i = 0; i <= N; ++i) grid[std::size_t(i)] = t0 + kTwoPi * i / N;
  IntegratorOptions io;
  io.rtol = 1e-12;
  io.atol = 1e-14;
  integrate(full, y0, t0, grid, io, [&](double t, std::span<const double> y) { sig.push_back(full.sigma(t, y)); });
  EXPECT_EQ(sig.size(), std::size_t(N + 1));
  double s = sig.front() + sig.back();
  for (int i = 1; i < N; ++i) s += (i % 2 ? 4 : 2) * sig[std::size_t(i)];
  return s / (3.0 * N);  // (h/3) sum / T with h = T/N
}

std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& M) {
  const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(M, false).eigenvalues();
  return {e.data(), e.data() + e.size()};
}

std::vector<std::complex<double>> closed_form_multipliers(const InPlaneOrbit& o, int L) {
  const MonodromyOptions mo;
  InitialState init2 = o.init;
  ModeAmplitudes f2(2);
  for (int m = -2; m <= 2; ++m) f2.at(2, m) = o.init.f.at(2, m);
  init2.f = f2;
  const FullModel full2(o.p, init2);
  const MonodromyAction a2(full2, full2.initial_state(), o.t0, mo);
  auto all = eigenvalues(a2.dense());
  const FullModel full(o.p, o.init);
  const double sbar = mean_sigma(full, full.initial_state(), o.t0);
  for (int l = 3; l <= L; ++l) {
    const double E = std::exp(kTwoPi * Upsilon(o.p, l, sbar));
    for (int m = -l; m <= l; ++m) all.insert(all.end(), 2, (m % 2 ? -E : E));
  }
  return all;
}

std::vector<std::complex<double>> by_modulus(std::vector<std::complex<double>> v) {
  std::stable_sort(v.begin(), v.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  return v;
}

// Tolerances: the variational integration runs at rtol 1e-11, so each monodromy column carries
// ~1e-10 relative error over one period; leading multipliers of size O(1) then agree to ~1e-9.
// 1e-7 (relative to 1 + |mu|) leaves margin for the repeated (derogatory) values.
TEST(FloquetArpack, LeadingMultipliersMatchDenseMonodromyAndClosedForm) {
  const int L = 6;
  const InPlaneOrbit o = in_plane_orbit(L);
  const FullModel full(o.p, o.init);
  const MonodromyOptions mo;
  ArpackOptions ao;
  ao.k = 12;
  ao.tol = 1e-10;
  const FloquetResult fr = leading_floquet_multipliers(full, full.initial_state(), o.t0, mo, ao);
  ASSERT_EQ(fr.arpack.status, ArpackStatus::converged) << fr.arpack.message;
  const auto got = std::vector<std::complex<double>>(fr.arpack.eigenvalues.data(),
                                                     fr.arpack.eigenvalues.data() + fr.arpack.eigenvalues.size());
  const MonodromyAction action(full, full.initial_state(), o.t0, mo);
  bool ok = false;
  const auto dense = by_modulus(eigenvalues(action.dense(&ok)));
  ASSERT_TRUE(ok);
  const auto closed = by_modulus(closed_form_multipliers(o, L));
  // The dense monodromy has exactly the closed-form spectrum (the decoupling claim, verified).
  EXPECT_LT(test::multiset_distance(dense, closed), 1e-7);
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(std::abs(got[i]), std::abs(dense[i]), 1e-7 * (1 + std::abs(dense[i]))) << i;
  }
  EXPECT_LT(test::multiset_distance(got, dense), 1e-7);
  // The conserved excess area gives a trivial multiplier 1 (here below the unstable l = 3, 4 ones).
  double d1 = 1;
  for (const auto& mu : dense) d1 = std::min(d1, std::abs(mu - 1.0));
  EXPECT_LT(d1, 1e-8);
  EXPECT_LT(fr.integrations, std::size_t(dense.size()) * 4);
}

// L = 12 (n = 330): only ARPACK and the closed form (no dense monodromy).
TEST(FloquetArpack, LeadingMultipliersMatchClosedFormAtL12) {
  const int L = 12;
  const InPlaneOrbit o = in_plane_orbit(L);
  const FullModel full(o.p, o.init);
  ArpackOptions ao;
  ao.k = 12;
  ao.tol = 1e-10;
  const FloquetResult fr = leading_floquet_multipliers(full, full.initial_state(), o.t0, {}, ao);
  ASSERT_EQ(fr.arpack.status, ArpackStatus::converged) << fr.arpack.message;
  const auto got = std::vector<std::complex<double>>(fr.arpack.eigenvalues.data(),
                                                     fr.arpack.eigenvalues.data() + fr.arpack.eigenvalues.size());
  const auto closed = by_modulus(closed_form_multipliers(o, L));
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_NEAR(std::abs(got[i]), std::abs(closed[i]), 1e-7 * (1 + std::abs(closed[i]))) << i;
  EXPECT_LT(test::multiset_distance(got, closed), 1e-7);
  EXPECT_GT(std::abs(got[0]), 1);  // the in-plane orbit is unstable to l >= 3 (Upsilon_4 > 0 on average)
}

TEST(FloquetArpack, DenseImplicitSteppersAreRejected) {
  MonodromyOptions mo;
  for (Stepper st : {Stepper::msbdf, Stepper::bsimp, Stepper::rk4imp}) {
    mo.integrator.stepper = st;
    EXPECT_THROW(mo.validate(), InvalidArgument) << to_string(st);
  }
  mo.integrator.stepper = Stepper::rosenbrock;  // block-triangular O(n) solves (floquet_implicit_test.cpp)
  EXPECT_NO_THROW(mo.validate());
}

}  // namespace
}  // namespace rbcstab
