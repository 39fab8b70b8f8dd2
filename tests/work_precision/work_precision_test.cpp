// Work-precision tables: the reference is consistent across levels, and errors follow the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/work_precision.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/io/work_precision_io.hpp"

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

// The one CSV, JSON and text of a table: a stopped row's missing error is an empty field, a null with its reason and
// "n/a", never "nan".
TEST(WorkPrecision, RenderersShowAStoppedRowsMissingNumbers) {
  SceneFile sf = parse_scene("");
  WorkPrecisionTable t;
  t.scene_name = sf.scene.name;
  t.reference_Delta = {0.9, 0.1};
  t.reference_sigma = -30;
  t.reference_rtol = 1e-13;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.rows.push_back(
      {ModelLevel::modal, Stepper::rk8pd, 1e-4, IntegrationStatus::success, 10, 0, 5, 0.5, 1e-5, 2e-6, 3, false, ""});
  t.rows.push_back({ModelLevel::full, Stepper::rkck, 1e-6, IntegrationStatus::time_limit, 20, 0, 9, 30, nan, nan, 2,
                    false, "time limit"});
  const std::string csv = work_precision_csv(t);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_NE(csv.find("full,rkck,1e-06,time_limit,20,0,9,30,,,2,0\n"), std::string::npos) << csv;
  const nlohmann::json j = work_precision_json(sf, t);
  EXPECT_TRUE(unexplained_nulls(j).empty());
  EXPECT_EQ(j["reference"]["rtol"], 1e-13);
  EXPECT_TRUE(j["rows"][1]["error_Delta"].is_null());
  EXPECT_NE(j["rows"][1]["error_Delta_reason"].get<std::string>().find("time limit"), std::string::npos);
  const std::string text = work_precision_text(t);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_NE(text.find("n/a"), std::string::npos);
  EXPECT_NE(text.find("time_limit"), std::string::npos);
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
