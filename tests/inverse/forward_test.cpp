// The forward model: the physical map it uses, the in-plane attractor against the paper's S >> 1 steady state,
// the closed-form frequencies, the transition shear rate, and the finite-difference sensitivities.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/inverse/forward.hpp"
#include "rbcstab/model/physical.hpp"
#include "synthetic_cell.hpp"

namespace rbcstab {
namespace {

TEST(Forward, ConditionParametersAreThePhysicalMap) {
  const CellModel cell = synthetic_cell();
  const Parameters p = condition_parameters(cell, 150, 1.2e-3);
  EXPECT_DOUBLE_EQ(p.B, bending_number(1.2e-3, 150, cell.radius, cell.bending_modulus));
  EXPECT_DOUBLE_EQ(p.C, capillary_number(1.2e-3, 150, cell.radius, cell.shear_modulus));
  EXPECT_EQ(p.lambda, cell.lambda);
  CellModel with_inner = cell;
  with_inner.inner_viscosity = 6e-3;
  EXPECT_DOUBLE_EQ(condition_parameters(with_inner, 150, 1.2e-3).lambda, 5.0);
}

TEST(Forward, LargeSApproachesTheSteadyStateOfEqSsRed) {
  // Eq. ss_red (S >> 1, Lambda < 1): Psi = arccos Lambda, so psi = arccos(Lambda)/2, with an O(1/S) swing.
  const CellModel cell = synthetic_cell();
  double previous_gap = INFINITY;
  for (double rate : {2e3, 2e4}) {
    const Parameters p = condition_parameters(cell, rate, 1e-3);
    const InPlaneMotion m = in_plane_motion(p);
    ASSERT_EQ(m.regime, Regime::swinging) << m.reason;
    const double gap = std::abs(m.mean_psi - 0.5 * std::acos(p.Lambda()));
    EXPECT_LT(gap, 2.0 / p.S()) << "S = " << p.S();
    EXPECT_LT(gap, previous_gap);
    EXPECT_LT(m.amplitude_psi, 2.0 / p.S());
    previous_gap = gap;
  }
}

TEST(Forward, FrequenciesAreTheMembraneRotation) {
  const CellModel cell = synthetic_cell();
  ObservedRow row;
  row.shear_rate = 300;
  row.viscosity = 1e-3;
  row.observable = Observable::swinging_frequency;
  EXPECT_DOUBLE_EQ(predict(cell, row).value, 300 / kTwoPi);
  row.observable = Observable::tank_treading_frequency;
  EXPECT_DOUBLE_EQ(predict(cell, row).value, 300 / (2 * kTwoPi));
}

TEST(Forward, TransitionSeparatesTumblingFromSwinging) {
  const CellModel cell = synthetic_cell();
  ObservedRow row;
  row.observable = Observable::transition_shear_rate;
  row.viscosity = 1e-3;
  ForwardOptions o;
  o.transition_rtol = 1e-3;
  const Prediction pr = predict(cell, row, o);
  ASSERT_TRUE(pr.ok()) << pr.reason;
  EXPECT_EQ(in_plane_motion(condition_parameters(cell, 0.98 * pr.value, 1e-3)).regime, Regime::tumbling);
  EXPECT_EQ(in_plane_motion(condition_parameters(cell, 1.02 * pr.value, 1e-3)).regime, Regime::swinging);
  // A tumbling condition predicts no inclination angle and says why.
  row.observable = Observable::inclination_angle;
  row.shear_rate = 0.5 * pr.value;
  const Prediction none = predict(cell, row, o);
  EXPECT_FALSE(none.ok());
  EXPECT_NE(none.reason.find("tumbles"), std::string::npos) << none.reason;
}

TEST(Forward, WarmTransitionIsTheColdCell) {
  // The warm start (from the cell found at a nearby Lambda) ends on the same cell of the ln S grid as the cold scan
  // and bisection: equal values. The check separates cells: lambda 1 % apart moves the value by ~25 cells.
  const CellModel cell = synthetic_cell();
  ObservedRow row;
  row.observable = Observable::transition_shear_rate;
  row.viscosity = 1e-3;
  ForwardOptions o;
  o.transition_rtol = 1e-4;
  ForwardOptions warm = o;
  warm.transition_memo = make_transition_memo();
  CellModel moved = cell;
  moved.lambda *= 1.01;
  const Prediction cold_moved = predict(moved, row, o);  // no memo: cold
  const Prediction cold = predict(cell, row, warm);      // cold, and remembered
  const Prediction again = predict(cell, row, warm);     // the remembered cell: two runs
  const Prediction warm_moved = predict(moved, row, warm);
  ASSERT_TRUE(cold.ok() && cold_moved.ok()) << cold.reason << cold_moved.reason;
  EXPECT_EQ(again.value, cold.value);
  EXPECT_EQ(warm_moved.value, cold_moved.value);
  EXPECT_GT(std::abs(std::log(cold_moved.value / cold.value)), 10 * o.transition_rtol);
}

TEST(Forward, CentralDifferencesAgreeAtTwoSteps) {
  // The fit's step 1e-4 (in ln mu and ln lambda) against 1e-5: the central differences agree to 1e-6 of the
  // largest entry (measured 2.7e-8), so neither the evaluation noise (integration to rtol 1e-11, extrema from 1024
  // samples per period) nor the O(h^2) truncation error (measured 1.3e-5 at 1e-3) matters at 1e-4; a one-sided
  // difference at 1e-4 agrees to O(h).
  const CellModel cell = synthetic_cell();
  const ObservationData data = synthetic_data(cell, 0.0, 1);
  const std::vector<FitParameter> free = {FitParameter::shear_modulus, FitParameter::lambda};
  FitOptions o;
  const Linearisation a = linearise(data.rows, free, cell, o, 1e-4);
  const Linearisation b = linearise(data.rows, free, cell, o, 1e-5);
  ASSERT_TRUE(a.ok) << a.reason;
  ASSERT_TRUE(b.ok) << b.reason;
  double largest = 0;
  for (const auto& row : a.J)
    for (double v : row) largest = std::max(largest, std::abs(v));
  ASSERT_GT(largest, 1.0);  // the observables do depend on mu and lambda
  for (std::size_t i = 0; i < a.J.size(); ++i)
    for (std::size_t j = 0; j < free.size(); ++j) EXPECT_NEAR(a.J[i][j], b.J[i][j], 1e-6 * largest) << i << "," << j;
  CellModel plus = cell;
  plus.shear_modulus *= std::exp(1e-4);
  const Linearisation p = linearise(data.rows, {}, plus, o, 1e-4);
  ASSERT_TRUE(p.ok);
  for (std::size_t i = 0; i < a.J.size(); ++i) EXPECT_NEAR((p.r[i] - a.r[i]) / 1e-4, a.J[i][0], 1e-3 * largest) << i;
}

}  // namespace
}  // namespace rbcstab
