// grow_tree (recursive branch switching) on closed-form systems with known trees:
// - two pitchforks in sequence, x' = x (p - x^2), y' = y (x^2 - a - y^2): the trivial branch has one BP at p = 0,
//   each branch x = +-sqrt(p) (y = 0) a BP at p = a where y's eigenvalue x^2 - a crosses 0, and the grandchildren
//   are x^2 = p, y^2 = p - a (four of them);
// - the same branch reachable twice: x' = x (x - (p^2 - 1)), y' = x - y has the trivial branch with BPs at p = -1
//   and p = 1 joined by the parabola x = p^2 - 1, so from p = 1 both halves are the parabola found from p = -1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "rbcstab/continuation/branch_tree.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

constexpr double kTreeA = 0.5;

class TwoPitchforks final : public ContinuationProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& v, double p, Eigen::VectorXd& F) const override {
    const double x = v[0], y = v[1];
    F.resize(2);
    F << x * (p - x * x), y * (x * x - kTreeA - y * y);
  }
  void jacobian(const Eigen::VectorXd& v, double p, Eigen::MatrixXd& J) const override {
    const double x = v[0], y = v[1];
    J.resize(2, 2);
    J << p - 3 * x * x, 0, 2 * x * y, x * x - kTreeA - 3 * y * y;
  }
  void parameter_derivative(const Eigen::VectorXd& v, double, Eigen::VectorXd& Fp) const override {
    Fp.resize(2);
    Fp << v[0], 0;
  }
};

class Parabola final : public ContinuationProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& v, double p, Eigen::VectorXd& F) const override {
    F.resize(2);
    F << v[0] * (v[0] - (p * p - 1)), v[0] - v[1];
  }
  void jacobian(const Eigen::VectorXd& v, double p, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << 2 * v[0] - (p * p - 1), 0, 1, -1;
  }
  void parameter_derivative(const Eigen::VectorXd& v, double p, Eigen::VectorXd& Fp) const override {
    Fp.resize(2);
    Fp << -2 * p * v[0], 0;
  }
};

// x' = x (1 - x^2 - p^2), y' = x - y: the trivial branch with pitchforks at p = -1 and 1 joined by the circle
// x^2 + p^2 = 1, a closed branch.
class Circle final : public ContinuationProblem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& v, double p, Eigen::VectorXd& F) const override {
    F.resize(2);
    F << v[0] * (1 - v[0] * v[0] - p * p), v[0] - v[1];
  }
  void jacobian(const Eigen::VectorXd& v, double p, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << 1 - 3 * v[0] * v[0] - p * p, 0, 1, -1;
  }
  void parameter_derivative(const Eigen::VectorXd& v, double p, Eigen::VectorXd& Fp) const override {
    Fp.resize(2);
    Fp << -2 * p * v[0], 0;
  }
};

TreeOptions tree_options(int depth, double lo, double hi) {
  TreeOptions o;
  o.depth = depth;
  o.switching.continuation.p_min = lo;
  o.switching.continuation.p_max = hi;
  o.switching.continuation.max_step = 0.2;
  return o;
}

Branch tree_trivial(const ContinuationProblem& pr, double lo, double hi) {
  ContinuationOptions o;
  o.p_min = lo;
  o.p_max = hi;
  o.max_step = 0.2;
  o.direction = Direction::both;
  return continue_branch(pr, Eigen::Vector2d::Zero(), 0.5 * (lo + hi) + 0.01, o);
}

int count_outcomes(const BranchTree& t, EmanationOutcome o) {
  int n = 0;
  for (const TreeEmanation& e : t.emanations) n += e.outcome == o ? 1 : 0;
  return n;
}

