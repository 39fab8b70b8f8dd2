// Two-parameter fold curve of the cusp normal form x' = p1 + p2 x - x^3 (+ a decoupled stable
// direction): F = 0 and F_x = 0 give (p1, p2) = (-2 x^3, 3 x^2), i.e. 27 p1^2 = 4 p2^3, with the
// cusp at the origin.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/continuation/fold_curve.hpp"

namespace rbcstab {
namespace {

class Cusp final : public TwoParameterProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& x, double p1, double p2, Eigen::VectorXd& F) const override {
    F.resize(2);
    F[0] = p1 + p2 * x[0] - x[0] * x[0] * x[0];
    F[1] = -x[1] + 0.5 * x[0] * x[0];
  }
};

TEST(FoldCurve, CuspFoldCurveMatchesClosedFormThroughTheCusp) {
  const Cusp cusp;
  // 1. One-parameter run in p1 at p2 = 1: two folds at x = -+1/sqrt(3), p1 = +-2/(3 sqrt 3).
  const SliceProblem slice(cusp, 1.0);
  ContinuationOptions o;
  o.p_min = -3;
  o.p_max = 3;
  o.max_step = 0.1;
  Eigen::VectorXd x0(2);
  x0 << -1.5, 1.125;
  const double p1_0 = -(1.0 * -1.5 - std::pow(-1.5, 3));  // on the branch: p1 = x^3 - p2 x
  const Branch b = continue_branch(slice, x0, p1_0, o);
  std::vector<SpecialPoint> lps;
  for (const auto& sp : b.special_points)
    if (sp.type == SpecialPointType::LP) lps.push_back(sp);
  ASSERT_EQ(lps.size(), 2u);
  const double x_fold = 1 / std::sqrt(3.0);
  EXPECT_NEAR(std::abs(lps[0].p), 2 * x_fold / 3, 1e-8);
  EXPECT_NEAR(std::abs(lps[0].x[0]), x_fold, 1e-8);

  // 2. The fold curve from the first LP, continued in p2 both ways: down through the cusp (a turning
  // point of the curve in p2, reported as its LP) and up to p2 = 2 on both sides.
  const FoldCurveProblem fc(cusp, lps[0], 1.0);
  ContinuationOptions o2;
  o2.p_max = 2;
  o2.p_min = -1;
  o2.max_step = 0.05;
  o2.direction = Direction::both;
  const Branch curve = continue_branch(fc, fc.start(), 1.0, o2);
  ASSERT_EQ(curve.status, ContinuationStatus::completed) << curve.message;
  ASSERT_EQ(curve.parameter_names.size(), 2u);
  EXPECT_EQ(curve.parameter_names[0], "p1");
  EXPECT_DOUBLE_EQ(curve.points.front().p, 2.0);
  EXPECT_DOUBLE_EQ(curve.points.back().p, 2.0);
  for (const auto& pt : curve.points) {
    const double p1 = pt.parameters[0], p2 = pt.parameters[1], x = pt.x[0];
    // 1e-10: Newton to 1e-12 on a residual whose fold equation comes from a finite-difference
    // Jacobian (error ~1e-10 relative) -- the curve itself lies where that g vanishes, so the
    // closed form holds to that level.
    EXPECT_NEAR(p1, -2 * x * x * x, 1e-9) << "p2 = " << p2;
    EXPECT_NEAR(p2, 3 * x * x, 1e-9) << "x = " << x;
  }
  // Both signs of x visited: the curve went through the cusp to the other fold.
  EXPECT_LT(curve.points.front().x[0] * curve.points.back().x[0], 0);
  std::size_t cusps = 0;
  for (const auto& sp : curve.special_points) {
    if (sp.type != SpecialPointType::LP) continue;
    ++cusps;
    EXPECT_LT(std::abs(sp.p), 1e-8);              // p2 = 0 at the cusp
    EXPECT_LT(std::abs(sp.parameters[0]), 1e-8);  // p1 = 0
  }
  EXPECT_EQ(cusps, 1u);
}

}  // namespace
}  // namespace rbcstab
