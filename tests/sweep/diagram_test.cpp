// Phase-diagram sweeps: axes, point scenes, determinism over threads/schedules/shards, journal
// resume, merge, and the [diagram] scene table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <sstream>
#include <thread>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/point_record.hpp"

namespace rbcstab {
namespace {

namespace fs = std::filesystem;

// A small, quick diagram: 4 x 3 points over ln B, ln C around the Fig. 3 case, short horizon.
Scene small_scene() {
  Scene s;
  s.L = 5;
  s.T = 40;
  s.dt = 40;
  return s;
}
DiagramSpec small_spec() {
  DiagramSpec d;
  d.x = {Axis::lnB, -1, 5, 4};
  d.y = {Axis::lnC, -5, 1, 3};
  d.classifier = Classifier::final;
  return d;
}
std::string temp_path(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rbcstab_sweep_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}
std::string csv_of(const DiagramRun& r, const DiagramSpec& spec) { return diagram_csv(spec, r.points, {false}); }

TEST(DiagramSpec, DefaultsAreValidAndAxisEndsExact) {
  DiagramSpec d;
  EXPECT_NO_THROW(d.validate());
  EXPECT_EQ(d.x.value(0), -1.0);
  EXPECT_EQ(d.x.value(63), 6.0);
  EXPECT_EQ(d.y.value(63), 2.0);
  EXPECT_NO_THROW(DiagramOptions{}.validate());
  AxisRange one{Axis::beta, 0.3, 9, 1};
  EXPECT_EQ(one.value(0), 0.3);
}

TEST(DiagramSpec, RejectsSameAxisTwiceAndUnknownNames) {
  DiagramSpec d;
  d.y.axis = Axis::lnB;
  EXPECT_THROW(d.validate(), InvalidArgument);
  EXPECT_THROW(axis_from_string("lnD"), InvalidArgument);
  EXPECT_THROW(classifier_from_string("mean"), InvalidArgument);
  EXPECT_THROW(shard_from_string("2/2"), InvalidArgument);
  EXPECT_THROW(shard_from_string("1-2"), InvalidArgument);
  const Shard s = shard_from_string("1/3");
  EXPECT_EQ(s.k, 1);
  EXPECT_EQ(s.n, 3);
  EXPECT_TRUE(s.contains(4));
  EXPECT_FALSE(s.contains(5));
}

TEST(PointScene, AppliesAxesAndAlphaKeepsTheOtherAxis) {
  DiagramSpec d = small_spec();
  const Scene base = small_scene();
  const Scene s = point_scene(base, d, 7);  // i = 3, j = 1
  EXPECT_DOUBLE_EQ(s.parameters.B, std::exp(5.0));
  EXPECT_DOUBLE_EQ(s.parameters.C, std::exp(-2.0));
  EXPECT_EQ(s.parameters.lambda, base.parameters.lambda);
  // alpha with ln B: C = B / alpha, so B/C is alpha.
  d.y = {Axis::alpha, 10, 100, 2};
  const Scene a = point_scene(base, d, 5);  // i = 1, j = 1
  EXPECT_DOUBLE_EQ(a.parameters.B, std::exp(1.0));
  EXPECT_NEAR(a.parameters.alpha(), 100, 1e-12);
  // alpha with lambda: C kept, B = alpha C (Fig. 5).
  d.x = {Axis::lambda, 1, 5, 2};
  const Scene b = point_scene(base, d, 3);
  EXPECT_EQ(b.parameters.lambda, 5);
  EXPECT_EQ(b.parameters.C, base.parameters.C);
  EXPECT_NEAR(b.parameters.alpha(), 100, 1e-12);
  EXPECT_THROW(point_scene(base, d, 4), InvalidArgument);
  // Fig. 5: ln C - lambda plane at fixed alpha.
  DiagramSpec f;
  f.x = {Axis::lnC, -5, 1, 3};
  f.y = {Axis::lambda, 1, 5, 2};
  f.alpha = 40;
  const Scene c = point_scene(base, f, 4);
  EXPECT_DOUBLE_EQ(c.parameters.C, std::exp(-2.0));
  EXPECT_NEAR(c.parameters.alpha(), 40, 1e-12);
  f.y.axis = Axis::alpha;
  EXPECT_THROW(f.validate(), InvalidArgument);
}

// Physics check against the paper's criteria (Sec. IV): l_* >= 2.5 needs alpha >= (35/8)^2 ~ 19.1,
// so a point with alpha = 1 cannot destabilise (stable); the Fig. 3 case (B = 2, C = 0.04,
// lambda = 5, OP) sends its excess area to l = 3 (Fig. 3b). These do not depend on the sweep code.
TEST(RunPoint, StableBelowAlphaStarAndFig3CaseUnstableToL3) {
  Scene base;  // Fig. 3 OP defaults, L = 10, T = 500
  base.T = 200;
  base.dt = 200;
  DiagramSpec d;
  d.x = {Axis::lnB, std::log(2.0), std::log(2.0), 1};
  d.y = {Axis::alpha, 1, 50, 2};
  d.classifier = Classifier::final;
  const PointResult stable = run_point(base, {}, d, 0);
  EXPECT_EQ(stable.status, IntegrationStatus::success);
  EXPECT_EQ(stable.verdict, Verdict::stable);
  EXPECT_EQ(stable.l_Delta, 2);
  const PointResult fig3 = run_point(base, {}, d, 1);
  EXPECT_NEAR(point_scene(base, d, 1).parameters.C, 0.04, 1e-15);
  EXPECT_EQ(fig3.verdict, Verdict::unstable);
  EXPECT_EQ(fig3.l_Delta, 3);
  EXPECT_GT(fig3.growth, 0.1);  // an O(1) transfer, not a perturbation-sized one
  EXPECT_GT(fig3.rhs_evaluations, 0u);
}

TEST(RunDiagram, BitIdenticalForAnyThreadCountAndSchedule) {
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  DiagramOptions o;
  o.threads = 1;
  const DiagramRun serial = run_diagram(base, {}, spec, o);
  ASSERT_TRUE(serial.complete);
  ASSERT_EQ(serial.points.size(), spec.size());
  for (std::size_t k = 0; k < serial.points.size(); ++k) EXPECT_EQ(serial.points[k].index, k);
  const std::string reference = csv_of(serial, spec);
  for (int threads : {2, 3, 5})
    for (bool dynamic : {true, false}) {
      o.threads = threads;
      o.dynamic_schedule = dynamic;
      EXPECT_EQ(csv_of(run_diagram(base, {}, spec, o), spec), reference) << threads << " threads, dynamic " << dynamic;
    }
}

TEST(RunDiagram, JournalResumesWithoutRecomputingAndShardsMerge) {
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  const std::string journal = temp_path("resume.journal");
  fs::remove(journal);
  DiagramOptions o;
  o.threads = 2;
  o.journal = journal;
  o.shard = {0, 2};
  const DiagramRun half = run_diagram(base, {}, spec, o);
  EXPECT_EQ(half.computed, 6u);
  EXPECT_TRUE(half.complete);
  // A torn last line (a kill inside write) is dropped, not misread.
  { std::ofstream(journal, std::ios::app) << "P " << half.config_hash << " 1 unstable 3 0.5"; }
  o.shard = {};
  const DiagramRun full = run_diagram(base, {}, spec, o);
  EXPECT_EQ(full.resumed, 6u);
  EXPECT_EQ(full.computed, 6u);
  const DiagramRun again = run_diagram(base, {}, spec, o);
  EXPECT_EQ(again.resumed, 12u);
  EXPECT_EQ(again.computed, 0u);
  DiagramOptions fresh;
  const std::string reference = csv_of(run_diagram(base, {}, spec, fresh), spec);
  EXPECT_EQ(csv_of(full, spec), reference);
  EXPECT_EQ(csv_of(again, spec), reference);
  // Journal lines: the header plus exactly one line per point (nothing computed twice).
  std::ifstream in(journal);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 1 + spec.size());

