// The in-plane observables' sensitivities from the variational equations of the periodic orbit against central
// differences of the forward model, on several cells, conditions and free parameters; and a wrong derivative (a
// dropped term of the chain) fails the same comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/inverse/sensitivity.hpp"
#include "synthetic_cell.hpp"

namespace rbcstab {
namespace {

TEST(Sensitivity, VariationalAgreesWithCentralDifferences) {
  // Two cells at one condition each (angle and amplitude) against central differences at 1e-4 of the forward model.
  // Differences at 1e-4 and 1e-5 agree to ~3e-8 of a column's largest entry (Forward.CentralDifferencesAgreeAtTwoSteps)
  // and the variational Jacobian agrees with them to 1.6e-8 (mu, lambda) and 4.3e-8 (eta_in, Delta, Delta0, R): 1e-6
  // leaves a margin of 20 and fails a dropped term (below). With the parabola's extrema (O(dt^3)) in place of the
  // quartic the amplitude rows missed by 1.1e-5: the bias's derivative, which the differences carried.
  for (const SensitivityCase& k : sensitivity_cases()) {
    FitOptions variational, fd;
    fd.jacobian = JacobianMethod::finite_difference;
    const std::vector<ObservedRow> rows(k.data.rows.begin(), k.data.rows.begin() + 2);
    const Linearisation v = linearise(rows, k.free, k.cell, variational, 1e-4);
    const Linearisation a = linearise(rows, k.free, k.cell, fd, 1e-4);
    ASSERT_TRUE(v.ok && a.ok) << v.reason << a.reason;
    for (std::size_t i = 0; i < v.r.size(); ++i) EXPECT_EQ(v.r[i], a.r[i]);  // the same forward evaluation
    EXPECT_LT(column_gap(v.J, a.J), 1e-6);
  }
}

TEST(Sensitivity, ADroppedTermFailsTheComparison) {
  // The same rows assembled from the orbit's derivatives with one term of the chain dropped (the 1/Lambda path,
  // or the periodic orbit's factor 1/2 of psi = Psi/2 on the mean): far outside 1e-6.
  const SensitivityCase k = sensitivity_cases().front();
  FitOptions fd;
  fd.jacobian = JacobianMethod::finite_difference;
  const std::vector<ObservedRow> rows(k.data.rows.begin(), k.data.rows.begin() + 2);
  const Linearisation a = linearise(rows, k.free, k.cell, fd, 1e-4);
  ASSERT_TRUE(a.ok) << a.reason;
  std::vector<std::vector<double>> right = a.J, no_invL = a.J, doubled = a.J;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ObservedRow& o = rows[i];
    const Parameters p = condition_parameters(k.cell, o.shear_rate, o.viscosity);
    const InPlaneMotion m = in_plane_motion(p);
    const OrbitSensitivity s = orbit_sensitivity(p, m, {});
    ASSERT_TRUE(s.ok) << s.reason;
    EXPECT_LT(s.multiplier, 1);
    const bool mean = o.observable == Observable::inclination_angle;
    const double da = mean ? s.mean_invL : s.amplitude_invL, dk = mean ? s.mean_kappa : s.amplitude_kappa;
    for (std::size_t j = 0; j < k.free.size(); ++j) {
      const auto g = coefficient_gradient(k.cell, k.free[j], true, o.shear_rate, o.viscosity);
      right[i][j] = (da * g[0] + dk * g[1]) / o.uncertainty;
      no_invL[i][j] = dk * g[1] / o.uncertainty;
      doubled[i][j] = (mean ? 2 : 1) * right[i][j];
    }
  }
  EXPECT_LT(column_gap(right, a.J), 1e-6);
  EXPECT_GT(column_gap(no_invL, a.J), 1e-2);
  EXPECT_GT(column_gap(doubled, a.J), 1e-2);
}

}  // namespace
}  // namespace rbcstab
