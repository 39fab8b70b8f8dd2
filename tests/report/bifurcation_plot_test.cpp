// Bifurcation diagrams (report/bifurcation_plot.hpp): the axes, series and stability segments decided
// for branch JSONs written by `rbcstab continue` runs (an orbit branch, equilibria with their switched
// branch, a BP curve), the segments on a hand-made branch with every stability and the contract's
// label/type keys, the derived measures against closed forms, bad input, and draw_plot's files.
#include <gtest/gtest.h>

#include <algorithm>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/report.hpp"
#include "report/png_size.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::string expect_invalid(const std::function<void()>& f, const std::string& parameter) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), parameter) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "expected InvalidArgument(" << parameter << ")";
  return "";
}

std::size_t count(const std::vector<std::string>& v, const std::string& x) {
  return std::size_t(std::count(v.begin(), v.end(), x));
}

// A hand-made branch in lambda: r = lambda, stabilities s s u u ? ? s (the last two from "stable"
// alone), a BP with label 3 between points 1 and 2 and an EP with label 7 on the last point.
json hand_branch() {
  json pts = json::array();
  const char* st[] = {"stable", "stable", "unstable", "unstable", "uncertain", "uncertain", nullptr};
  for (int k = 0; k < 7; ++k) {
    json p{{"lambda", double(k)}, {"r", double(k)}, {"Psi", 0.1 * k}, {"stable", k < 2 || k == 6}, {"n_unstable", 0}};
    if (st[k]) p["stability"] = st[k];
    p["label"] = k == 4 ? json(5) : json(nullptr);
    p["type"] = k == 6 ? "EP" : "";
    if (k == 6) p["label"] = 7;
    pts.push_back(p);
  }
  json sp{{"type", "BP"}, {"name", "BP"}, {"lambda", 1.5},           {"r", 1.5},
          {"Psi", 0.15},  {"label", 3},   {"stability", "uncertain"}};
  return {{"kind", "equilibrium"},
          {"level", "reduced"},
          {"free_parameter", "lambda"},
          {"parameters", {{"lambda", 0.0}, {"Delta", 1.0}, {"Delta0", 0.01}, {"B", 2.0}, {"C", nullptr}}},
          {"beta", 0.0},
          {"branch", pts},
          {"special_points", json::array({sp})},
          {"status", "completed"}};
}