  // Another configuration must not reuse this journal.
  Scene other = base;
  other.T = 41;
  EXPECT_THROW(run_diagram(other, {}, spec, o), InvalidArgument);

  // Shards merge to the serial result, byte for byte.
  const nlohmann::json header = diagram_header(base, {}, spec);
  std::vector<nlohmann::json> docs;
  for (int k = 0; k < 3; ++k) {
    DiagramOptions so;
    so.shard = {k, 3};
    const DiagramRun r = run_diagram(base, {}, spec, so);
    docs.push_back(nlohmann::json::parse(diagram_json(header, spec, r.points, so.shard, {false}).dump()));
  }
  const MergeResult m = merge_diagrams(docs);
  EXPECT_TRUE(m.missing.empty());
  EXPECT_EQ(diagram_csv(m.spec, m.points, {false}), reference);
  EXPECT_EQ(diagram_json(m.header, m.spec, m.points, {}, {false}).dump(),
            diagram_json(header, spec, full.points, {}, {false}).dump());
  docs.pop_back();
  EXPECT_EQ(merge_diagrams(docs).missing.size(), 4u);
}

TEST(DiagramFile, ParsesTableAndSceneParserIgnoresIt) {
  const std::string text = R"(
name = "panel"
[parameters]
lambda = 1.0
[diagram]
axes = ["lnC", "lambda"]
x_range = [-5.0, 2.0]
y_range = [0.5, 6]
counts = [8, 5]
classifier = "tail"
)";
  const DiagramSpec d = diagram_spec(parse_scene(text));
  EXPECT_EQ(d.x.axis, Axis::lnC);
  EXPECT_EQ(d.y.axis, Axis::lambda);
  EXPECT_EQ(d.x.min, -5.0);
  EXPECT_EQ(d.y.max, 6.0);
  EXPECT_EQ(d.x.count, 8);
  EXPECT_EQ(d.y.count, 5);
  EXPECT_EQ(d.classifier, Classifier::tail_mean);
  EXPECT_EQ(parse_scene(text).scene.parameters.lambda, 1.0);
  EXPECT_THROW(diagram_spec(parse_scene("[diagram]\nsteps = 3\n")), InvalidArgument);
  EXPECT_THROW(diagram_spec(parse_scene("[diagram]\naxes = [\"lnB\"]\n")), InvalidArgument);
  EXPECT_THROW(diagram_spec(parse_scene("[diagram]\ncounts = [0, 3]\n")), InvalidArgument);
  EXPECT_EQ(diagram_spec(parse_scene("name = 'x'\n")).size(), DiagramSpec{}.size());
}

