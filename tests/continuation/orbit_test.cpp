// Periodic orbits by multiple shooting: LPC / PD / NS on textbook forced systems whose orbit and
// Floquet multipliers are known in closed form, and the in-plane reduced system (Floquet multipliers
// against a finite-difference monodromy, the trivial multiplier, independence of the number of
// segments, a long direct simulation, the swinging <-> tumbling transition).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// Forced saddle-node: x1' = p - (x1 - sin t)^2 + cos t, x2' = -x2 + sin t. With u = x1 - sin t,
// u' = p - u^2: orbits x1 = sin t +- sqrt(p), x2 = (sin t - cos t)/2, multipliers e^{-+4 pi sqrt(p)}
// and e^{-2 pi}. The two orbits meet in a fold of cycles (LPC) at p = 0.
class ForcedFold final : public ForcedSystem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override {
    const double u = x[0] - std::sin(t);
    f[0] = p - u * u + std::cos(t);
    f[1] = -x[1] + std::sin(t);
  }
  void jacobian(double t, std::span<const double> x, double, Eigen::MatrixXd& J) const override {
    J.setZero(2, 2);
    J(0, 0) = -2 * (x[0] - std::sin(t));
    J(1, 1) = -1;
  }
  void parameter_derivative(double, std::span<const double>, double, std::span<double> fp) const override {
    fp[0] = 1;
    fp[1] = 0;
  }
};

// x' = A(t) x + b(t) + c |x - x_p(t)|^2 e_1 with the known orbit x_p(t) = (cos t + a sin 2t, sin t)
// (b(t) = x_p' - A x_p). The quadratic term vanishes to second order on the orbit, so the multipliers
// are those of A(t) alone, but Newton and the continuation see a nonlinear problem.
class ForcedLinear : public ForcedSystem {
 public:
  Eigen::Index dimension() const override { return 2; }
  virtual Eigen::Matrix2d A(double t, double a) const = 0;
  static Eigen::Vector2d xp(double t, double a) { return {std::cos(t) + a * std::sin(2 * t), std::sin(t)}; }
  static Eigen::Vector2d xp_dot(double t, double a) { return {-std::sin(t) + 2 * a * std::cos(2 * t), std::cos(t)}; }
  void rhs(double t, std::span<const double> x, double a, std::span<double> f) const override {
    const Eigen::Vector2d X(x[0], x[1]), e = X - xp(t, a);
    const Eigen::Vector2d F = A(t, a) * e + xp_dot(t, a) + Eigen::Vector2d(0.7 * e.squaredNorm(), 0);
    f[0] = F[0];
    f[1] = F[1];
  }
  void jacobian(double t, std::span<const double> x, double a, Eigen::MatrixXd& J) const override {
    const Eigen::Vector2d e = Eigen::Vector2d(x[0], x[1]) - xp(t, a);
    J = A(t, a);
    J.row(0) += 1.4 * e.transpose();
  }
};

// Half-turn rotating frame: x = R(t/2) u with u' = diag(a, -1) u, so A(t) = J/2 + R D R^T and the
// monodromy is R(pi) e^{2 pi D}: multipliers -e^{2 pi a}, -e^{-2 pi}. PD at a = 0.
class ForcedFlip final : public ForcedLinear {
 public:
  Eigen::Matrix2d A(double t, double a) const override {
    const double c = std::cos(t / 2), s = std::sin(t / 2);
    Eigen::Matrix2d R, D, Jr;
    R << c, -s, s, c;
    D << a, 0, 0, -1;
    Jr << 0, -0.5, 0.5, 0;
    return Jr + R * D * R.transpose();
  }
};

// Complex mode x' = (a + i omega) x (omega = 0.3, away from strong resonances): multipliers
// e^{2 pi (a +- i omega)}, NS at a = 0.
class ForcedFocus final : public ForcedLinear {
 public:
  Eigen::Matrix2d A(double, double a) const override {
    Eigen::Matrix2d M;
    M << a, -0.3, 0.3, a;
    return M;
  }
};

Eigen::VectorXd orbit_state(const Eigen::Vector2d& x) { return Eigen::VectorXd(x); }

