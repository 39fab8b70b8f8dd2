// The Fig. 6e grid (sweep/fig6e.hpp): Delta~2 of the integer surviving mode against the simulated Delta-bar_2,
// and the reasons where no post-instability state exists.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rbcstab/sweep/fig6e.hpp"

namespace rbcstab {
namespace {

TEST(Fig6e, TableSmall) {
  Fig6eOptions o;
  o.lambdas = {5};
  o.B = {2};
  o.C = {0.04, 0.5};
  const std::vector<Fig6eRow> rows = fig6e_table(o);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(rows[0].Delta2_bar.valid());
  ASSERT_TRUE(rows[0].ratio_integer.valid());
  EXPECT_NEAR(rows[0].ratio_integer.value, 1, 1e-6);  // measured 1e-9 (tail mean over 10 at T = 500)
  EXPECT_NEAR(rows[0].ln_alpha, std::log(50.0), 1e-14);
  // alpha = 4 < 9: stable, no post-instability state; every field explains itself.
  EXPECT_FALSE(rows[1].Delta2_bar.valid());
  EXPECT_FALSE(rows[1].ratio.reason.empty());
}

}  // namespace
}  // namespace rbcstab
