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
#include "continuation/in_plane_orbit.hpp"
#include "rbcstab/continuation/monodromy.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

using test::in_plane_orbit;
using test::InPlaneOrbit;

std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& M) {
  const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(M, false).eigenvalues();
  return {e.data(), e.data() + e.size()};
}

// (-1)^m exp(2 pi Upsilon_l(sigma_bar)) twice per (l, m), l >= 3, and the l = 2 block's dense monodromy.
std::vector<std::complex<double>> closed_form_multipliers(const InPlaneOrbit& o, int L) {
  return test::exact_in_plane_monodromy(o, L).multipliers();
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
  ASSERT_TRUE(o.ok);
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
  ASSERT_TRUE(o.ok);
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
