// switch_branch on textbook normal forms with known bifurcating branches: the pitchfork
// x' = p x - x^3 (new branch x^2 = p), the transcritical x' = p x - x^2 (new branch x = p, both sides),
// each with a slaved second unknown y' = x^2 - y so that the kernel lives in a larger space; and a
// doubly degenerate point (3-D kernel) that must be refused.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

class NormalForm final : public ContinuationProblem {
 public:
  enum Kind { pitchfork, transcritical, double_pitchfork };
  explicit NormalForm(Kind k) : k_(k) {}
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override {
    F.resize(2);
    F[0] = k_ == transcritical ? p * x[0] - x[0] * x[0] : p * x[0] - x[0] * x[0] * x[0];
    F[1] = k_ == double_pitchfork ? p * x[1] - x[1] * x[1] * x[1] : x[0] * x[0] - x[1];
  }
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override {
    J.setZero(2, 2);
    J(0, 0) = k_ == transcritical ? p - 2 * x[0] : p - 3 * x[0] * x[0];
    if (k_ == double_pitchfork) {
      J(1, 1) = p - 3 * x[1] * x[1];
    } else {
      J(1, 0) = 2 * x[0];
      J(1, 1) = -1;
    }
  }
  void parameter_derivative(const Eigen::VectorXd& x, double, Eigen::VectorXd& Fp) const override {
    Fp.resize(2);
    Fp[0] = x[0];
    Fp[1] = k_ == double_pitchfork ? x[1] : 0.0;
  }

 private:
  Kind k_;
};

// The trivial branch x = 0 through p = 0 from p = -1 to 1, and its BP.
Branch trivial(const ContinuationProblem& pr) {
  ContinuationOptions o;
  o.p_min = -1;
  o.p_max = 1;
  o.max_step = 0.3;
  return continue_branch(pr, Eigen::Vector2d::Zero(), -1, o);
}

TEST(BranchSwitch, PitchforkNewBranchIsXSquaredEqualsP) {
  const NormalForm pr(NormalForm::pitchfork);
  const Branch b = trivial(pr);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  EXPECT_NEAR(bp->p, 0.0, 1e-8);
  for (int side : {1, -1}) {
    BranchSwitchOptions o;
    o.side = side;
    o.continuation.p_min = -1;
    o.continuation.p_max = 1;
    const BranchSwitchResult sw = switch_branch(pr, b, *bp, o);
    ASSERT_TRUE(sw.switched) << sw.message;
    EXPECT_DOUBLE_EQ(sw.branch.points.back().p, 1.0);  // supercritical: continued towards p > 0
    for (const BranchPoint& pt : sw.branch.points) {
      // Newton's tolerance 1e-12: the branch x^2 = p, y = x^2 to 1e-10, on the requested side.
      EXPECT_NEAR(pt.x[0] * pt.x[0], pt.p, 1e-10);
      EXPECT_NEAR(pt.x[1], pt.p, 1e-10);
      EXPECT_GT(pt.x[0] * side, 0);
      EXPECT_TRUE(pt.stable);  // x = +-sqrt(p): eigenvalues -2p, -1
    }
  }
}

TEST(BranchSwitch, TranscriticalNewBranchIsXEqualsPOnBothSides) {
  const NormalForm pr(NormalForm::transcritical);
  const Branch b = trivial(pr);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  double p_ends[2];
  int k = 0;
  for (int side : {1, -1}) {
    BranchSwitchOptions o;
    o.side = side;
    o.continuation.p_min = -1;
    o.continuation.p_max = 1;
    const BranchSwitchResult sw = switch_branch(pr, b, *bp, o);
    ASSERT_TRUE(sw.switched) << sw.message;
    for (const BranchPoint& pt : sw.branch.points) {
      EXPECT_NEAR(pt.x[0], pt.p, 1e-10);
      EXPECT_NEAR(pt.x[1], pt.p * pt.p, 1e-10);
    }
    p_ends[k++] = sw.branch.points.back().p;
  }
  // The two sides leave the BP in opposite directions of p and reach both bounds.
  EXPECT_DOUBLE_EQ(std::max(p_ends[0], p_ends[1]), 1.0);
  EXPECT_DOUBLE_EQ(std::min(p_ends[0], p_ends[1]), -1.0);
}

TEST(BranchSwitch, RefusesAThreeDimensionalKernel) {
  const NormalForm pr(NormalForm::double_pitchfork);  // x and y bifurcate together at p = 0
  const Branch b = trivial(pr);
  // Two real eigenvalues cross at once, so det[J F_p; t^T] keeps its sign (no BP is detected; the
  // engine reports the change of the unstable count). Hand switch_branch the point itself.
  SpecialPoint bp;
  bp.type = SpecialPointType::BP;
  bp.x = Eigen::Vector2d::Zero();
  bp.p = 0;
  for (std::size_t i = 0; i + 1 < b.points.size(); ++i)
    if (b.points[i].p < 0 && b.points[i + 1].p >= 0) bp.after_index = i;
  const BranchSwitchResult sw = switch_branch(pr, b, bp, {});
  EXPECT_FALSE(sw.switched);
  EXPECT_NE(sw.message.find("more than 2-D"), std::string::npos) << sw.message;
}

TEST(BranchSwitch, RejectsBadOptionsAndNonBPs) {
  const NormalForm pr(NormalForm::pitchfork);
  const Branch b = trivial(pr);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  BranchSwitchOptions o;
  o.amplitude = -1;
  EXPECT_THROW(switch_branch(pr, b, *bp, o), InvalidArgument);
  SpecialPoint lp = *bp;
  lp.type = SpecialPointType::LP;
  EXPECT_THROW(switch_branch(pr, b, lp, {}), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
