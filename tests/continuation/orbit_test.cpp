// Periodic orbits by multiple shooting: LPC / PD / NS on textbook forced systems whose orbit and
// Floquet multipliers are known in closed form, and the in-plane reduced system (Floquet multipliers
// against a finite-difference monodromy, the trivial multiplier, independence of the number of
// segments, a long direct simulation, the swinging <-> tumbling transition).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include <Eigen/Eigenvalues>

#include "continuation/fig2_fixture.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab {
namespace {

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

// Located to 1e-8 in the parameter (the required accuracy); the location tolerance is 1e-11 in (X, p).
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

// Two-parameter forced fold: x1' = p1 + p2 u - u^2 + cos t with u = x1 - sin t, x2' = -x2 + sin t.
// Orbits u = (p2 +- sqrt(D))/2, D = p2^2 + 4 p1, multipliers e^{-+2 pi sqrt(D)}: the LPC curve is
// p1 = -p2^2/4 with x1(0) = p2/2.
class ForcedFold2 final : public ForcedSystem2 {
 public:
  Eigen::Index dimension() const override { return 2; }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    const double u = x[0] - std::sin(t);
    f[0] = p1 + p2 * u - u * u + std::cos(t);
    f[1] = -x[1] + std::sin(t);
  }
  void jacobian(double t, std::span<const double> x, double, double p2, Eigen::MatrixXd& J) const override {
    J.setZero(2, 2);
    J(0, 0) = p2 - 2 * (x[0] - std::sin(t));
    J(1, 1) = -1;
  }
  void parameter_derivative(double, std::span<const double>, double, double, std::span<double> fp) const override {
    fp[0] = 1;
    fp[1] = 0;
  }
};

// The LPC curve from a one-parameter LPC, continued in p2 over [-1, 1], against p1 = -p2^2/4 and
// x1(0) = p2/2. 1e-9: the curve's Newton converges to 1e-12 on residuals integrated at rtol 1e-12.
TEST(OrbitNormalForms, FoldOfCyclesCurveInTwoParameters) {
  const ForcedFold2 sys;
  OrbitOptions oo;
  oo.segments = 3;
  const double p2 = 0.4;
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const double p1 = 0.2;  // D = 0.96: upper orbit u = (0.4 + sqrt(0.96))/2
  const double u0 = (p2 + std::sqrt(p2 * p2 + 4 * p1)) / 2;
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(Eigen::Vector2d(u0 + 0.02, -0.5), p1), p1);
  ASSERT_TRUE(nr.converged);
  ContinuationOptions o;
  o.direction = Direction::backward;
  o.p_min = -1;
  o.max_step = 0.1;
  o.max_points = 40;
  const Branch b = continue_branch(pr, nr.x, p1, o);
  ASSERT_GE(b.special_points.size(), 1u);
  const SpecialPoint& lpc = b.special_points.front();
  ASSERT_EQ(lpc.type, SpecialPointType::LPC);
  EXPECT_NEAR(lpc.p, -p2 * p2 / 4, 1e-8);

  const OrbitTwoParameterProblem base(sys, oo);
  const FoldCurveProblem curve(base, lpc, p2);
  ContinuationOptions co;
  co.direction = Direction::both;
  co.p_min = -1;
  co.p_max = 1;
  co.max_step = 0.1;
  co.compute_stability = false;  // the shooting Jacobian's eigenvalues are not a stability
  const Branch c = continue_branch(curve, curve.start(), p2, co);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_DOUBLE_EQ(c.points.front().p, -1.0);
  EXPECT_DOUBLE_EQ(c.points.back().p, 1.0);
  EXPECT_GE(c.points.size(), 10u);
  for (const auto& pt : c.points) {
    const double q2 = pt.p, q1 = pt.x[pt.x.size() - 1];
    EXPECT_NEAR(q1, -q2 * q2 / 4, 1e-9) << q2;
    EXPECT_NEAR(pt.x[0], q2 / 2, 1e-9) << q2;
  }
}

