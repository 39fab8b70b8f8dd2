// The verdict service: predict() (the summary's predictors) on the paper's Fig. 3 scenes, the same asymptotic
// verdict as the boundary tracer's criterion (one function), and the shared reduced transient.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "model/test_scenes.hpp"
#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

Scene fig3(double lambda, double beta) {
  Scene s = testing::fig3_scene(beta);
  s.parameters.lambda = lambda;
  return s;
}

// The three predictors on the paper's Fig. 3 scenes (B = 2, C = 0.04, alpha = 50): the paper reports that
// l = 3 takes the area in both orientations (Fig. 3 b-c).
TEST(Predict, Figure3Scenes) {
  for (double beta : {1e-3, kHalfPi}) {
    const Scene s = fig3(5, beta);
    SimulationOptions so;
    so.record_trajectory = false;
    const SimulationResult r = simulate(s, so);
    ASSERT_EQ(r.status, IntegrationStatus::success);
    const ScenePrediction pr = predict(s, &r);
    ASSERT_TRUE(pr.sigma_R_asymptotic.valid()) << pr.sigma_R_asymptotic.reason;
    EXPECT_EQ(pr.out_of_plane, beta < 0.1);
    EXPECT_EQ(pr.asymptotic.unstable, unstable_modes(pr.sigma_R_asymptotic.value, s.parameters.alpha(), s.L));
    for (int l = 2; l <= s.L; ++l)
      EXPECT_DOUBLE_EQ(pr.asymptotic.rate[std::size_t(l - 2)], Upsilon_l(s.parameters, l, pr.sigma_R_asymptotic.value));
    std::printf("beta %g: <sigma_R> %.6g (%s), l_Delta asymptotic %d, finite horizon %d, simulation %d\n", beta,
                pr.sigma_R_asymptotic.value, pr.asymptotic_source.c_str(), pr.asymptotic.l_Delta,
                pr.finite_horizon.l_Delta, pr.simulation.l_Delta);
    EXPECT_EQ(pr.simulation.l_Delta, 3);
    EXPECT_EQ(pr.asymptotic.l_Delta, 3);
  }
}

// One asymptotic verdict: on in-plane scenes (Appendix E(a) plane, lambda = 1, Delta = 1, L = 5) the summary's
// predictor, the tracer's criterion and the agreement's point verdict all come from asymptotic_sigma_R, so
// <sigma_R> is the same double and the verdicts (stable or unstable, and the mode) are the same. The scenes
// straddle the l = 3 boundary (ln C = -2: unstable, ln C = 0: stable; the traced App. E(a) boundary runs
// between them at ln B = 3), so both outcomes are compared.
TEST(Verdict, SummaryPredictorAndTraceCriterionAgreeInPlane) {
  Scene base = fig3(1, kHalfPi);
  base.L = 5;
  DiagramSpec plane;
  plane.x = {Axis::lnB, 2, 4, 3};
  plane.y = {Axis::lnC, -3, 1, 5};
  TraceOptions to;  // the tracer's own options: rtol 1e-12 reduced runs, the periodic-orbit average
  const ModeCriteria criteria = plane_criteria(base, plane, to);
  int stable = 0, unstable = 0;
  for (double lnC : {-2.0, 0.0}) {
    const Scene s = plane_scene(base, plane, 3.0, lnC);
    const ScenePrediction pr = predict(s, nullptr, to.predictor, to.orbit);
    const AsymptoticVerdict v = asymptotic_verdict(s, to.predictor, to.orbit);
    const CriterionSample c = criteria.at(3.0, lnC);
    ASSERT_TRUE(pr.sigma_R_asymptotic.valid()) << pr.sigma_R_asymptotic.reason;
    EXPECT_EQ(pr.asymptotic_sigma.source, SigmaSource::periodic_orbit) << pr.asymptotic_source;
    EXPECT_EQ(pr.sigma_R_asymptotic.value, v.sigma_R);
    EXPECT_EQ(pr.sigma_R_asymptotic.value, c.sigma_R);
    EXPECT_EQ(!pr.asymptotic.unstable.empty(), v.unstable);
    EXPECT_EQ(pr.asymptotic.l_Delta, v.l);
    // The tracer's criteria mu_l (l = 3..L) are the predictor's rates.
    ASSERT_EQ(c.g.size() + 1, pr.asymptotic.rate.size());
    for (std::size_t k = 0; k < c.g.size(); ++k) EXPECT_EQ(c.g[k], pr.asymptotic.rate[k + 1]);
    (v.unstable ? unstable : stable) += 1;
    std::printf("ln C %g: <sigma_R> %.12g, verdict %s (l = %d)\n", lnC, v.sigma_R, v.unstable ? "unstable" : "stable",
                v.l);
  }
  EXPECT_EQ(stable, 1);
  EXPECT_EQ(unstable, 1);
}

