// The scene adapters of two_parameter.hpp against closed forms and against a second method.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "modal_fixtures.hpp"
#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

// Lambda(lambda, Delta) = sqrt(Delta) (23 lambda + 32) / (8 sqrt(30 pi)) = 1, solved for Delta.
double Delta_at_Lambda_one(double lambda) {
  const double d = 8 * std::sqrt(30 * M_PI) / (23 * lambda + 32);
  return d * d;
}

// Vesicle limit (S = inf: Delta0 = 0, C = inf): the tank-treading branch r = 1, Psi = arccos Lambda folds
// at Lambda = 1 (reduced_equilibrium_test), so the LP curve in (lambda, Delta) is Lambda(lambda, Delta) = 1
// with r = 1, Psi = 0. The LP is found by a one-parameter run in lambda, then continued in Delta.
TEST(SceneTwoParameterProblem, VesicleFoldCurveIsLambdaEqualsOne) {
  Scene s;
  s.beta = 0;
  s.parameters.lambda = 5;
  s.parameters.Delta = 0.2;  // Lambda = 0.85 < 1: on the r = 1 branch
  s.parameters.Delta0 = 0;
  s.parameters.C = INFINITY;
  const ReducedEquilibriumProblem pr(s, ContinuationParameter::lambda);
  const double L0 = s.parameters.Lambda();
  Eigen::VectorXd y(3);
  y << L0, -std::sqrt(1 - L0 * L0), 0;  // z = e^{-i Psi}, cos Psi = Lambda
  ContinuationOptions o;
  o.p_min = 0;
  o.p_max = 20;
  const Branch b = continue_branch(pr, y, s.parameters.lambda, o);
  const SpecialPoint* lp = find_special_point(b, SpecialPointType::LP);
  ASSERT_NE(lp, nullptr);
  ASSERT_EQ(lp->status, LocationStatus::located);
  const SceneTwoParameterProblem<ReducedEquilibriumProblem> base(s, ContinuationParameter::lambda,
                                                                 ContinuationParameter::Delta);
  EXPECT_EQ(base.dimension(), 3);
  EXPECT_EQ(base.name1(), "lambda");
  EXPECT_EQ(base.name2(), "Delta");
  const FoldCurveProblem curve(base, *lp, 0.2);
  ContinuationOptions oc;
  oc.p_min = 0.1;
  oc.p_max = 2;
  oc.direction = Direction::both;
  const Branch c = continue_branch(curve, curve.start(), 0.2, oc);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  ASSERT_GE(c.points.size(), 10u);
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& pt : c.points) lo = std::min(lo, pt.p), hi = std::max(hi, pt.p);
  EXPECT_DOUBLE_EQ(lo, 0.1);  // both ends land on the bounds
  EXPECT_DOUBLE_EQ(hi, 2.0);
  for (const auto& pt : c.points) {
    const double lambda = pt.parameters[0], Delta = pt.parameters[1];
    // 1e-9 relative: Newton stops at |dX| <= 1e-12, the fold test function g is O(1)-scaled near the
    // fold, and Delta(lambda) has slope ~ 2 Delta / lambda; measured ~1e-15.
    EXPECT_NEAR(Delta, Delta_at_Lambda_one(lambda), 1e-9 * Delta) << "lambda = " << lambda;
    const PolarState g = polar(pt.x.head(3));
    EXPECT_NEAR(g.r, 1.0, 1e-10);
    EXPECT_NEAR(std::sin(g.Psi), 0.0, 1e-6);  // Psi = arccos(1): sqrt-sensitive to the fold's location
    // The spectrum is the dynamics' on the sphere's tangent plane (2 eigenvalues, one ~0 at the fold),
    // not the 3 x 3 Newton Jacobian's (whose normal eigenvalue 2|y|^2 > 0 would read "unstable").
    EXPECT_EQ(pt.spectrum.size(), 2);
    EXPECT_EQ(pt.n_unstable, 0);
  }
}

TEST(SceneTwoParameterProblem, CoupledPairsAreRejected) {
  const Scene s = modal_fixtures::scene();
  using P = ContinuationParameter;
  const std::vector<std::pair<P, P>> coupled{
      {P::Lambda, P::Delta}, {P::lambda, P::Lambda}, {P::S, P::C}, {P::Delta0, P::S}, {P::B, P::B}};
  for (const auto& [a, b] : coupled) {
    try {
      const SceneTwoParameterProblem<ReducedEquilibriumProblem> pr(s, a, b);
      ADD_FAILURE() << to_string(a) << ", " << to_string(b) << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "p2");
    }
  }
  EXPECT_NO_THROW((SceneTwoParameterProblem<ReducedEquilibriumProblem>(s, P::Lambda, P::S)));
  EXPECT_NO_THROW((SceneTwoParameterProblem<ReducedEquilibriumProblem>(s, P::C, P::B)));
}