// Two-parameter flip: the half-turn rotating frame of ForcedFlip with u' = diag(p1 - p2^2, -1) u and
// the orbit x_p(t) = (cos t + p1 sin 2t, sin t + p2 cos 2t): multipliers -e^{2 pi (p1 - p2^2)},
// -e^{-2 pi}, so the PD curve is p1 = p2^2 with x(0) = (1, p2).
class ForcedFlip2 final : public ForcedSystem2 {
 public:
  Eigen::Index dimension() const override { return 2; }
  static Eigen::Matrix2d A(double t, double a) {
    const double c = std::cos(t / 2), s = std::sin(t / 2);
    Eigen::Matrix2d R, D, Jr;
    R << c, -s, s, c;
    D << a, 0, 0, -1;
    Jr << 0, -0.5, 0.5, 0;
    return Jr + R * D * R.transpose();
  }
  static Eigen::Vector2d xp(double t, double p1, double p2) {
    return {std::cos(t) + p1 * std::sin(2 * t), std::sin(t) + p2 * std::cos(2 * t)};
  }
  static Eigen::Vector2d xp_dot(double t, double p1, double p2) {
    return {-std::sin(t) + 2 * p1 * std::cos(2 * t), std::cos(t) - 2 * p2 * std::sin(2 * t)};
  }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    const Eigen::Vector2d e = Eigen::Vector2d(x[0], x[1]) - xp(t, p1, p2);
    const Eigen::Vector2d F = A(t, p1 - p2 * p2) * e + xp_dot(t, p1, p2) + Eigen::Vector2d(0.7 * e.squaredNorm(), 0);
    f[0] = F[0];
    f[1] = F[1];
  }
  void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const override {
    const Eigen::Vector2d e = Eigen::Vector2d(x[0], x[1]) - xp(t, p1, p2);
    J = A(t, p1 - p2 * p2);
    J.row(0) += 1.4 * e.transpose();
  }
  // df/dp1 = dA/da e - A dxp/dp1 + d(xp_dot)/dp1 - 1.4 (e . dxp/dp1) e_1, with dA/da = R e1 e1^T R^T.
  void parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                            std::span<double> fp) const override {
    const Eigen::Vector2d e = Eigen::Vector2d(x[0], x[1]) - xp(t, p1, p2);
    const Eigen::Vector2d r(std::cos(t / 2), std::sin(t / 2));  // R e_1
    const Eigen::Vector2d dxp(std::sin(2 * t), 0), dxp_dot(2 * std::cos(2 * t), 0);
    const Eigen::Vector2d F = r * r.dot(e) - A(t, p1 - p2 * p2) * dxp + dxp_dot - Eigen::Vector2d(1.4 * e.dot(dxp), 0);
    fp[0] = F[0];
    fp[1] = F[1];
  }
};

// The PD curve from a one-parameter PD point, continued in p2 over [-1, 1], against p1 = p2^2 and
// x(0) = (1, p2) to 1e-9 (Newton to 1e-12 on residuals integrated at rtol 1e-12).
TEST(OrbitNormalForms, PeriodDoublingCurveInTwoParameters) {
  const ForcedFlip2 sys;
  OrbitOptions oo;
  oo.segments = 3;
  const double p2 = 0.5;
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const NewtonResult nr =
      solve_fixed_parameter(pr, pr.shooting_guess(ForcedFlip2::xp(0, 0.1, p2) + Eigen::Vector2d(0.02, 0.01), 0.1), 0.1);
  ASSERT_TRUE(nr.converged);
  ContinuationOptions o;
  o.p_max = 0.4;
  o.max_step = 0.1;
  const Branch b = continue_branch(pr, nr.x, 0.1, o);
  ASSERT_EQ(b.special_points.size(), 1u);
  const SpecialPoint& pd = b.special_points[0];
  ASSERT_EQ(pd.type, SpecialPointType::PD);
  EXPECT_NEAR(pd.p, p2 * p2, 1e-8);

  const OrbitTwoParameterProblem base(sys, oo);
  const PeriodDoublingCurveProblem curve(base, pd, p2);
  ContinuationOptions co;
  co.direction = Direction::both;
  co.p_min = -1;
  co.p_max = 1;
  co.max_step = 0.1;
  const Branch c = continue_branch(curve, curve.start(), p2, co);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_DOUBLE_EQ(c.points.front().p, -1.0);
  EXPECT_DOUBLE_EQ(c.points.back().p, 1.0);
  EXPECT_GE(c.points.size(), 10u);
  for (const auto& pt : c.points) {
    const double q2 = pt.p, q1 = pt.x[pt.x.size() - 1];
    EXPECT_NEAR(q1, q2 * q2, 1e-9) << q2;
    EXPECT_NEAR(pt.x[0], 1.0, 1e-9) << q2;
    EXPECT_NEAR(pt.x[1], q2, 1e-9) << q2;
    // A multiplier -1 all along the curve (neutral: no spurious PD points are reported).
    double d = 1e300;
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) d = std::min(d, std::abs(pt.spectrum[i] + 1.0));
    EXPECT_LT(d, 1e-9) << q2;
  }
  for (const auto& sp : c.special_points) EXPECT_NE(sp.type, SpecialPointType::PD);
  std::printf("points %zu steps %zu rejected %zu newton %zu loc %zu sps %zu\n", c.points.size(), c.counters.steps,
              c.counters.rejected_steps, c.counters.newton_iterations, c.counters.location_iterations,
              c.special_points.size());
}