TEST(PlotSpec, StabilitySegmentsSplitWhereStabilityChanges) {
  PlotOptions o;
  o.y = "r";
  const PlotSpec spec = plot_spec({plot_input(hand_branch(), "hand.json")}, o);
  ASSERT_EQ(spec.series.size(), 1u);
  const PlotSeries& s = spec.series[0];
  EXPECT_EQ(s.kind, "equilibrium");
  EXPECT_EQ(s.stability,
            (std::vector<std::string>{"stable", "stable", "unstable", "unstable", "uncertain", "uncertain", "stable"}));
  ASSERT_EQ(s.segments.size(), 4u);
  const std::vector<std::pair<std::string, std::string>> kinds{
      {"stable", "solid"}, {"unstable", "dashed"}, {"uncertain", "dotted"}, {"stable", "solid"}};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(s.segments[k].stability, kinds[k].first) << k;
    EXPECT_EQ(s.segments[k].style, kinds[k].second) << k;
  }
  // The BP is where the first change happens; the others, without a special point, at the midpoints.
  EXPECT_EQ(s.segments[0].x, (std::vector<double>{0, 1, 1.5}));
  EXPECT_EQ(s.segments[1].x, (std::vector<double>{1.5, 2, 3, 3.5}));
  EXPECT_EQ(s.segments[2].x, (std::vector<double>{3.5, 4, 5, 5.5}));
  EXPECT_EQ(s.segments[3].x, (std::vector<double>{5.5, 6}));
  EXPECT_EQ(s.segments[1].y, s.segments[1].x);  // r = lambda
  // The special point and the typed end point are marked "TYPE LABEL"; the labelled regular point is not.
  ASSERT_EQ(spec.points.size(), 2u);
  EXPECT_EQ(spec.points[0].text, "BP 3");
  EXPECT_EQ(spec.points[0].marker, "special");
  EXPECT_EQ(spec.points[0].stability, "uncertain");
  EXPECT_EQ(spec.points[1].text, "EP 7");
  EXPECT_EQ(spec.points[1].marker, "end");
  o.all_labels = true;
  const PlotSpec all = plot_spec({plot_input(hand_branch(), "hand.json")}, o);
  ASSERT_EQ(all.points.size(), 3u);  // in branch order: BP, then the points 4 and 6
  EXPECT_EQ(all.points[1].text, "5");
  EXPECT_EQ(all.points[1].marker, "regular");
  EXPECT_EQ(all.points[1].x, 4.0);
  EXPECT_EQ(all.points[2].text, "EP 7");
  // The JSON of what was drawn: the same segments, styles for the legend, labels as integers.
  const json j = to_json(spec);
  EXPECT_EQ(j.at("format"), "rbcstab-plot");
  EXPECT_EQ(j.at("series")[0].at("segments")[2].at("style"), "dotted");
  EXPECT_EQ(j.at("styles").size(), 3u);
  EXPECT_EQ(j.at("points")[0].at("label"), 3);
  EXPECT_EQ(j.at("x").at("label"), "$\\lambda$");
  EXPECT_EQ(j.at("points")[0].at("criticality"), "");  // no normal form: nothing claimed
  // A special point's normal form marks it: sub/supercritical in the text and the spec; degenerate is not marked.
  for (const char* c : {"supercritical", "subcritical", "degenerate"}) {
    json b = hand_branch();
    b["special_points"][0]["normal_form"] = {{"kind", "pitchfork"}, {"criticality", c}};
    const PlotSpec marked = plot_spec({plot_input(b, "hand.json")}, o);
    const std::string want = std::string(c) == "degenerate" ? "" : c;
    EXPECT_EQ(marked.points[0].criticality, want) << c;
    EXPECT_EQ(marked.points[0].text, want.empty() ? "BP 3" : want == "supercritical" ? "BP 3 super" : "BP 3 sub") << c;
  }
  // The default y of reduced-system equilibria is Psi; the fixed parameters title the figure.
  const PlotSpec def = plot_spec({plot_input(hand_branch(), "hand.json")});
  EXPECT_EQ(def.y.name, "Psi");
  EXPECT_EQ(def.title, "$\\Delta = 1$, $\\Delta_0 = 0.01$, $\\mathcal{B} = 2$, $\\mathcal{C} = \\infty$, $\\beta = 0$");
}

// Coinciding special points share one text, each type and label once ("BP 1" is not part of "BP 12").
TEST(PlotSpec, CoincidingPointsShareOneText) {
  json j = hand_branch();
  json sps = json::array();
  for (auto [type, label] : {std::pair{"BP", 12}, std::pair{"LP", 2}, std::pair{"BP", 1}, std::pair{"LP", 2}})
    sps.push_back({{"type", type}, {"lambda", 1.5}, {"r", 1.5}, {"Psi", 0.15}, {"label", label}});
  j["special_points"] = sps;
  PlotOptions o;
  o.y = "r";
  const PlotSpec spec = plot_spec({plot_input(j, "c.json")}, o);
  ASSERT_EQ(spec.points.size(), 5u);  // four special points and the EP
  EXPECT_EQ(spec.points[0].text, "BP 12, LP 2, BP 1");
  for (std::size_t k = 1; k < 4; ++k) EXPECT_EQ(spec.points[k].text, "") << k;
  EXPECT_EQ(spec.points[4].text, "EP 7");
}

// A switched branch is a series when switching succeeded ("switched", or points without the key) and a
// note when it failed.
TEST(PlotSpec, SwitchedBranchIsDrawnOrNoted) {
  json j = hand_branch();
  j["switched_branch"] = {{"branch", json::array({hand_branch()["branch"][0]})}, {"special_points", json::array()}};
  const PlotSpec drawn = plot_spec({plot_input(j, "s.json")});
  ASSERT_EQ(drawn.series.size(), 2u);
  EXPECT_EQ(drawn.series[1].role, "switched");
  EXPECT_TRUE(drawn.notes.empty());
  j["switched_branch"] = {{"switched", false}, {"message", "no BP located"}, {"branch", json::array()}};
  const PlotSpec noted = plot_spec({plot_input(j, "s.json")});
  EXPECT_EQ(noted.series.size(), 1u);
  ASSERT_EQ(noted.notes.size(), 1u);
  EXPECT_EQ(noted.notes[0], "s.json: the switched branch is not drawn: no BP located");
}

