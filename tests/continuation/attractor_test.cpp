// The attractor refinement behind certified early termination (continuation/attractor.hpp): the chord Newton
// iteration on the period map against closed forms and against the multiple-shooting orbit solver, its
// failure reasons, and the modal subsystem against the full modal orbit problem.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>

#include "rbcstab/continuation/attractor.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

// x' = A x + Re(c e^{it}): the periodic orbit is x*(t) = Re((iI - A)^{-1} c e^{it}), the monodromy e^{2 pi A}.
class LinearForced final : public ForcedSystem {
 public:
  explicit LinearForced(const Eigen::Matrix3d& A) : A_(A) {
    c_ << std::complex<double>(1, 0.5), 0.3, std::complex<double>(0, -2);
  }
  Eigen::Index dimension() const override { return 3; }
  void rhs(double t, std::span<const double> x, double, std::span<double> f) const override {
    const Eigen::Vector3d X(x[0], x[1], x[2]);
    const Eigen::Vector3d F = A_ * X + (c_ * std::polar(1.0, t)).real();
    for (int i = 0; i < 3; ++i) f[std::size_t(i)] = F[i];
  }
  void jacobian(double, std::span<const double>, double, Eigen::MatrixXd& J) const override { J = A_; }
  Eigen::Vector3d orbit(double t) const {
    const Eigen::Matrix3cd shifted =
        std::complex<double>(0, 1) * Eigen::Matrix3cd::Identity() - A_.cast<std::complex<double>>();
    return (shifted.partialPivLu().solve(c_) * std::polar(1.0, t)).real();
  }
  Eigen::Matrix3d A_;
  Eigen::Vector3cd c_;
};

Eigen::Matrix3d stable_matrix() {
  Eigen::Matrix3d A;
  A << -0.3, 1.0, 0.0, -1.0, -0.3, 0.2, 0.0, 0.0, -0.7;
  return A;
}

// Oracle: the closed-form orbit and multipliers e^{2 pi lambda}. The refined state is as accurate as the
// plain runs (rtol 1e-10 of an O(1) state over one period: 1e-9 leaves room), the multipliers within their
// certified bounds, and deviation_sum = (I - e^{2 pi A})^{-1} (x0 - x*).
TEST(RefinePeriodicOrbit, LinearForcedSystemAgainstClosedForm) {
  const LinearForced sys(stable_matrix());
  const double t0 = 1.234;
  const Eigen::Vector3d perturbation(2e-4, -5e-4, 3e-4);
  const Eigen::VectorXd x0 = sys.orbit(t0) + perturbation;
  const PeriodicRefinement r = refine_periodic_orbit(sys, 0.0, t0, x0);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_LT((r.x - sys.orbit(t0)).norm(), 1e-9);
  EXPECT_LE(r.residual, 1e-9);
  EXPECT_NEAR(r.distance, perturbation.norm(), 1e-9);
  EXPECT_LT(r.contraction, 0.01);  // linear: the chord converges at once up to the variational run's tolerance
  const Eigen::Matrix3d M = (kTwoPi * stable_matrix()).exp();
  EXPECT_LT((r.monodromy - M).norm(), 1e-6);
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::Matrix3d>(stable_matrix()).eigenvalues();
  ASSERT_EQ(r.multipliers.values.size(), 3);
  for (Eigen::Index i = 0; i < 3; ++i) {
    double nearest = INFINITY;
    for (Eigen::Index k = 0; k < 3; ++k)
      nearest = std::min(nearest, std::abs(r.multipliers.values[i] - std::exp(kTwoPi * lambda[k])));
    EXPECT_LE(nearest, r.multipliers.errors[i]) << i;
  }
  const Eigen::Vector3d sum = (Eigen::Matrix3d::Identity() - M).partialPivLu().solve(Eigen::Vector3d(x0 - r.x));
  EXPECT_LT((r.deviation_sum - sum).norm(), 1e-6 * sum.norm());
}

// A multiplier 1 (a neutral direction) makes the chord matrix singular: a reason, no exception.
TEST(RefinePeriodicOrbit, NeutralDirectionIsAReasonNotAnException) {
  Eigen::Matrix3d A = stable_matrix();
  A(2, 2) = 0;
  A(1, 2) = 0;
  const LinearForced sys(A);
  const PeriodicRefinement r = refine_periodic_orbit(sys, 0.0, 0.5, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.reason.empty());
}

