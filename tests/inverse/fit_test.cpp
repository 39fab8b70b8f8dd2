// The fit: synthetic recovery (noiseless to the optimiser's tolerance; with noise inside the 95 % intervals), the
// statuses, and the plain statement of what the data cannot identify.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/model/physical.hpp"
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

// Data made with mu at the lower end of its box: the optimum is on the bound, where an interior-point iterate stops
// short of it by the barrier's distance (here 5 % in mu: the motion barely changes with mu at S ~ 10^4) and the
// interval reaches past it; at_bound says so (a 1e-6 tolerance in ln missed it), while the noiseless interior fit
// is not at a bound.
TEST(Fit, AnEstimateOnABoundIsMarked) {
  CellModel truth = synthetic_cell();
  truth.shear_modulus = plausible_range("shear_modulus").min;
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  FitOptions o;
  o.starts = 1;
  const FitResult r = fit(data, {"mu"}, synthetic_cell(), o);
  ASSERT_EQ(r.estimates.size(), 1u) << r.message;
  EXPECT_TRUE(r.estimates[0].at_bound) << r.estimates[0].value;
  const FitResult interior = fit(synthetic_data(synthetic_cell(), 0.0, 1), {"mu"}, start_of(synthetic_cell()), o);
  ASSERT_EQ(interior.estimates.size(), 1u) << interior.message;
  EXPECT_FALSE(interior.estimates[0].at_bound);
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

// FitOptions::stop set from the progress callback once the first of three starts has finished: the fit returns
// `interrupted` with that start's estimate and no intervals, never `converged`; the same fit unstopped converges
// (the control: the status is the stop's, not the data's).
TEST(Fit, StopAfterTheFirstStartIsInterruptedNotConverged) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = one_viscosity(synthetic_data(truth, 0.0, 1));
  CellModel start = truth;
  start.lambda *= std::exp(-0.3);
  std::atomic<bool> stop{false};
  std::vector<int> done;  // starts_done as reported
  FitOptions o;
  o.starts = 3;
  o.stop = &stop;
  o.on_progress = [&](const FitProgress& p) {
    EXPECT_EQ(p.starts, 3);
    if (done.empty() || done.back() != p.starts_done) done.push_back(p.starts_done);
    if (p.starts_done == 1) stop = true;
  };
  const FitResult r = fit(data, {"lambda"}, start, o);
  EXPECT_EQ(r.status, FitStatus::interrupted) << r.message;
  EXPECT_EQ(done, (std::vector<int>{0, 1}));  // Ipopt iterations of the first start, then its end
  ASSERT_EQ(r.starts.size(), 1u);
  EXPECT_EQ(r.starts[0].status, FitStatus::converged);
  ASSERT_EQ(r.estimates.size(), 1u);
  EXPECT_NEAR(r.cell.lambda / truth.lambda, 1.0, 1e-6);  // the finished start's estimate is kept
  EXPECT_TRUE(std::isnan(r.estimates[0].lo95)) << "an interval claimed after a stop";
  EXPECT_NE(r.message.find("interrupted after 1 of 3 starts"), std::string::npos) << r.message;
  EXPECT_EQ(r.residuals.size(), data.rows.size());
  EXPECT_EQ(to_json(r).at("status"), "interrupted");
  EXPECT_EQ(fit_text(r).rfind("fit: interrupted", 0), 0u) << fit_text(r);

  o.stop = nullptr;
  o.on_progress = nullptr;
  o.starts = 1;
  EXPECT_EQ(fit(data, {"lambda"}, start, o).status, FitStatus::converged);
}