// x' = -(x - x_q(t)) + x_q'(t): the orbit x_q(t) = (2 + cos(t + 0.37), sin t + 0.3 p sin 2t) attracts
// (multipliers e^{-2 pi}) and does not wind around 0, so r = |x| and Psi = -arg x have extrema between
// the samples (the phase 0.37 keeps r's off t = 0).
class ForcedOffset final : public ForcedSystem {
 public:
  static Eigen::Vector2d xq(double t, double p) {
    return {2 + std::cos(t + 0.37), std::sin(t) + 0.3 * p * std::sin(2 * t)};
  }
  Eigen::Index dimension() const override { return 2; }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override {
    const Eigen::Vector2d q = xq(t, p), dq(-std::sin(t + 0.37), std::cos(t) + 0.6 * p * std::cos(2 * t));
    f[0] = -(x[0] - q[0]) + dq[0];
    f[1] = -(x[1] - q[1]) + dq[1];
  }
  void jacobian(double, std::span<const double>, double, Eigen::MatrixXd& J) const override {
    J = -Eigen::MatrixXd::Identity(2, 2);
  }
};

// The maximum over t of g (a smooth 2 pi-periodic function): a 20000-point grid, then golden section
// to 1e-13 in t around the best grid point.
template <class G>
double closed_form_max(const G& g) {
  constexpr int n = 20000;
  int best = 0;
  for (int k = 1; k < n; ++k)
    if (g(kTwoPi * k / n) > g(kTwoPi * best / n)) best = k;
  double a = kTwoPi * (best - 1) / n, b = kTwoPi * (best + 1) / n;
  const double phi = (std::sqrt(5.0) - 1) / 2;
  while (b - a > 1e-13) {
    const double c = b - phi * (b - a), d = a + phi * (b - a);
    (g(c) > g(d) ? b : a) = g(c) > g(d) ? d : c;
  }
  return g(0.5 * (a + b));
}

// The orbit's r_max, r_min, Psi_min, Psi_max are the solution's extrema, not the samples': against the
// closed-form orbit's to 1e-10 (the shooting's rtol 1e-12 and the refinement's 1e-10 in t, which moves an
// extremum's value by ~1e-20; measured ~1e-15). The sampled values (summary(..., false) keeps them for r_max
// and Psi; 64 samples per segment, h = 0.012) miss by 2e-6 (r_max) and 8e-9 (Psi_min), checked > 1e-9.
TEST(OrbitSummaryTest, ExtremaAreTheSolutionsNotTheSamples) {
  const ForcedOffset sys;
  const PeriodicOrbitProblem pr(sys, OrbitOptions{});
  const double p = 1;
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(ForcedOffset::xq(0, p), p), p);
  ASSERT_TRUE(nr.converged);
  const OrbitSummary s = pr.summary(nr.x, p), sampled = pr.summary(nr.x, p, false);
  auto r = [&](double t) { return ForcedOffset::xq(t, p).norm(); };
  auto Psi = [&](double t) { return -std::atan2(ForcedOffset::xq(t, p)[1], ForcedOffset::xq(t, p)[0]); };
  const double r_max = closed_form_max(r), r_min = -closed_form_max([&](double t) { return -r(t); });
  const double Psi_max = closed_form_max(Psi), Psi_min = -closed_form_max([&](double t) { return -Psi(t); });
  EXPECT_EQ(s.winding, 0);
  EXPECT_NEAR(s.r_max, r_max, 1e-10);
  EXPECT_NEAR(s.r_min, r_min, 1e-10);
  EXPECT_NEAR(s.Psi_max, Psi_max, 1e-10);
  EXPECT_NEAR(s.Psi_min, Psi_min, 1e-10);
  // The check can tell: the samples' extrema miss by far more than its bound.
  EXPECT_GT(r_max - sampled.r_max, 1e-9);
  EXPECT_GT(sampled.Psi_min - Psi_min, 1e-9);
  std::printf("r_max %.3e (samples %.3e)  Psi_min %.3e (samples %.3e)\n", s.r_max - r_max, sampled.r_max - r_max,
              s.Psi_min - Psi_min, sampled.Psi_min - Psi_min);
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

