// The summary and threshold views read back against the run, the prediction and the threshold report.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/analysis/post_instability.hpp"
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

// The quantities whose number must carry its SI value on a physical scene, found in an output's text by name: a
// tension ("sigma...", "<sigma...>" = x) must be followed by "(y N/m)", an angle ("Psi... = x") by " rad (y deg)",
// a time ("T = x", "last x") by "(y s)". Returns the offending excerpts ("" when every one carries its unit).
std::string missing_units(const std::string& text) {
  std::string missing;
  auto check = [&](std::size_t at, const std::vector<std::string>& after) {
    const char* begin = text.c_str() + at;
    char* end = nullptr;
    std::strtod(begin, &end);
    if (end == begin) return;  // not a number here ("n/a", a reason)
    const std::string rest(end);
    for (const std::string& a : after)
      if (rest.rfind(a, 0) == 0) return;
    missing += "[" + text.substr(at > 30 ? at - 30 : 0, 70) + "] ";
  };
  const std::vector<std::string> si = {" ("}, angle = {" rad ("}, window = {" (", " time units ("};
  for (const auto& [name, after] : {std::pair{std::string("sigma"), si}, std::pair{std::string("Psi"), angle},
                                    std::pair{std::string("T = "), si}, std::pair{std::string("the last "), window}})
    for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
      std::size_t value = at + name.size();
      if (name == "sigma" || name == "Psi") {  // sigma_*, sigma_R(0), <sigma_R^->, sigma tail mean, Psi~ = x
        const std::size_t eq = text.find(" = ", at);
        if (eq == std::string::npos || eq > text.find_first_of(",:\n", at)) continue;
        if (text.substr(at, eq - at).find(") ") != std::string::npos) continue;  // "(.. sigma_l^c) l_s = 3"
        value = eq + 3;
      }
      check(value, after);
    }
  for (const std::string unit : {" N/m)", " deg)", " s)"})
    if (text.find(unit) == std::string::npos) missing += "[no" + unit + "] ";
  return missing;
}

// The healthy cell of docs/units.md in a 1000/s, 1.2 mPa s flow, a short horizon: every physical output of
// thresholds, summary and post writes its tensions also in N/m, its angles also in degrees, its times also in s.
// The same outputs of a plain (dimensionless) scene have no SI values: the scan reports them, so it can fail.
TEST(VerdictIo, PhysicalOutputsCarryTheirUnits) {
  SceneFile cell = parse_scene(
      "name = 'cell'\n[physical]\nshear_rate = '1000/s'\nviscosity = '1.2 mPa s'\ninner_viscosity = '6 mPa s'\n"
      "radius = '2.8 um'\nbending_modulus = '2e-19 J'\nshear_modulus = '6 uN/m'\n[parameters]\nDelta = 1\n"
      "Delta0 = 0.5\n[run]\nL = 4\nT = 10\n");
  cell.L_reason = "set by the test";
  SceneFile plain = short_scene();
  plain.scene.L = 4;
  plain.scene.T = 10;
  for (const SceneFile* sf : {&cell, &plain}) {
    const bool physical = sf == &cell;
    const ThresholdReport t = threshold_report(sf->scene, false);
    const SimulationResult r = simulate(sf->scene, sf->options);
    const ScenePrediction pr = predict(sf->scene, &r);
    const PostInstability post = post_instability(sf->scene.parameters, sf->scene.L, 0.0);
    for (const std::string& text : {thresholds_text(*sf, t), summary_text(*sf, r, pr), post_text(*sf, post, r)}) {
      const std::string m = missing_units(text);
      if (physical)
        EXPECT_EQ(m, "") << text;
      else
        EXPECT_NE(m, "") << text;
    }
  }
  // The C thresholds also as this cell's shear rates, as the JSON gives them (C = c gamma).
  const std::string text = thresholds_text(cell, threshold_report(cell.scene, false));
  EXPECT_NE(text.find("as shear rates of this cell: C_*^- at "), std::string::npos) << text;
}

}  // namespace
}  // namespace rbcstab
