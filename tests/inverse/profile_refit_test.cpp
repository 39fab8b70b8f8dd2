// A profile point's Gauss-Newton re-fit (inverse/detail/profile_refit.hpp) against Ipopt's fit of the same
// parameters with the held one fixed: the same minimum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "rbcstab/inverse/detail/profile_refit.hpp"
#include "synthetic_cell.hpp"

namespace rbcstab {
namespace {

struct HeldMu {
  std::vector<FitParameter> free{FitParameter::shear_modulus, FitParameter::lambda};
  std::vector<double> lo, hi;
  explicit HeldMu(const CellModel& c) {
    for (FitParameter q : free) {
      const FitParameterInfo i = fit_parameter_info(q, c);
      lo.push_back(std::log(i.lo));
      hi.push_back(std::log(i.hi));
    }
  }
};

TEST(ProfileRefit, EqualsIpoptsFitOfTheOthers) {
  // ln mu held 0.05 off the truth (a few standard errors: a profile point, not the optimum), lambda re-fitted from
  // e^0.2 away. Both stop at their tolerances: Ipopt's scaled gradient of chi^2/2 below 1e-8, Gauss-Newton's
  // predicted decrease below 1e-9 max(chi^2, 1); either leaves chi^2 above the minimum by < 1e-8 relative and ln
  // lambda within ~sqrt(1e-9 chi^2) se of it. The test asks chi^2 to 1e-7 relative and ln lambda to 1e-5 (se of
  // ln lambda ~ 0.03 here): a point off the minimum by 1e-3 in ln lambda moves chi^2 by ~1e-3, far outside.
  const CellModel truth = synthetic_cell();
  const ObservationData data = one_viscosity(synthetic_data(truth, 1.0, 7));
  CellModel held = truth;
  held.shear_modulus = truth.shear_modulus * std::exp(0.05);
  held.lambda = truth.lambda * std::exp(0.2);
  FitOptions o;
  o.starts = 1;
  const FitResult ip = fit(data, {"lambda"}, held, o);
  ASSERT_EQ(ip.status, FitStatus::converged) << ip.message;
  const HeldMu h(truth);
  const std::vector<double> start{std::log(held.shear_modulus), std::log(held.lambda)};
  const detail::LeastSquaresRefit gn =
      detail::least_squares_refit(data.rows, h.free, truth, o, start, 0, h.lo, h.hi, {});
  ASSERT_TRUE(gn.converged) << gn.reason;
  EXPECT_EQ(gn.x[0], start[0]);  // the held coordinate untouched
  std::printf("Gauss-Newton chi^2 %.12g ln lambda %.10g (%d iterations, %d evaluations); Ipopt %.12g %.10g (%d)\n",
              gn.chi2, gn.x[1], gn.iterations, gn.evaluations, ip.chi2, std::log(ip.cell.lambda),
              ip.starts[0].iterations);
  EXPECT_NEAR(gn.chi2 / ip.chi2, 1.0, 1e-7);
  EXPECT_NEAR(gn.x[1], std::log(ip.cell.lambda), 1e-5);
  // A wrong point fails the same check: lambda 1e-3 off the re-fitted value.
  std::vector<double> r;
  std::string why;
  std::vector<FitParameterInfo> info;
  for (FitParameter q : h.free) info.push_back(fit_parameter_info(q, truth));
  const std::vector<double> off{gn.x[0], gn.x[1] + 1e-3};
  ASSERT_TRUE(detail::residuals_at(data.rows, detail::cell_at(truth, info, off), o.forward, r, why)) << why;
  double chi2_off = 0;
  for (double v : r) chi2_off += v * v;
  EXPECT_GT(std::abs(chi2_off / ip.chi2 - 1.0), 1e-5);
  // Started at its own optimum it stops at once: one Jacobian, nothing moved.
  const detail::LeastSquaresRefit again =
      detail::least_squares_refit(data.rows, h.free, truth, o, gn.x, 0, h.lo, h.hi, {});
  ASSERT_TRUE(again.converged) << again.reason;
  EXPECT_EQ(again.iterations, 1);
  EXPECT_EQ(again.x, gn.x);
}

TEST(ProfileRefit, StaysInsideTheBoxAndStopsWhenAsked) {
  // lambda's lower bound just below a start whose optimum lies beyond it: the re-fit ends on the bound, converged
  // (the gradient pushes outward there), never past it.
  const CellModel truth = synthetic_cell();
  const ObservationData data = one_viscosity(synthetic_data(truth, 0.0, 1));
  const HeldMu box(truth);
  HeldMu h = box;
  FitOptions o;
  const std::vector<double> start{std::log(truth.shear_modulus), std::log(truth.lambda) + 0.3};
  h.lo[1] = std::log(truth.lambda) + 0.1;
  const detail::LeastSquaresRefit b =
      detail::least_squares_refit(data.rows, h.free, truth, o, start, 0, h.lo, h.hi, {});
  ASSERT_TRUE(b.converged) << b.reason;
  EXPECT_EQ(b.x[1], h.lo[1]);
  const detail::LeastSquaresRefit s =
      detail::least_squares_refit(data.rows, box.free, truth, o, start, 0, box.lo, box.hi, [] { return false; });
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.reason, "interrupted");
}

}  // namespace
}  // namespace rbcstab