namespace rbcstab {
namespace {
Scene fig2_ip(double Delta) { return test::fig2_in_plane(Delta); }
// The reduced system's analytic df/dp (through 1/Lambda and kappa) against central differences of
// its rhs in p, for every parameter, at states off and on the sphere and several times. 1e-7
// relative: the difference's truncation (~h^2, h ~ 6e-6) and rounding (~eps/h ~ 4e-11) errors.
TEST(ReducedOrbit, ParameterDerivativeMatchesDifferences) {
  for (const std::string& name : continuation_parameter_names()) {
    const ContinuationParameter q = continuation_parameter_from_string(name);
    Scene s = fig2_ip(0.3);
    s.physical = unit_cell(s.parameters);  // shear_rate, a table row, needs a cell
    const ReducedForcedSystem sys(s, q);
    const double p = sys.start_parameter();
    for (double t : {0.0, 1.3, 4.0}) {
      for (const Eigen::Vector3d& y : {Eigen::Vector3d(0.3, -0.5, 0.81), Eigen::Vector3d(0.9, 0.2, -0.3)}) {
        double a[3], f[3];
        const std::span<const double> ys(y.data(), 3);
        sys.parameter_derivative(t, ys, p, a);
        sys.ForcedSystem::parameter_derivative(t, ys, p, f);
        const double scale = std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2]), 1e-3});
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], f[i], 1e-7 * scale) << name << " t = " << t << " i = " << i;
      }
    }
  }
}

// flow_terms (one call per stage: f, the dense df/dx from ReducedModel::dense_terms, df/dp from the same phasor)
// against the separate rhs, jacobian (the StructuredJacobian path) and parameter_derivative, for every
// parameter, on and off the sphere: the same formulas in other code, so to rounding (1e-14 relative). Not
// vacuous: the same terms at another time differ by more than 1e-3.
TEST(ReducedOrbit, FlowTermsEqualTheSeparateCalls) {
  for (const std::string& name : continuation_parameter_names()) {
    const ContinuationParameter q = continuation_parameter_from_string(name);
    Scene s = fig2_ip(0.3);
    s.physical = unit_cell(s.parameters);
    const ReducedForcedSystem sys(s, q);
    const double p = sys.start_parameter();
    for (double t : {0.0, 1.3, 4.0}) {
      for (const Eigen::Vector3d& y : {Eigen::Vector3d(0.3, -0.5, 0.81), Eigen::Vector3d(0.9, 0.2, -0.3)}) {
        const std::span<const double> ys(y.data(), 3);
        double f[3], fp[3], f_ref[3], fp_ref[3], f_only[3];
        Eigen::MatrixXd J, J_ref, J_only, J_later;
        sys.flow_terms(t, ys, p, f, J, fp);
        sys.flow_terms(t, ys, p, f_only, J_only, {});
        sys.rhs(t, ys, p, f_ref);
        sys.jacobian(t, ys, p, J_ref);
        sys.parameter_derivative(t, ys, p, fp_ref);
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(f[i], f_ref[i], 1e-14 * (1 + std::abs(f_ref[i]))) << name;
          EXPECT_NEAR(fp[i], fp_ref[i], 1e-14 * (1 + std::abs(fp_ref[i]))) << name;
          EXPECT_EQ(f_only[i], f[i]);
        }
        EXPECT_LE((J - J_ref).norm(), 1e-14 * (1 + J_ref.norm())) << name;
        EXPECT_EQ(J_only, J);
        double f_later[3], fp_later[3];
        sys.flow_terms(t + 1, ys, p, f_later, J_later, fp_later);
        EXPECT_GT((J_later - J_ref).norm(), 1e-3) << name;
      }
    }
  }
}

