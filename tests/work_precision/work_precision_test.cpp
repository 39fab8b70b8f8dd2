// Work-precision tables: the reference is consistent across levels, and errors follow the tolerance.
#include <gtest/gtest.h>

#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/work_precision.hpp"

namespace rbcstab {
namespace {

TEST(WorkPrecision, ErrorsShrinkWithTolerance) {
  Scene s;  // Fig. 3 out of plane, shortened
  s.T = 60;
  s.L = 5;
  WorkPrecisionOptions o;
  o.levels = {ModelLevel::modal};
  o.steppers = {Stepper::rk8pd, Stepper::rosenbrock};
  o.rtols = {1e-4, 1e-8};
  const WorkPrecisionTable t = work_precision(s, o);
  // The two exact levels at rtol 1e-13 differ only by integration error: ~1e-13 relative, with margin.
  EXPECT_LT(t.reference_spread, 1e-10);
  ASSERT_EQ(t.rows.size(), 4u);
  for (std::size_t i = 0; i < t.rows.size(); i += 2) {
    const auto& loose = t.rows[i];
    const auto& tight = t.rows[i + 1];
    EXPECT_EQ(loose.status, IntegrationStatus::success);
    EXPECT_EQ(tight.status, IntegrationStatus::success);
    // Four decades of tolerance buy at least two decades of global error (global error is not
    // proportional to the local tolerance, but it must improve markedly).
    EXPECT_LT(tight.error_Delta, 1e-2 * loose.error_Delta) << to_string(loose.stepper);
    EXPECT_GT(tight.rhs_evaluations, loose.rhs_evaluations);
    // Global error stays within a few hundred times the local tolerance over T = 60.
    EXPECT_LT(tight.error_Delta, 1e3 * tight.rtol);
    EXPECT_FALSE(tight.verdict_changed);
  }
}

TEST(WorkPrecision, RejectsBadOptions) {
  WorkPrecisionOptions o;
  o.rtols = {0.5};
  EXPECT_THROW(o.validate(), InvalidArgument);
  o = {};
  o.steppers.clear();
  EXPECT_THROW(o.validate(), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
