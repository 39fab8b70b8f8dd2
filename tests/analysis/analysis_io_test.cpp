// The analysis JSON and text views read back against the structs they render.
#include <gtest/gtest.h>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {
namespace {

TEST(AnalysisIo, QuantityIsNullWithItsReasonOutsideItsDomain) {
  nlohmann::json j;
  put(j, "a", Quantity::of(1.5));
  put(j, "b", Quantity::outside("why"));
  put(j, "c", Quantity::at_limit(2.0, "edge"));
  EXPECT_EQ(j["a"].get<double>(), 1.5);
  EXPECT_FALSE(j.contains("a_reason"));
  EXPECT_TRUE(j["b"].is_null());
  EXPECT_EQ(j["b_reason"], "why");
  EXPECT_EQ(j["c"].get<double>(), 2.0);
  EXPECT_EQ(j["c_reason"], "edge");
  EXPECT_EQ(to_text(Quantity::of(1.5)), "1.5");
  EXPECT_EQ(to_text(Quantity::outside("why")), "n/a (why)");
  EXPECT_EQ(mode_list({}), "none");
  EXPECT_EQ(mode_list({3, 4}), "3, 4");
}

TEST(AnalysisIo, PostJsonReadsBackThePredictionAndTheRun) {
  SceneFile sf = parse_scene("");
  sf.scene.L = 6;
  sf.L_reason = "set by the test";
  const PostInstability post = post_instability(sf.scene.parameters, sf.scene.L, 0.0);
  SimulationResult r;
  r.status = IntegrationStatus::success;
  r.l_Delta = 4;
  r.Delta_tail_mean = {0.25, 0.5};
  r.sigma_tail_mean = -7;
  const nlohmann::json j = post_json(sf, post, r);
  EXPECT_EQ(j["L"], 6);
  EXPECT_EQ(j["L_reason"], "set by the test");
  EXPECT_EQ(j["surviving_mode"], post.surviving_mode);
  EXPECT_EQ(j["Delta2_simulated"].get<double>(), 0.25);
  EXPECT_EQ(j["l_Delta_simulated"], 4);
  EXPECT_EQ(j["sigma_tail_mean_simulated"].get<double>(), -7);
  EXPECT_EQ(j["continuous"]["variant"], post.continuous.variant);
  EXPECT_EQ(j["continuous"]["l"].get<double>(), post.continuous.l);
  EXPECT_EQ(j["integer_mode"]["sigma_s"].get<double>(), post.integer_mode.sigma_s);
  EXPECT_EQ(j["integer_mode"]["roots"][1].get<double>(), post.integer_mode.roots[1]);
  EXPECT_EQ(j["T"].get<double>(), sf.scene.T);
  EXPECT_NE(post_text(sf, post, r).find("Truncation: set by the test\n"), std::string::npos);

  r.l_Delta = 2;
  EXPECT_TRUE(post_json(sf, post, r)["Delta2_simulated"].is_null());
  r.status = IntegrationStatus::step_size_underflow;
  EXPECT_FALSE(simulated_Delta2(r).valid());
}

}  // namespace
}  // namespace rbcstab
