// The summary and threshold views read back against the run, the prediction and the threshold report.
#include <gtest/gtest.h>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

namespace rbcstab {
namespace {

SceneFile short_scene() {
  SceneFile sf = parse_scene("");
  sf.scene.L = 5;
  sf.scene.T = 20;
  sf.L_reason = "set by the test";
  return sf;
}

TEST(VerdictIo, SummaryJsonReadsBackTheRunAndThePrediction) {
  const SceneFile sf = short_scene();
  const SimulationResult r = simulate(sf.scene, sf.options);
  const ScenePrediction pr = predict(sf.scene, &r);
  const nlohmann::json j = summary_json(sf, r, pr);
  EXPECT_EQ(j["scene"], sf.scene.name);
  EXPECT_EQ(j["L"], 5);
  EXPECT_EQ(j["L_reason"], "set by the test");
  EXPECT_EQ(j["steps"], r.counters.steps);
  EXPECT_EQ(j["l_Delta"], r.l_Delta);
  EXPECT_FALSE(j.contains("trajectory"));
  EXPECT_EQ(j["regime"], to_string(pr.regime.regime));
  EXPECT_EQ(j["asymptotic"]["unstable_modes"].get<std::vector<int>>(), pr.asymptotic.unstable);
  EXPECT_EQ(j["finite_horizon"]["l_Delta"], pr.finite_horizon.l_Delta);
  EXPECT_EQ(j["finite_horizon"]["T"].get<double>(), pr.horizon.T);
  EXPECT_EQ(j["simulation"]["l_Delta"], pr.simulation.l_Delta);
  EXPECT_EQ(j["sigma_star"].get<double>(), sigma_star(sf.scene.parameters.alpha()));
  EXPECT_EQ(j["tail_window"].get<double>(), sf.options.tail_window);
  const std::string text = summary_text(sf, r, pr);
  EXPECT_NE(text.find("Truncation   set by the test\n"), std::string::npos);
  EXPECT_NE(text.find("l_Delta = " + std::to_string(r.l_Delta)), std::string::npos);
}

TEST(VerdictIo, ModePredictionJson) {
  ModePrediction m;
  m.unstable = {3};
  m.l_Delta = 3;
  m.rate = {-1, 0.5};
  m.status = DomainStatus::limit;
  m.reason = "edge";
  const nlohmann::json j = to_json(m);
  EXPECT_EQ(j["unstable_modes"].get<std::vector<int>>(), m.unstable);
  EXPECT_EQ(j["l_Delta"], 3);
  EXPECT_EQ(j["rate"]["3"].get<double>(), 0.5);
  EXPECT_EQ(j["status"], "limit");
  EXPECT_EQ(j["reason"], "edge");
}

TEST(VerdictIo, ThresholdsJsonReadsBackTheReport) {
  const SceneFile sf = short_scene();
  const ThresholdReport t = threshold_report(sf.scene, false);
  const nlohmann::json j = thresholds_json(sf, t);
  EXPECT_EQ(j["L"], 5);
  EXPECT_EQ(j["r0"].get<double>(), t.r0);
  EXPECT_EQ(j["equilibrium"]["r"].get<double>(), t.criterion.equilibrium.r);
  EXPECT_EQ(j["unstable_modes_exact_equilibrium"].get<std::vector<int>>(), t.criterion.unstable_exact);
  EXPECT_EQ(j["unstable_modes_asymptotic"].get<std::vector<int>>(), t.prediction.asymptotic.unstable);
  EXPECT_EQ(j["lambda_star_minus"].is_null(), !t.lambda_star_minus.valid());
  EXPECT_FALSE(j.contains("C_star_exact_out_of_plane"));
  EXPECT_NE(thresholds_text(sf, t).find("Truncation: set by the test\n"), std::string::npos);
}

}  // namespace
}  // namespace rbcstab
