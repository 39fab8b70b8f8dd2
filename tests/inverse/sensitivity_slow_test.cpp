// The variational Jacobian against central differences on every row of two cells (slow: ~10 s), a transition row
// beside the in-plane rows, and the time per Jacobian of both methods.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/inverse/sensitivity.hpp"
#include "synthetic_cell.hpp"

namespace rbcstab {
namespace {

double seconds_of(const std::function<void()>& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(SensitivitySlow, EveryRowAgreesWithCentralDifferences) {
  // Every row (4 conditions) of both cells against differences at 8192 samples per period (1e-6, as the fast test);
  // the default 1024 samples put the amplitude's sampled-parabola bias (~1e-5 relative) into the differences but
  // not into the variational equations, which differentiate the exact extremum.
  for (const SensitivityCase& k : sensitivity_cases()) {
    FitOptions variational, fd, fd_default;
    fd.jacobian = fd_default.jacobian = JacobianMethod::finite_difference;
    fd.forward.samples_per_period = 8192;
    Linearisation v, a, b;
    const double tv = seconds_of([&] { v = linearise(k.data.rows, k.free, k.cell, variational, 1e-4); });
    const double tf = seconds_of([&] { b = linearise(k.data.rows, k.free, k.cell, fd_default, 1e-4); });
    a = linearise(k.data.rows, k.free, k.cell, fd, 1e-4);
    ASSERT_TRUE(v.ok && a.ok && b.ok) << v.reason << a.reason << b.reason;
    EXPECT_LT(column_gap(v.J, a.J), 1e-6);
    std::printf(
        "%zu free, %zu rows: Jacobian %.3f s variational, %.3f s central differences; gap to 1024-sample "
        "differences %.2e, to 8192-sample %.2e\n",
        k.free.size(), k.data.rows.size(), tv, tf, column_gap(v.J, b.J), column_gap(v.J, a.J));
  }
}

TEST(SensitivitySlow, TransitionRowsKeepCentralDifferences) {
  // A transition row has no variational route: its Jacobian row is the central difference, so both methods give
  // the same row; the in-plane rows beside it still agree to 1e-6.
  const SensitivityCase k = sensitivity_cases().front();
  ObservationData d = k.data;
  ObservedRow t;
  t.line = 99;
  t.observable = Observable::transition_shear_rate;
  t.viscosity = 1e-3;
  t.unit = "1/s";
  t.uncertainty = 1;
  FitOptions variational, fd;
  variational.forward.transition_rtol = fd.forward.transition_rtol = 1e-9;
  fd.jacobian = JacobianMethod::finite_difference;
  t.value = predict(k.cell, t, fd.forward).value;
  d.rows.push_back(t);
  const std::vector<FitParameter> mu = {FitParameter::shear_modulus};
  const Linearisation v = linearise(d.rows, mu, k.cell, variational, 1e-4);
  const Linearisation a = linearise(d.rows, mu, k.cell, fd, 1e-4);
  ASSERT_TRUE(v.ok && a.ok) << v.reason << a.reason;
  EXPECT_EQ(v.J.back()[0], a.J.back()[0]);
  EXPECT_LT(column_gap(v.J, a.J), 1e-6);
}

}  // namespace
}  // namespace rbcstab
