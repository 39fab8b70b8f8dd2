// The sweep views read back against hand-made results.
#include <gtest/gtest.h>

#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/sweep_io.hpp"

namespace rbcstab {
namespace {

TEST(SweepIo, Fig6eRowsReadBack) {
  SceneFile sf = parse_scene("");
  sf.L_reason = "set by the test";
  Fig6eRow row;
  row.lambda = 1, row.B = 2, row.C = 0.01, row.l_Delta = 4;
  row.Delta2_tilde = Quantity::of(0.3);
  row.Delta2_bar = Quantity::outside("stable");
  const nlohmann::json j = fig6e_json(sf, {row});
  EXPECT_EQ(j["L_reason"], "set by the test");
  ASSERT_EQ(j["rows"].size(), 1u);
  EXPECT_EQ(j["rows"][0]["B"].get<double>(), 2);
  EXPECT_EQ(j["rows"][0]["l_Delta"], 4);
  EXPECT_EQ(j["rows"][0]["Delta2_tilde"].get<double>(), 0.3);
  EXPECT_TRUE(j["rows"][0]["Delta2_simulated"].is_null());
  EXPECT_EQ(j["rows"][0]["Delta2_simulated_reason"], "stable");
}

TEST(SweepIo, DiagramAndMergeBriefsCountTheVerdicts) {
  SceneFile sf = parse_scene("");
  DiagramRun r;
  r.points.resize(4);
  r.points[1].verdict = Verdict::unstable;
  r.points[2].verdict = Verdict::failed;
  r.points[3].verdict = Verdict::unstable;
  r.computed = 3, r.resumed = 1, r.complete = true, r.config_hash = "abc";
  const VerdictCounts c = count_verdicts(r.points);
  EXPECT_EQ(c.stable, 1u);
  EXPECT_EQ(c.unstable, 2u);
  EXPECT_EQ(c.failed, 1u);
  const nlohmann::json j = diagram_brief_json(sf, r, "out");
  EXPECT_EQ(j["csv"], "out.csv");
  EXPECT_EQ(j["points"], 4);
  EXPECT_EQ(j["stable"], 1);
  EXPECT_EQ(j["unstable"], 2);
  EXPECT_EQ(j["failed"], 1);
  EXPECT_EQ(j["resumed"], 1);
  EXPECT_EQ(j["config_hash"], "abc");
  EXPECT_TRUE(j.contains("L_reason"));
  MergeResult m;
  m.points.resize(3);
  m.missing = {5};
  const nlohmann::json mj = merge_brief_json(m, 2, "merged");
  EXPECT_EQ(mj["json"], "merged.json");
  EXPECT_EQ(mj["inputs"], 2);
  EXPECT_EQ(mj["points"], 3);
  EXPECT_EQ(mj["missing"], 1);
  EXPECT_EQ(mj["complete"], false);
}

TEST(SweepIo, TraceDocumentCsvAndBriefReadBack) {
  const SceneFile sf = parse_scene("");
  DiagramSpec plane;
  TraceResult t;
  TraceCurve c;
  c.l = 3;
  c.points.push_back({});
  c.points.back().x = 0.5, c.points.back().y = -1, c.points.back().mu = 1e-12;
  t.curves = {c};
  t.evaluations = 17;
  TraceOptions to;
  const nlohmann::json doc = trace_json(sf, plane, to, t);
  EXPECT_EQ(doc["format"], "rbcstab-trace");
  EXPECT_EQ(doc["curves"][0]["l"], 3);
  EXPECT_EQ(doc["curves"][0]["x"][0].get<double>(), 0.5);
  EXPECT_EQ(doc["options"]["T"].get<double>(), sf.scene.T);
  EXPECT_EQ(doc["evaluations"], 17);
  const std::string csv = trace_csv(plane, t);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2);
  const nlohmann::json brief = trace_brief_json(doc, "tr");
  EXPECT_EQ(brief["pieces"], 1);
  EXPECT_EQ(brief["evaluations"], 17);
  EXPECT_EQ(brief["analytic_lines"], doc["analytic_lines"].size());
  EXPECT_EQ(brief["L"], doc["L"]);
  EXPECT_FALSE(brief.contains("agreement"));
}

// A diagram's progress line, as the diagram, report and paper commands print it.
TEST(SweepIo, ProgressLineOfADiagram) {
  Progress p;
  p.done = 12;
  p.total = 64;
  p.resumed = 4;
  p.elapsed = 2.5;
  p.rate = 3.21;
  p.eta = 15;
  EXPECT_EQ(progress_text(p, true), "diagram 12/64 (4 resumed), 3.2 points/s, elapsed 2.5s, ETA 15.0s");
  EXPECT_EQ(progress_text(p, false), "diagram 12/64, 3.2 points/s, ETA 15.0s");
  p.rate = 0;
  p.resumed = 0;
  EXPECT_EQ(progress_text(p, true), "diagram 12/64, 0.0 points/s, elapsed 2.5s, ETA ?");
}

}  // namespace
}  // namespace rbcstab
