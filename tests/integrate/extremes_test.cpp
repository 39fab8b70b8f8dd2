// Extremes that must run to the end with finite output (the polar-coordinate traps the regular coordinates avoid):
// beta = 0 exactly (reduced starts at r = 0), C = inf, Delta0 = 0, delta = 1e-14, L = 2, and the
// reduced level with S = inf, which tends smoothly to r = 1, Psi = arccos(Lambda) (Eq. ss_red, Lambda < 1).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "integrate/run_helpers.hpp"
#include "model/test_scenes.hpp"

#include "rbcstab/core/constants.hpp"

namespace rbcstab {
namespace {

using testing::all_finite;
using testing::fig2_scene;
using testing::fig3_scene;
using testing::run;

struct Extreme {
  std::string name;
  Scene scene;
  ModelLevel level;
};

Scene modified(Scene s, void (*f)(Scene&)) {
  f(s);
  return s;
}

void PrintTo(const Extreme& e, std::ostream* os) { *os << e.name; }

class Extremes : public ::testing::TestWithParam<Extreme> {};

TEST_P(Extremes, RunsToTheEndWithFiniteOutput) {
  const Extreme& e = GetParam();
  for (Stepper st : {Stepper::rk8pd, Stepper::rosenbrock}) {
    const SimulationResult r = run(e.scene, e.level, 1e-8, st);
    EXPECT_EQ(r.status, IntegrationStatus::success) << e.name << " " << to_string(st) << ": " << r.reason;
    EXPECT_EQ(r.t_reached, e.scene.T);
    EXPECT_TRUE(all_finite(r)) << e.name;
    EXPECT_LE(r.excess_area_drift, 1e2 * 1e-8 * r.Delta_total_initial) << e.name;
    if (e.level != ModelLevel::automatic) {
      EXPECT_EQ(r.level.level, e.level);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, Extremes,
    ::testing::Values(Extreme{"reduced_beta0", fig2_scene(1.0, 0.0), ModelLevel::reduced},
                      Extreme{"modal_beta0", fig2_scene(1.0, 0.0), ModelLevel::modal},
                      Extreme{"full_beta0", modified(fig3_scene(0.0), [](Scene& s) { s.T = 60; }), ModelLevel::full},
                      Extreme{"modal_C_inf",
                              modified(fig3_scene(0.0),
                                       [](Scene& s) {
                                         s.parameters.C = INFINITY;
                                         s.T = 100;
                                       }),
                              ModelLevel::modal},
                      Extreme{"full_C_inf",
                              modified(fig3_scene(kPi / 2),
                                       [](Scene& s) {
                                         s.parameters.C = INFINITY;
                                         s.T = 50;
                                         s.L = 5;
                                       }),
                              ModelLevel::full},
                      Extreme{"reduced_C_inf",
                              modified(fig2_scene(0.5, kPi / 2), [](Scene& s) { s.parameters.C = INFINITY; }),
                              ModelLevel::reduced},
                      Extreme{"modal_Delta0_0",
                              modified(fig3_scene(kPi / 2),
                                       [](Scene& s) {
                                         s.parameters.Delta0 = 0;
                                         s.T = 100;
                                       }),
                              ModelLevel::modal},
                      Extreme{"reduced_Delta0_0",
                              modified(fig2_scene(1.0, kPi / 2), [](Scene& s) { s.parameters.Delta0 = 0; }),
                              ModelLevel::reduced},
                      Extreme{"modal_delta_1e-14",
                              modified(fig3_scene(0.001),
                                       [](Scene& s) {
                                         s.delta = 1e-14;
                                         s.T = 200;
                                       }),
                              ModelLevel::modal},
                      Extreme{"full_delta_1e-14",
                              modified(fig3_scene(0.001),
                                       [](Scene& s) {
                                         s.delta = 1e-14;
                                         s.T = 100;
                                         s.L = 5;
                                       }),
                              ModelLevel::full},
                      Extreme{"auto_L2",
                              modified(fig3_scene(kPi / 2),
                                       [](Scene& s) {
                                         s.L = 2;
                                         s.T = 50;
                                       }),
                              ModelLevel::automatic},
                      Extreme{"full_L2",
                              modified(fig3_scene(0.3),
                                       [](Scene& s) {
                                         s.L = 2;
                                         s.T = 50;
                                       }),
                              ModelLevel::full},
                      Extreme{"modal_L2",
                              modified(fig3_scene(0.3),
                                       [](Scene& s) {
                                         s.L = 2;
                                         s.T = 50;
                                       }),
                              ModelLevel::modal}),
    [](const ::testing::TestParamInfo<Extreme>& param_info) {
      std::string n = param_info.param.name;
      for (char& c : n)
        if (c == '-') c = 'm';
      return n;
    });

TEST(Extremes, DeltaTinyStillGrowsWithoutLosingDigits) {
  // delta = 1e-14 at an unstable point: ln Delta_3 grows linearly at first; the modal level carries
  // ln Delta_l, so Delta_3 is resolved from 1e-14 on. Compare with delta = 1e-10 shifted in time:
  // both must end with l_Delta = 3 (the instability is reached from either seed).
  Scene s = fig3_scene(0.001);
  s.delta = 1e-14;
  s.T = 300;
  const SimulationResult r = run(s, ModelLevel::modal, 1e-9);
  ASSERT_EQ(r.status, IntegrationStatus::success);
  EXPECT_EQ(r.l_Delta, 3);
  EXPECT_GT(r.Delta_final[1], 0.1);
}

TEST(Extremes, ReducedWithInfiniteSTendsToTankTreading) {
  // Lambda = 0.19 < 1 and S = inf (Delta0 = 0, and separately C = inf): Eq. ss_red gives r -> 1 and
  // Psi -> arccos(Lambda). From the out-of-plane start beta = 0 exactly (r = 0), through r = 1.
  for (int variant = 0; variant < 2; ++variant) {
    Scene s = fig2_scene(0.01, 0.0);
    if (variant == 0)
      s.parameters.Delta0 = 0;
    else
      s.parameters.C = INFINITY;
    s.T = 200;
    ASSERT_TRUE(std::isinf(s.parameters.S()));
    const double Lambda = s.parameters.Lambda();
    ASSERT_LT(Lambda, 1);
    const SimulationResult r = run(s, ModelLevel::reduced, 1e-10);
    ASSERT_EQ(r.status, IntegrationStatus::success) << r.reason;
    ASSERT_TRUE(all_finite(r));
    // w = sqrt(1 - r^2) decays exponentially (w' = mu w with mu -> -sqrt(1 - Lambda^2)/Lambda < 0):
    // by T = 200, 1 - r is far below the integration tolerance; 1e-8 allows for it.
    EXPECT_NEAR(r.r_final, 1.0, 1e-8);
    EXPECT_NEAR(std::remainder(r.Psi_final - std::acos(Lambda), 2 * kPi), 0, 1e-7);
    // Smooth approach: r is monotone non-decreasing along the samples and never exceeds 1.
    for (std::size_t k = 1; k < r.trajectory.r.size(); ++k) {
      EXPECT_GE(r.trajectory.r[k], r.trajectory.r[k - 1] - 1e-9) << "t = " << r.trajectory.t[k];
      EXPECT_LE(r.trajectory.r[k], 1.0);
    }
  }
}

TEST(ReducedEquilibrium, OutOfPlaneLongTimeStateMatchesClosedForm) {
  // docs/theory.md: for r0 = 0 the reduced system is autonomous and its equilibrium has
  // u = r^2 the root in (0, 1) of Lambda^2 u^2 - (1 + Lambda^2 + S^-2) u + 1 = 0, cos Psi = Lambda r.
  // Direct integration from beta = 0 must end there (convergence is exponential: by T = 300 the
  // distance is far below the 1e-7 we allow; the integration error at rtol 1e-11 is smaller still).
  struct P {
    double Delta, C;
  };
  // (Lambda, S) ~ (0.19, 2), (1.9, 2), (0.7, 20), (1.9, 5): Lambda on both sides of 1, S from 2 to 20.
  for (const P q : {P{0.01, 0.04}, P{1.0, 0.04}, P{0.1368, 0.412}, P{1.0, 0.1}}) {
    Scene s = fig2_scene(q.Delta, 0.0);
    s.parameters.C = q.C;
    s.T = 300;
    const double L = s.parameters.Lambda(), S = s.parameters.S();
    const double b = 1 + L * L + 1 / (S * S);
    const double u = 2 / (b + std::sqrt(b * b - 4 * L * L));  // the smaller root, written without cancellation
    ASSERT_GT(u, 0);
    ASSERT_LT(u, 1);
    const SimulationResult r = run(s, ModelLevel::reduced, 1e-11);
    ASSERT_EQ(r.status, IntegrationStatus::success) << r.reason;
    EXPECT_NEAR(r.r_final, std::sqrt(u), 1e-7) << "Lambda = " << L << ", S = " << S;
    EXPECT_NEAR(std::cos(r.Psi_final), L * std::sqrt(u), 1e-7) << "Lambda = " << L << ", S = " << S;
  }
}

}  // namespace
}  // namespace rbcstab
