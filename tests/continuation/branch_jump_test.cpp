// The branch-jump guard (ContinuationOptions::confirm_special_points): two branches that nearly touch, in
// closed form, and the large-S out-of-plane branches of the reduced model continued in Lambda,
// each against its own closed form or a small-step reference branch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "continuation/branch_jump_cases.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"

namespace rbcstab {
namespace {

// x' = x^2 - p^2 - eps: the branches x = -sqrt(p^2 + eps) (stable, J = 2x < 0) and x = +sqrt(p^2 + eps)
// (unstable) come within 2 sqrt(eps) of each other at p = 0, where each turns by 90 degrees over an arclength
// ~ sqrt(eps). A step much longer than that goes straight on along x = p onto the other branch, whose tangent
// there is the same (the 60-degree turn test cannot see it).
class NearlyTouching final : public ContinuationProblem {
 public:
  explicit NearlyTouching(double eps) : eps_(eps) {}
  Eigen::Index dimension() const override { return 1; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override {
    F.resize(1);
    F[0] = x[0] * x[0] - p * p - eps_;
  }
  void jacobian(const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) const override {
    J.resize(1, 1);
    J(0, 0) = 2 * x[0];
  }

 private:
  double eps_;
};

Branch jump_lower_branch(double eps, bool guard, double min_step = 1e-10) {
  const NearlyTouching pr(eps);
  ContinuationOptions o;
  o.p_min = -1;
  o.p_max = 1;
  o.max_step = 1;
  o.min_step = min_step;
  o.initial_step = std::max(1e-2, min_step);
  o.confirm_special_points = guard;
  Eigen::VectorXd x0(1);
  x0[0] = -std::sqrt(1 + eps);
  return continue_branch(pr, x0, -1.0, o);
}

// How many points lie on the other branch (x > 0); every point is on one of the two to 1e-12 (Newton).
int jump_on_other_branch(const Branch& b) {
  int n = 0;
  for (const auto& pt : b.points) n += pt.x[0] > 0;
  return n;
}

TEST(BranchJump, NearlyTouchingBranchesJumpWithoutTheGuardOnly) {
  const double eps = 1e-6;  // gap 2e-3, turn over ~1e-3: steps grow to ~0.3 before p = 0
  const Branch unguarded = jump_lower_branch(eps, false);
  // The old rule: the run jumps onto x = +sqrt(p^2 + eps) and calls it completed.
  EXPECT_EQ(unguarded.status, ContinuationStatus::completed);
  EXPECT_GT(jump_on_other_branch(unguarded), 0);
  EXPECT_EQ(unguarded.counters.unconfirmed_steps, 0u);

  const Branch b = jump_lower_branch(eps, true);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_EQ(jump_on_other_branch(b), 0);
  for (const auto& pt : b.points) {
    EXPECT_NEAR(pt.x[0], -std::sqrt(pt.p * pt.p + eps), 1e-12) << "p = " << pt.p;
    EXPECT_TRUE(pt.stable) << "p = " << pt.p;
  }
  EXPECT_DOUBLE_EQ(b.points.back().p, 1.0);
  EXPECT_TRUE(b.special_points.empty());  // the branch has none; a jump left a guessed BP
  EXPECT_GT(b.counters.unconfirmed_steps, 0u);
  EXPECT_LE(b.counters.unconfirmed_steps, b.counters.rejected_steps);
  // Guessed special points of the unguarded run: the jump's unlocatable BP.
  bool guessed = false;
  for (const auto& sp : unguarded.special_points) guessed |= sp.status == LocationStatus::guess;
  EXPECT_TRUE(guessed);
}

TEST(BranchJump, FarApartBranchesCostNothing) {
  // eps = 1: the branches are 2 apart and the run never needs the guard.
  const Branch b = jump_lower_branch(1.0, true);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_EQ(b.counters.unconfirmed_steps, 0u);
  EXPECT_EQ(jump_on_other_branch(b), 0);
}

TEST(BranchJump, BranchThatCannotBeFollowedEndsBranchLost) {
  // The turn (~1e-4 long) is shorter than min_step = 1e-3: no allowed step stays on the branch.
  const Branch b = jump_lower_branch(1e-8, true, 1e-3);
  ASSERT_EQ(b.status, ContinuationStatus::branch_lost) << b.message;
  EXPECT_EQ(jump_on_other_branch(b), 0);
  const double p_end = b.points.back().p;
  EXPECT_LT(p_end, 0);
  EXPECT_GT(p_end, -0.01);
  EXPECT_NE(b.message.find("lost the branch after point " + std::to_string(b.points.size() - 1)), std::string::npos)
      << b.message;
  EXPECT_NE(b.message.find("p = "), std::string::npos) << b.message;
  EXPECT_EQ(to_string(b.status), "branch_lost");
  // The old rule reports the same run completed, on the wrong branch.
  const Branch unguarded = jump_lower_branch(1e-8, false, 1e-3);
  EXPECT_EQ(unguarded.status, ContinuationStatus::completed);
  EXPECT_GT(jump_on_other_branch(unguarded), 0);
}

// The reported cases: S = 1e3 and 1e4, starts at Lambda = 0.5 and 3, max step 0.5 and 2, Lambda over
// [0.01, 10], reduced level. Without the guard they jump onto the unstable mirror branch (Psi -> -Psi,
// w -> -w) near Lambda = 1 and end completed; with it every point is the stable branch's closed-form state
// (1e-8) with the reference's unstable count, or the run ends branch_lost.
TEST(BranchJump, LargeShearOutOfPlaneBranchInLambdaStaysOnItsBranch) {
  using namespace jump_cases;
  int jumped_unguarded = 0;
  for (double S : {1e3, 1e4})
    for (double L0 : {0.5, 3.0})
      for (double h : {0.5, 2.0}) {
        Case c{Level::reduced, S, L0, h, true};
        const Outcome g = run_case(c);
        EXPECT_TRUE(g.followed()) << describe(c) << ": " << g.first << "; " << to_string(g.branch.status) << " ("
                                  << g.branch.message << ")";
        EXPECT_EQ(g.branch.status, ContinuationStatus::completed) << describe(c) << ": " << g.branch.message;
        c.guard = false;
        const Outcome u = run_case(c);
        jumped_unguarded += !u.honest();
      }
  EXPECT_GT(jumped_unguarded, 0);  // the cases do test the guard
}

// Representative cells of the slow grid (branch_jump_grid_test.cpp) at the modal level (L = 4: the l = 3, 4
// modes' BPs on the way are genuine and must still be located).
TEST(BranchJump, ModalLevelLargeShearCells) {
  using namespace jump_cases;
  for (double L0 : {0.5, 3.0}) {
    const Case c{Level::modal, 1e5, L0, 1.0, true};
    const Outcome g = run_case(c);
    EXPECT_TRUE(g.honest()) << describe(c) << ": " << g.first << "; " << g.branch.message;
    EXPECT_TRUE(g.followed()) << describe(c) << ": " << g.first << "; " << g.branch.message;
  }
}

// The full level's reference (x_{2,0} = -w, x_{2,2} = z, the rest 0) is the full model's equilibrium on the whole
// branch, past any l >= 3 onset too (nothing drives those modes): the full residual vanishes at it to rounding,
// and it is the problem's own embedding of the out-of-plane closed form (another code path: analysis/
// steady_states) to 1e-12. The mirror state (Psi -> -Psi, w -> -w) is also an equilibrium: the comparison
// against the reference tells them apart (1e-8 is far below their distance ~2 sqrt(2/S)).
TEST(BranchJump, FullLevelReferenceIsTheEllipsoidalEquilibrium) {
  using namespace jump_cases;
  const Case c{Level::full, 1e3, 0.5, 1.0, true};
  const std::unique_ptr<ContinuationProblem> pr = problem_of(c);
  const auto& full = dynamic_cast<const FullEquilibriumProblem&>(*pr);
  EXPECT_EQ(pr->dimension(), 21);  // (L + 1)^2 - 4, L = 4
  for (double p : {0.3, 0.99, 1.01, 5.0}) {
    const Eigen::VectorXd x = reference_state(c, pr->dimension(), p);
    Eigen::VectorXd G;
    pr->residual(x, p, G);
    EXPECT_LT(G.lpNorm<Eigen::Infinity>(), 1e-13) << p;
    EXPECT_LT((x - full.ellipsoidal_state(p)).lpNorm<Eigen::Infinity>(), 1e-12) << p;
    Eigen::VectorXd mirror = x;
    mirror[0] = -mirror[0];  // w -> -w
    mirror[4] = -mirror[4];  // Im z = -r sin Psi -> r sin Psi
    pr->residual(mirror, p, G);
    EXPECT_LT(G.lpNorm<Eigen::Infinity>(), 1e-13) << p;
    EXPECT_GT((mirror - x).lpNorm<Eigen::Infinity>(), 1e-2) << p;
  }
}

}  // namespace
}  // namespace rbcstab
