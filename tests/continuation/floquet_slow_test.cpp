// Leading Floquet multipliers of the full model at L = 60 (n = 7434) around the in-plane orbit, by
// ARPACK on the implicit (rosenbrock) monodromy action, against the closed form (label slow: ~2 min).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "continuation/in_plane_orbit.hpp"

namespace rbcstab {
namespace {

// The default MonodromyOptions pick rosenbrock at L = 60 (implicit_from_L = 40); here at rtol 1e-8
// (action error ~1.4e-9 relative, measured by BM_FloquetAction) to keep the ~60 actions at ~2 s each.
// The l >= 3 blocks of Phi are diagonal (condition 1), so the leading multipliers carry about the action
// error; 1e-7 relative to 1 + |mu| leaves a factor ~50 for ARPACK's handling of the 9-fold +-695.
TEST(FloquetSlow, LeadingMultipliersAtL60MatchClosedForm) {
  const int L = 60;
  const test::InPlaneOrbit o = test::in_plane_orbit(L);
  ASSERT_TRUE(o.ok);
  const FullModel full(o.p, o.init);
  MonodromyOptions mo;
  ASSERT_EQ(mo.integrator_for(full).stepper, Stepper::rosenbrock);
  mo.implicit.rtol = 1e-8;
  mo.implicit.atol = 1e-10;
  ArpackOptions ao;
  ao.k = 12;
  ao.tol = 1e-10;
  const FloquetResult fr = leading_floquet_multipliers(full, full.initial_state(), o.t0, mo, ao);
  ASSERT_EQ(fr.arpack.status, ArpackStatus::converged) << fr.arpack.message;
  const auto& e = fr.arpack.eigenvalues;
  const test::ExactInPlaneMonodromy exact = test::exact_in_plane_monodromy(o, L);
  const auto want = exact.multipliers();
  EXPECT_LT(test::multiset_distance({e.data(), e.data() + e.size()}, want), 1e-7);
  EXPECT_NEAR(std::abs(e(0)), std::abs(exact.factor(4, 0)), 1e-7 * std::abs(exact.factor(4, 0)));
  // Accuracy-bound steps (rk8pd would need ~11000 per action here, stability-bound).
  EXPECT_LT(fr.counters.steps, fr.integrations * 3000);
  // One action on a generic vector against the exact Phi v (every mode, including the stiffest l = 60).
  const std::vector<double> v = test::test_vector(full.dimension());
  std::vector<double> want_v(v.size()), got(v.size());
  exact.apply(v, want_v);
  ASSERT_TRUE(MonodromyAction(full, full.initial_state(), o.t0, mo).apply(v, got));
  double d = 0, w = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    d += (got[i] - want_v[i]) * (got[i] - want_v[i]);
    w += want_v[i] * want_v[i];
  }
  EXPECT_LT(std::sqrt(d / w), 1e-7);
}

}  // namespace
}  // namespace rbcstab
