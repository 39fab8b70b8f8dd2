// The branch-jump grid (label slow): the out-of-plane equilibrium branch continued in Lambda over
// [0.01, 10] for S log-spaced from 1 to 1e6, starts on both sides of Lambda = 1, the reduced, modal and full
// levels (L = 4) and max steps from 0.05 to 2, each run compared point by point with the closed-form reference
// (branch_jump_cases.hpp): it follows its branch or ends branch_lost, never a different branch called
// completed. Prints the counts with and without the guard and the cost per point (docs/continuation.md).
// ctest --test-dir build/release -L slow -R BranchJumpGrid --output-on-failure
// (the full level alone: build/release/tests/continuation/branch_jump_grid_tests --gtest_filter='*Full*')
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "continuation/branch_jump_cases.hpp"

namespace rbcstab {
namespace {

using namespace jump_cases;

struct Tally {
  int runs = 0, followed = 0, lost = 0, dishonest = 0;
  std::size_t points = 0, steps = 0, rejected = 0, unconfirmed = 0;
  double seconds = 0;
};

void run_grid(Level level) {
  const double steps[] = {0.05, 0.1, 0.2, 0.5, 1.0, 2.0};
  Tally with, without;
  for (int e = 0; e <= 12; ++e) {  // S = 10^(e/2): 1, 3.16, ..., 1e6
    const double S = std::pow(10.0, 0.5 * e);
    for (double L0 : {0.5, 0.9, 1.1, 3.0})
      for (double h : steps)
        for (bool guard : {true, false}) {
          const Case c{level, S, L0, h, guard};
          const auto t0 = std::chrono::steady_clock::now();
          const Outcome o = run_case(c);
          Tally& t = guard ? with : without;
          t.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          ++t.runs;
          t.followed += o.followed();
          t.lost += o.branch.status == ContinuationStatus::branch_lost;
          t.dishonest += !o.honest();
          t.points += o.branch.points.size();
          t.steps += o.branch.counters.steps;
          t.rejected += o.branch.counters.rejected_steps;
          t.unconfirmed += o.branch.counters.unconfirmed_steps;
          if (guard) {
            EXPECT_TRUE(o.honest()) << describe(c) << ": " << o.first << "; " << to_string(o.branch.status) << " ("
                                    << o.branch.message << ")";
            // The honest status: a branch_lost run's points up to the loss are still the reference's.
            if (o.branch.status == ContinuationStatus::branch_lost) {
              EXPECT_TRUE(o.followed()) << describe(c) << ": " << o.first;
            }
          }
        }
  }
  for (const Tally* t : {&with, &without})
    std::printf(
        "%s %s: %d runs, %d follow the branch, %d branch_lost, %d on another branch called completed; %zu points, "
        "%zu steps, %zu rejected (%zu by the guard), %.3f s (%.1f us/point)\n",
        level_name(level), t == &with ? "guarded" : "unguarded", t->runs, t->followed, t->lost, t->dishonest, t->points,
        t->steps, t->rejected, t->unconfirmed, t->seconds, 1e6 * t->seconds / static_cast<double>(t->points));
}

TEST(BranchJumpGrid, EveryRunFollowsItsBranchOrSaysItLostIt) {
  run_grid(Level::reduced);
  run_grid(Level::modal);
}

// Two cells of the grid at the full level (L = 4, n = 21; 14 s, too slow for the default suite): with the guard each
// follows the closed form (every point to 1e-8 with the reference's unstable count) and ends completed; without it the
// same cells jump (so the comparison can fail).
TEST(BranchJumpGrid, FullLevelLargeShearCells) {
  using namespace jump_cases;
  int jumped_unguarded = 0;
  for (double L0 : {0.5, 3.0}) {
    Case c{Level::full, 1e5, L0, 1.0, true};
    const Outcome g = run_case(c);
    EXPECT_TRUE(g.followed()) << describe(c) << ": " << g.first << "; " << g.branch.message;
    EXPECT_EQ(g.branch.status, ContinuationStatus::completed) << describe(c) << ": " << g.branch.message;
    c.guard = false;
    jumped_unguarded += !run_case(c).honest();
  }
  EXPECT_GT(jumped_unguarded, 0);
}

TEST(BranchJumpGrid, FullLevelFollowsItsBranchOrSaysItLostIt) { run_grid(Level::full); }

}  // namespace
}  // namespace rbcstab