// The in-plane reduced orbit (Appendix E(a) point). Oracle: the multiple-shooting solver (8 segments,
// rtol 1e-12, Newton to 1e-12) and its Floquet multipliers. Started at phase 0 from the relaxed state pushed
// 1e-4 off the orbit along the sphere, the chord refinement lands on the oracle's x*(0) to the plain runs'
// accuracy and its multipliers lie within their bounds of the oracle's.
TEST(RefinePeriodicOrbit, ReducedInPlaneOrbitAgainstMultipleShooting) {
  Scene s;
  s.parameters.lambda = 1;
  s.parameters.Delta = 1;
  s.parameters.B = std::exp(1.0);
  s.parameters.C = std::exp(-2.0);
  s.beta = std::numbers::pi / 2;
  s.L = 2;
  s.delta = 0;
  const ReducedForcedSystem sys(s, ContinuationParameter::B);
  const double p = sys.start_parameter();
  const PeriodicOrbitProblem orbit(sys);
  const Eigen::VectorXd relaxed = sys.relaxed_state(kTwoPi * 20);
  const NewtonResult nr = solve_fixed_parameter(orbit, orbit.shooting_guess(relaxed, p), p, 1e-12, 20);
  ASSERT_TRUE(nr.converged);
  const Eigen::VectorXd x_star = orbit.state_at_zero(nr.x);
  const Eigen::VectorXcd mu = orbit.floquet(nr.x, p).multipliers;

  Eigen::VectorXd x0 = x_star + 1e-4 * Eigen::Vector3d(0.3, -0.5, 0.2);
  x0 /= x0.norm();
  const PeriodicRefinement r = refine_periodic_orbit(sys, p, 3 * kTwoPi, x0);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_LT((r.x - x_star).norm(), 1e-9);
  EXPECT_NEAR(r.x.norm(), 1.0, 1e-9);
  ASSERT_EQ(r.multipliers.values.size(), mu.size());
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    double nearest = INFINITY;
    for (Eigen::Index k = 0; k < mu.size(); ++k) nearest = std::min(nearest, std::abs(r.multipliers.values[i] - mu[k]));
    EXPECT_LE(nearest, r.multipliers.errors[i] + 1e-10) << i;
  }
}

// The subsystem is the full modal orbit problem on the subspace where the other modes vanish. Oracle:
// ModalForcedSystem itself (rhs, Jacobian, sigma) at random unit states and times, in and out of plane.
TEST(ModalSubsystem, EqualsTheFullSystemOnItsSubspace) {
  for (double beta : {0.3, std::numbers::pi / 2}) {
    Scene s;
    s.beta = beta;
    s.L = 6;
    const ModalForcedSystem full(total_area_scene(s), ContinuationParameter::B);
    const double p = full.start_parameter();
    const ModalSubsystem sub(full, p, {4, 6});
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    for (int trial = 0; trial < 5; ++trial) {
      Eigen::VectorXd x(sub.dimension());
      for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = g(rng);
      x /= x.norm();
      const double t = 10 * g(rng);
      const Eigen::VectorXd xf = sub.embed(x);
      EXPECT_EQ(sub.restrict(xf), x);
      Eigen::VectorXd f(sub.dimension()), ff(full.dimension());
      sub.rhs(t, {x.data(), std::size_t(x.size())}, p, {f.data(), std::size_t(f.size())});
      full.rhs(t, {xf.data(), std::size_t(xf.size())}, p, {ff.data(), std::size_t(ff.size())});
      EXPECT_LT((f - sub.restrict(ff)).norm(), 1e-13 * (1 + ff.norm())) << beta;
      Eigen::MatrixXd J, Jf;
      sub.jacobian(t, {x.data(), std::size_t(x.size())}, p, J);
      full.jacobian(t, {xf.data(), std::size_t(xf.size())}, p, Jf);
      for (Eigen::Index j = 0; j < x.size(); ++j) {
        Eigen::VectorXd e = Eigen::VectorXd::Zero(x.size());
        e[j] = 1;
        EXPECT_LT((J * e - sub.restrict(Jf * sub.embed(e))).norm(), 1e-12 * (1 + Jf.norm())) << beta << " column " << j;
      }
      EXPECT_NEAR(sub.sigma(t, {x.data(), std::size_t(x.size())}), full.observe(t, xf, p).sigma,
                  1e-12 * (1 + std::abs(full.observe(t, xf, p).sigma)));
    }
  }
}

TEST(ModalSubsystem, RejectsModesOutsideTheTruncation) {
  Scene s;
  s.L = 5;
  const ModalForcedSystem full(total_area_scene(s), ContinuationParameter::B);
  EXPECT_THROW(ModalSubsystem(full, full.start_parameter(), {2}), InvalidArgument);
  EXPECT_THROW(ModalSubsystem(full, full.start_parameter(), {6}), InvalidArgument);
  EXPECT_THROW(ModalSubsystem(full, full.start_parameter(), {4, 3}), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
