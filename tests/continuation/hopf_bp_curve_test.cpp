// Two-parameter Hopf and branch-point curves against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/hopf_curve.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

// Brusselator x' = a - (b + 1) x + x^2 y, y' = b x - x^2 y, plus a slaved stable z' = -z + (x - a)^2.
// Equilibrium (a, b/a, 0); Jacobian of (x, y) [[b - 1, a^2], [-b, -a^2]]: trace b - 1 - a^2,
// determinant a^2, so the Hopf curve is b = 1 + a^2 with omega = a. p1 = b, p2 = a.
class Brusselator final : public TwoParameterProblem {
 public:
  Eigen::Index dimension() const override { return 3; }
  void residual(const Eigen::VectorXd& u, double b, double a, Eigen::VectorXd& F) const override {
    const double x = u[0], y = u[1], z = u[2];
    F.resize(3);
    F << a - (b + 1) * x + x * x * y, b * x - x * x * y, -z + (x - a) * (x - a);
  }
  void jacobian(const Eigen::VectorXd& u, double b, double a, Eigen::MatrixXd& J) const override {
    const double x = u[0], y = u[1];
    J.resize(3, 3);
    J << -(b + 1) + 2 * x * y, x * x, 0, b - 2 * x * y, -x * x, 0, 2 * (x - a), 0, -1;
  }
  std::string name1() const override { return "b"; }
  std::string name2() const override { return "a"; }
};

TEST(HopfCurve, BrusselatorHopfCurveMatchesClosedForm) {
  const Brusselator br;
  const double a0 = 1;
  const SliceProblem slice(br, a0);
  ContinuationOptions o;
  o.p_min = 1.2;
  o.p_max = 3;
  o.max_step = 0.1;
  Eigen::VectorXd x0(3);
  x0 << a0, 1.2 / a0, 0;
  const Branch b = continue_branch(slice, x0, 1.2, o);
  const SpecialPoint* hb = find_special_point(b, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  EXPECT_NEAR(hb->p, 1 + a0 * a0, 1e-8);

  const HopfCurveProblem hc(br, *hb, a0);
  ContinuationOptions o2;
  o2.p_min = 0.3;  // away from omega = a -> 0 (Bogdanov-Takens at a = 0)
  o2.p_max = 3;
  o2.max_step = 0.1;
  o2.direction = Direction::both;
  o2.detect_bifurcations = false;  // the critical pair sits on the imaginary axis all along
  const Branch curve = continue_branch(hc, hc.start(), a0, o2);
  ASSERT_EQ(curve.status, ContinuationStatus::completed) << curve.message;
  EXPECT_DOUBLE_EQ(curve.points.front().p, 0.3);
  EXPECT_DOUBLE_EQ(curve.points.back().p, 3.0);
  ASSERT_GT(curve.points.size(), 20u);
  for (const auto& pt : curve.points) {
    const double bb = pt.parameters[0], a = pt.parameters[1];
    // 1e-9: Newton to 1e-12 with the analytic Jacobian; the bordered G is exact up to rounding.
    EXPECT_NEAR(bb, 1 + a * a, 1e-9) << "a = " << a;
    EXPECT_NEAR(hc.omega(pt.x), a, 1e-9) << "a = " << a;
    EXPECT_NEAR(pt.x[0], a, 1e-9);
    EXPECT_NEAR(pt.x[1], bb / a, 1e-9);
  }
}

TEST(HopfCurve, StartMustBeALocatedHopfPoint) {
  const Brusselator br;
  SpecialPoint lp;
  lp.type = SpecialPointType::LP;
  lp.status = LocationStatus::located;
  lp.x = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(HopfCurveProblem(br, lp, 1.0), InvalidArgument);
}

// Pitchfork with Z2 symmetry x -> -x: x' = x (p1 + sin p2 - x^2 - y), y' = -y + x^2. The trivial
// branch x = y = 0 has J = diag(p1 + sin p2, -1): the BP curve is p1 = -sin p2.
class Pitchfork final : public TwoParameterProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& u, double p1, double p2, Eigen::VectorXd& F) const override {
    const double x = u[0], y = u[1];
    F.resize(2);
    F << x * (p1 + std::sin(p2) - x * x - y), -y + x * x;
  }
  void jacobian(const Eigen::VectorXd& u, double p1, double p2, Eigen::MatrixXd& J) const override {
    const double x = u[0], y = u[1];
    J.resize(2, 2);
    J << p1 + std::sin(p2) - 3 * x * x - y, -x, 2 * x, -1;
  }
  void parameter_derivative(const Eigen::VectorXd& u, double, double, Eigen::VectorXd& Fp) const override {
    Fp.resize(2);
    Fp << u[0], 0;
  }
};

// Transcritical with an invariant trivial solution: x' = (p1 - p2^2) x - x^2 + x y, y' = -2 y + x^3.
// BP curve p1 = p2^2 (default finite-difference parameter derivative).
class Transcritical final : public TwoParameterProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& u, double p1, double p2, Eigen::VectorXd& F) const override {
    const double x = u[0], y = u[1];
    F.resize(2);
    F << (p1 - p2 * p2) * x - x * x + x * y, -2 * y + x * x * x;
  }
  void jacobian(const Eigen::VectorXd& u, double p1, double p2, Eigen::MatrixXd& J) const override {
    const double x = u[0], y = u[1];
    J.resize(2, 2);
    J << p1 - p2 * p2 - 2 * x + y, x, 3 * x * x, -2;
  }
};

