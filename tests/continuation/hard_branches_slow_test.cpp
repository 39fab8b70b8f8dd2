// The swinging <-> tumbling boundary to S = 200 (label slow: hundreds of shooting steps). Reference: the UZ of
// one-parameter branches at fixed S, each from its own relaxation and shooting start. And restart_table.hpp's runs,
// every label restarted to every other label's value (the default suite's restart_table_test.cpp goes to the next
// label's only).
#include <gtest/gtest.h>

#include <cstdio>

#include "continuation/fig2_fixture.hpp"
#include "continuation/restart_table.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/scene_curve.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;

// The curve from the branch of Fig. 2's cell at Delta = 1 in q1 (Lambda over [1, 2]: UZ at Lambda* = 1.17408;
// lambda over [2, 5]: UZ at lambda* = 2.57327; S = 1.96) in S to S_end, and the UZ of a branch in q1 at S = S_end from
// its own relaxation and start: both converged to 1e-12 and located to 1e-11, 1e-9. Lambda is moved through Delta
// (Lambda ~ sqrt(Delta) at fixed lambda), which leaves its domain (0, 4 pi) before S = 200 (Lambda* ~ 10 there:
// outside_domain, measured); lambda is not bounded, so the curve to S = 200 is continued in (lambda, S).
void expect_curve_end_is_the_branch_uz(P q1, double lo, double hi, double S_end, double half_width) {
  BranchSpec spec = test::spec_of(test::fig2_in_plane(1.0), ProblemKind::orbit, q1, lo, hi, Direction::backward);
  spec.orbit.segments = 4;
  const SceneCurve c = continue_curve(spec, test::curve_of(CurveKind::UZ, P::S, 1.9, S_end));
  ASSERT_TRUE(c.started) << c.message;
  const Branch& b = c.curve.branch;
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_EQ(b.points.back().p, S_end);
  const double q1_c = b.points.back().parameters[0];
  BranchSpec at = spec;
  at.scene = with_parameter(with_parameter(spec.scene, P::S, S_end), q1, q1_c + 0.8 * half_width);
  at.engine.p_min = q1_c - half_width;
  at.engine.p_max = q1_c + half_width;
  at.engine.max_step = 0.2 * half_width;
  const SceneBranch one = continue_scene(at);
  ASSERT_EQ(one.branch.branch.status, ContinuationStatus::completed) << one.branch.branch.message;
  const SpecialPoint* uz = find_special_point(one.branch.branch, SpecialPointType::UZ);
  ASSERT_NE(uz, nullptr);
  std::printf("S = %g: curve %s* = %.13f (%zu points), one-parameter UZ %.13f\n", S_end, to_string(q1).c_str(), q1_c,
              b.points.size(), uz->p);
  EXPECT_EQ(uz->status, LocationStatus::located);
  EXPECT_NEAR(uz->p, q1_c, 1e-9);
}

class RestartTableAll : public ::testing::TestWithParam<std::size_t> {};

TEST_P(RestartTableAll, EveryLabelRestartsToEveryLabelsValue) { restart_table::check_row(GetParam(), true); }

INSTANTIATE_TEST_SUITE_P(Runs, RestartTableAll, ::testing::Range<std::size_t>(0, restart_table::rows().size()));

TEST(HardBranchesSlow, SwingTumbleCurveToS20) { expect_curve_end_is_the_branch_uz(P::Lambda, 1, 2, 20, 0.05); }
TEST(HardBranchesSlow, SwingTumbleCurveToS200) { expect_curve_end_is_the_branch_uz(P::lambda, 2, 5, 200, 0.5); }

}  // namespace
}  // namespace rbcstab