TEST(BranchTree, TwoPitchforksDepthOneFindsTheChildPair) {
  const TwoPitchforks pr;
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -1, 1), tree_options(1, -1, 1));
  ASSERT_EQ(t.branches.size(), 3u);
  std::set<int> sides;
  for (std::size_t k = 1; k < 3; ++k) {
    const TreeBranch& c = t.branches[k];
    EXPECT_EQ(c.parent, 0);
    EXPECT_EQ(c.depth, 1);
    sides.insert(c.side);
    EXPECT_DOUBLE_EQ(c.branch.points.back().p, 1.0);
    for (const BranchPoint& q : c.branch.points) {
      // x^2 = p, y = 0: Newton's tolerance 1e-12, with room for the conditioning near p = 0.
      EXPECT_NEAR(q.x[0] * q.x[0], q.p, 1e-10);
      EXPECT_NEAR(q.x[1], 0.0, 1e-10);
    }
    // Its own BP, at p = a (x^2 - a = 0), located to the engine's location tolerance; not followed at depth 1.
    const SpecialPoint* bp = find_special_point(c.branch, SpecialPointType::BP);
    ASSERT_NE(bp, nullptr);
    EXPECT_NEAR(bp->p, kTreeA, 1e-8);
    EXPECT_NEAR(std::abs(bp->x[0]), std::sqrt(kTreeA), 1e-8);
  }
  EXPECT_EQ(sides, (std::set<int>{1, -1}));
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::followed), 2);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::depth_limit), 2);
  // The two children are on opposite sides: x > 0 on one, x < 0 on the other.
  EXPECT_LT(t.branches[1].branch.points.back().x[0] * t.branches[2].branch.points.back().x[0], 0);
}

TEST(BranchTree, TwoPitchforksDepthTwoFindsTheFourGrandchildren) {
  const TwoPitchforks pr;
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -1, 1), tree_options(2, -1, 1));
  ASSERT_EQ(t.branches.size(), 7u);
  std::set<std::pair<int, int>> quadrants;
  for (const TreeBranch& g : t.branches) {
    if (g.depth != 2) continue;
    EXPECT_NEAR(g.branch.points.front().p, kTreeA, 1e-5);  // starts next to the secondary BP
    EXPECT_DOUBLE_EQ(g.branch.points.back().p, 1.0);
    for (const BranchPoint& q : g.branch.points) {
      EXPECT_NEAR(q.x[0] * q.x[0], q.p, 1e-10);
      EXPECT_NEAR(q.x[1] * q.x[1], q.p - kTreeA, 1e-10);
    }
    const auto& e = g.branch.points.back().x;
    quadrants.insert({e[0] > 0 ? 1 : -1, e[1] > 0 ? 1 : -1});
  }
  EXPECT_EQ(quadrants.size(), 4u);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::followed), 6);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::duplicate), 0);
}

TEST(BranchTree, MirrorSymmetriesMarkTheCopiesInsteadOfFollowingThem) {
  const TwoPitchforks pr;
  TreeOptions o = tree_options(2, -1, 1);
  o.symmetries = {[](const Eigen::VectorXd& v) { return Eigen::VectorXd(Eigen::Vector2d(-v[0], v[1])); },
                  [](const Eigen::VectorXd& v) { return Eigen::VectorXd(Eigen::Vector2d(v[0], -v[1])); }};
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -1, 1), o);
  // Root, one child, one grandchild: the other child is the x-mirror of the first, the other grandchild the
  // y-mirror of the first; the mirror child's BP is never reached (it is not followed).
  ASSERT_EQ(t.branches.size(), 3u);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::symmetric), 2);
  for (const TreeEmanation& e : t.emanations)
    if (e.outcome == EmanationOutcome::symmetric) {
      EXPECT_EQ(e.branch_to, e.branch + 1);
    }
}

TEST(BranchTree, TheSameBranchReachedFromTwoBPsIsFollowedOnce) {
  const Parabola pr;
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -2, 2), tree_options(2, -2, 2));
  // The trivial branch and the two halves of the parabola from p = -1; from p = 1 both halves lie on the one
  // that passed through it, and that half's own BP at p = 1 is the trivial branch's.
  ASSERT_EQ(t.branches.size(), 3u);
  int through = -1;
  for (std::size_t k = 1; k < 3; ++k) {
    for (const BranchPoint& q : t.branches[k].branch.points) EXPECT_NEAR(q.x[0], q.p * q.p - 1, 1e-10);
    if (t.branches[k].branch.points.back().p > 1.5) through = static_cast<int>(k);
  }
  ASSERT_GT(through, 0);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::duplicate), 2);
  for (const TreeEmanation& e : t.emanations) {
    if (e.outcome == EmanationOutcome::duplicate) {
      EXPECT_EQ(e.branch, 0);
      EXPECT_EQ(e.branch_to, through);
      EXPECT_NEAR(t.branches[0].branch.special_points[e.point].p, 1.0, 1e-8);
    }
    if (e.outcome == EmanationOutcome::already_switched) {
      EXPECT_EQ(e.branch, through);
      EXPECT_EQ(e.branch_to, 0);
    }
  }
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::already_switched), 1);
}

