// Neimark-Sacker curves of forced periodic orbits against closed forms: a forced system whose orbit
// and Floquet multipliers are known, so the NS curve, its angle theta and the neutral saddles of the
// squared-monodromy test function are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "continuation/ns_fixtures.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/ns_curve.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {
using ns_fixtures::Forced3;

constexpr double kOmega = 0.3;

// The NS point of the one-parameter run in p1 at fixed p2 (started off the orbit).
SpecialPoint locate_ns(const Forced3& sys, const OrbitOptions& oo, double p2) {
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const double p1 = p2 * p2 - 0.1;
  const NewtonResult nr =
      solve_fixed_parameter(pr, pr.shooting_guess(Forced3::xp(0, p1, p2) + Eigen::Vector3d(0.02, 0.01, -0.01), p1), p1);
  EXPECT_TRUE(nr.converged);
  ContinuationOptions o;
  o.p_max = p2 * p2 + 0.1;
  o.max_step = 0.05;
  const Branch b = continue_branch(pr, nr.x, p1, o);
  EXPECT_EQ(b.special_points.size(), 1u);
  return b.special_points.empty() ? SpecialPoint{} : b.special_points[0];
}

// The NS curve continued in p2 over [-0.8, 0.8] against p1 = p2^2, x(0) = xp(0), kappa = cos(2 pi omega)
// and the pair e^{+-2 pi i omega} of the computed monodromy, all to 1e-9 (Newton to 1e-12 on residuals
// integrated at rtol 1e-12; the multipliers of a one-period integration at rtol 1e-12 are good to ~1e-10).
TEST(NeimarkSackerCurve, ClosedFormCurve) {
  const Forced3 sys(-kOmega * kOmega);
  OrbitOptions oo;
  oo.segments = 3;
  const double p2 = 0.4;
  const SpecialPoint ns = locate_ns(sys, oo, p2);
  ASSERT_EQ(ns.type, SpecialPointType::NS);
  ASSERT_EQ(ns.status, LocationStatus::located);
  EXPECT_NEAR(ns.p, p2 * p2, 1e-8);

  const NeimarkSackerCurveProblem curve(sys, oo, ns, p2);
  EXPECT_NEAR(curve.start()[curve.start().size() - 1], std::cos(kTwoPi * kOmega), 1e-8);
  ContinuationOptions co;
  co.direction = Direction::both;
  co.p_min = -0.8;
  co.p_max = 0.8;
  co.max_step = 0.1;
  co.events = {curve.resonance_event()};
  const Branch c = continue_branch(curve, curve.start(), p2, co);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_DOUBLE_EQ(c.points.front().p, -0.8);
  EXPECT_DOUBLE_EQ(c.points.back().p, 0.8);
  EXPECT_GE(c.points.size(), 10u);
  const Eigen::Index m = curve.dimension() - 2;
  for (const auto& pt : c.points) {
    const double q2 = pt.p, q1 = pt.x[m], kappa = pt.x[m + 1];
    EXPECT_NEAR(q1, q2 * q2, 1e-9) << q2;
    EXPECT_NEAR((pt.x.head(3) - Forced3::xp(0, q1, q2)).norm(), 0, 1e-9) << q2;
    EXPECT_NEAR(kappa, std::cos(kTwoPi * kOmega), 1e-9) << q2;
    const NeimarkSackerKind k = curve.classify(pt.x);
    EXPECT_FALSE(k.neutral_saddle);
    EXPECT_NEAR(k.theta, kTwoPi * kOmega, 1e-9) << q2;
    // The NS condition on the computed monodromy: the pair e^{+-i theta}, and the stable e^{-2 pi}.
    const Eigen::VectorXcd mu = curve.floquet(pt.x.head(m), q1, q2).multipliers;
    const std::complex<double> ex = std::polar(1.0, kTwoPi * kOmega);
    double d_pair = 1e300, d_conj = 1e300, d_stable = 1e300;
    for (Eigen::Index i = 0; i < mu.size(); ++i) {
      d_pair = std::min(d_pair, std::abs(mu[i] - ex));
      d_conj = std::min(d_conj, std::abs(mu[i] - std::conj(ex)));
      d_stable = std::min(d_stable, std::abs(mu[i] - std::exp(-kTwoPi)));
    }
    EXPECT_LT(d_pair, 1e-9) << q2;
    EXPECT_LT(d_conj, 1e-9) << q2;
    EXPECT_LT(d_stable, 1e-9) << q2;
    // G vanishes on the curve (all four entries, not only the two continued).
    EXPECT_LT(curve.test_functions(pt.x.head(m), q1, kappa, q2).cwiseAbs().maxCoeff(), 1e-9) << q2;
  }
  // The pair stays on the unit circle: no NS points along the curve, no resonance (kappa fixed).
  for (const auto& sp : c.special_points) {
    EXPECT_NE(sp.type, SpecialPointType::NS);
    EXPECT_NE(sp.type, SpecialPointType::UZ);
  }
}