// A stop within a solve ends it at the next Ipopt iteration (User_Requested_Stop): its last iterate is the best
// so far, marked as such.
TEST(Fit, StopWithinAStartEndsItAtTheNextIteration) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = one_viscosity(synthetic_data(truth, 0.0, 1));
  CellModel start = truth;
  start.lambda *= std::exp(-0.3);
  std::atomic<bool> stop{false};
  FitOptions o;
  o.starts = 2;
  o.stop = &stop;
  o.on_progress = [&](const FitProgress& p) {
    if (p.iterations == 2) stop = true;
  };
  const FitResult r = fit(data, {"lambda"}, start, o);
  EXPECT_EQ(r.status, FitStatus::interrupted);
  ASSERT_EQ(r.starts.size(), 1u);
  EXPECT_EQ(r.starts[0].status, FitStatus::interrupted);
  EXPECT_EQ(r.starts[0].ipopt_status, "User_Requested_Stop");
  EXPECT_LE(r.starts[0].iterations, 2);
  EXPECT_NE(r.message.find("(interrupted, its last iterate)"), std::string::npos) << r.message;
}

// A stop during the profiles keeps the estimate and its Fisher interval and drops the unfinished profile.
TEST(Fit, StopDuringTheProfileDropsIt) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = one_viscosity(synthetic_data(truth, 1.0, 7));
  std::atomic<bool> stop{false};
  FitOptions o;
  o.starts = 1;
  o.profiles.enabled = true;
  o.stop = &stop;
  o.on_progress = [&](const FitProgress& p) {
    if (p.profile_points == 3) stop = true;
  };
  const FitResult r = fit(data, {"lambda"}, truth, o);
  EXPECT_EQ(r.status, FitStatus::interrupted);
  ASSERT_EQ(r.estimates.size(), 1u);
  EXPECT_TRUE(std::isfinite(r.estimates[0].lo95));
  EXPECT_FALSE(r.estimates[0].profile.computed);
  EXPECT_NE(r.message.find("interrupted before the profile of lambda was finished"), std::string::npos) << r.message;
}

TEST(Fit, ProfileOfOneParameterAgreesWithFisher) {
  // One free parameter: the profile is chi^2 along it (nothing to re-fit). The same justification as
  // FitSlow.ProfileOfAWellDeterminedParameterAgreesWithFisher: the parabola (x - xhat)^2/se^2 at one se to 10 %,
  // the ends within 10 % of the Fisher half-width, each at Delta chi^2 = 3.84 (not a grid point).
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 1.0, 7);
  FitOptions o;
  o.starts = 1;
  o.profiles.enabled = true;
  const FitResult r = fit(data, {"lambda"}, truth, o);
  ASSERT_EQ(r.status, FitStatus::converged) << r.message;
  const FitEstimate& e = r.estimates[0];
  const Profile& p = e.profile;
  SCOPED_TRACE(p.statement);
  ASSERT_TRUE(std::isfinite(p.lo95) && std::isfinite(p.hi95));
  EXPECT_FALSE(p.flat);
  const double x = std::log(e.value), se = e.standard_error;
  for (double side : {-1.0, 1.0}) EXPECT_NEAR(profile_at(p, x + side * se), 1.0, 0.1);
  EXPECT_NEAR(profile_at(p, std::log(p.lo95)), 3.841458820694124, 2e-3);
  EXPECT_NEAR(profile_at(p, std::log(p.hi95)), 3.841458820694124, 2e-3);
  EXPECT_LT(p.max_shift, 0.1);
  EXPECT_FALSE(p.nonlinear);
  std::printf("lambda alone: profile [%.6g, %.6g] Fisher [%.6g, %.6g] shift %.4f solves %d\n", p.lo95, p.hi95, e.lo95,
              e.hi95, p.max_shift, p.solves);
  EXPECT_NE(fit_text(r).find("profile of lambda: 95 % interval"), std::string::npos) << fit_text(r);
  EXPECT_EQ(to_json(r)["estimates"][0]["profile"]["flat"], false);
}

TEST(Fit, ProfileOfKappaAloneIsFlat) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  FitOptions o;
  o.starts = 1;
  o.profiles.enabled = true;
  const FitResult r = fit(data, {"kappa"}, truth, o);
  const Profile& p = r.estimates[0].profile;
  EXPECT_TRUE(p.flat) << p.statement;
  EXPECT_TRUE(std::isnan(p.lo95) && std::isnan(p.hi95));
  EXPECT_NEAR(p.coordinate.front(), std::log(r.estimates[0].parameter.lo), 1e-12);
  EXPECT_NEAR(p.coordinate.back(), std::log(r.estimates[0].parameter.hi), 1e-12);
  for (double d : p.delta_chi2) EXPECT_EQ(d, 0.0);
  EXPECT_NE(p.statement.find("as the Fisher information says"), std::string::npos) << p.statement;
  ASSERT_EQ(r.unidentifiable.size(), 1u);
  EXPECT_NE(r.unidentifiable[0].find("an observation of the shape-instability onset"), std::string::npos)
      << r.unidentifiable[0];
}

