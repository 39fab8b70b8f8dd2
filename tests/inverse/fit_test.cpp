// The fit: synthetic recovery (noiseless to the optimiser's tolerance; with noise inside the 95 % intervals), the
// statuses, and the plain statement of what the data cannot identify.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/inverse/fit.hpp"
#include "synthetic_cell.hpp"

namespace rbcstab {
namespace {

// The start: the truth's moduli and lambda moved by factors of e^0.4 and e^-0.3.
CellModel start_of(const CellModel& truth) {
  CellModel s = truth;
  s.shear_modulus *= std::exp(0.4);
  s.lambda *= std::exp(-0.3);
  return s;
}

TEST(Fit, NoiselessDataRecoverTheTruth) {
  const CellModel truth = synthetic_cell();
  ObservationData data = synthetic_data(truth, 0.0, 1);
  // Two rows name the regime they were seen in: the right one and a wrong one (compared, not fitted).
  data.rows[0].has_regime = data.rows[1].has_regime = true;
  data.rows[0].regime = Regime::swinging;
  data.rows[1].regime = Regime::tumbling;
  FitOptions o;
  o.starts = 1;
  const FitResult r = fit(data, {"mu", "lambda"}, start_of(truth), o);
  ASSERT_EQ(r.status, FitStatus::converged) << r.message;
  EXPECT_TRUE(r.residuals[0].regime_agrees);
  EXPECT_FALSE(r.residuals[1].regime_agrees);
  EXPECT_NE(fit_text(r).find("(seen tumbling, predicted swinging)"), std::string::npos) << fit_text(r);
  EXPECT_NEAR(r.cell.shear_modulus / truth.shear_modulus, 1.0, 1e-6);
  EXPECT_NEAR(r.cell.lambda / truth.lambda, 1.0, 1e-6);
  EXPECT_LT(r.chi2, 1e-8);
  EXPECT_TRUE(r.unidentifiable.empty());
  for (const FitEstimate& e : r.estimates) {
    EXPECT_TRUE(e.identifiable);
    EXPECT_LT(e.lo95, e.value);
    EXPECT_GT(e.hi95, e.value);
  }
}

TEST(Fit, NoisyDataCoverTheTruthWithinTheirIntervals) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 1.0, 7);
  FitOptions o;
  o.starts = 2;
  const FitResult r = fit(data, {"shear_modulus", "lambda"}, start_of(truth), o);
  ASSERT_EQ(r.status, FitStatus::converged) << r.message;
  ASSERT_EQ(r.estimates.size(), 2u);
  const double t[] = {truth.shear_modulus, truth.lambda};
  for (std::size_t j = 0; j < 2; ++j) {
    const FitEstimate& e = r.estimates[j];
    EXPECT_LE(e.lo95, t[j]) << e.parameter.name;
    EXPECT_GE(e.hi95, t[j]) << e.parameter.name;
    // Near: within 3 standard errors, and the interval is informative (narrower than a factor 2 either way).
    EXPECT_LT(std::abs(std::log(e.value / t[j])), 3 * e.standard_error) << e.parameter.name;
    EXPECT_LT(e.hi95 / e.lo95, 4.0) << e.parameter.name;
  }
  // chi^2 of 8 rows with 2 parameters: within the central 99.9 % of chi^2(6).
  EXPECT_GT(r.chi2, 0.38);
  EXPECT_LT(r.chi2, 22.5);
  EXPECT_EQ(r.residuals.size(), data.rows.size());
  EXPECT_NEAR(r.correlation[0][0], 1.0, 1e-12);
}

TEST(Fit, NamesAParameterNoObservableDependsOn) {
  // The reduced motion holds no B (Eq. red_eqs), so no observable of the file depends on kappa.
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  FitOptions o;
  o.starts = 1;
  const FitResult r = fit(data, {"mu", "kappa"}, truth, o);
  EXPECT_EQ(r.status, FitStatus::converged) << r.message;
  ASSERT_EQ(r.estimates.size(), 2u);
  EXPECT_TRUE(r.estimates[0].identifiable);
  EXPECT_NEAR(r.estimates[0].value / truth.shear_modulus, 1.0, 1e-6);
  EXPECT_FALSE(r.estimates[1].identifiable);
  EXPECT_TRUE(std::isnan(r.estimates[1].lo95));
  EXPECT_TRUE(std::isnan(r.correlation[0][1]));
  ASSERT_EQ(r.unidentifiable.size(), 1u) << r.message;
  EXPECT_NE(r.message.find("no observable given depends on bending_modulus"), std::string::npos) << r.message;
}

TEST(Fit, StatusesAreNeverSilent) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  FitOptions o;
  o.starts = 1;
  o.max_iterations = 1;
  const FitResult r = fit(data, {"mu", "lambda"}, start_of(truth), o);
  EXPECT_EQ(r.status, FitStatus::maximum_iterations);
  EXPECT_NE(r.message.find("did not converge"), std::string::npos) << r.message;
}

TEST(Fit, RefusesBadRequests) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  EXPECT_THROW(fit(data, {}, truth), InvalidArgument);
  EXPECT_THROW(fit(data, {"mu", "shear_modulus"}, truth), InvalidArgument);
  EXPECT_THROW(fit(data, {"stiffness"}, truth), InvalidArgument);
  FitOptions o;
  o.starts = 0;
  EXPECT_THROW(fit(data, {"mu"}, truth, o), InvalidArgument);
  CellModel outside = truth;
  outside.shear_modulus = 1.0;  // N/m: beyond plausible_range
  EXPECT_THROW(fit(data, {"mu"}, outside), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
