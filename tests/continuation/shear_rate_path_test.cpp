// shear_rate as a continuation parameter (model/parameter_table.hpp): on a physical scene it moves B and C
// together (B = b gamma, C = c gamma), so each branch point must be the equilibrium of the plain scene at the
// converted (B, C), obtained here independently of the path: the cell converted afresh at that shear rate
// (physical_parameters), the closed form for the reduced system and the C-parameterised modal residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/physical.hpp"

namespace rbcstab {
namespace {

// eta = 1 mPa s, R = 3 um, kappa = 2e-19 J and mu chosen so that C = 0.08 at 10/s (B = 1.35, alpha = 16.9).
PhysicalCell cell(double rate) {
  PhysicalCell c;
  c.shear_rate = rate;
  c.viscosity = 1e-3;
  c.radius = 3e-6;
  c.bending_modulus = 2e-19;
  c.shear_modulus = 3.75e-7;
  return c;
}

Scene physical_scene(double lambda, double Delta0, int L) {
  Scene s;
  s.beta = 0;  // out-of-plane rest shape: the autonomous problems
  s.parameters.lambda = lambda;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = Delta0;
  s.L = L;
  s.physical = cell(10);
  s.parameters = physical_parameters(*s.physical, s.parameters);
  return s;
}

// The scene at `rate` without the path: a plain scene (no cell) with the cell's numbers converted afresh.
Scene converted(const Scene& s, double rate) {
  Scene plain = s;
  plain.physical.reset();
  plain.parameters = physical_parameters(cell(rate), s.parameters);
  return plain;
}

// Reduced out-of-plane equilibrium: cos Psi = Lambda r, sqrt(1 - r^2) sin Psi = r/S, u = r^2 the root in (0, 1)
// of Lambda^2 u^2 - (1 + Lambda^2 + S^-2) u + 1 = 0 (docs/theory.md). 1e-10: Newton stops at |dX| <= 1e-12
// (1 + |X|) and the conversion differs from the path's B, C by a few ulps, so the budget is a few 1e-12.
TEST(ShearRatePath, ReducedBranchIsTheClosedFormAtTheConvertedScene) {
  const Scene s = physical_scene(5, 0.01, 10);
  const ReducedEquilibriumProblem pr(s, ContinuationParameter::shear_rate);
  EXPECT_EQ(pr.parameter_name(), "shear_rate");
  auto closed_form = [](const Parameters& p) {
    const double L = p.Lambda(), iS = 1 / p.S();
    const double b = 1 + L * L + iS * iS;
    const double u = 2 / (b + std::sqrt(b * b - 4 * L * L));
    return std::pair{std::sqrt(u), std::atan2(iS / std::sqrt(1 - u), L)};
  };
  const auto [r0, Psi0] = closed_form(s.parameters);
  Eigen::VectorXd y(3);
  y << r0 * std::cos(Psi0) + 1e-2, -r0 * std::sin(Psi0), std::sqrt(1 - r0 * r0) - 1e-2;
  ContinuationOptions o;
  o.p_min = 1;
  o.p_max = 200;  // C from 0.008 to 1.6
  o.direction = Direction::both;
  o.max_step = 5;
  const Branch b = continue_branch(pr, y, 10, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_DOUBLE_EQ(b.points.front().p, 1);
  EXPECT_DOUBLE_EQ(b.points.back().p, 200);
  ASSERT_GE(b.points.size(), 10u);
  for (const BranchPoint& pt : b.points) {
    const auto [r, Psi] = closed_form(converted(s, pt.p).parameters);
    const PolarState g = polar(pt.x);
    EXPECT_NEAR(g.r, r, 1e-10) << "shear_rate = " << pt.p;
    EXPECT_NEAR(g.Psi, Psi, 1e-10) << "shear_rate = " << pt.p;
  }
}

// Modal level: every point of the shear-rate branch solves the C-parameterised problem of the converted scene,
// and its spectrum, where B enters (the l >= 3 rates Upsilon_l), is that scene's. 1e-9 on the residual: the
// engine's points satisfy max|F| <= 1e-12 and the converted B, C differ from the path's by a few ulps. 1e-9
// relative on the eigenvalues: the same states and parameters to a few ulps through O(10) products.
TEST(ShearRatePath, ModalBranchSolvesTheConvertedScene) {
  const Scene s = physical_scene(1, 0.01, 6);
  const ModalEquilibriumProblem pr(s, ContinuationParameter::shear_rate);
  ContinuationOptions o;
  o.p_min = 2;
  o.p_max = 10;
  o.direction = Direction::backward;
  const Branch b = continue_branch(pr, pr.ellipsoidal_state(10), 10, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_GE(b.points.size(), 5u);
  // The largest distance from an eigenvalue of u to the nearest of v (conjugate pairs and ties need no order).
  auto distance = [](const Eigen::VectorXcd& u, const Eigen::VectorXcd& v) {
    double worst = 0;
    for (const auto& z : u) worst = std::max(worst, (v.array() - z).abs().minCoeff() / (1 + std::abs(z)));
    return worst;
  };
  for (const BranchPoint& pt : b.points) {
    const Scene plain = converted(s, pt.p);
    const ModalEquilibriumProblem by_C(plain, ContinuationParameter::C);
    Eigen::VectorXd G;
    by_C.residual(pt.x, plain.parameters.C, G);
    EXPECT_LE(G.lpNorm<Eigen::Infinity>(), 1e-9) << "shear_rate = " << pt.p;
    const Eigen::VectorXcd path = pr.spectrum(pt.x, pt.p), direct = by_C.spectrum(pt.x, plain.parameters.C);
    ASSERT_EQ(path.size(), direct.size());
    EXPECT_LE(std::max(distance(path, direct), distance(direct, path)), 1e-9) << "shear_rate = " << pt.p;
  }
  // With B left at the start's (C alone moved) the spectrum differs: the comparison sees B.
  const BranchPoint& end = b.points.back();
  Scene C_only = s;
  C_only.physical.reset();
  C_only.parameters.C = converted(s, end.p).parameters.C;
  const Eigen::VectorXcd wrong =
      ModalEquilibriumProblem(C_only, ContinuationParameter::C).spectrum(end.x, C_only.parameters.C);
  EXPECT_GT(distance(wrong, pr.spectrum(end.x, end.p)), 1e-3);
}

// Without a physical cell the problem refuses shear_rate before any work, naming it.
TEST(ShearRatePath, PlainSceneIsRefusedNamingShearRate) {
  Scene plain;
  plain.beta = 0;
  try {
    (void)ReducedEquilibriumProblem(plain, ContinuationParameter::shear_rate).start_parameter();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "shear_rate");
    EXPECT_NE(std::string(e.what()).find("physical scene"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)with_parameter(plain.parameters, ContinuationParameter::shear_rate, 10), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