// Smallest over largest eigenvalue of the Fisher information J^T J at `cell`.
double fisher_ratio(std::span<const ObservedRow> rows, std::span<const FitParameter> free, const CellModel& cell) {
  const Linearisation lin = linearise(rows, free, cell, FitOptions{}, 1e-4);
  EXPECT_TRUE(lin.ok) << lin.reason;
  const std::size_t n = free.size();
  Eigen::MatrixXd J(lin.r.size(), n);
  for (std::size_t i = 0; i < lin.r.size(); ++i)
    for (std::size_t j = 0; j < n; ++j) J(i, j) = lin.J[i][j];
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(J.transpose() * J).eigenvalues();
  double lo = kNotGiven, hi = kNotGiven;
  for (Eigen::Index k = 0; k < ev.size(); ++k) {
    lo = k == 0 ? ev(k) : std::min(lo, ev(k));
    hi = k == 0 ? ev(k) : std::max(hi, ev(k));
  }
  return lo / hi;
}

TEST(Fit, SaysWhichObservationWouldPinAFlatDirection) {
  // lambda and Delta enter only through Lambda: flat with lambda held across viscosities; the statement says that
  // fitting the inner viscosity over two outer viscosities would pin it, and so it does (the Fisher information
  // becomes regular), while one viscosity does not.
  CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  FitOptions o;
  o.starts = 1;
  o.max_iterations = 2;  // the statement comes from the Fisher information wherever Ipopt stops in the valley
  const FitResult r = fit(data, {"lambda", "Delta"}, truth, o);
  ASSERT_EQ(r.unidentifiable.size(), 1u) << r.message;
  EXPECT_NE(r.unidentifiable[0].find("Fitting inner_viscosity instead of lambda with rows at two or more outer"),
            std::string::npos)
      << r.unidentifiable[0];
  const std::vector<FitParameter> by_lambda{FitParameter::lambda, FitParameter::Delta};
  EXPECT_LT(fisher_ratio(data.rows, by_lambda, truth), 1e-8);

  truth.inner_viscosity = 5e-3;  // lambda = 5 at 1 mPa s, 2.5 at 2 mPa s
  const ObservationData two = synthetic_data(truth, 0.0, 1);
  std::vector<ObservedRow> one;
  for (const ObservedRow& row : two.rows)
    if (row.viscosity == 1e-3) one.push_back(row);
  const std::vector<FitParameter> by_eta_in{FitParameter::inner_viscosity, FitParameter::Delta};
  const double ratio_two = fisher_ratio(two.rows, by_eta_in, truth), ratio_one = fisher_ratio(one, by_eta_in, truth);
  std::printf("Fisher eigenvalue ratio: lambda, Delta %.3g; eta_in, Delta at two viscosities %.3g, at one %.3g\n",
              fisher_ratio(data.rows, by_lambda, synthetic_cell()), ratio_two, ratio_one);
  EXPECT_GT(ratio_two, 1e-4);
  EXPECT_LT(ratio_one, 1e-8);
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
  FitOptions bad_profile;
  bad_profile.profiles.points = 0;
  EXPECT_THROW(fit(data, {"mu"}, truth, bad_profile), InvalidArgument);
  bad_profile.profiles.points = 4;
  bad_profile.profiles.span = -1;
  EXPECT_THROW(fit(data, {"mu"}, truth, bad_profile), InvalidArgument);
  CellModel outside = truth;
  outside.shear_modulus = 1.0;  // N/m: beyond plausible_range
  EXPECT_THROW(fit(data, {"mu"}, outside), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