// Off the curve G does not vanish: at p1 = p2^2 + 0.05 (|mu| = e^{0.1 pi}) and at the right p1 with a
// wrong kappa. Guards against a test function that is identically small.
TEST(NeimarkSackerCurve, TestFunctionNonzeroOffCurve) {
  const Forced3 sys(-kOmega * kOmega);
  OrbitOptions oo;
  oo.segments = 3;
  const double p2 = 0.4;
  const SpecialPoint ns = locate_ns(sys, oo, p2);
  ASSERT_EQ(ns.type, SpecialPointType::NS);
  const NeimarkSackerCurveProblem curve(sys, oo, ns, p2);
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const double p1 = p2 * p2 + 0.05;
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(Forced3::xp(0, p1, p2), p1), p1);
  ASSERT_TRUE(nr.converged);
  const double kappa = std::cos(kTwoPi * kOmega);
  EXPECT_GT(curve.test_functions(nr.x, p1, kappa, p2).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT(curve.test_functions(ns.x, ns.p, kappa + 0.1, p2).cwiseAbs().maxCoeff(), 1e-3);
}

// A neutral saddle (real pair e^{+-2 pi s}, product 1) also zeroes the squared-monodromy test function,
// with kappa = cosh(2 pi s) > 1. System with q = p2 - omega^2: an NS point at p2 = 0 (theta = 2 pi omega),
// a neutral saddle with s = sqrt(p2 - omega^2) on a = 0 for p2 > omega^2. There all four entries of G
// vanish on the orbit with kappa = cosh(2 pi s) (1e-9, as on the NS curve) and not with kappa + 0.1;
// Newton on the curve's equations at fixed p2 converges to it from an offset guess; classify() reports
// it as a neutral saddle with the real multiplier e^{2 pi s} (closed form), not as an NS.
TEST(NeimarkSackerCurve, NeutralSaddleReportedAsSuch) {
  const Forced3 sys(-kOmega * kOmega, 1.0);
  OrbitOptions oo;
  oo.segments = 3;
  const SpecialPoint ns = locate_ns(sys, oo, 0.0);
  ASSERT_EQ(ns.type, SpecialPointType::NS);
  const NeimarkSackerCurveProblem curve(sys, oo, ns, 0.0);
  const double s = 0.15, p2 = kOmega * kOmega + s * s, p1 = p2 * p2, kappa = std::cosh(kTwoPi * s);
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(Forced3::xp(0, p1, p2), p1), p1);
  ASSERT_TRUE(nr.converged);
  EXPECT_LT(curve.test_functions(nr.x, p1, kappa, p2).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT(curve.test_functions(nr.x, p1, kappa + 0.1, p2).cwiseAbs().maxCoeff(), 1e-3);
  // The orbit's own multipliers confirm the real pair with product 1 (no complex pair on the circle).
  const Eigen::VectorXcd mu = curve.floquet(nr.x, p1, p2).multipliers;
  int real_pair = 0;
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    if (std::abs(mu[i].imag()) < 1e-12 &&
        (std::abs(mu[i].real() - std::exp(kTwoPi * s)) < 1e-9 || std::abs(mu[i].real() - std::exp(-kTwoPi * s)) < 1e-9))
      ++real_pair;
  EXPECT_EQ(real_pair, 2);

  Eigen::VectorXd X0(nr.x.size() + 2);
  X0 << nr.x, p1 + 0.01, kappa + 0.05;
  const NewtonResult cr = solve_fixed_parameter(curve, X0, p2);
  ASSERT_TRUE(cr.converged);
  const Eigen::Index m = nr.x.size();
  EXPECT_NEAR(cr.x[m], p1, 1e-9);
  EXPECT_NEAR(cr.x[m + 1], kappa, 1e-9);
  const NeimarkSackerKind k = curve.classify(cr.x);
  EXPECT_TRUE(k.neutral_saddle);
  EXPECT_NEAR(k.real_multiplier, std::exp(kTwoPi * s), 1e-8);
  EXPECT_DOUBLE_EQ(k.theta, 0.0);
}

