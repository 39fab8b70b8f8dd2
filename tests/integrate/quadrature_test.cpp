// The quadrature adapter (integrate/quadrature.hpp): q' = g(t, x, F(t, x)) beside a base system.
//  - an integrand of the rate, g = w' (the reduced model's third component), integrates to w(T) - w(0);
//  - the tension integral equals Simpson's rule on the model's own sigma_R samples;
//  - the adapter's structured Jacobian (quadrature rows b w^T) and dF/dt match central differences, and an
//    implicit stepper (which uses them) gives the explicit stepper's integral.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "model/test_scenes.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/quadrature.hpp"
#include "rbcstab/model/reduced_model.hpp"

namespace rbcstab {
namespace {

// In-plane Fig. 2 scene: swinging, with the rotating rest shape (explicit time dependence).
ReducedModel in_plane_model() {
  const Scene s = testing::fig2_scene(0.01, std::numbers::pi / 2);
  return ReducedModel(s.parameters, initial_state(s));
}

IntegratorOptions tight(Stepper stepper) {
  IntegratorOptions o;
  o.stepper = stepper;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  return o;
}

TEST(Quadrature, IntegrandOfTheRateIntegratesToTheChangeOfState) {
  const ReducedModel m = in_plane_model();
  Quadrature q;
  q.rate = [](double, std::span<const double>, std::span<const double> f, std::span<double> rate) { rate[0] = f[2]; };
  const WithQuadratures sys(m, q);
  ASSERT_EQ(sys.dimension(), 4u);
  const std::vector<double> y0 = sys.initial_state();
  ASSERT_EQ(y0.size(), 4u);
  EXPECT_EQ(y0[3], 0.0);
  const double grid[1] = {7.3};
  const IntegrationResult r = integrate(sys, y0, 0.0, grid, tight(Stepper::rk8pd), {});
  ASSERT_EQ(r.status, IntegrationStatus::success);
  // Both are the same integral under one error control: agreement to the tolerance (O(1) state).
  EXPECT_NEAR(r.y[3], r.y[2] - y0[2], 1e-9);
  EXPECT_GT(std::abs(r.y[2] - y0[2]), 1e-3);  // w moves: not a vacuous check
  // No multiplier coefficients: the Jacobian is refused.
  StructuredJacobian J;
  std::vector<double> dfdt(4);
  EXPECT_THROW(sys.jacobian(0.0, y0, J, dfdt), std::logic_error);
}

TEST(Quadrature, TensionIntegralIsTheIntegralOfSigmaR) {
  const ReducedModel m = in_plane_model();
  const WithQuadratures sys(m, tension_integral(m));
  const double T = 2 * std::numbers::pi;
  const int n = 2000;
  std::vector<double> grid;
  for (int k = 1; k <= n; ++k) grid.push_back(T * k / n);
  // Simpson's rule on the model's own sigma_R at the samples of the same run (error ~ T h^4 max|d4 sigma|/180).
  const std::vector<double> y0 = sys.initial_state();
  std::vector<double> samples = {m.sigma(0.0, std::span<const double>(y0).first(3))};
  double I = 0;
  const IntegrationResult r =
      integrate(sys, y0, 0.0, grid, tight(Stepper::rk8pd), [&](double t, std::span<const double> y) {
        samples.push_back(m.sigma(t, y.first(3)));
        I = y[3];
      });
  ASSERT_EQ(r.status, IntegrationStatus::success);
  double simpson = samples.front() + samples.back();
  for (int k = 1; k < n; ++k) simpson += (k % 2 == 1 ? 4 : 2) * samples[std::size_t(k)];
  simpson *= T / (3 * n);
  EXPECT_NEAR(I, simpson, 1e-9 * std::abs(I));
}

TEST(Quadrature, JacobianMatchesCentralDifferencesAndImplicitStepsAgree) {
  const ReducedModel m = in_plane_model();
  const WithQuadratures sys(m, tension_integral(m));
  const std::size_t n = sys.dimension();
  const std::vector<double> y = testing::perturbed(sys.initial_state(), 0.2);
  const double t = 1.9;
  StructuredJacobian J;
  std::vector<double> dfdt(n);
  sys.jacobian(t, y, J, dfdt);
  std::vector<double> A(n * n);
  J.to_dense(A);
  std::vector<double> yp(y), ym(y), fp(n), fm(n);
  double scale = 1;
  for (double a : A) scale = std::max(scale, std::abs(a));
  // Central differences, h = 1e-6: error ~ h^2 |F'''| + eps |F| / h ~ 1e-10 of the scale; bound 1e-7.
  const double h = 1e-6;
  for (std::size_t j = 0; j < n; ++j) {
    yp = y;
    ym = y;
    yp[j] += h;
    ym[j] -= h;
    sys.rhs(t, yp, fp);
    sys.rhs(t, ym, fm);
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_NEAR(A[i * n + j], (fp[i] - fm[i]) / (2 * h), 1e-7 * scale) << "dF_" << i << "/dy_" << j;
  }
  sys.rhs(t + h, y, fp);
  sys.rhs(t - h, y, fm);
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(dfdt[i], (fp[i] - fm[i]) / (2 * h), 1e-7 * scale) << "dF_" << i << "/dt";
  EXPECT_GT(std::abs(dfdt[3]), 1e-3);  // the rest shape rotates: sigma_R depends on t explicitly

  const double grid[1] = {20.0};
  const IntegrationResult explicit_run = integrate(sys, sys.initial_state(), 0.0, grid, tight(Stepper::rk8pd), {});
  IntegratorOptions ro = tight(Stepper::rosenbrock);
  ro.rtol = 1e-9;
  const IntegrationResult implicit_run = integrate(sys, sys.initial_state(), 0.0, grid, ro, {});
  ASSERT_EQ(explicit_run.status, IntegrationStatus::success);
  ASSERT_EQ(implicit_run.status, IntegrationStatus::success);
  EXPECT_GT(implicit_run.counters.jacobian_evaluations, 0u);
  // Global error of the rtol 1e-9 run over 20 time units: 1e-6 relative bound.
  EXPECT_NEAR(implicit_run.y[3], explicit_run.y[3], 1e-6 * std::abs(explicit_run.y[3]));
}

}  // namespace
}  // namespace rbcstab
