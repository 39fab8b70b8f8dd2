// The reduced runs behind the predictors: (b) finite horizon against (c) the modal simulation, the time average
// of sigma_R against closed forms, and the regime of the reduced dynamics (paper Fig. 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

Scene fig3(double lambda, double beta) {
  Scene s;  // defaults: B = 2, C = 0.04, Delta = 1, Delta0 = 0.01, L = 10, T = 500
  s.parameters.lambda = lambda;
  s.beta = beta;
  return s;
}

// While the Delta_l stay small, sigma = sigma_R + O(sum Delta_l / Delta) and every l >= 3 obeys
// Delta_l' = 2 Upsilon_l(sigma) Delta_l exactly, so ln(Delta_l(T)/Delta_l(0)) = 2 G_l(T) + O(max Delta_l * T *
// |dUpsilon/dsigma|).
TEST(FiniteHorizon, MatchesModalSimulationWhileModesAreSmall) {
  for (double lambda : {1.0, 5.0})
    for (double beta : {0.0, kHalfPi}) {
      Scene s = fig3(lambda, beta);
      s.delta = 1e-10;
      s.L = 8;
      s.model = ModelLevel::modal;
      // Horizon with max_l 2 G_l(T) ~ ln(1e5): the modes grow to ~1e-5 and stay small.
      const FiniteHorizon probe = finite_horizon_growth(s, 20);
      const double g_max = *std::max_element(probe.G.begin() + 1, probe.G.end());
      s.T = g_max > 0 ? std::min(20.0, 20 * std::log(1e5) / (2 * g_max)) : 20.0;
      const FiniteHorizon h = finite_horizon_growth(s, s.T);
      ASSERT_EQ(h.status, IntegrationStatus::success);
      SimulationOptions so;
      so.integrator.rtol = 1e-11;
      so.integrator.atol = 1e-14;
      const SimulationResult r = simulate(s, so);
      ASSERT_EQ(r.status, IntegrationStatus::success);
      double max_Delta = 0, worst = 0;
      for (int l = 3; l <= s.L; ++l) {
        const std::size_t k = std::size_t(l - 2);
        max_Delta = std::max(max_Delta, r.Delta_final[k]);
        if (!(r.Delta_final[k] > 0)) continue;  // a decayed mode below the smallest double: nothing to compare
        const double measured = std::log(r.Delta_final[k] / r.Delta_initial[k]);
        worst = std::max(worst, std::abs(measured - 2 * h.G[k]));
      }
      std::printf("lambda %g beta %g T %g: max Delta_l(T) %.3g, max |ln ratio - 2 G_l| %.3g, 2 G_3 = %.4g\n", lambda,
                  beta, s.T, max_Delta, worst, 2 * h.G[1]);
      ASSERT_LT(max_Delta, 1e-4);  // the modes stayed small: the linear prediction applies
      // Error budget: the nonlinear feedback sum Delta_l/Delta <= 1e-4 over T = 20 and the rtol 1e-11 runs.
      EXPECT_LT(worst, 1e-3 + 1e-4 * s.T * std::abs(Gamma2(lambda, s.L) / s.parameters.B));
    }
}

// The finite-horizon G_l are an exact quadrature: a finer tolerance changes them by O(rtol).
TEST(FiniteHorizon, ConvergesWithTolerance) {
  const Scene s = fig3(5, kHalfPi);
  PredictorOptions fine;
  fine.integrator.rtol = 1e-13;
  const FiniteHorizon a = finite_horizon_growth(s, 100), b = finite_horizon_growth(s, 100, fine);
  for (std::size_t k = 0; k < a.G.size(); ++k) EXPECT_NEAR(a.G[k], b.G[k], 1e-7 * (1 + std::abs(b.G[k])));
}

// A transient serves every B of its flow (transient_at_B): G_l(T) from a run at B = 2 mapped to another B equals
// that of a direct run there to their integration error (rtol 1e-10 of int sigma_R: 1e-7 relative leaves a
// factor ~1000; the mapping itself is exact to rounding). Flows of both orientations, small to large B and C.
TEST(FiniteHorizon, TransientMapsAcrossB) {
  for (double beta : {0.001, kHalfPi})
    for (double C : {0.01, 0.5, 7.4}) {
      Scene s = fig3(5, beta);
      s.parameters.C = C;
      const ReducedTransient source = reduced_transient(s, s.T);
      ASSERT_EQ(source.status, IntegrationStatus::success);
      for (double B : {0.37, 2.0, 40.0, 400.0}) {
        Scene t = s;
        t.parameters.B = B;
        const FiniteHorizon mapped = finite_horizon_growth(t, transient_at_B(source, t));
        const FiniteHorizon direct = finite_horizon_growth(t, t.T);
        EXPECT_NEAR(mapped.mean_sigma_R, direct.mean_sigma_R, 1e-7 * (1 + std::abs(direct.mean_sigma_R)))
            << "beta " << beta << " C " << C << " B " << B;
        for (std::size_t k = 0; k < direct.G.size(); ++k)
          EXPECT_NEAR(mapped.G[k], direct.G[k], 1e-7 * (1 + std::abs(direct.G[k])))
              << "beta " << beta << " C " << C << " B " << B << " l " << k + 2;
      }
      // The same B: the transient itself.
      EXPECT_EQ(transient_at_B(source, s).integral_end, source.integral_end);
      Scene other = s;
      other.parameters.C = 2 * C;
      EXPECT_THROW((void)transient_at_B(source, other), InvalidArgument);
    }
}