template <class Curve>
void check_bp_curve(const TwoParameterProblem& base, double p2_0, double p1_lo, double p1_hi, Curve&& closed) {
  const SliceProblem slice(base, p2_0);
  ContinuationOptions o;
  o.p_min = p1_lo;
  o.p_max = p1_hi;
  o.max_step = 0.1;
  const Branch b = continue_branch(slice, Eigen::VectorXd::Zero(2), p1_lo, o);  // the trivial branch
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  EXPECT_NEAR(bp->p, closed(p2_0), 1e-8);

  const BranchPointCurveProblem bc(base, *bp, p2_0);
  ContinuationOptions o2;
  o2.p_min = -2;
  o2.p_max = 2;
  o2.max_step = 0.1;
  o2.direction = Direction::both;
  o2.detect_bifurcations = false;  // one eigenvalue is zero all along the curve
  const Branch curve = continue_branch(bc, bc.start(), p2_0, o2);
  ASSERT_EQ(curve.status, ContinuationStatus::completed) << curve.message;
  EXPECT_DOUBLE_EQ(curve.points.front().p, -2.0);
  EXPECT_DOUBLE_EQ(curve.points.back().p, 2.0);
  ASSERT_GT(curve.points.size(), 20u);
  for (const auto& pt : curve.points) {
    const double p1 = pt.parameters[0], p2 = pt.parameters[1];
    // 1e-9: Newton to 1e-12 on a regular system; the finite-difference F_p1 (transcritical case)
    // is exact here because F is linear in p1.
    EXPECT_NEAR(p1, closed(p2), 1e-9) << "p2 = " << p2;
    EXPECT_NEAR(pt.x[0], 0, 1e-10);
    EXPECT_NEAR(pt.x[1], 0, 1e-10);
    EXPECT_LT(std::abs(bc.mu(pt.x)), 1e-12);           // the BP persists: no unfolding needed
    EXPECT_NEAR(std::abs(bc.psi(pt.x)[0]), 1, 1e-10);  // the critical direction is x
  }
}

TEST(BranchPointCurve, PitchforkCurveMatchesClosedForm) {
  check_bp_curve(Pitchfork(), 0.5, -1.5, 1.0, [](double p2) { return -std::sin(p2); });
}

TEST(BranchPointCurve, TranscriticalCurveMatchesClosedForm) {
  check_bp_curve(Transcritical(), 0.5, -1.0, 1.5, [](double p2) { return p2 * p2; });
}

// A symmetry-breaking second parameter: x' = p1 x - x^3 + p2. The BP of the symmetric problem
// (p2 = 0, at p1 = 0) does not persist: along the extended system's curve mu = -p2 (psi = 1, x = 0:
// F + mu psi = p2 + mu), so mu measures the imperfection and vanishes only at p2 = 0.
class Imperfect final : public TwoParameterProblem {
 public:
  Eigen::Index dimension() const override { return 1; }
  void residual(const Eigen::VectorXd& u, double p1, double p2, Eigen::VectorXd& F) const override {
    F.resize(1);
    F << p1 * u[0] - u[0] * u[0] * u[0] + p2;
  }
};

TEST(BranchPointCurve, SymmetryBreakingParameterShowsAsNonzeroMu) {
  const Imperfect base;
  const SliceProblem slice(base, 0.0);
  ContinuationOptions o;
  o.p_min = -1;
  o.p_max = 1;
  o.max_step = 0.1;
  const Branch b = continue_branch(slice, Eigen::VectorXd::Zero(1), -1.0, o);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  const BranchPointCurveProblem bc(base, *bp, 0.0);
  ContinuationOptions o2;
  o2.p_min = -0.5;
  o2.p_max = 0.5;
  o2.max_step = 0.05;
  o2.direction = Direction::both;
  o2.detect_bifurcations = false;
  const Branch curve = continue_branch(bc, bc.start(), 0.0, o2);
  ASSERT_EQ(curve.status, ContinuationStatus::completed) << curve.message;
  EXPECT_DOUBLE_EQ(curve.points.front().p, -0.5);  // reached both ends: mu grows to |p2| = 0.5
  EXPECT_DOUBLE_EQ(curve.points.back().p, 0.5);
  for (const auto& pt : curve.points) {
    const double psi = bc.psi(pt.x)[0];
    // Closed form: J^T psi = p1 - 3x^2 = 0 and F_p1 psi = x = 0 give x = 0, p1 = 0; then mu psi = -p2.
    // 1e-9: finite-difference Jacobian of the extended system (central differences, ~1e-10).
    EXPECT_NEAR(bc.mu(pt.x) * psi, -pt.p, 1e-9);
    EXPECT_NEAR(pt.parameters[0], 0, 1e-9);
  }
}

}  // namespace
}  // namespace rbcstab