// Through the 1:1 resonance: with q = p2 - omega^2 the NS curve a = 0 (p1 = p2^2) reaches kappa = 1 at
// p2 = omega^2 (double multiplier 1) and continues as a neutral-saddle curve, kappa = cos(2 pi sqrt(-q))
// before and cosh(2 pi sqrt(q)) after (one analytic function of q). Every point is checked against the
// closed form (1e-9) and classified from kappa. The resonance is reported as a UZ event near
// p2 = omega^2, but only to ~1e-3: in this system the forced orbit persists through the double
// multiplier 1, so dF/dp lies in the range of the singular shooting Jacobian and the 1:1 point is a
// singular point of the defining system (Newton stalls next to it; a generic R1 point sits on an LPC
// curve instead). Bifurcation detection is off: the engine would report that singularity as a BP.
TEST(NeimarkSackerCurve, ThroughResonanceIntoNeutralSaddle) {
  const Forced3 sys(-kOmega * kOmega, 1.0);
  OrbitOptions oo;
  oo.segments = 3;
  const SpecialPoint ns = locate_ns(sys, oo, 0.0);
  ASSERT_EQ(ns.type, SpecialPointType::NS);
  const NeimarkSackerCurveProblem curve(sys, oo, ns, 0.0);
  ContinuationOptions co;
  co.p_min = -0.05;
  co.p_max = 0.15;
  co.max_step = 0.02;
  co.detect_bifurcations = false;
  co.max_location_iterations = 20;
  co.events = {curve.resonance_event()};
  const Branch c = continue_branch(curve, curve.start(), 0.0, co);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_DOUBLE_EQ(c.points.back().p, 0.15);
  const Eigen::Index m = curve.dimension() - 2;
  for (const auto& pt : c.points) {
    const double q = pt.p - kOmega * kOmega;
    const double kappa = q < 0 ? std::cos(kTwoPi * std::sqrt(-q)) : std::cosh(kTwoPi * std::sqrt(q));
    EXPECT_NEAR(pt.x[m], pt.p * pt.p, 1e-9) << pt.p;
    EXPECT_NEAR(pt.x[m + 1], kappa, 1e-9) << pt.p;
    EXPECT_EQ(curve.classify(pt.x).neutral_saddle, q > 0) << pt.p;
  }
  int uz = 0;
  for (const auto& sp : c.special_points) {
    if (sp.type != SpecialPointType::UZ) continue;
    ++uz;
    EXPECT_NEAR(sp.p, kOmega * kOmega, 1e-3);
  }
  EXPECT_EQ(uz, 1);
}

// A norm-conserving forced system (x . f = 0 identically, like the reduced in-plane system):
// f = g |x|^2 - (x . g) x with g = (a x1 - omega x2 + eps cos t, omega x1 + a x2 + eps sin t, 0),
// a = p1 - p2^2. Near the pole x = e_3 the tangent dynamics is the forced focus, so an NS curve exists
// near a = 0, shifted by O(eps^2) (no closed form). Oracles: the one-parameter NS location of a
// ForcedSlice run at p2 = 0.5 (the engine's multiplier-product test function, located to 1e-11 in
// (X, p)) against the curve's point at p2 = 0.5 (a UZ event), and at every curve point the tangent-plane
// multipliers (computed independently of the pencil, by orbit.hpp's restriction to x0^perp) with a pair
// e^{+-i theta}, theta = arccos kappa, and the trivial multiplier 1, to 1e-9.
class NormConserving final : public ForcedSystem2 {
 public:
  Eigen::Index dimension() const override { return 3; }
  bool conserves_norm() const override { return true; }
  static Eigen::Vector3d g(double t, const Eigen::Vector3d& x, double a) {
    return {a * x[0] - kOmega * x[1] + kEps * std::cos(t), kOmega * x[0] + a * x[1] + kEps * std::sin(t), 0};
  }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    const Eigen::Vector3d X(x[0], x[1], x[2]), G = g(t, X, p1 - p2 * p2);
    const Eigen::Vector3d F = G * X.squaredNorm() - X.dot(G) * X;
    for (int i = 0; i < 3; ++i) f[static_cast<std::size_t>(i)] = F[i];
  }
  // df/dx = Dg |x|^2 + 2 g x^T - (x . g) I - x (g + Dg^T x)^T.
  void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const override {
    const double a = p1 - p2 * p2;
    const Eigen::Vector3d X(x[0], x[1], x[2]), G = g(t, X, a);
    Eigen::Matrix3d Dg;
    Dg << a, -kOmega, 0, kOmega, a, 0, 0, 0, 0;
    J = Dg * X.squaredNorm() + 2 * G * X.transpose() - X.dot(G) * Eigen::Matrix3d::Identity() -
        X * (G + Dg.transpose() * X).transpose();
  }
  // dg/da = (x1, x2, 0) =: h; df/dp1 = h |x|^2 - (x . h) x.
  void parameter_derivative(double, std::span<const double> x, double, double, std::span<double> fp) const override {
    const Eigen::Vector3d X(x[0], x[1], x[2]), h(x[0], x[1], 0);
    const Eigen::Vector3d F = h * X.squaredNorm() - X.dot(h) * X;
    for (int i = 0; i < 3; ++i) fp[static_cast<std::size_t>(i)] = F[i];
  }

 private:
  static constexpr double kEps = 0.2;
};

