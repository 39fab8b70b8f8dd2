// The Rosenbrock stepper takes its linear algebra from System::make_shifted_solver(). A system that
// delegates to the full model but solves (I - cJ) x = b by dense LU of the same J (an independent
// solver) must give the same trajectory as the default structured O(n) solve, and the stepper must
// call the hook once per step (jacobian_evaluations). The default's bitwise identity with the former
// built-in structured solve was checked offline (hex dumps of full/modal/reduced runs, docs/continuation.md).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <vector>

#include "integrate/full_state.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

class DenseLuSystem final : public testing::FullState {
 public:
  explicit DenseLuSystem(const System& base) : FullState(base) {}
  std::unique_ptr<ShiftedSolver> make_shifted_solver() const override {
    ++solvers_made;
    return std::make_unique<Solver>(*this);
  }
  mutable int solvers_made = 0;
  mutable std::size_t linearizations = 0;

 private:
  struct Solver final : ShiftedSolver {
    explicit Solver(const DenseLuSystem& s) : sys(s) {}
    void linearize(double t, std::span<const double> y, std::span<double> dfdt) override {
      ++sys.linearizations;
      StructuredJacobian J;
      sys.base().jacobian(t, y, J, dfdt);
      const auto n = static_cast<Eigen::Index>(y.size());
      std::vector<double> d(y.size() * y.size());
      J.to_dense(d);
      dense = Eigen::Map<Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(d.data(), n, n);
    }
    bool solve(double c, std::span<const double> b, std::span<double> x) override {
      const auto n = dense.rows();
      const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) - c * dense;
      Eigen::Map<Eigen::VectorXd>(x.data(), n) = A.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(b.data(), n));
      return true;
    }
    const DenseLuSystem& sys;
    Eigen::MatrixXd dense;
  };
};

TEST(ShiftedSolverHook, RosenbrockUsesTheSystemsSolver) {
  Scene s;
  s.L = 4;
  s.beta = 1.0;
  s.delta = 1e-2;
  s.rest_delta_l[3] = 1e-3;  // time-dependent drive: dF/dt enters the stages
  const auto full = make_system(s.parameters, initial_state(s), ModelLevel::full);
  const DenseLuSystem dense(*full);
  IntegratorOptions o;
  o.stepper = Stepper::rosenbrock;
  o.rtol = 1e-9;
  const double grid[1] = {10.0};
  const IntegrationResult a = integrate(*full, full->initial_state(), 0.0, grid, o, {});
  const IntegrationResult b = integrate(dense, dense.initial_state(), 0.0, grid, o, {});
  ASSERT_EQ(a.status, IntegrationStatus::success) << a.reason;
  ASSERT_EQ(b.status, IntegrationStatus::success) << b.reason;
  EXPECT_EQ(dense.solvers_made, 1);  // one solver per integration
  EXPECT_EQ(dense.linearizations, b.counters.jacobian_evaluations);
  EXPECT_GT(b.counters.jacobian_evaluations, 10u);
  // Sherman-Morrison vs LU differ by rounding (~1e-15 relative per solve); the error controller sees the
  // same local errors, so the trajectories agree far below rtol (1e-11 relative leaves a factor ~1e3).
  double d = 0, n = 0;
  for (std::size_t i = 0; i < a.y.size(); ++i) {
    d = std::max(d, std::abs(a.y[i] - b.y[i]));
    n = std::max(n, std::abs(a.y[i]));
  }
  EXPECT_LT(d, 1e-11 * n);
}

}  // namespace
}  // namespace rbcstab
