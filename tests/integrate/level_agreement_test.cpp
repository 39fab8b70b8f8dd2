// Agreement between model levels where two are exact (docs/theory.md, "Model levels and why they are exact"):
// full vs modal on the Fig. 3 scenes, modal vs reduced on the Fig. 2 scenes, and the modal
// level's reconstructed amplitudes against the full model's f_{l,m}.
//
// Tolerances: both levels integrate the same exact dynamics, so they differ by the sum of their
// global errors. The convergence test (conservation_test.cpp) shows the global error of these
// scenes stays below ~1e2 * rtol (relative to Delta, resp. |sigma|) for rk8pd; we allow 1e3 * rtol.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrate/run_helpers.hpp"
#include "model/test_scenes.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/full_model.hpp"
#include "rbcstab/model/modal_model.hpp"

namespace rbcstab {
namespace {

constexpr double kRtol = 1e-10;
constexpr double kGrowth = 1e3;  // global error / rtol allowed (see the header comment)
using testing::fig2_scene;
using testing::fig3_scene;
using testing::max_deviation;
using testing::run;

class FullVsModal : public ::testing::TestWithParam<double> {};

TEST_P(FullVsModal, Fig3TrajectoriesAgree) {
  // The paper's whole horizon T = 500 (the full level takes ~0.2 s here).
  const Scene s = fig3_scene(GetParam());
  const SimulationResult full = run(s, ModelLevel::full, kRtol);
  const SimulationResult modal = run(s, ModelLevel::modal, kRtol);
  ASSERT_EQ(full.status, IntegrationStatus::success) << full.reason;
  ASSERT_EQ(modal.status, IntegrationStatus::success) << modal.reason;
  ASSERT_EQ(full.trajectory.t.size(), modal.trajectory.t.size());
  const auto d = max_deviation(full, modal);
  std::cout << "full vs modal, beta = " << GetParam() << ": max |dDelta_l| = " << d.Delta
            << ", max |dsigma| = " << d.sigma << ", max |dr| = " << d.r << "\n";
  const double Delta = s.parameters.Delta;
  const double sigma_scale = std::abs(full.sigma_initial) + std::abs(full.sigma_final);
  EXPECT_LE(d.Delta, kGrowth * kRtol * Delta);
  EXPECT_LE(d.sigma, kGrowth * kRtol * sigma_scale);
  EXPECT_LE(d.r, kGrowth * kRtol);
  // The scene is not trivial: area really moved to l = 3.
  EXPECT_GT(full.Delta_final[1], 0.3);
  EXPECT_EQ(full.l_Delta, modal.l_Delta);
}

INSTANTIATE_TEST_SUITE_P(OutOfPlaneAndInPlane, FullVsModal, ::testing::Values(0.001, kPi / 2));

struct Fig2Case {
  double Delta, beta;
};
void PrintTo(const Fig2Case& c, std::ostream* os) { *os << "{Delta " << c.Delta << ", beta " << c.beta << "}"; }
class ModalVsReduced : public ::testing::TestWithParam<Fig2Case> {};

TEST_P(ModalVsReduced, Fig2TrajectoriesAgree) {
  const Scene s = fig2_scene(GetParam().Delta, GetParam().beta);
  const SimulationResult modal = run(s, ModelLevel::modal, kRtol);
  const SimulationResult red = run(s, ModelLevel::reduced, kRtol);
  ASSERT_EQ(modal.status, IntegrationStatus::success) << modal.reason;
  ASSERT_EQ(red.status, IntegrationStatus::success) << red.reason;
  EXPECT_TRUE(red.level.exact);
  const auto d = max_deviation(modal, red);
  std::cout << "modal vs reduced, Delta = " << GetParam().Delta << ", beta = " << GetParam().beta
            << ": max |dr| = " << d.r << ", max |dPsi| = " << d.Psi << ", max |dsigma| = " << d.sigma << "\n";
  const double sigma_scale = std::abs(modal.sigma_initial) + std::abs(modal.sigma_final) + 1;
  EXPECT_LE(d.r, kGrowth * kRtol);
  // Psi is an angle: the error of z = r e^{-i Psi} divided by r (r >= sqrt(3)/2 or grows from 0 fast).
  EXPECT_LE(d.Psi, kGrowth * kRtol / std::max(1e-3, std::min(modal.r_final, red.r_final)));
  EXPECT_LE(d.sigma, kGrowth * kRtol * sigma_scale);
  EXPECT_LE(d.Delta, kGrowth * kRtol * s.parameters.Delta);
}

INSTANTIATE_TEST_SUITE_P(Fig2, ModalVsReduced,
                         ::testing::Values(Fig2Case{0.01, 0.0}, Fig2Case{0.01, kPi / 2}, Fig2Case{1.0, 0.0},
                                           Fig2Case{1.0, kPi / 2}));

TEST(ModalAmplitudes, ReconstructedAmplitudesMatchFullModel) {
  // A generic orientation (all m present) on the Fig. 3 material, through the instability.
  Scene s = fig3_scene(0.7);
  s.L = 6;
  const InitialState init = initial_state(s);
  FullModel full(s.parameters, init);
  ModalModel modal(s.parameters, init);
  IntegratorOptions o;
  o.rtol = kRtol;
  o.atol = 1e-16;
  for (double T : {5.0, 30.0, 60.0}) {
    const std::vector<double> grid{T};
    const auto rf = integrate(full, full.initial_state(), 0, grid, o, {});
    const auto rm = integrate(modal, modal.initial_state(), 0, grid, o, {});
    ASSERT_EQ(rf.status, IntegrationStatus::success);
    ASSERT_EQ(rm.status, IntegrationStatus::success);
    const ModeAmplitudes ff = full.amplitudes(T, rf.y), fm = modal.amplitudes(T, rm.y);
    double worst = 0;
    for (int l = 2; l <= s.L; ++l) {
      // Each f_{l,m} to kGrowth * (rtol * |block| + atol), the mixed error control of both runs,
      // with |block| = sqrt(Delta_l / a_l). Decayed blocks (Delta_l ~ 1e-130 at T = 60) are held by
      // the full level only to atol, so they pass on the absolute part.
      const double block = std::sqrt(ff.excess_area(l) / a_l(l));
      for (int m = -l; m <= l; ++m) {
        const double err = std::abs(ff.at(l, m) - fm.at(l, m));
        if (block > 1e-6) worst = std::max(worst, err / block);
        EXPECT_LE(err, kGrowth * (kRtol * block + o.atol)) << "T = " << T << ", l = " << l << ", m = " << m;
      }
    }
    std::cout << "amplitudes at T = " << T << ": max relative error of blocks > 1e-6: " << worst << "\n";
    EXPECT_LE(worst, kGrowth * kRtol);
  }
}

TEST(SigmaFollowsReduced, WhilePerturbationsAreSmall) {
  // Sec. IV / Fig. 3(d): sigma(t) first follows sigma_R(t) of the reduced system. With beta = 0 the
  // reduced system is the modal one without the l >= 3 modes, so the difference is caused by their
  // area eps(t) = sum_{l>=3} Delta_l(t) / Delta only: sigma = -N/D with N, D perturbed by relative
  // O(eps (Pi_l + 4 alpha/Pi_l)/|sigma|) <= O(10 eps) here; we allow 100 eps |sigma| + 1e3 rtol |sigma|.
  Scene s = fig3_scene(0.0);
  s.delta = 1e-10;
  s.T = 6;
  s.dt = 0.25;
  const SimulationResult modal = run(s, ModelLevel::modal, kRtol);
  Scene r2 = s;
  r2.L = 2;
  const SimulationResult red = run(r2, ModelLevel::reduced, kRtol);
  ASSERT_EQ(modal.status, IntegrationStatus::success);
  ASSERT_EQ(red.status, IntegrationStatus::success);
  ASSERT_EQ(modal.trajectory.t.size(), red.trajectory.t.size());
  double worst = 0;
  for (std::size_t k = 0; k < modal.trajectory.t.size(); ++k) {
    double eps = 0;
    for (std::size_t j = 1; j < modal.trajectory.Delta_l[k].size(); ++j) eps += modal.trajectory.Delta_l[k][j];
    eps /= s.parameters.Delta;
    const double sm = modal.trajectory.sigma[k], sr = red.trajectory.sigma[k];
    worst = std::max(worst, std::abs(sm - sr) / (eps * std::abs(sr)));
    EXPECT_NEAR(sm, sr, (100 * eps + kGrowth * kRtol) * std::abs(sr)) << "t = " << modal.trajectory.t[k];
  }
  std::cout << "max |sigma - sigma_R| / (eps |sigma_R|) = " << worst << "\n";
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
// final_amplitudes rebuilds f_{l,m}(T) on the level the run chose (modal here): each block's excess area equals
// the run's own Delta_l(T), which the simulation observes independently from the state (relative 1e-12: the
// same numbers through two formulas).
TEST(FinalAmplitudes, AreasEqualTheRunsDeltaAtT) {
  Scene s = testing::fig3_scene(0.7);
  s.L = 6;
  s.T = 30;
  SimulationOptions o;
  o.full_horizon = true;
  const SimulationResult r = simulate(s, o);
  ASSERT_EQ(r.status, IntegrationStatus::success);
  ASSERT_EQ(r.level.level, ModelLevel::modal);
  const ModeAmplitudes f = final_amplitudes(s, r);
  for (int l = 2; l <= s.L; ++l)
    EXPECT_NEAR(f.excess_area(l), r.Delta_final[std::size_t(l - 2)], 1e-12 * r.Delta_final[std::size_t(l - 2)]) << l;
}
}  // namespace
}  // namespace rbcstab