// The front ends' plane (CLI flags, Python keywords) on top of the table: given fields replace it, empty ones
// keep it, and every refusal names the field.
TEST(DiagramFile, PlaneChoiceOverridesTheTableAndNamesBadFields) {
  const SceneFile table = parse_scene("[diagram]\naxes = [\"lnC\", \"lambda\"]\ny_range = [0.5, 6]\ncounts = [8, 5]\n");
  PlaneChoice c;
  c.x_range = {-4, 1};
  c.counts = {3, 2};
  c.alpha_fixed = 100;
  const DiagramSpec d = plane_spec(table, c);
  EXPECT_EQ(d.x.axis, Axis::lnC);
  EXPECT_EQ(d.y.axis, Axis::lambda);
  EXPECT_EQ(d.x.min, -4.0);
  EXPECT_EQ(d.y.max, 6.0);
  EXPECT_EQ(d.x.count, 3);
  EXPECT_EQ(d.y.count, 2);
  EXPECT_EQ(d.alpha, 100.0);
  EXPECT_EQ(plane_spec(table, {}).size(), 40u);
  auto field_of = [&](const PlaneChoice& bad) {
    try {
      plane_spec(SceneFile{}, bad);
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field_of({{"lnB"}, {}, {}, {}, {}, {}}), "axes");
  EXPECT_EQ(field_of({{"lnB", "lnD"}, {}, {}, {}, {}, {}}), "axis");
  EXPECT_EQ(field_of({{}, {0, 1, 2}, {}, {}, {}, {}}), "x_range");
  EXPECT_EQ(field_of({{}, {}, {std::nan(""), 1}, {}, {}, {}}), "y_range");
  EXPECT_EQ(field_of({{}, {}, {}, {4}, {}, {}}), "counts");
  EXPECT_EQ(field_of({{}, {}, {}, {4, 0}, {}, {}}), "counts");
  EXPECT_EQ(field_of({{}, {}, {}, {4, 1'000'001}, {}, {}}), "counts");
  EXPECT_EQ(field_of({{}, {}, {}, {}, "mean", {}}), "classifier");
  EXPECT_EQ(field_of({{}, {}, {}, {}, {}, -1.0}), "alpha_fixed");
  EXPECT_EQ(field_of({{"lnB", "lnC"}, {-1, 6}, {-5.5, 2}, {64, 64}, "auto", 0.0}), "accepted");
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> v;
  for (std::string line; std::getline(in, line);) v.push_back(line);
  return v;
}
void write_lines(const std::string& path, const std::vector<std::string>& lines, const std::string& tail = "") {
  std::ofstream out(path, std::ios::trunc);
  for (const auto& l : lines) out << l << '\n';
  out << tail;
}
// Sets the n-th space-separated field of a journal record (keeping its old checksum, as a hand edit would).
void set_field(std::string& line, int n, const std::string& value) {
  std::size_t begin = 0;
  for (int k = 0; k < n; ++k) begin = line.find(' ', begin) + 1;
  line.replace(begin, line.find(' ', begin) - begin, value);
}
std::string field(const std::string& line, int n) {
  std::istringstream f(line);
  std::string w;
  for (int k = 0; k <= n; ++k) f >> w;
  return w;
}

TEST(Journal, SecondWriterIsRefusedNamingTheHolder) {
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  const std::string journal = temp_path("locked.journal");
  fs::remove(journal);
  std::promise<void> holding, tried;
  std::shared_future<void> release = tried.get_future().share();
  bool told = false;
  DiagramOptions first;
  first.journal = journal;
  first.progress_interval = 0.01;
  first.on_progress = [&](const Progress&) {
    if (told) return;
    told = true;
    holding.set_value();  // the journal is open and locked until run_diagram returns
    release.wait();
  };
  std::thread writer([&] { run_diagram(base, {}, spec, first); });
  holding.get_future().wait();
  DiagramOptions second;
  second.journal = journal;
  try {
    run_diagram(base, {}, spec, second);
    ADD_FAILURE() << "a second writer of " << journal << " was not refused";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.parameter(), "journal");
    EXPECT_NE(what.find(journal), std::string::npos) << what;
    EXPECT_NE(what.find("pid " + std::to_string(::getpid())), std::string::npos) << what;
  }
  tried.set_value();
  writer.join();
  // Once the holder is done the journal is free again, and complete.
  const DiagramRun again = run_diagram(base, {}, spec, second);
  EXPECT_EQ(again.resumed, spec.size());
  EXPECT_TRUE(again.rejected.empty());
}