TEST(BranchTree, AClosedBranchEndsBackAtItsFirstPoint) {
  // From p = -1 the circle goes round through the BP at p = 1 and back: it ends there (not at max_points = 1000),
  // every point on x^2 + p^2 = 1; the other half and both halves at p = 1 lie on it, its BPs are the trivial
  // branch's.
  const Circle pr;
  TreeOptions o = tree_options(2, -2, 2);
  o.switching.continuation.max_step = 0.1;
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -2, 2), o);
  ASSERT_EQ(t.branches.size(), 2u);
  const Branch& c = t.branches[1].branch;
  EXPECT_EQ(c.message, "closed: back at its first point");
  EXPECT_LT(c.points.size(), 200u);
  double p_min = 0, p_max = 0;
  for (const BranchPoint& q : c.points) {
    EXPECT_NEAR(q.x[0] * q.x[0] + q.p * q.p, 1.0, 1e-10);
    p_min = std::min(p_min, q.p), p_max = std::max(p_max, q.p);
  }
  EXPECT_LT(p_min, -0.99);  // round the whole circle
  EXPECT_GT(p_max, 0.99);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::duplicate), 3);
  EXPECT_GE(count_outcomes(t, EmanationOutcome::already_switched), 2);
}

TEST(BranchTree, LiesOnSeparatesTheBranchFromOneNextToIt) {
  // The check the duplicates rest on can fail: a point of the parabola lies on the parabola's branch, not on the
  // trivial branch it crosses, and a point 1e-3 off the parabola (the switching amplitude) lies on neither.
  const Parabola pr;
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -2, 2), tree_options(1, -2, 2));
  ASSERT_GE(t.branches.size(), 3u);
  const double p = 1.001, x = p * p - 1;
  const Eigen::Vector3d on(x, x, p), off(x + 1e-3, x + 1e-3, p), trivial_point(0, 0, 0.3);
  int hits = 0;
  for (const TreeBranch& b : t.branches) hits += lies_on(pr, b.branch, on, 1e-7) ? 1 : 0;
  EXPECT_EQ(hits, 1);
  for (const TreeBranch& b : t.branches) EXPECT_FALSE(lies_on(pr, b.branch, off, 1e-7));
  EXPECT_TRUE(lies_on(pr, t.branches[0].branch, trivial_point, 1e-7));
  EXPECT_FALSE(lies_on(pr, t.branches[1].branch, trivial_point, 1e-7));
}

TEST(BranchTree, DepthZeroAndUnavailableSwitchersAreListedNotFollowed) {
  const TwoPitchforks pr;
  BranchTree t = grow_tree(pr, tree_trivial(pr, -1, 1), tree_options(0, -1, 1));
  ASSERT_EQ(t.branches.size(), 1u);
  ASSERT_EQ(t.emanations.size(), 1u);
  EXPECT_EQ(t.emanations[0].outcome, EmanationOutcome::depth_limit);
  TreeOptions o = tree_options(1, -1, 1);
  o.switchers.clear();  // as for HB and PD today
  t = grow_tree(pr, tree_trivial(pr, -1, 1), o);
  ASSERT_EQ(t.branches.size(), 1u);
  EXPECT_EQ(t.emanations[0].outcome, EmanationOutcome::not_available);
  EXPECT_EQ(t.emanations[0].message, "switching at BP is not available");
}

TEST(BranchTree, StopFlagMarksTheRestInterrupted) {
  const TwoPitchforks pr;
  std::atomic<bool> stop{true};
  TreeOptions o = tree_options(2, -1, 1);
  o.stop = &stop;
  const BranchTree t = grow_tree(pr, tree_trivial(pr, -1, 1), o);
  EXPECT_TRUE(t.interrupted);
  EXPECT_EQ(t.branches.size(), 1u);
  EXPECT_EQ(count_outcomes(t, EmanationOutcome::interrupted), 1);
}

TEST(BranchTree, OptionsAreValidatedNamingTheField) {
  TreeOptions o;
  o.depth = 21;
  EXPECT_THROW(o.validate(), InvalidArgument);
  o.depth = 1;
  o.duplicate_tol = 1e-3;  // not below amplitude / 10: a branch's first point would look like its parent's
  try {
    o.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "duplicate_tol");
  }
}

}  // namespace
}  // namespace rbcstab
