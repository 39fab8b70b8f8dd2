// Every run kind restarts from each of its own labels and continues to a label's value: the
// runs of restart_table.hpp (reduced, modal and full equilibria, the in-plane orbit; LP, BP, HB and UZ curves),
// each round-tripped through its branch file, each labelled point restarted with a bound set to the next label's
// value (every label restarted from, every label's value reached once; every pair is hard_branches_slow_test's).
// The branch (curve) must start, end `completed` and hold a point at that value bit for bit: the bound is landed
// on exactly, a fold within location_tol of it is the end (an LP label's value is the top of its branch), and a
// label stores the values it was computed at, so nothing is rebuilt by arithmetic.
#include "continuation/restart_table.hpp"

namespace rbcstab {
namespace {

class RestartTable : public ::testing::TestWithParam<std::size_t> {};

TEST_P(RestartTable, EveryLabelRestartsToTheNextLabelsValue) { restart_table::check_row(GetParam(), false); }

// The fast rows (< 1 s each); the orbit and UZ-curve rows (1-2 s: shooting) are in the slow all-pairs table only.
INSTANTIATE_TEST_SUITE_P(Runs, RestartTable, ::testing::ValuesIn(restart_table::fast_rows()));

// The check fails: a restart bounded 1e-12 short of the next label's value never holds that value.
TEST(RestartTable, ACheckThatCannotReachTheValueFails) {
  using namespace restart_table;
  const ContinuationRun run = round_trip(rows()[0].run());
  const std::vector<LabelledPoint> labels = labelled_points(run);
  const double v0 = values_of(run, labels[1])[0], v = values_of(run, labels[2])[0];
  RestartChanges ch;
  ch.direction = v > v0 ? Direction::forward : Direction::backward;
  (v > v0 ? ch.p_max : ch.p_min) = v - (v > v0 ? 1e-12 : -1e-12);
  const SceneBranch r = restart(run, labels[1].label, ch);
  EXPECT_EQ(r.branch.branch.status, ContinuationStatus::completed);
  EXPECT_FALSE(holds_value(r.branch.branch, 0, v));
}

}  // namespace
}  // namespace rbcstab
