// Out-of-plane equilibria of the reduced system against the closed form (docs/theory.md):
// cos Psi = Lambda r, sqrt(1 - r^2) sin Psi = r / S, u = r^2 the root in (0, 1) of
// Lambda^2 u^2 - (1 + Lambda^2 + S^-2) u + 1 = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

PolarState closed_form(const Parameters& p) {
  const double L = p.Lambda(), iS = 1 / p.S();
  const double b = 1 + L * L + iS * iS;
  const double u = 2 / (b + std::sqrt(b * b - 4 * L * L));  // smaller root, cancellation-free
  const double r = std::sqrt(u);
  return {r, std::atan2(iS / std::sqrt(1 - u), L)};  // sin Psi / cos Psi = (r/(S w)) / (Lambda r)
}

Scene op_scene() {
  Scene s;
  s.beta = 0;  // out-of-plane rest shape: autonomous reduced system
  s.parameters.lambda = 0;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.01;
  s.parameters.C = 0.04;
  return s;
}

// Continues from a start 1e-2 away from the closed form and checks every branch point (and the
// bound landing) against the closed form at that point's parameter. 1e-10: Newton converges to
// |dX| <= 1e-12 (1 + |X|) and the closed form is evaluated cancellation-free, so the error budget is
// a few 1e-12; 1e-10 is the required accuracy.
void check_branch(ContinuationParameter q, Scene s, double p_lo, double p_hi, std::size_t min_points) {
  const ReducedEquilibriumProblem pr(s, q);
  const double p0 = get_parameter(s.parameters, q);
  const PolarState c0 = closed_form(s.parameters);
  const double w0 = std::sqrt(1 - c0.r * c0.r);
  Eigen::VectorXd y(3);
  y << c0.r * std::cos(c0.Psi) + 1e-2, -c0.r * std::sin(c0.Psi), w0 - 1e-2;
  ContinuationOptions o;
  o.p_min = p_lo;
  o.p_max = p_hi;
  o.direction = Direction::both;
  o.max_step = 0.5;
  const Branch b = continue_branch(pr, y, p0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << to_string(q) << ": " << b.message;
  EXPECT_DOUBLE_EQ(b.points.front().p, p_lo);
  EXPECT_DOUBLE_EQ(b.points.back().p, p_hi);
  EXPECT_GE(b.points.size(), min_points);
  for (const auto& pt : b.points) {
    const PolarState c = closed_form(with_parameter(s.parameters, q, pt.p));
    const PolarState g = polar(pt.x);
    EXPECT_NEAR(g.r, c.r, 1e-10) << to_string(q) << " = " << pt.p;
    EXPECT_NEAR(g.Psi, c.Psi, 1e-10) << to_string(q) << " = " << pt.p;
    EXPECT_NEAR(pt.x.norm(), 1.0, 1e-13);
    EXPECT_GT(pt.x[2], 0);
    EXPECT_TRUE(pt.stable) << to_string(q) << " = " << pt.p;  // the attracting OP state
  }
  EXPECT_TRUE(b.special_points.empty());
}

TEST(ReducedEquilibrium, OutOfPlaneBranchInLambdaMatchesClosedForm) {
  check_branch(ContinuationParameter::lambda, op_scene(), 0.0, 20.0, 20);
}

TEST(ReducedEquilibrium, OutOfPlaneBranchInEveryParameter) {
  Scene s = op_scene();
  s.parameters.lambda = 5;
  check_branch(ContinuationParameter::Lambda, s, 0.2, 3.0,
               5);  // through Lambda = 1 at finite S (Delta >= Delta0: Lambda >= 0.19)
  check_branch(ContinuationParameter::S, s, 0.05, 50.0, 5);  // r -> 1 regime as S grows
  check_branch(ContinuationParameter::C, s, 0.001, 1.0, 5);
  check_branch(ContinuationParameter::Delta, s, 0.02, 3.0, 5);
  // kappa = 1/(Lambda S) ~ sqrt(Delta0): the branch has a square-root end at Delta0 = 0 (a fold in
  // this parameterisation), so Delta0 is continued on [1e-4, 0.5]; S or C reach the S -> inf regime.
  check_branch(ContinuationParameter::Delta0, s, 1e-4, 0.5, 5);
  // B does not enter the reduced equilibrium: a straight branch.
  check_branch(ContinuationParameter::B, s, 0.1, 10.0, 3);
}

TEST(ReducedEquilibrium, StartFromRelaxedSimulation) {
  // An independent start: the state after relaxing from the undeformed orientation reaches the
  // closed form (the branch is the attractor).
  Scene s = op_scene();
  s.parameters.lambda = 5;
  const ReducedEquilibriumProblem pr(s, ContinuationParameter::lambda);
  const NewtonResult n = solve_fixed_parameter(pr, pr.relaxed_state(200), 5.0);
  ASSERT_TRUE(n.converged);
  const PolarState c = closed_form(s.parameters), g = polar(n.x);
  EXPECT_NEAR(g.r, c.r, 1e-12);
  EXPECT_NEAR(g.Psi, c.Psi, 1e-12);
}

TEST(ReducedEquilibrium, VesicleLimitTankTreadingEndsAtLambdaOne) {
  // S = inf (Delta0 = 0), paper Eq. ss_red: for Lambda < 1 the equilibria are r = 1, Psi = +-arccos
  // Lambda (+ stable, - unstable); they merge at Lambda = 1, where the r = 1/Lambda family
  // (w != 0) is born: a fold of the r = 1 branch that is also a branch point, both at Lambda = 1.
  Scene s = op_scene();
  s.parameters.lambda = 5;
  s.parameters.Delta = 0.2;  // Lambda = 0.85
  s.parameters.Delta0 = 0;
  const ReducedEquilibriumProblem pr(s, ContinuationParameter::Lambda);
  const double L0 = s.parameters.Lambda();
  Eigen::VectorXd y(3);
  y << L0, -std::sqrt(1 - L0 * L0), 0;  // z = e^{-i Psi}, cos Psi = Lambda
  ContinuationOptions o;
  o.p_min = 0.3;
  o.p_max = 3;
  o.max_step = 0.05;
  const Branch b = continue_branch(pr, y, L0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_DOUBLE_EQ(b.points.back().p, 0.3);  // came back on the mirror branch
  for (const auto& pt : b.points) {
    const PolarState g = polar(pt.x);
    EXPECT_NEAR(g.r, 1.0, 1e-12);
    EXPECT_NEAR(std::cos(g.Psi), pt.p, 1e-10);
    EXPECT_EQ(pt.stable, g.Psi > 0) << "Lambda = " << pt.p;
  }
  bool lp = false, bp = false;
  for (const auto& sp : b.special_points) {
    EXPECT_NEAR(sp.p, 1.0, 1e-8) << to_string(sp.type);
    lp = lp || sp.type == SpecialPointType::LP;
    bp = bp || sp.type == SpecialPointType::BP;
    EXPECT_NE(sp.type, SpecialPointType::HB);
  }
  EXPECT_TRUE(lp);
  EXPECT_TRUE(bp);

  // The r = 1/Lambda family for Lambda > 1 is a centre (eigenvalues +-i omega): neutral, so no
  // spurious HB may be read from rounding noise in the spectral test function.
  s.parameters.Delta = 1;  // Lambda = 1.9
  const ReducedEquilibriumProblem pr2(s, ContinuationParameter::Lambda);
  const double L1 = s.parameters.Lambda();
  Eigen::VectorXd y2(3);
  y2 << 1 / L1, 0, std::sqrt(1 - 1 / (L1 * L1));
  o.p_min = 1.05;
  o.direction = Direction::both;
  const Branch c = continue_branch(pr2, y2, L1, o);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  EXPECT_TRUE(c.special_points.empty());
  for (const auto& pt : c.points) {
    EXPECT_NEAR(polar(pt.x).r, 1 / pt.p, 1e-10);
    EXPECT_NEAR(pt.spectrum[0].real(), 0.0, 1e-12);
  }
}

TEST(ReducedEquilibrium, InPlaneRestShapeIsRejected) {
  Scene s = op_scene();
  s.beta = M_PI / 2;
  try {
    ReducedEquilibriumProblem pr(s, ContinuationParameter::lambda);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "beta");
  }
  EXPECT_THROW(continuation_parameter_from_string("kappa"), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