TEST(Journal, EditedRecordsAreReportedWithLineAndRecomputed) {
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  const nlohmann::json header = diagram_header(base, {}, spec);
  const std::string clean = diagram_json(header, spec, run_diagram(base, {}, spec, {}).points, {}, {false}).dump();
  const std::string journal = temp_path("edited.journal");
  fs::remove(journal);
  DiagramOptions o;
  o.journal = journal;
  run_diagram(base, {}, spec, o);
  std::vector<std::string> l = lines_of(journal);
  ASSERT_EQ(l.size(), 1 + spec.size());
  // Line k + 2 holds index k (one thread: index order); record fields: P hash index verdict l_Delta growth ...
  set_field(l[2], 3, field(l[2], 3) == "stable" ? "unstable" : "stable");  // verdict flipped
  set_field(l[3], 4, field(l[3], 4) == "3" ? "4" : "3");                   // l_Delta changed
  set_field(l[4], 5, "nan");                                               // growth
  set_field(l[5], 2, "5");                                                 // index 4 swapped for 5
  // A record with a valid checksum but an impossible value (l_Delta above L) is refused too.
  PointResult forged = run_diagram(base, {}, spec, {}).points[6];
  forged.l_Delta = base.L + 3;
  l[8] = point_to_line(forged, config_hash(base, {}, spec));
  l[8].pop_back();
  l.pop_back();  // index 11 was being written when the process died: its record is torn
  write_lines(journal, l, "P " + config_hash(base, {}, spec) + " 11 stab");
  const DiagramRun r = run_diagram(base, {}, spec, o);
  ASSERT_EQ(r.rejected.size(), 6u) << ::testing::PrintToString(r.rejected);
  for (int line : {3, 4, 5, 6, 9, 13})
    EXPECT_TRUE(std::any_of(
        r.rejected.begin(), r.rejected.end(),
        [&](const std::string& why) { return why.rfind(journal + ":" + std::to_string(line) + ": ", 0) == 0; }))
        << "line " << line << " not reported";
  EXPECT_NE(r.rejected[0].find("checksum"), std::string::npos) << r.rejected[0];
  EXPECT_NE(r.rejected[4].find("l_Delta " + std::to_string(base.L + 3)), std::string::npos) << r.rejected[4];
  EXPECT_NE(r.rejected[5].find("torn"), std::string::npos) << r.rejected[5];
  EXPECT_EQ(r.computed, 6u);  // indices 1, 2, 3, 4, 6 and the torn 11 (never merged)
  EXPECT_EQ(diagram_json(header, spec, r.points, {}, {false}).dump(), clean);
  // The rejected records are gone from the file: the next run resumes everything silently.
  const DiagramRun again = run_diagram(base, {}, spec, o);
  EXPECT_TRUE(again.rejected.empty());
  EXPECT_EQ(again.resumed, spec.size());
  EXPECT_EQ(lines_of(journal).size(), 1 + spec.size());
}

