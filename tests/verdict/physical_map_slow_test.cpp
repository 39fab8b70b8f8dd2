// The physical map's regime stepper (verdict/physical_map.hpp, regime_stepper): an implicit stepper classifies the
// reduced regime as the default explicit one does. Slow (rosenbrock costs ~14x rk8pd here): label slow, run with
//   ctest --test-dir build/release -R PhysicalMapSlow
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/verdict/physical_map.hpp"
#include "verdict/physical_map_cell.hpp"

namespace rbcstab {
namespace {

// An implicit regime stepper (regime_stepper = rosenbrock) classifies the reduced regime as the explicit rk8pd
// does, on both sides of the tumbling boundary the rk8pd map finds (the two points differ in regime, so agreement
// there is not agreement by default), and at the smallest C of scenes/physical_map.toml (1 mPa s, 0.1/s: C ~ 5e-5).
// Two regime runs per point: rosenbrock costs about 14x rk8pd here (docs/units.md, "Cost").
TEST(PhysicalMapSlow, StiffRegimeStepperKeepsTheClassification) {
  PhysicalMapOptions o = test::fast_map(25e-3, 25e-3, 1);
  ASSERT_EQ(o.regime_stepper, Stepper::rk8pd);
  const RateCrossing e = physical_map(test::map_cell(), o).columns[0].tumbling_to_swinging;
  ASSERT_TRUE(e.found) << e.reason;
  auto regime = [&](double eta, double rate, Stepper stepper) {
    Scene s = with_physical_value(test::map_cell(), "viscosity", eta);
    s.beta = std::acos(0.0);
    set_parameter(s, SceneParameter::shear_rate, rate);
    PredictorOptions p = o.predictor;
    p.integrator.stepper = stepper;
    return reduced_regime(s, p).regime;
  };
  const std::pair<double, double> points[] = {{25e-3, e.lo / 1.5}, {25e-3, e.hi * 1.5}, {1e-3, 0.1}};
  Regime seen[3];
  for (int k = 0; k < 3; ++k) {
    const auto& [eta, rate] = points[k];
    seen[k] = regime(eta, rate, Stepper::rk8pd);
    EXPECT_EQ(to_string(regime(eta, rate, Stepper::rosenbrock)), to_string(seen[k])) << eta << " Pa s, " << rate;
  }
  EXPECT_EQ(seen[0], Regime::tumbling);
  EXPECT_NE(seen[1], Regime::tumbling);
}

}  // namespace
}  // namespace rbcstab