TEST(PlotSpec, BadInputNamesTheAxisTheValueAndTheChoices) {
  const PlotInput in = plot_input(hand_branch(), "hand.json");
  PlotOptions o;
  o.y = "foo";
  std::string m = expect_invalid([&] { (void)plot_spec({in}, o); }, "y");
  EXPECT_NE(m.find("y = 'foo'"), std::string::npos) << m;
  EXPECT_NE(m.find("hand.json"), std::string::npos) << m;
  EXPECT_NE(m.find("available: lambda, Psi"), std::string::npos) << m;
  o = {};
  o.x = "kappa";
  m = expect_invalid([&] { (void)plot_spec({in}, o); }, "x");
  EXPECT_NE(m.find("x = 'kappa'"), std::string::npos) << m;
  expect_invalid([] { (void)plot_spec({}); }, "inputs");

  for (const json& bad :
       {json{{"a", 1}}, json::array(), json{{"branch", json::array()}},
        json{{"branch", {1, 2}}, {"free_parameter", "C"}}, json{{"branch", {{{"lambda", 1}}}}, {"free_parameter", "C"}},
        json{{"format", "rbcstab-plot"}, {"branch", json::array()}, {"free_parameter", "C"}}}) {
    m = expect_invalid([&] { (void)plot_input(bad, "x.json"); }, "file");
    EXPECT_NE(m.find("x.json is not a branch JSON"), std::string::npos) << m;
  }
  json wrong = hand_branch();
  wrong["branch"][2]["stability"] = "wobbly";
  m = expect_invalid([&] { (void)plot_spec({plot_input(wrong, "w.json")}); }, "file");
  EXPECT_NE(m.find("stability = 'wobbly'"), std::string::npos) << m;

  const fs::path dir = test::fresh_dir("plot_test", "bad");
  const std::string text = hand_branch().dump();
  write_file_atomic((dir / "cut.json").string(), text.substr(0, text.size() / 2));
  m = expect_invalid([&] { (void)read_plot_input((dir / "cut.json").string()); }, "file");
  EXPECT_NE(m.find("cut.json is not valid JSON"), std::string::npos) << m;
  expect_invalid([&] { (void)read_plot_input((dir / "missing.json").string()); }, "file");
  fs::remove_all(dir);
}

#ifdef RBCSTAB_CLI
// The fixtures: `rbcstab continue ... --json` runs, as a user makes them.
PlotInput continue_json(const fs::path& dir, const std::string& name, const std::string& args) {
  const fs::path out = dir / (name + ".json");
  const std::string cmd = std::string(RBCSTAB_CLI) + " continue " + args + " --json > '" + out.string() + "' 2> '" +
                          (dir / (name + ".err")).string() + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd << "\n" << read_file((dir / (name + ".err")).string());
  return read_plot_input(out.string());
}

const std::string kModal =
    "--kind modal --parameter C --min 0.015 --max 0.08 --direction backward --lambda 1 --B 1 "
    "--C 0.08 --Delta 1 --Delta0 0.01 --L 6";