// Modal symmetry-breaking BP curve in (C, B) two ways: the generic BP system (2n + 2 unknowns) over
// the modal adapter, and the closed form sigma = sigma_3^c(alpha = B / C) on the ellipsoidal branch.
TEST(SceneTwoParameterProblem, ModalBranchPointCurveGenericSystemMatchesSigmaCritical) {
  const Scene s = modal_fixtures::scene(0.08, 4);
  const ModalEquilibriumProblem pr(s, ContinuationParameter::C);
  ContinuationOptions o;
  o.p_min = 0.02;
  o.p_max = 0.08;
  o.direction = Direction::backward;
  const Branch b = continue_branch(pr, pr.ellipsoidal_state(0.08), 0.08, o);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  ASSERT_EQ(bp->status, LocationStatus::located);
  ASSERT_EQ(critical_mode(pr, bp->x, bp->p), 3);
  Scene at_bp = s;
  at_bp.parameters.C = bp->p;
  const SceneTwoParameterProblem<ModalEquilibriumProblem> base(at_bp, ContinuationParameter::C,
                                                               ContinuationParameter::B);
  const BranchPointCurveProblem curve(base, *bp, 1.0);
  ContinuationOptions oc;
  oc.p_min = 0.7;
  oc.p_max = 1.5;
  oc.direction = Direction::both;
  const Branch c = continue_branch(curve, curve.start(), 1.0, oc);
  ASSERT_EQ(c.status, ContinuationStatus::completed) << c.message;
  ASSERT_GE(c.points.size(), 5u);
  for (const auto& pt : c.points) {
    const double C = pt.parameters[0], B = pt.parameters[1];
    const ModalState st = base.at(B).observe(pt.x.head(base.dimension()), C);
    // 1e-8 relative: sigma ~ 20 is computed from a state converged to 1e-12 (the BP system is regular).
    EXPECT_NEAR(st.sigma, sigma_c(3, B / C), 1e-8 * std::abs(st.sigma)) << "B = " << B;
    EXPECT_NEAR(curve.mu(pt.x), 0.0, 1e-10);  // a structurally stable (Z2) BP: no imperfection
  }
}

// ReducedForcedSystem2 is ReducedForcedSystem at p2, and its d/dp1 matches central differences of rhs.
TEST(ReducedForcedSystem2, IsTheOneParameterSystemAtP2) {
  Scene s;
  s.beta = M_PI / 2;
  s.parameters.lambda = 5;
  s.parameters.Delta = 0.3;
  s.parameters.Delta0 = 0.01;
  s.parameters.B = 2;
  s.parameters.C = 0.04;
  s.L = 2;
  const ReducedForcedSystem2 sys2(s, ContinuationParameter::Delta, ContinuationParameter::C);
  Scene t = s;
  t.parameters.C = 0.05;
  const ReducedForcedSystem sys1(t, ContinuationParameter::Delta);
  const std::vector<double> x{0.3, -0.4, std::sqrt(1 - 0.25)};
  std::vector<double> f1(3), f2(3), fp(3), fa(3), fb(3);
  for (double time : {0.0, 1.3, 4.0}) {
    sys1.rhs(time, x, 0.35, f1);
    sys2.rhs(time, x, 0.35, 0.05, f2);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(f1[static_cast<std::size_t>(i)], f2[static_cast<std::size_t>(i)]);
    sys2.parameter_derivative(time, x, 0.35, 0.05, fp);
    const double h = 1e-5;
    sys2.rhs(time, x, 0.35 + h, 0.05, fa);
    sys2.rhs(time, x, 0.35 - h, 0.05, fb);
    // Central difference error ~ h^2 f''' ~ 1e-10 plus rounding eps / h ~ 1e-11.
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(fp[i], (fa[i] - fb[i]) / (2 * h), 1e-8);
  }
  EXPECT_TRUE(sys2.conserves_norm());
  EXPECT_EQ(sys2.name1(), "Delta");
  EXPECT_EQ(sys2.name2(), "C");
}

}  // namespace
}  // namespace rbcstab