// The summary's asymptotic <sigma_R> in plane is now the attracting orbit's period average, where it used a
// time average over [500, 2500]. The two agree to the time average's own error, estimated by its halves
// (as OrbitAverage.EqualsLongTimeAverage, whose window holds whole periods; here it does not, so the bound
// also covers the partial-period error ~ period / window of the oscillation amplitude: 1e-3 relative).
// The measured difference is printed (recorded in the change's report).
TEST(Verdict, InPlaneSummaryUsesTheAttractingOrbit) {
  for (double lambda : {1.0, 5.0}) {
    const Scene s = fig3(lambda, kHalfPi);
    const ScenePrediction pr = predict(s, nullptr);
    ASSERT_TRUE(pr.sigma_R_asymptotic.valid()) << pr.sigma_R_asymptotic.reason;
    const SigmaAverage ta = time_averaged_sigma_R(s);
    ASSERT_TRUE(ta.mean.valid()) << ta.mean.reason;
    const double diff = pr.sigma_R_asymptotic.value - ta.mean.value;
    std::printf("lambda %g in plane: %s <sigma_R> %.12g, time average %.12g, difference %.3g (halves differ by %.3g)\n",
                lambda, to_string(pr.asymptotic_sigma.source).c_str(), pr.sigma_R_asymptotic.value, ta.mean.value, diff,
                ta.first_half - ta.second_half);
    if (pr.asymptotic_sigma.source == SigmaSource::periodic_orbit)
      EXPECT_NEAR(pr.sigma_R_asymptotic.value, ta.mean.value,
                  4 * std::abs(ta.first_half - ta.second_half) + 1e-3 * std::abs(ta.mean.value));
    else
      EXPECT_FALSE(pr.asymptotic_sigma.note.empty());
  }
}

// Out of plane the asymptotic verdict is the exact equilibrium, as before the verdicts were unified.
TEST(Verdict, OutOfPlaneSummaryUsesTheExactEquilibrium) {
  const Scene s = fig3(5, 1e-3);
  const ScenePrediction pr = predict(s, nullptr);
  EXPECT_EQ(pr.asymptotic_sigma.source, SigmaSource::equilibrium);
  EXPECT_EQ(pr.sigma_R_asymptotic.value, out_of_plane_equilibrium(s.parameters).sigma_R);
  EXPECT_EQ(pr.asymptotic_source, "exact out-of-plane equilibrium");
}

// predict() from the transient the truncation rule reads (the summary's path): the finite-horizon verdict is
// finite_horizon_growth of that transient, the asymptotic one does not depend on it, and G_l(T) agrees with
// predict()'s own one-checkpoint run to the integration error (1e-7 relative, FiniteHorizon.ConvergesWithTolerance).
TEST(Predict, SharedTransient) {
  for (double beta : {1e-3, kHalfPi}) {
    const Scene s = fig3(5, beta);
    const ReducedTransient tr = truncation_transient(s);
    const ScenePrediction shared = predict(s, tr, nullptr), own = predict(s, nullptr);
    const FiniteHorizon h = finite_horizon_growth(s, tr);
    EXPECT_EQ(shared.horizon.G, h.G);
    EXPECT_EQ(shared.horizon.counters.rhs_evaluations, tr.counters.rhs_evaluations);
    EXPECT_EQ(shared.sigma_R_asymptotic.value, own.sigma_R_asymptotic.value);
    EXPECT_EQ(shared.finite_horizon.unstable, own.finite_horizon.unstable);
    EXPECT_EQ(shared.finite_horizon.l_Delta, own.finite_horizon.l_Delta);
    ASSERT_EQ(shared.horizon.G.size(), own.horizon.G.size());
    for (std::size_t k = 0; k < h.G.size(); ++k)
      EXPECT_NEAR(shared.horizon.G[k], own.horizon.G[k], 1e-7 * (1 + std::abs(own.horizon.G[k])));
  }
  Scene s = fig3(5, 1e-3);
  const ReducedTransient tr = truncation_transient(s);
  s.T = 400;
  try {
    (void)predict(s, tr, nullptr);
    FAIL() << "a transient over another horizon was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "transient");
  }
}

TEST(Predict, SimulationVerdictNeedsARun) {
  const ModePrediction c = simulation_prediction(nullptr);
  EXPECT_EQ(c.status, DomainStatus::outside_domain);
  EXPECT_EQ(c.reason, "no simulation supplied");
}

}  // namespace
}  // namespace rbcstab