// Located to 1e-8 in the parameter (the bar); the location tolerance is 1e-11 in (X, p).
TEST(OrbitNormalForms, FoldOfCyclesLocatedAtZero) {
  const ForcedFold sys;
  OrbitOptions oo;
  oo.segments = 4;
  const PeriodicOrbitProblem pr(sys, oo);
  const double p0 = 0.25;
  const Eigen::VectorXd X0 = pr.shooting_guess(Eigen::Vector2d(0.5 + 0.05, -0.5 + 0.02), p0);
  const NewtonResult nr = solve_fixed_parameter(pr, X0, p0);
  ASSERT_TRUE(nr.converged);
  EXPECT_NEAR(nr.x[0], 0.5, 1e-10);  // x1(0) = sin 0 + sqrt(p)
  ContinuationOptions o;
  o.direction = Direction::backward;
  o.p_min = -1;
  o.p_max = 0.3;
  o.max_step = 0.1;
  o.max_points = 60;
  const Branch b = continue_branch(pr, nr.x, p0, o);
  ASSERT_GE(b.special_points.size(), 1u);
  const SpecialPoint& lpc = b.special_points.front();
  EXPECT_EQ(lpc.type, SpecialPointType::LPC);
  EXPECT_EQ(lpc.status, LocationStatus::located);
  EXPECT_NEAR(lpc.p, 0.0, 1e-8);
  // Past the fold the branch is the unstable orbit x1 = sin t - sqrt(p), multiplier e^{4 pi sqrt p}.
  bool saw_lower = false;
  for (const auto& pt : b.points) {
    const double sq = std::sqrt(std::max(pt.p, 0.0));
    const bool lower = pt.x[0] < 0;
    saw_lower = saw_lower || (lower && pt.p > 0.01);
    EXPECT_NEAR(pt.x[0], lower ? -sq : sq, 1e-9) << pt.p;
    // Multipliers in closed form; 1e-9: integration at rtol 1e-12 over one period.
    std::vector<double> mu = {pt.spectrum[0].real(), pt.spectrum[1].real()};
    std::sort(mu.begin(), mu.end());
    const double m1 = std::exp((lower ? 4 : -4) * M_PI * sq), m2 = std::exp(-kTwoPi);
    std::vector<double> ex = {m1, m2};
    std::sort(ex.begin(), ex.end());
    EXPECT_NEAR(mu[0], ex[0], 1e-9 * ex[0] + 1e-12);
    EXPECT_NEAR(mu[1], ex[1], 1e-9 * ex[1]);
    EXPECT_EQ(pt.stable, !lower);
  }
  EXPECT_TRUE(saw_lower);
}

template <class System>
Branch continue_linear(const System& sys, int segments, double a0, double a_lo, double a_hi) {
  OrbitOptions oo;
  oo.segments = segments;
  const PeriodicOrbitProblem pr(sys, oo);
  // Start off the orbit so Newton has work to do.
  const Eigen::VectorXd X0 = pr.shooting_guess(orbit_state(ForcedLinear::xp(0, a0) + Eigen::Vector2d(0.03, -0.02)), a0);
  const NewtonResult nr = solve_fixed_parameter(pr, X0, a0);
  EXPECT_TRUE(nr.converged);
  EXPECT_NEAR((nr.x.head(2) - ForcedLinear::xp(0, a0)).norm(), 0, 1e-10);
  ContinuationOptions o;
  o.direction = Direction::forward;
  o.p_min = a_lo;
  o.p_max = a_hi;
  o.max_step = 0.05;
  return continue_branch(pr, nr.x, a0, o);
}

TEST(OrbitNormalForms, PeriodDoublingLocatedAtZero) {
  const ForcedFlip sys;
  const Branch b = continue_linear(sys, 6, -0.13, -0.2, 0.1);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_EQ(b.special_points.size(), 1u);
  const SpecialPoint& pd = b.special_points[0];
  EXPECT_EQ(pd.type, SpecialPointType::PD);
  EXPECT_EQ(pd.status, LocationStatus::located);
  EXPECT_NEAR(pd.p, 0.0, 1e-8);
  EXPECT_NEAR(pd.eigenvalue.real(), -1.0, 1e-8);
  EXPECT_EQ(pd.unstable_before, 0);
  EXPECT_EQ(pd.unstable_after, 1);
  for (const auto& pt : b.points) {
    // The orbit x_p and the multipliers -e^{2 pi a}, -e^{-2 pi} in closed form (1e-9: rtol 1e-12).
    for (int j = 0; j < 6; ++j)
      EXPECT_NEAR((pt.x.segment(2 * j, 2) - ForcedLinear::xp(kTwoPi * j / 6, pt.p)).norm(), 0, 1e-10);
    std::vector<double> mu = {pt.spectrum[0].real(), pt.spectrum[1].real()};
    std::sort(mu.begin(), mu.end());
    EXPECT_NEAR(mu[0], -std::exp(kTwoPi * pt.p), 1e-9);
    EXPECT_NEAR(mu[1], -std::exp(-kTwoPi), 1e-9);
    EXPECT_NEAR(pt.spectrum[0].imag(), 0, 1e-9);
  }
}

TEST(OrbitNormalForms, NeimarkSackerLocatedAtZero) {
  const ForcedFocus sys;
  const Branch b = continue_linear(sys, 5, -0.11, -0.2, 0.1);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_EQ(b.special_points.size(), 1u);
  const SpecialPoint& ns = b.special_points[0];
  EXPECT_EQ(ns.type, SpecialPointType::NS);
  EXPECT_EQ(ns.status, LocationStatus::located);
  EXPECT_NEAR(ns.p, 0.0, 1e-8);
  EXPECT_NEAR(std::abs(ns.eigenvalue), 1.0, 1e-8);
  EXPECT_NEAR(std::arg(ns.eigenvalue), kTwoPi * 0.3, 1e-8);
  EXPECT_EQ(ns.unstable_before, 0);
  EXPECT_EQ(ns.unstable_after, 2);
  for (const auto& pt : b.points) {
    const std::complex<double> ex = std::exp(kTwoPi * std::complex<double>(pt.p, 0.3));
    const std::complex<double> got = pt.spectrum[0].imag() > 0 ? pt.spectrum[0] : pt.spectrum[1];
    EXPECT_NEAR(std::abs(got - ex), 0, 1e-9) << pt.p;
  }
}

TEST(OrbitOptionsTest, ValidateNamesTheField) {
  OrbitOptions o;
  o.segments = 0;
  try {
    o.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("segments"), std::string::npos);
  }
  o = {};
  o.rtol = 1e-3;
  EXPECT_THROW(o.validate(), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