// The user's case: an orbit branch in lambda is drawn against lambda (not Psi_max) and called orbits.
TEST(PlotSpec, OrbitBranchAgainstItsFreeParameter) {
  const fs::path dir = test::fresh_dir("plot_test", "orbit");
  const PlotInput in = continue_json(dir, "o",
                                     "--kind orbit --parameter lambda --min 3 --max 7 --lambda 5 "
                                     "--Delta 0.3 --Delta0 0.01 --B 2 --C 0.04 --L 2");
  const PlotSpec spec = plot_spec({in});
  EXPECT_EQ(spec.x.name, "lambda");
  EXPECT_EQ(spec.y.name, "r_max");
  ASSERT_EQ(spec.series.size(), 1u);
  const PlotSeries& s = spec.series[0];
  EXPECT_EQ(s.kind, "orbit");
  EXPECT_EQ(s.name, "periodic orbits (reduced system)");
  const json& pts = in.branch.at("branch");
  ASSERT_EQ(s.x.size(), pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    EXPECT_EQ(s.x[k], pts[k].at("lambda").get<double>());
    EXPECT_EQ(s.y[k], pts[k].at("r_max").get<double>());
  }
  // The swinging -> tumbling UZ point (the orbit through r = 0: docs/continuation.md) sits on the line.
  // Marked: the UZ point and the branch's two labelled ends (EP).
  ASSERT_EQ(spec.points.size(), 3u);
  const auto uz = std::find_if(spec.points.begin(), spec.points.end(), [](const auto& q) { return q.type == "UZ"; });
  ASSERT_NE(uz, spec.points.end());
  EXPECT_EQ(uz->x, in.branch.at("special_points")[0].at("lambda").get<double>());
  EXPECT_EQ(std::count_if(spec.points.begin(), spec.points.end(), [](const auto& q) { return q.type == "EP"; }), 2);
  // Derived measures: the forcing period 2 pi; max |mu| < 1 exactly where the engine says stable.
  for (const char* m : {"period", "max_abs_multiplier", "r_min", "r_max", "Psi", "B"})
    EXPECT_EQ(count(spec.measures, m), 1u) << m;
  PlotOptions o;
  o.y = "period";
  const PlotSpec period = plot_spec({in}, o);
  for (double T : period.series[0].y) EXPECT_EQ(T, 2 * std::numbers::pi);
  o.y = "max_abs_multiplier";
  const PlotSeries mu = plot_spec({in}, o).series[0];
  for (std::size_t k = 0; k < pts.size(); ++k) EXPECT_EQ(mu.y[k] < 1, pts[k].at("stable").get<bool>()) << k;
  o.y = "max_Re_eig";  // an equilibrium measure
  const std::string m = expect_invalid([&] { (void)plot_spec({in}, o); }, "y");
  EXPECT_NE(m.find("max_abs_multiplier"), std::string::npos) << m;
  fs::remove_all(dir);
}

// Modal equilibria in C with the branch switched at the first BP: two series, the primary stable until
// the BP at C = 0.036169 (the l = 3 onset, closed form: tests/continuation) and unstable after it.
TEST(PlotSpec, SwitchedBranchIsASecondSeriesAndSegmentsMeetAtTheBP) {
  const fs::path dir = test::fresh_dir("plot_test", "switch");
  const PlotInput in = continue_json(dir, "m", kModal + " --switch-at-bp");
  const PlotSpec spec = plot_spec({in});
  EXPECT_EQ(spec.x.name, "C");
  EXPECT_EQ(spec.y.name, "r");
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(spec.series[0].role, "primary");
  EXPECT_EQ(spec.series[1].role, "switched");
  EXPECT_EQ(spec.series[1].name, "equilibria (modal model), switched branch");
  EXPECT_EQ(spec.series[1].x.size(), in.branch.at("switched_branch").at("branch").size());
  const PlotSeries& p = spec.series[0];
  ASSERT_EQ(p.segments.size(), 2u);
  EXPECT_EQ(p.segments[0].stability, "stable");
  EXPECT_EQ(p.segments[1].stability, "unstable");
  const double c_bp = in.branch.at("special_points")[0].at("C").get<double>();
  EXPECT_NEAR(c_bp, 0.036169, 1e-6);
  EXPECT_EQ(p.segments[0].x.back(), c_bp);
  EXPECT_EQ(p.segments[1].x.front(), c_bp);
  std::size_t bps = 0;
  for (const PlotPoint& q : spec.points) bps += q.type == "BP";
  EXPECT_EQ(bps, in.branch.at("special_points").size() + in.branch.at("switched_branch").at("special_points").size());

  // max Re(eigenvalue) is not stored at special points: interpolated along the branch, it is 0 at the
  // onset BP (the critical eigenvalue crosses there) to the linear interpolation's error, a few 1e-3
  // against a change of 0.45 over the step.
  PlotOptions o;
  o.y = "max_Re_eig";
  const PlotSpec eig = plot_spec({in}, o);
  EXPECT_EQ(eig.points[0].x, c_bp);
  EXPECT_NEAR(eig.points[0].y, 0.0, 1e-2);
  // On the ellipsoidal branch all the excess area is in l = 2: (sum Delta_l^2)^(1/2) = Delta = 1.
  o.y = "norm_Delta";
  const PlotSpec norm = plot_spec({in}, o);
  for (double v : norm.series[0].y) EXPECT_NEAR(v, 1.0, 1e-12);
  fs::remove_all(dir);
}

