// Structured Jacobians J = M + v w^T and dF/dt of every level against central finite differences
// of rhs(), and the O(n) shifted solve against a dense Eigen LU solve.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "model/test_scenes.hpp"
#include "rbcstab/model/structured_jacobian.hpp"

namespace rbcstab {
namespace {

using testing::generic_scene;
using testing::perturbed;

struct Case {
  std::string name;
  int L;
  ModelLevel level;
  bool rest_high;
};

std::unique_ptr<System> make(const Case& c) {
  const Scene s = generic_scene(c.L, c.rest_high);
  return make_system(s.parameters, initial_state(s), c.level);
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class JacobianTest : public ::testing::TestWithParam<Case> {};

Eigen::MatrixXd dense(const StructuredJacobian& J) {
  const auto n = Eigen::Index(J.size());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> A(n, n);
  J.to_dense({A.data(), std::size_t(n * n)});
  return A;
}

TEST_P(JacobianTest, MatchesCentralDifferencesOfRhs) {
  const auto sys = make(GetParam());
  const std::size_t n = sys->dimension();
  // A generic state off the initial manifold (the reduced level also off the unit sphere).
  const std::vector<double> y = perturbed(sys->initial_state(), 0.2);
  const double t = 3.7;
  StructuredJacobian J;
  std::vector<double> dfdt(n);
  sys->jacobian(t, y, J, dfdt);
  ASSERT_EQ(J.size(), n);
  const Eigen::MatrixXd A = dense(J);

  // Central differences: error ~ h^2 |F'''|/6 + eps |F| / h. With h = 1e-5 (relative to |y_j|, at
  // least 1e-5 absolute) both are ~1e-10 of the Jacobian's scale here; 1e-7 of max |J| is the bound.
  const double scale = std::max(1.0, A.cwiseAbs().maxCoeff());
  std::vector<double> yp(y), ym(y), fp(n), fm(n);
  double worst = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double h = 1e-5 * std::max(1.0, std::abs(y[j]));
    yp = y;
    ym = y;
    yp[j] += h;
    ym[j] -= h;
    sys->rhs(t, yp, fp);
    sys->rhs(t, ym, fm);
    for (std::size_t i = 0; i < n; ++i) {
      const double fd = (fp[i] - fm[i]) / (2 * h);
      worst = std::max(worst, std::abs(fd - A(Eigen::Index(i), Eigen::Index(j))));
      ASSERT_NEAR(A(Eigen::Index(i), Eigen::Index(j)), fd, 1e-7 * scale) << "dF_" << i << "/dy_" << j;
    }
  }
  // dF/dt likewise (explicit time dependence through the rotating stress-free shape g(t)).
  const double ht = 1e-5;
  sys->rhs(t + ht, y, fp);
  sys->rhs(t - ht, y, fm);
  double dscale = 1e-3;
  for (double v : dfdt) dscale = std::max(dscale, std::abs(v));
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_NEAR(dfdt[i], (fp[i] - fm[i]) / (2 * ht), 1e-7 * std::max(scale, dscale)) << "dF_" << i << "/dt";
  RecordProperty("max_fd_error", std::to_string(worst));
}

TEST_P(JacobianTest, ExplicitTimeDependenceIsPresent) {
  // Guards the previous test: with Delta0 > 0 and generic beta, F depends on t.
  const auto sys = make(GetParam());
  const std::size_t n = sys->dimension();
  const std::vector<double> y = perturbed(sys->initial_state(), 0.2);
  StructuredJacobian J;
  std::vector<double> dfdt(n);
  sys->jacobian(1.3, y, J, dfdt);
  double m = 0;
  for (double v : dfdt) m = std::max(m, std::abs(v));
  EXPECT_GT(m, 1e-4);
}

TEST_P(JacobianTest, ApplyAndShiftedSolveMatchDenseEigen) {
  const auto sys = make(GetParam());
  const std::size_t n = sys->dimension();
  const std::vector<double> y = perturbed(sys->initial_state(), 0.2);
  StructuredJacobian J;
  std::vector<double> dfdt(n);
  sys->jacobian(2.1, y, J, dfdt);
  const Eigen::MatrixXd A = dense(J);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) b(Eigen::Index(i)) = std::sin(1.0 + 3.0 * double(i));

  // apply(): J x equals the dense product to rounding (n terms of size |J||x|).
  std::vector<double> x(b.data(), b.data() + n), Jx(n);
  J.apply(x, Jx);
  const Eigen::VectorXd Jx_dense = A * b;
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(Jx[i], Jx_dense(Eigen::Index(i)),
                1e-13 * double(n) * A.cwiseAbs().maxCoeff() * b.cwiseAbs().maxCoeff());

  for (double c : {1e-4, 0.01, 0.3, -0.5, 2.0}) {
    const Eigen::MatrixXd S = Eigen::MatrixXd::Identity(Eigen::Index(n), Eigen::Index(n)) - c * A;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(S);
    const Eigen::VectorXd x_ref = lu.solve(b);
    std::vector<double> xs(n);
    const bool ok = J.solve_shifted(c, {b.data(), n}, xs);
    const double cond = 1 / lu.rcond();  // 1-norm condition number estimate
    if (cond > 1e12) continue;           // numerically singular: either answer is acceptable
    ASSERT_TRUE(ok) << "c = " << c << ", cond = " << cond;
    // Both solves are backward stable: forward errors ~ cond * eps each; 100 n eps cond bounds them.
    const double tol = 100 * double(n) * 2.2e-16 * cond * std::max(1.0, x_ref.cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(xs[i], x_ref(Eigen::Index(i)), tol) << "c = " << c << ", i = " << i;
    // Residual of our solution in the dense matrix.
    const Eigen::Map<const Eigen::VectorXd> xm(xs.data(), Eigen::Index(n));
    EXPECT_LE((S * xm - b).cwiseAbs().maxCoeff(), 1e-12 * (S.cwiseAbs().maxCoeff() * xm.cwiseAbs().maxCoeff() + 1));
  }
}

INSTANTIATE_TEST_SUITE_P(Levels, JacobianTest,
                         ::testing::Values(Case{"full_L4", 4, ModelLevel::full, true},
                                           Case{"full_L10", 10, ModelLevel::full, true},
                                           Case{"full_L10_ellipsoidal_rest", 10, ModelLevel::full, false},
                                           Case{"modal_L4", 4, ModelLevel::modal, false},
                                           Case{"modal_L10", 10, ModelLevel::modal, false},
                                           Case{"reduced", 2, ModelLevel::reduced, false}),
                         [](const ::testing::TestParamInfo<Case>& param_info) { return param_info.param.name; });

TEST(StructuredJacobian, SingularShiftIsReportedNotNaN) {
  // J = diag(1, 2) with no rank-one part: I - 1 * J is singular in its first entry.
  StructuredJacobian J;
  J.resize(2);
  J.diag = {1.0, 2.0};
  std::vector<double> b{1.0, 1.0}, x(2);
  EXPECT_FALSE(J.solve_shifted(1.0, b, x));
  EXPECT_TRUE(J.solve_shifted(0.25, b, x));
  EXPECT_NEAR(x[0], 1 / 0.75, 1e-15);
  EXPECT_NEAR(x[1], 1 / 0.5, 1e-15);
}

}  // namespace
}  // namespace rbcstab