TEST(Journal, OlderFormatWithoutChecksumsIsRefused) {
  const std::string journal = temp_path("v1.journal");
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  write_lines(journal, {"# rbcstab diagram journal v1 " + config_hash(base, {}, spec)});
  DiagramOptions o;
  o.journal = journal;
  try {
    run_diagram(base, {}, spec, o);
    ADD_FAILURE() << "a v1 journal was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("older format v1"), std::string::npos) << e.what();
  }
}

TEST(Merge, RefusesOutOfDomainValuesNamingFileLineAndValue) {
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  const std::string good =
      diagram_json(diagram_header(base, {}, spec), spec, run_diagram(base, {}, spec, {}).points, {}, {false}).dump(1);
  auto line_of = [](const std::string& text, const std::string& needle) {
    const auto at = text.find(needle);
    return 1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n');
  };
  struct Case {
    std::size_t point;
    std::string key, from, to, message;
  };
  for (const Case& c :
       {Case{2, "l_Delta", "", "-7", "l_Delta -7 is outside [2, 5]"},
        Case{5, "verdict", "", "\"banana\"", "'banana' is not one of: stable, unstable, failed"},
        Case{7, "status", "", "\"sideways\"", "'sideways'"}, Case{3, "growth", "", "\"x\"", "growth = \"x\""}}) {
    nlohmann::json doc = nlohmann::json::parse(good);
    doc["points"][c.point][c.key] = nlohmann::json::parse(c.to);
    const std::string text = doc.dump(1);
    const std::string needle = "\"" + c.key + "\": " + c.to;
    try {
      merge_diagrams(std::vector<MergeInput>{{"shard.json", text}});
      ADD_FAILURE() << c.key << " = " << c.to << " was merged";
    } catch (const InvalidArgument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("shard.json:" + std::to_string(line_of(text, needle)) + ":"), std::string::npos) << what;
      EXPECT_NE(what.find(c.message), std::string::npos) << what;
    }
  }
  EXPECT_EQ(merge_diagrams(std::vector<MergeInput>{{"shard.json", good}}).points.size(), spec.size());
}

