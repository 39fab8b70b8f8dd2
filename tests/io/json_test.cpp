// JSON views: documented keys present, non-finite numbers become null.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rbcstab/io/json.hpp"

namespace rbcstab {
namespace {

TEST(Json, NonFiniteBecomesNull) {
  EXPECT_TRUE(number_or_null(NAN).is_null());
  EXPECT_TRUE(number_or_null(INFINITY).is_null());
  EXPECT_EQ(number_or_null(1.5).get<double>(), 1.5);
  Parameters p;
  p.C = INFINITY;
  const auto j = to_json(p);
  EXPECT_TRUE(j["C"].is_null());
  EXPECT_TRUE(j["S"].is_null());
  EXPECT_EQ(j["C_reason"], "infinite: the vesicle limit");
  EXPECT_EQ(j["alpha"].get<double>(), 0.0);
}

TEST(Json, EveryNullGetsAReasonNamingTheInput) {
  nlohmann::json j = {{"a", INFINITY},
                      {"b", 1.0},
                      {"m", {{1.0, NAN}}},
                      {"o", {{"c", nullptr}, {"c_reason", "known"}}},
                      {"list", {{{"d", NAN}}}}};
  EXPECT_EQ(unexplained_nulls(j).size(), 3u);  // a, m and list/0/d: o/c has its reason
  explain_nulls(j, "why");
  EXPECT_TRUE(unexplained_nulls(j).empty());
  EXPECT_TRUE(j["a"].is_null());
  EXPECT_EQ(j["a_reason"], "why");
  EXPECT_EQ(j["m_reason"], "why");
  EXPECT_FALSE(j.contains("b_reason"));
  EXPECT_EQ(j["o"]["c_reason"], "known");
  EXPECT_EQ(j["list"][0]["d_reason"], "why");
  Parameters p;
  p.lambda = 1e308;
  EXPECT_NE(nonfinite_reason(p).find("lambda = 1e+308"), std::string::npos) << nonfinite_reason(p);
  EXPECT_TRUE(unexplained_nulls(to_json(p)).empty());
  p = Parameters{};
  p.C = INFINITY;
  EXPECT_NE(S_reason(p).find("C = inf"), std::string::npos) << S_reason(p);
  EXPECT_EQ(to_json(p)["S_reason"], S_reason(p));
}

// One reason per null (S_reason, no S_note copy); an input so small that its inverse overflows is named too.
TEST(Json, OneReasonPerNullAndTinyInputsAreNamed) {
  Parameters p;
  p.C = INFINITY;
  const auto j = to_json(p);
  EXPECT_TRUE(j.contains("S_reason"));
  EXPECT_FALSE(j.contains("S_note"));
  p = Parameters{};
  p.B = 1e-300;
  EXPECT_NE(nonfinite_reason(p).find("B = 1e-300"), std::string::npos) << nonfinite_reason(p);
  p.B = 1e-100;  // its square's inverse is 1e200: no overflow, not named
  EXPECT_EQ(nonfinite_reason(p).find("B ="), std::string::npos) << nonfinite_reason(p);
}

TEST(Json, CsvNumberIsExactOrEmptyNeverNan) {
  EXPECT_EQ(csv_number(NAN), "");
  EXPECT_EQ(csv_number(-INFINITY), "");
  EXPECT_EQ(std::stod(csv_number(0.1 + 0.2)), 0.1 + 0.2);  // round trip
  EXPECT_EQ(csv_number(1.5), "1.5");
}

TEST(Json, ByModeIsKeyedFromTwo) {
  const auto j = by_mode({1.0, 2.0, 3.0});
  EXPECT_EQ(j.size(), 3u);
  EXPECT_EQ(j["2"].get<double>(), 1.0);
  EXPECT_EQ(j["4"].get<double>(), 3.0);
}

TEST(Json, SimulationResultHasTheDocumentedKeys) {
  Scene s;
  s.T = 5;
  const SimulationResult r = simulate(s);
  const auto j = to_json(r);
  for (const char* key : {"model", "status", "excess_area_initial", "excess_area_final", "excess_area_tail_mean",
                          "l_Delta", "sigma_final", "excess_area_drift", "steps", "rhs_evaluations", "seconds"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["excess_area_final"].size(), std::size_t(s.L - 1));
  EXPECT_TRUE(j["excess_area_final"].contains("10"));
  EXPECT_EQ(j["model"], "modal");
  EXPECT_EQ(j["status"], "success");
}

}  // namespace
}  // namespace rbcstab