// Newton from the scene relaxed for T = 300 (a state at a multiple of 2 pi).
Eigen::VectorXd reduced_orbit(const ReducedForcedSystem& sys, const PeriodicOrbitProblem& pr) {
  const double p0 = sys.start_parameter();
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(300), p0), p0);
  EXPECT_TRUE(nr.converged);
  return nr.x;
}

// Flow of the reduced model over whole periods, integrated directly (not through the shooting code).
Eigen::Vector3d period_map(const ReducedModel& m, const Eigen::Vector3d& y, int periods = 1) {
  IntegratorOptions io;
  io.rtol = 1e-13;
  io.atol = 1e-14;
  const double grid[1] = {kTwoPi * periods};
  const IntegrationResult r = integrate(m, std::span<const double>(y.data(), 3), 0.0, grid, io, {});
  return {r.y[0], r.y[1], r.y[2]};
}

// The monodromy against central differences of the directly integrated period map, and the trivial
// multiplier. h = 1e-4: truncation ~h^2 |third derivative| ~ 1e-8 and integration noise ~1e-13/h =
// 1e-9, so the finite-difference monodromy is good to ~1e-7; its (separated) eigenvalues likewise.
TEST(ReducedOrbit, FloquetMatchesFiniteDifferenceMonodromy) {
  for (double Delta : {0.2, 1.0}) {  // swinging, tumbling
    const ReducedForcedSystem sys(fig2_ip(Delta), ContinuationParameter::Delta);
    const PeriodicOrbitProblem pr(sys);
    const Eigen::VectorXd X = reduced_orbit(sys, pr);
    const Floquet f = pr.floquet(X, Delta);
    const Eigen::Vector3d x0 = X.head(3);
    EXPECT_NEAR(x0.norm(), 1.0, 1e-13);
    Eigen::Matrix3d Mfd;
    const double h = 1e-4;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(i);
      Mfd.col(i) = (period_map(sys.model(Delta), x0 + e) - period_map(sys.model(Delta), x0 - e)) / (2 * h);
    }
    EXPECT_LT((Mfd - f.monodromy).lpNorm<Eigen::Infinity>(), 1e-7) << Delta;
    // Trivial multiplier: exactly 1 by the conservation of |y|^2; 1e-11 ~ 10 x the rtol.
    ASSERT_TRUE(f.trivial.has_value());
    EXPECT_NEAR(*f.trivial, 1.0, 1e-11);
    const Eigen::VectorXcd all = Eigen::EigenSolver<Eigen::Matrix3d>(Mfd, false).eigenvalues();
    // Each nontrivial multiplier and 1 appear among the finite-difference eigenvalues.
    const std::vector<std::complex<double>> want = {f.multipliers[0], f.multipliers[1], 1.0};
    for (const auto& w : want) {
      double best = 1e300;
      for (Eigen::Index i = 0; i < 3; ++i) best = std::min(best, std::abs(all[i] - w));
      EXPECT_LT(best, 1e-6) << Delta << " multiplier " << w;
    }
  }
}

