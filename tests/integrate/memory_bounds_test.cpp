// Memory bounds checked before a run starts: the kept samples and the dense steppers' matrices. The oracles are
// the documented formulas: 8 (L + 8) bytes a sample (+ 25 (L + 4) as CSV text) and k n^2 8 bytes of matrices.
#include <gtest/gtest.h>

#include <string>

#include "model/test_scenes.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"

namespace rbcstab {
namespace {

std::string refusal(const Scene& s, const SimulationOptions& o, std::string* parameter = nullptr) {
  try {
    (void)simulate(s, o);
  } catch (const InvalidArgument& e) {
    if (parameter) *parameter = e.parameter();
    return e.what();
  }
  return "";
}

TEST(MemoryBounds, TrajectoryBytesFollowTheDocumentedFormula) {
  Scene s;
  s.L = 10;
  s.T = 1000;
  s.dt = 1;
  SimulationOptions o;
  EXPECT_EQ(trajectory_bytes(s, o), 1002.0 * 8 * (10 + 8));
  o.trajectory_text = true;
  EXPECT_EQ(trajectory_bytes(s, o), 1002.0 * (8 * (10 + 8) + 25 * (10 + 4)));
  o.record_trajectory = false;
  EXPECT_EQ(trajectory_bytes(s, o), 0.0);
}

TEST(MemoryBounds, TooManySamplesAreRefusedWithTheEstimateAndTheLimit) {
  Scene s;
  s.L = 100;
  s.T = 1e7;
  s.dt = 1;
  s.delta = 0;
  SimulationOptions o;
  o.trajectory_text = true;
  std::string parameter;
  const std::string m = refusal(s, o, &parameter);
  EXPECT_EQ(parameter, "dt");
  EXPECT_NE(m.find("1e+07 output samples"), std::string::npos) << m;
  EXPECT_NE(m.find("34.6 GB"), std::string::npos) << m;  // (1e7 + 2) (8 * 108 + 25 * 104) bytes
  EXPECT_NE(m.find("2.15 GB"), std::string::npos) << m;  // kMaxTrajectoryBytes = 2 GiB
  // Without the samples kept, the same horizon is no memory concern.
  o.record_trajectory = false;
  o.integrator.max_steps = 10;
  EXPECT_EQ(refusal(s, o), "");
}

TEST(MemoryBounds, DenseSteppersAreRefusedAboveTheirDimensionBeforeTheRun) {
  Scene s = testing::fig3_scene(0.001);
  s.L = 40;  // the full level: n = 2 ((L + 1)^2 - 4) = 3354 > 3000
  s.model = ModelLevel::full;
  SimulationOptions o;
  o.integrator.stepper = Stepper::msbdf;
  std::string parameter;
  const std::string m = refusal(s, o, &parameter);
  EXPECT_EQ(parameter, "stepper");
  EXPECT_NE(m.find("full level at L = 40"), std::string::npos) << m;
  EXPECT_NE(m.find("2 dense 3354 x 3354 matrices, about 180 MB"), std::string::npos) << m;  // 2 * 3354^2 * 8
  EXPECT_NE(m.find("dimension 3000 (144 MB)"), std::string::npos) << m;
  EXPECT_EQ(dense_matrices(Stepper::rk4imp), 5);
  EXPECT_EQ(dense_matrices(Stepper::rosenbrock), 0);
  // rosenbrock solves in O(n): the same scene runs (a few steps).
  o.integrator.stepper = Stepper::rosenbrock;
  o.integrator.max_steps = 3;
  EXPECT_EQ(refusal(s, o), "");
}

}  // namespace
}  // namespace rbcstab