// Found by fuzzing: fractions and wide integers were truncated (index 0.5 read as 0), a non-string config_hash
// escaped as a JSON exception, an edited header (its scene, or no scene_toml at all) was merged as the
// configuration that computed the points, and a point held twice with another growth was merged silently.
TEST(Merge, RefusesTruncatedIntegersEditedHeadersAndDisagreeingDuplicates) {
  const Scene base = small_scene();
  const DiagramSpec spec = small_spec();
  const nlohmann::json good =
      diagram_json(diagram_header(base, {}, spec), spec, run_diagram(base, {}, spec, {}).points, {}, {false});
  auto refused = [&](const std::function<void(nlohmann::json&)>& edit, const std::string& fragment,
                     bool twice = false) {
    nlohmann::json doc = good;
    edit(doc);
    std::vector<MergeInput> inputs{{"shard.json", doc.dump(1)}};
    if (twice) inputs.insert(inputs.begin(), {"first.json", good.dump(1)});
    try {
      merge_diagrams(inputs);
      ADD_FAILURE() << fragment << ": merged";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused([](nlohmann::json& d) { d["points"][1]["index"] = 0.5; }, "points[1].index: 0.5 is not an integer in [0, ");
  refused([](nlohmann::json& d) { d["points"][1]["l_Delta"] = 4294967299LL; },
          "points[1].l_Delta: 4294967299 is not an integer in [");
  refused([](nlohmann::json& d) { d["points"][1]["steps"] = -1; }, "points[1].steps: -1 is not an integer in [0, ");
  refused([](nlohmann::json& d) { d["diagram"]["x"]["count"] = 4294967298LL; }, "4294967298 is not an integer");
  refused([](nlohmann::json& d) { d["config_hash"] = 12; }, "has no config_hash string (12)");
  refused([](nlohmann::json& d) { d["seconds_included"] = "yes"; },
          "seconds_included = \"yes\": must be true or false");
  refused([](nlohmann::json& d) { d["scene"]["T"] = 99; }, "input 1 has scene = ");
  refused([](nlohmann::json& d) { d["scene_toml"] = "[run]\nT = 99.0\n"; }, "hash to");
  refused([](nlohmann::json& d) { d.erase("scene_toml"); }, "no scene_toml");
  refused([](nlohmann::json& d) { d["points"][2]["growth"] = 0.125; }, "appears twice with different results", true);
  EXPECT_EQ(merge_diagrams(std::vector<MergeInput>{{"a.json", good.dump(1)}, {"b.json", good.dump(1)}}).points.size(),
            spec.size());
}

TEST(PointIo, FailedPointWritesNoNanText) {
  const DiagramSpec spec = small_spec();
  PointResult p;
  p.index = 3;
  p.status = IntegrationStatus::non_finite_state;
  p.verdict = Verdict::failed;
  p.l_Delta = 4;
  p.growth = std::nan("");
  p.sigma_final = std::nan("");
  p.t_reached = 1.5;
  p.reason = "state became non-finite";
  const std::string line = point_to_line(p, "0123456789abcdef");
  EXPECT_EQ(line.find("nan"), std::string::npos) << line;
  const auto back = parse_point_line(line, "0123456789abcdef", spec, 5);
  ASSERT_TRUE(back.point) << back.error;
  EXPECT_TRUE(std::isnan(back.point->sigma_final));
  EXPECT_EQ(point_to_line(*back.point, "0123456789abcdef"), line);
  const std::string csv = diagram_csv(spec, {*back.point}, {true});
  EXPECT_EQ(csv.find("nan"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",4,,0,,non_finite_state,1.5,"), std::string::npos) << csv;
  // A real failed run (a step limit) too.
  SimulationOptions so;
  so.integrator.max_steps = 3;
  const DiagramRun r = run_diagram(small_scene(), so, spec, {});
  ASSERT_EQ(r.points.front().verdict, Verdict::failed);
  EXPECT_EQ(diagram_csv(spec, r.points, {false}).find("nan"), std::string::npos);
}
}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {
// Every diagram scene of the paper's figures parses, as a scene and as a diagram.
TEST(DiagramScenes, PaperPanelsParse) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(RBCSTAB_SCENES_DIR)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("fig4", 0) != 0 && name.rfind("fig5", 0) != 0 && name.rfind("appE", 0) != 0) continue;
    const std::string text = read_file(e.path().string());
    const SceneFile sf = parse_scene(text, name);
    ASSERT_TRUE(sf.diagram.has_value()) << name;
    const DiagramSpec d = diagram_spec(sf);
    EXPECT_NO_THROW(point_scene(sf.scene, d, d.size() - 1).validate()) << name;
    if (name.rfind("appE", 0) == 0) {
      EXPECT_EQ(d.classifier, Classifier::tail_mean) << name;
    }
    if (name.rfind("fig5", 0) == 0) {
      EXPECT_GT(d.alpha, 0) << name;
    }
    ++n;
  }
  EXPECT_EQ(n, 12);
}
// --counts of diagram and report, read one way: nx,ny, NxM or two texts; anything else names the flag and the form.
TEST(DiagramFile, CountsAsAUserTypesThem) {
  const std::vector<long long> want{3, 2};
  EXPECT_EQ(parse_counts({"3,2"}, "--counts"), want);
  EXPECT_EQ(parse_counts({"3x2"}, "--counts"), want);
  EXPECT_EQ(parse_counts({"3", "2"}, "--counts"), want);
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"3"}, {"3,a"}, {"0x2"}, {"3,,2"}, {"3x2x1"}, {"1000001,2"}, {"3", "2", "1"}, {""}}) {
    try {
      (void)parse_counts(bad, "--counts");
      ADD_FAILURE() << "accepted " << bad.front();
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "--counts");
      EXPECT_NE(std::string(e.what()).find("nx,ny or NxM"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace rbcstab