// Liouville: det M = exp(int_0^{2 pi} tr J dt), and the trivial multiplier is 1, so the product of
// the nontrivial multipliers is exp(int tr J) -- an independent oracle for their *relative* accuracy
// (the quadrature: periodic trapezoid on 4000 samples of a directly integrated orbit, spectrally
// accurate). Measured relative errors of the plain monodromy product (printed for the docs): 6e-10
// at |mu_1 mu_2| = 2.5e-13, 2e-13 at 3e-5, 3e-15 at 3e-2; the bound 1e-8 leaves margin for rounding.
TEST(ReducedOrbit, MultiplierProductMatchesLiouville) {
  for (double Delta : {0.05, 0.2, 1.0}) {
    const ReducedForcedSystem sys(fig2_ip(Delta), ContinuationParameter::Delta);
    const PeriodicOrbitProblem pr(sys);
    const Eigen::VectorXd X = reduced_orbit(sys, pr);
    const Eigen::Vector3d x0 = X.head(3);
    const ReducedModel& m = sys.model(Delta);
    std::vector<double> grid;
    const int K = 4000;
    for (int k = 1; k < K; ++k) grid.push_back(kTwoPi * k / K);
    double integral = 0;
    auto add_trace = [&](double t, std::span<const double> y) {
      StructuredJacobian J;
      double dfdt[3];
      m.jacobian(t, y, J, dfdt);
      Eigen::Matrix<double, 3, 3, Eigen::RowMajor> D;
      J.to_dense(std::span<double>(D.data(), 9));
      integral += D.trace() * kTwoPi / K;
    };
    add_trace(0, std::span<const double>(x0.data(), 3));
    IntegratorOptions io;
    io.rtol = 1e-13;
    io.atol = 1e-14;
    integrate(m, std::span<const double>(x0.data(), 3), 0.0, grid, io, add_trace);
    const Eigen::VectorXcd mu = pr.spectrum(X, Delta);
    const double product = (mu[0] * mu[1]).real(), expected = std::exp(integral);
    const double rel = std::abs(product - expected) / expected;
    std::printf("Delta = %g: mu1 mu2 = %.6e, exp(int tr J) = %.6e, relative error %.2e\n", Delta, product, expected,
                rel);
    EXPECT_LT(rel, 1e-8) << Delta;
  }
}

// The orbit is the attractor of the dynamics: a long direct integration from the scene's shape
// (40 periods; the multipliers are < 0.2, so transients are < 0.2^40) lands on x_0, and its period
// average equals the orbit's. 1e-9: the required accuracy, ~1000 x the integration tolerance.
TEST(ReducedOrbit, MatchesLongSimulation) {
  for (double Delta : {0.2, 1.0}) {
    const ReducedForcedSystem sys(fig2_ip(Delta), ContinuationParameter::Delta);
    const PeriodicOrbitProblem pr(sys);
    const Eigen::VectorXd X = reduced_orbit(sys, pr);
    const ReducedModel& m = sys.model(Delta);
    const std::vector<double> y0 = m.initial_state();
    const Eigen::Vector3d yT = period_map(m, Eigen::Vector3d(y0[0], y0[1], y0[2]), 40);
    EXPECT_LT((yT - X.head(3)).norm(), 1e-9) << Delta;
    // Period average of the simulation over one more period: 2000 uniform samples (the periodic
    // trapezoid rule, spectrally accurate, and independent of the summary's 8 x 64 samples).
    std::vector<double> grid;
    for (int k = 1; k <= 2000; ++k) grid.push_back(kTwoPi * k / 2000);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    IntegratorOptions io;
    io.rtol = 1e-12;
    integrate(m, std::span<const double>(yT.data(), 3), 0.0, grid, io,
              [&](double, std::span<const double> y) { mean += Eigen::Vector3d(y[0], y[1], y[2]) / 2000.0; });
    const OrbitSummary s = pr.summary(X, Delta);
    EXPECT_LT((s.mean - mean).norm(), 1e-9) << Delta;
    EXPECT_EQ(s.kind, Delta < 0.38 ? OrbitKind::swinging : OrbitKind::tumbling);
    if (s.kind == OrbitKind::tumbling) {
      EXPECT_EQ(s.winding, 1);  // z turns counter-clockwise: Psi decreases by 2 pi per period
      EXPECT_GE(s.Psi_max - s.Psi_min, kTwoPi - 1e-9);
    } else {
      EXPECT_LT(s.Psi_max - s.Psi_min, M_PI);
    }
  }
}