SpecialPoint locate_ns_sphere(const NormConserving& sys, const OrbitOptions& oo, double p2) {
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const double p1 = p2 * p2 - 0.1;
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(Eigen::Vector3d(0.1, 0.1, 0.99), p1), p1);
  EXPECT_TRUE(nr.converged);
  ContinuationOptions o;
  o.p_max = p2 * p2 + 0.1;
  o.max_step = 0.05;
  const Branch b = continue_branch(pr, nr.x, p1, o);
  EXPECT_EQ(b.special_points.size(), 1u);
  return b.special_points.empty() ? SpecialPoint{} : b.special_points[0];
}

TEST(NeimarkSackerCurve, ConservedNormAgreesWithSliceLocation) {
  const NormConserving sys;
  OrbitOptions oo;
  oo.segments = 3;
  const SpecialPoint ns = locate_ns_sphere(sys, oo, 0.2);
  ASSERT_EQ(ns.type, SpecialPointType::NS);
  ASSERT_EQ(ns.status, LocationStatus::located);
  const SpecialPoint ns5 = locate_ns_sphere(sys, oo, 0.5);
  ASSERT_EQ(ns5.type, SpecialPointType::NS);
  ASSERT_EQ(ns5.status, LocationStatus::located);

  const NeimarkSackerCurveProblem curve(sys, oo, ns, 0.2);
  ContinuationOptions co;
  co.p_min = 0.0;
  co.p_max = 0.6;
  co.max_step = 0.1;
  co.events = {UserEvent{"p2_half", [](const Eigen::VectorXd&, double p2) { return p2 - 0.5; }}};
  const Branch c = continue_branch(curve, curve.start(), 0.2, co);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_DOUBLE_EQ(c.points.back().p, 0.6);
  const Eigen::Index m = curve.dimension() - 2;
  for (const auto& pt : c.points) {
    const double q1 = pt.x[m], theta = curve.classify(pt.x).theta;
    EXPECT_FALSE(curve.classify(pt.x).neutral_saddle);
    const Floquet fl = curve.floquet(pt.x.head(m), q1, pt.p);
    ASSERT_TRUE(fl.trivial.has_value());
    EXPECT_NEAR(*fl.trivial, 1.0, 1e-9) << pt.p;
    ASSERT_EQ(fl.multipliers.size(), 2);
    for (Eigen::Index i = 0; i < 2; ++i) {
      EXPECT_NEAR(std::abs(fl.multipliers[i]), 1.0, 1e-9) << pt.p;
      EXPECT_NEAR(std::abs(std::arg(fl.multipliers[i])), theta, 1e-9) << pt.p;
    }
  }
  int uz = 0;
  for (const auto& sp : c.special_points) {
    if (sp.type != SpecialPointType::UZ) continue;
    ++uz;
    ASSERT_EQ(sp.status, LocationStatus::located);
    // Both locations converge to 1e-11 in (X, p); 1e-8 leaves room for the bracket widths.
    EXPECT_NEAR(sp.x[m], ns5.p, 1e-8);
    EXPECT_NEAR(std::acos(sp.x[m + 1]), std::abs(std::arg(ns5.eigenvalue)), 1e-8);
  }
  EXPECT_EQ(uz, 1);
}

TEST(NeimarkSackerCurve, RejectsNonNsStart) {
  const Forced3 sys(-kOmega * kOmega);
  SpecialPoint sp;
  sp.type = SpecialPointType::PD;
  sp.status = LocationStatus::located;
  EXPECT_THROW(NeimarkSackerCurveProblem(sys, OrbitOptions{}, sp, 0.0), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
