// The Floquet views read back against a hand-made result.
#include <gtest/gtest.h>

#include "rbcstab/continuation/floquet_io.hpp"

namespace rbcstab {
namespace {

TEST(FloquetIo, JsonAndTextReadBackTheResult) {
  Scene s;
  s.L = 4;
  SceneFloquetOptions o;
  o.relax_periods = 7;
  SceneFloquetResult r;
  r.dimension = 42;
  r.period = 6.5;
  r.periodicity_defect = 1e-9;
  r.floquet.integrations = 11;
  r.floquet.counters.steps = 99;
  r.floquet.arpack.eigenvalues.resize(2);
  r.floquet.arpack.eigenvalues << std::complex<double>(0.6, 0.8), std::complex<double>(-0.5, 0);
  const nlohmann::json j = floquet_json(s, o, r);
  EXPECT_EQ(j["status"], to_string(r.status));
  EXPECT_FALSE(j.contains("message"));
  EXPECT_EQ(j["n"], 42);
  EXPECT_EQ(j["relax_periods"], 7);
  EXPECT_EQ(j["period"].get<double>(), 6.5);
  EXPECT_EQ(j["integrations"], 11);
  EXPECT_EQ(j["steps"], 99);
  ASSERT_EQ(j["multipliers"].size(), 2u);
  EXPECT_EQ(j["multipliers"][0]["im"].get<double>(), 0.8);
  EXPECT_NEAR(j["multipliers"][0]["abs"].get<double>(), 1.0, 1e-15);
  EXPECT_EQ(j["multipliers"][1]["re"].get<double>(), -0.5);
  const std::string text = floquet_text(s, o, r);
  EXPECT_EQ(text.substr(0, 30), "full model L = 4 (n = 42), rel");
  EXPECT_NE(text.find("  mu = 0.6 + 0.8i  |mu| = 1\n"), std::string::npos);
}

}  // namespace
}  // namespace rbcstab