// Fig. 2's in-plane scene continued in Delta: the swinging orbit (Delta = 0.01) becomes tumbling
// (Delta = 1) where the orbit passes through z = 0 (r_min = 0) with both multipliers deep inside
// the unit circle: no LPC/PD/NS, only the UZ event. The number of segments changes neither the
// multipliers (to 1e-9) nor the labels nor the transition's location (to 1e-9).
TEST(ReducedOrbit, SwingingToTumblingIsPassageThroughZeroAndIndependentOfSegments) {
  std::vector<double> located;
  for (int N : {4, 16}) {
    const ReducedForcedSystem sys(fig2_ip(0.3), ContinuationParameter::Delta);
    OrbitOptions oo;
    oo.segments = N;
    const PeriodicOrbitProblem pr(sys, oo);
    const Eigen::VectorXd X = reduced_orbit(sys, pr);
    ContinuationOptions o;
    o.direction = Direction::forward;
    o.p_max = 0.45;
    o.max_step = 0.05;
    o.events.push_back(pr.transition_event());
    const Branch b = continue_branch(pr, X, 0.3, o);
    ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
    ASSERT_EQ(b.special_points.size(), 1u) << N;
    const SpecialPoint& uz = b.special_points[0];
    EXPECT_EQ(uz.type, SpecialPointType::UZ);
    EXPECT_EQ(uz.name, "swing_tumble");
    EXPECT_EQ(uz.status, LocationStatus::located);
    EXPECT_LT(uz.precision, 1e-10);
    located.push_back(uz.p);
    const OrbitSummary at = pr.summary(uz.x, uz.p);
    EXPECT_LT(at.r_min, 1e-8);
    const Eigen::VectorXcd mu = pr.spectrum(uz.x, uz.p);
    EXPECT_LT(std::abs(mu[0]), 0.1);
    EXPECT_LT(std::abs(mu[1]), 0.1);
    for (const auto& pt : b.points) {
      EXPECT_TRUE(pt.stable);
      const OrbitSummary s = pr.summary(pt.x, pt.p);
      EXPECT_EQ(s.winding, pt.p < uz.p ? 0 : 1) << pt.p;
      const Floquet f = pr.floquet(pt.x, pt.p);
      ASSERT_TRUE(f.trivial.has_value());
      EXPECT_NEAR(*f.trivial, 1.0, 1e-11);
    }
  }
  EXPECT_NEAR(located[0], located[1], 1e-9);
  EXPECT_NEAR(located[0], 0.38478125, 1e-6);  // measured at N = 8 (docs/continuation.md)
  // Multipliers at fixed Delta for N = 4, 8, 16 (plain monodromy products) agree to 1e-9.
  for (double Delta : {0.35, 1.0}) {
    std::vector<Eigen::VectorXcd> mus;
    for (int N : {4, 8, 16}) {
      const ReducedForcedSystem sys(fig2_ip(Delta), ContinuationParameter::Delta);
      OrbitOptions oo;
      oo.segments = N;
      const PeriodicOrbitProblem pr(sys, oo);
      mus.push_back(pr.spectrum(reduced_orbit(sys, pr), Delta));
    }
    for (std::size_t k = 1; k < mus.size(); ++k)
      for (Eigen::Index i = 0; i < 2; ++i) {
        double best = 1e300;
        for (Eigen::Index j = 0; j < 2; ++j) best = std::min(best, std::abs(mus[k][i] - mus[0][j]));
        EXPECT_LT(best, 1e-9) << Delta;
      }
  }
}

// Delta = 1 tumbles at lambda = 5 (Fig. 2) and swings at low viscosity ratio.
TEST(ReducedOrbit, ContinuesInLambdaThroughTheTransition) {
  const ReducedForcedSystem sys(fig2_ip(1.0), ContinuationParameter::lambda);
  const PeriodicOrbitProblem pr(sys);
  ContinuationOptions o;
  o.direction = Direction::backward;
  o.p_min = 2;
  o.max_step = 0.2;
  o.events.push_back(pr.transition_event());
  const Branch b = continue_branch(pr, reduced_orbit(sys, pr), 5.0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_EQ(b.special_points.size(), 1u);
  EXPECT_EQ(b.special_points[0].type, SpecialPointType::UZ);
  EXPECT_NEAR(b.special_points[0].p, 2.573269, 1e-5);  // measured at N = 8, max step 0.05
  EXPECT_EQ(pr.summary(b.points.back().x, b.points.back().p).kind, OrbitKind::swinging);
  EXPECT_EQ(pr.summary(b.points.front().x, b.points.front().p).kind, OrbitKind::tumbling);
}

}  // namespace
}  // namespace rbcstab
