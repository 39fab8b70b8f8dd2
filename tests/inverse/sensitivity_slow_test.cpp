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
  // Every row (4 conditions) of both cells against differences of the default forward and of one with 8192 samples
  // per period (1e-6, as the fast test; measured 1.6e-8 and 4.3e-8 for both: the quartic extrema's bias is below).
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
    EXPECT_LT(column_gap(v.J, b.J), 1e-6);
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
  const Linearisation t_only = linearise(std::vector<ObservedRow>{t}, mu, k.cell, fd, 1e-4);
  fd.forward.samples_per_period = 8192;  // the in-plane rows' oracle, as above
  const Linearisation a = linearise(k.data.rows, mu, k.cell, fd, 1e-4);
  ASSERT_TRUE(v.ok && a.ok && t_only.ok) << v.reason << a.reason << t_only.reason;
  EXPECT_EQ(v.r.back(), t_only.r[0]);
  EXPECT_EQ(v.J.back()[0], t_only.J[0][0]);
  std::vector<std::vector<double>> in_plane(v.J.begin(), v.J.end() - 1);
  EXPECT_LT(column_gap(in_plane, a.J), 1e-6);
}

TEST(SensitivitySlow, WarmTransitionCostsLessAndAgrees) {
  // A fit's sequence at one viscosity: the transition at a point, then at +-1e-4 in ln lambda and in ln mu (the
  // central differences), cold (no memo) against warm (one memo); the same values.
  const CellModel cell = synthetic_cell();
  ObservedRow row;
  row.observable = Observable::transition_shear_rate;
  row.viscosity = 1e-3;
  std::vector<CellModel> seq = {cell};
  for (double h : {1e-4, -1e-4}) {
    CellModel a = cell, b = cell;
    a.lambda *= std::exp(h);
    b.shear_modulus *= std::exp(h);
    seq.push_back(a);
    seq.push_back(b);
  }
  std::vector<double> cold, warm;
  const double t_cold = seconds_of([&] {
    for (const CellModel& c : seq) cold.push_back(predict(c, row).value);  // no memo: each call cold
  });
  ForwardOptions shared;
  shared.transition_memo = make_transition_memo();
  const double t_warm = seconds_of([&] {
    for (const CellModel& c : seq) warm.push_back(predict(c, row, shared).value);
  });
  for (std::size_t i = 0; i < seq.size(); ++i) EXPECT_EQ(warm[i], cold[i]) << i;
  std::printf("transition shear rate, %zu evaluations: cold %.3f s each, warm %.3f s each (the first one cold)\n",
              seq.size(), t_cold / static_cast<double>(seq.size()), t_warm / static_cast<double>(seq.size()));
}

}  // namespace
}  // namespace rbcstab