// Out of plane the attractor is the exact equilibrium: the converged time average equals its sigma_R.
TEST(AsymptoticPredictor, TimeAverageEqualsEquilibriumOutOfPlane) {
  for (double lambda : {1.0, 5.0}) {
    const Scene s = fig3(lambda, 0.0);
    const SigmaAverage avg = time_averaged_sigma_R(s);
    ASSERT_TRUE(avg.mean.valid()) << avg.mean.reason;
    const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(s.parameters);
    // After 500 time units the transient (decay >= 0.3, see the equilibrium tests) is below 1e-60.
    EXPECT_NEAR(avg.mean.value, eq.sigma_R, 1e-8 * std::abs(eq.sigma_R));
  }
}

// Eq. ss_st_red against the time average along an integrated trajectory: Lambda < 1, S >> 1,
// both orientations. The measured gap is O(1/S) (printed, recorded in docs/theory.md).
TEST(AsymptoticPredictor, MeanSigmaRMinusMatchesTimeAverage) {
  for (double beta : {0.0, kHalfPi}) {
    Scene s = fig3(1.0, beta);  // Lambda = 0.708
    s.parameters.C = 100;       // S = 4854
    const SigmaAverage avg = time_averaged_sigma_R(s);
    ASSERT_TRUE(avg.mean.valid()) << avg.mean.reason;
    const Quantity closed = mean_sigma_R_minus(s.parameters);
    std::printf("beta %g: <sigma_R> time average %.8g, Eq. ss_st_red %.8g (S = %.4g)\n", beta, avg.mean.value,
                closed.value, s.parameters.S());
    // O(1/S) corrections times the O(B sqrt(30 pi / Delta)) coefficient: 1e-3 covers S = 4854.
    EXPECT_NEAR(avg.mean.value, closed.value, 1e-3 * std::abs(closed.value));
  }
}

// Fig. 2: C = 0.04, lambda = 5, Delta0 = 0.01. In plane: swinging at Delta = 0.01, tumbling at Delta = 1;
// out of plane: a steady state (rolling) for both.
TEST(Regime, Figure2) {
  for (double Delta : {0.01, 1.0}) {
    Scene s = fig3(5, kHalfPi);
    s.parameters.Delta = Delta;
    const RegimeResult ip = reduced_regime(s);
    EXPECT_EQ(ip.regime, Delta < 0.1 ? Regime::swinging : Regime::tumbling) << Delta << ": " << ip.reason;
    std::printf("Delta %g in plane: %s, Psi range %.3g, r range %.3g\n", Delta, to_string(ip.regime).c_str(),
                ip.Psi_range, ip.r_range);
    s.beta = 1e-3;
    const RegimeResult op = reduced_regime(s);
    EXPECT_EQ(op.regime, Regime::rolling) << Delta << ": " << op.reason;
  }
}

// An out-of-plane start whose Psi and r oscillate (lambda = 10, C = 1: Psi range 0.08, measured) is not called
// swinging, the paper's in-plane motion (Sec. IV): the same oscillation's name says it started out of plane.
TEST(Regime, OutOfPlaneOscillationIsNotSwinging) {
  Scene s = fig3(10, 1e-3);
  s.parameters.C = 1;
  const RegimeResult op = reduced_regime(s);
  EXPECT_EQ(op.regime, Regime::oscillating_out_of_plane) << op.reason;
  EXPECT_GT(op.Psi_range, 1e-2) << op.reason;  // a real oscillation, far above the steady threshold 1e-4
  EXPECT_LT(op.Psi_range, kTwoPi) << op.reason;
  EXPECT_NE(op.reason.find("out-of-plane start"), std::string::npos) << op.reason;
  EXPECT_NE(to_string(op.regime), "swinging");
}

TEST(PredictorOptions, DefaultsAreValidAndBadFieldsAreNamed) {
  EXPECT_NO_THROW(PredictorOptions{}.validate());
  PredictorOptions o;
  o.window = -1;
  try {
    o.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "window");
  }
}

}  // namespace
}  // namespace rbcstab