// The BP curve in (C, B) is drawn in its plane; overlaid with its one-parameter branch (B fixed at 1),
// the branch crosses the curve at the curve's start.
TEST(PlotSpec, CurveIsDrawnInItsPlane) {
  const fs::path dir = test::fresh_dir("plot_test", "curve");
  const PlotInput curve = continue_json(dir, "c", kModal + " --curve BP --parameter2 B --min2 0.5 --max2 2");
  const PlotInput branch = continue_json(dir, "m", kModal);
  const PlotSpec spec = plot_spec({curve});
  EXPECT_EQ(spec.x.name, "C");
  EXPECT_EQ(spec.y.name, "B");
  EXPECT_EQ(spec.y.label, "$\\mathcal{B}$");
  ASSERT_EQ(spec.series.size(), 1u);
  EXPECT_EQ(spec.series[0].kind, "curve");
  EXPECT_EQ(spec.series[0].name, "BP curve (modal model)");
  ASSERT_EQ(spec.series[0].segments.size(), 1u);
  EXPECT_EQ(spec.series[0].segments[0].style, "solid");
  const json& pts = curve.branch.at("branch");
  for (std::size_t k = 0; k < pts.size(); ++k) {
    EXPECT_EQ(spec.series[0].x[k], pts[k].at("C").get<double>());
    EXPECT_EQ(spec.series[0].y[k], pts[k].at("B").get<double>());
  }
  ASSERT_GE(spec.points.size(), 1u);
  EXPECT_EQ(spec.points[0].type, "BP");
  EXPECT_EQ(spec.points[0].x, curve.branch.at("curve").at("start").at("C").get<double>());
  EXPECT_EQ(spec.points[0].y, 1.0);

  const PlotSpec both = plot_spec({curve, branch});
  ASSERT_EQ(both.series.size(), 2u);
  for (double b : both.series[1].y) EXPECT_EQ(b, 1.0);
  EXPECT_EQ(both.series[1].kind, "equilibrium");
  // The other order: the branch's default axes (C, r), which the curve's points also carry.
  EXPECT_EQ(plot_spec({branch, curve}).y.name, "r");
  fs::remove_all(dir);
}
#endif

TEST(DrawPlot, WritesThePngAndWhatWasDrawnOrNothing) {
  const fs::path dir = test::fresh_dir("plot_test", "draw");
  write_file_atomic((dir / "b.json").string(), hand_branch().dump());
  const PlotSpec spec = plot_spec({read_plot_input((dir / "b.json").string())});
  PlotDrawOptions o;
  o.output = (dir / "fig.png").string();
  o.width = 640;
  o.height = 480;
  const PlotFiles f = draw_plot(spec, o);
  EXPECT_EQ(f.json, (dir / "fig.json").string());
  EXPECT_EQ(test_support::png_size(f.png), (std::pair{640, 480}));
  EXPECT_EQ(json::parse(read_file(f.json)), to_json(spec));
  auto entries = [&] {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
  };
  EXPECT_EQ(entries(), 3u);  // b.json, fig.png, fig.json: no staging file left

  o.output = (dir / "b.png").string();  // its JSON would replace the input
  expect_invalid([&] { (void)draw_plot(spec, o); }, "output");
  // A file sharing the stem that is not a plot's JSON (a diagram's tree d.json beside d.b1.json) is kept; an
  // earlier plot's JSON is replaced.
  const std::string tree = "{\"format\": \"rbcstab-diagram\"}\n";
  write_file_atomic((dir / "d.json").string(), tree);
  o.output = (dir / "d.png").string();
  expect_invalid([&] { (void)draw_plot(spec, o); }, "output");
  EXPECT_EQ(read_file((dir / "d.json").string()), tree);
  fs::remove(dir / "d.json");
  o.output = (dir / "fig.png").string();
  EXPECT_EQ(draw_plot(spec, o).json, (dir / "fig.json").string());
  o.output = (dir / "fig.svg").string();
  expect_invalid([&] { (void)draw_plot(spec, o); }, "output");
  o.output = (dir / "none" / "fig.png").string();
  expect_invalid([&] { (void)draw_plot(spec, o); }, "output");
  o.output = (dir / "other.png").string();
  o.width = 100;
  expect_invalid([&] { (void)draw_plot(spec, o); }, "width");
  o.width = 640;
  o.python = "/nonexistent/python3";
  EXPECT_THROW((void)draw_plot(spec, o), ReportError);
  EXPECT_EQ(entries(), 3u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rbcstab
