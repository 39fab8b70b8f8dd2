// Figure panels (report/panels.hpp): the [fig6e], [continuation] and [physical_map] tables, the bifurcation data
// against the closed-form vesicle branch, the phase-diagram overlay against the traced boundary, and tiny diagram
// and physical-map panels end to end (the diagram's data equal an independent run's, the map's boundary is a true
// crossing of the reduced regime).
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {
namespace fs = std::filesystem;

const std::string kBase = R"(name = "panel"
[parameters]
lambda = 1.0
Delta = 0.8
Delta0 = 0.02
B = 2.0
C = 0.04
[initial]
beta = 0.001
delta = 1e-4
[run]
L = 6
T = 40
)";

std::string expect_invalid(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InvalidArgument";
  return "";
}

TEST(PanelKind, OneTableAtMost) {
  EXPECT_EQ(panel_kind(parse_scene(kBase)), PanelKind::none);
  EXPECT_EQ(panel_kind(parse_scene(kBase + "[diagram]\ncounts = [2, 2]\n")), PanelKind::diagram);
  EXPECT_EQ(panel_kind(parse_scene(kBase + "[fig6e]\nB = [1.0]\n")), PanelKind::fig6e);
  EXPECT_EQ(panel_kind(parse_scene(kBase + "[continuation]\nparameter = \"C\"\n")), PanelKind::continuation);
  const std::string m =
      expect_invalid([] { (void)panel_kind(parse_scene(kBase + "[fig6e]\n[continuation]\n", "two.toml")); });
  EXPECT_NE(m.find("more than one panel table"), std::string::npos) << m;
  // The scene parser accepts the panel tables (and ignores them).
  EXPECT_NO_THROW((void)parse_scene(kBase + "[fig6e]\nB = [1.0]\n"));
  EXPECT_NO_THROW((void)parse_scene(kBase + "[continuation]\nmin = 0.5\n"));
}

TEST(Fig6eTable, TakesTheRunFromTheSceneAndNamesBadKeys) {
  const std::string text = kBase + "[fig6e]\nlambda = [2.0]\nB = [1.0, 3.0]\nC = [0.05]\n";
  const SceneFile sf = parse_scene(text);
  const Fig6eOptions f = fig6e_options(sf);
  EXPECT_EQ(f.lambdas, std::vector<double>{2.0});
  EXPECT_EQ(f.B, (std::vector<double>{1.0, 3.0}));
  EXPECT_EQ(f.C, std::vector<double>{0.05});
  EXPECT_EQ(f.Delta, 0.8);
  EXPECT_EQ(f.Delta0, 0.02);
  EXPECT_EQ(f.L, 6);
  EXPECT_EQ(f.T, 40.0);
  EXPECT_EQ(f.delta, 1e-4);
  // Absent keys: the paper's grid.
  const Fig6eOptions d = fig6e_options(parse_scene(kBase + "[fig6e]\n"));
  EXPECT_EQ(d.B.size(), 10u);
  EXPECT_EQ(d.C.size(), 4u);
  std::string m = expect_invalid([&] { (void)fig6e_options(parse_scene(kBase + "[fig6e]\nkappa = 1\n")); });
  EXPECT_NE(m.find("fig6e.kappa"), std::string::npos) << m;
  m = expect_invalid([&] { (void)fig6e_options(parse_scene(kBase + "[fig6e]\nB = [1.0, -2.0]\n")); });
  EXPECT_NE(m.find("fig6e.B"), std::string::npos) << m;
  EXPECT_NE(m.find("> 0"), std::string::npos) << m;
  m = expect_invalid([&] { (void)fig6e_options(parse_scene(kBase + "[fig6e]\nC = \"x\"\n")); });
  EXPECT_NE(m.find("fig6e.C"), std::string::npos) << m;
}

// The CSV carries the table's values: read back, every number equals the row's to the 10 printed digits.
TEST(Fig6eTable, CsvRoundTripsTheRows) {
  const std::string text = kBase + "[fig6e]\nlambda = [1.0]\nB = [2.0]\nC = [0.01, 0.04]\n";
  const SceneFile sf = parse_scene(text);
  const Fig6eOptions f = fig6e_options(sf);
  const std::vector<Fig6eRow> rows = fig6e_table(f);
  ASSERT_EQ(rows.size(), 2u);
  std::istringstream in(fig6e_csv(f, rows));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# Fig. 6e", 0), 0u);
  std::getline(in, line);
  EXPECT_EQ(line,
            "lambda,B,C,alpha,ln_alpha,l_s,l_Delta,Delta2_tilde,Delta2_tilde_integer,Delta2_bar,ratio,ratio_integer");
  for (const Fig6eRow& r : rows) {
    ASSERT_TRUE(std::getline(in, line));
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 12u);
    EXPECT_DOUBLE_EQ(std::stod(cells[2]), r.C);
    EXPECT_EQ(std::stoi(cells[6]), r.l_Delta);
    auto same = [&](const std::string& cell, const Quantity& q) {
      if (!q.valid()) {
        EXPECT_EQ(cell, "n/a");
        return;
      }
      EXPECT_NEAR(std::stod(cell), q.value, 1e-9 * std::abs(q.value));  // 10 significant digits printed
    };
    same(cells[7], r.Delta2_tilde);
    same(cells[9], r.Delta2_bar);
    same(cells[10], r.ratio);
  }
}

TEST(ContinuationTable, ParsesAndNamesBadKeys) {
  const ContinuationPanel c =
      continuation_panel(parse_scene(
          kBase + "[continuation]\nparameter = \"C\"\nmin = 0.01\nmax = 2.0\ndirection = \"forward\"\nmeasure = \"r\"\n"
                  "max_points = 50\nnewton_tol = 1e-11\nmax_newton = 20\nmonitor = [\"Psi=0.5,0.6\"]\n"
                  "stop_at = [\"r=0.9\"]\n"));
  EXPECT_EQ(c.parameter, ContinuationParameter::C);
  EXPECT_EQ(c.engine.p_min, 0.01);
  EXPECT_EQ(c.engine.p_max, 2.0);
  EXPECT_EQ(c.engine.direction, Direction::forward);
  EXPECT_EQ(c.measure, "r");
  EXPECT_EQ(c.engine.max_points, 50u);
  // The tunable options by their keywords (tunable_options.hpp) and the monitors.
  EXPECT_EQ(c.engine.newton_tol, 1e-11);
  EXPECT_EQ(c.engine.max_newton, 20);
  ASSERT_EQ(c.monitors.size(), 2u);
  EXPECT_EQ(c.monitors[0].name, "Psi");
  EXPECT_EQ(c.monitors[0].values, (std::vector<double>{0.5, 0.6}));
  EXPECT_FALSE(c.monitors[0].stop);
  EXPECT_TRUE(c.monitors[1].stop);
  EXPECT_EQ(branch_spec(c, Scene{}).monitors.size(), 2u);
  for (const auto& [table, name] :
       {std::pair{"measure = \"Q\"\n", "continuation.measure"},
        std::pair{"parameter = \"kappa\"\n", "continuation.parameter"},
        std::pair{"direction = \"up\"\n", "continuation.direction"},
        std::pair{"min = 2.0\nmax = 1.0\n", "continuation.max"},
        std::pair{"max_points = 1\n", "continuation.max_points"}, std::pair{"colour = 1\n", "continuation.colour"},
        std::pair{"newton_tol = 0.5\n", "continuation.newton_tol: newton_tol = 0.5 is out of range"},
        std::pair{"monitor = [\"Psi\"]\n", "continuation.monitor"},
        std::pair{"segments = 4\n", "continuation.segments"}}) {
    const std::string m =
        expect_invalid([&] { (void)continuation_panel(parse_scene(kBase + "[continuation]\n" + table)); });
    EXPECT_NE(m.find(name), std::string::npos) << table << ": " << m;
  }
}

// Oracle: at C = inf the tank-treading equilibria are r = 1, Psi = +-arccos(Lambda) (docs/continuation.md,
// docs/theory.md), stable for Psi > 0; the fold (LP) is at Lambda = 1.
TEST(BifurcationJson, VesicleBranchFollowsTheClosedForm) {
  std::string text = kBase + "[continuation]\nmin = 0.0\nmax = 10.0\nmeasure = \"Psi\"\n";
  text.replace(text.find("C = 0.04"), 8, "C = inf");
  text.replace(text.find("beta = 0.001"), 12, "beta = 0.0");
  const SceneFile sf = parse_scene(text);
  const ContinuationPanel c = continuation_panel(sf);
  const SceneBranch r = continue_scene(branch_spec(c, sf.scene));
  const Branch& b = r.branch.branch;
  const nlohmann::json j = bifurcation_json(r, c.measure);
  EXPECT_EQ(j.at("measure"), c.measure);
  ASSERT_FALSE(j.contains("switched_branch"));  // one branch
  const auto& br = j.at("branch");
  ASSERT_EQ(br.size(), b.points.size());
  ASSERT_GT(b.points.size(), 10u);
  Parameters p = sf.scene.parameters;
  for (std::size_t k = 0; k < b.points.size(); ++k) {
    p.lambda = br[k].at("lambda").get<double>();
    const double psi = br[k].at(c.measure).get<double>();
    // Newton converges to 1e-12 (newton_tol); arccos loses up to sqrt of that near Lambda = 1.
    EXPECT_NEAR(std::abs(psi), std::acos(std::min(1.0, p.Lambda())), 2e-6) << "lambda = " << p.lambda;
    if (std::abs(psi) > 1e-3) {
      EXPECT_EQ(br[k].at("stable").get<bool>(), psi > 0) << "lambda = " << p.lambda;
    }
  }
  bool lp = false;
  for (const auto& sp : j.at("special_points"))
    if (sp.at("type") == "LP") {
      lp = true;
      p.lambda = sp.at("lambda").get<double>();
      EXPECT_NEAR(p.Lambda(), 1.0, 1e-6);  // located to 1e-8 in the parameter (docs/continuation.md)
    }
  EXPECT_TRUE(lp);
}

TEST(PhaseOverlay, HoldsTheTracedBoundaryAndTheAnalyticLines) {
  TraceCurve a, b;
  a.l = 3;
  a.points = {TracePoint{0, 1, 3, 0, 0, 0}, TracePoint{1, 2, 3, 0, 0, 0}};
  b.l = 4;
  b.points = {TracePoint{1, 2, 4, 0, 0, 0}, TracePoint{2, 2.5, 4, 0, 0, 0}};
  const std::vector<Overlay> lines{
      {"l_star=2.5", {0, 1}, {-3, -2}}, {"C_star_plus", {0, 2}, {1, 1}}, {"empty", {}, {}}};
  DiagramSpec spec;  // ln B x ln C
  const nlohmann::json o = phase_overlay_json(spec, {a, b}, lines);
  EXPECT_EQ(o.at("axes").at("x"), "$\\ln \\mathcal{B}$");  // the parameter table's symbols
  EXPECT_EQ(o.at("axes").at("y"), "$\\ln \\mathcal{C}$");
  spec.x.axis = Axis::shear_rate;
  EXPECT_EQ(phase_overlay_json(spec, {}, {}).at("axes").at("x"), "$\\dot\\gamma$ [1/s]");
  const auto& c = o.at("curves");
  ASSERT_EQ(c.size(), 4u);  // two boundary pieces, two non-empty lines
  EXPECT_EQ(c[0].at("x"), (std::vector<double>{0, 1}));
  EXPECT_EQ(c[1].at("y"), (std::vector<double>{2, 2.5}));
  EXPECT_TRUE(c[0].contains("label"));
  EXPECT_FALSE(c[1].contains("label"));  // one legend entry for the boundary
  EXPECT_EQ(c[2].at("label"), "$l_* = 2.5$");
  EXPECT_EQ(c[3].at("label"), "$\\mathcal{C}_*^+$");
}

// A 4 x 3 diagram panel end to end; the data behind the figure equals an independent single-thread run.
TEST(PanelReport, TinyDiagramBuildsAndItsDataEqualAnIndependentRun) {
  const std::string text = kBase +
                           "[diagram]\naxes = [\"lnB\", \"lnC\"]\nx_range = [-1.0, 6.0]\n"
                           "y_range = [-5.5, 2.0]\ncounts = [9, 9]\nclassifier = \"final\"\n";
  const SceneFile sf = parse_scene(text);
  const fs::path parent = test::fresh_dir("panels_test", "diagram");
  ReportOptions ro;
  ro.output = (parent / "panel").string();
  PanelOptions po;
  po.threads = 2;
  po.nx = 4;
  po.ny = 3;
  po.trace.lines = 20;
  const PanelReportResult r = build_panel_report(sf, po, ro);
  EXPECT_EQ(r.kind, PanelKind::diagram);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.failed, 0u);
  const fs::path dir = parent / "panel";
  for (const char* f : {"index.html", "README.md", "report.json", "scene.toml", "phase_diagram.csv",
                        "phase_diagram_overlay.json", "diagram.json", "fig_phase_diagram.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  EXPECT_EQ(read_file((dir / "scene.toml").string()), text);  // reproduces the panel, [diagram] table included
  EXPECT_GT(fs::file_size(dir / "fig_phase_diagram.png"), 1000u);
  // No staging folder is left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(parent)) ++entries;
  EXPECT_EQ(entries, 1);
  DiagramSpec spec = diagram_spec(sf);
  spec.x.count = 4;
  spec.y.count = 3;
  DiagramOptions one;
  one.threads = 1;
  const DiagramRun serial = run_diagram(sf.scene, sf.options, spec, one);
  EXPECT_EQ(read_file((dir / "phase_diagram.csv").string()),
            diagram_csv(spec, serial.points, DiagramOutputOptions{false}));
  const nlohmann::json overlay = nlohmann::json::parse(read_file((dir / "phase_diagram_overlay.json").string()));
  EXPECT_GE(overlay.at("curves").size(), 2u);  // the traced boundary and at least the l_* = 2.5 line
}

// The hook flags (--phase-diagram FILE) still draw another command's output into a scene report.
TEST(PanelReport, HookFlagsStillDrawIntoASceneReport) {
  const fs::path parent = test::fresh_dir("panels_test", "hooks");
  const fs::path csv = parent / "d.csv";
  {
    std::ofstream f(csv);
    f << "index,i,j,lnB,lnC,verdict,l_Delta\n0,0,0,0,0,stable,2\n1,1,0,1,0,unstable,3\n2,0,1,0,1,stable,2\n"
         "3,1,1,1,1,unstable,4\n";
  }
  SceneFile sf;
  sf.scene.L = 3;
  sf.scene.T = 4;
  sf.scene.dt = 1;
  ReportOptions ro;
  ro.output = (parent / "scene").string();
  ro.shape = {8, 16};
  ro.frame_shape = {6, 12};
  ro.frames = 2;
  ro.phase_diagram = csv.string();
  const ReportResult r = build_report(sf, ro);
  EXPECT_TRUE(fs::is_regular_file(parent / "scene" / "trajectory.csv"));
  EXPECT_EQ(read_file((parent / "scene" / "phase_diagram.csv").string()), read_file(csv.string()));
  EXPECT_GT(fs::file_size(parent / "scene" / "fig_phase_diagram.png"), 1000u);
}

// A physical cell for the [physical_map] table (the nominal healthy cell of docs/units.md, R = 2.8 um).
const std::string kCell = R"(name = "cell"
[physical]
shear_rate = "10/s"
viscosity = "25 mPa s"
inner_viscosity = "6 mPa s"
radius = "2.8 um"
bending_modulus = "2e-19 J"
shear_modulus = "6 uN/m"
[parameters]
Delta = 1.0
Delta0 = 0.5
)";

// Quantities with or without units (a bare number only where plausible), and every bad key named.
TEST(PhysicalMapTable, ReadsQuantitiesAndNamesBadKeys) {
  const PhysicalMapPanel p =
      physical_map_panel(parse_scene(
          kCell + "[physical_map]\nviscosity = [\"2 mPa s\", 0.04]\nviscosities = 4\nshear_rate = [\"0.5/s\", 2000]\n"
                  "samples_per_decade = 2\nrtol = 1e-3\nonset = false\nspreads = \"healthy\"\n"));
  EXPECT_DOUBLE_EQ(p.options.min_viscosity, 2e-3);
  EXPECT_EQ(p.options.max_viscosity, 0.04);
  EXPECT_EQ(p.options.viscosities, 4);
  EXPECT_EQ(p.options.min_rate, 0.5);
  EXPECT_EQ(p.options.max_rate, 2000);
  EXPECT_EQ(p.options.samples_per_decade, 2);
  EXPECT_EQ(p.options.rtol, 1e-3);
  EXPECT_FALSE(p.options.onset);
  EXPECT_TRUE(p.healthy_spreads);
  EXPECT_EQ(panel_kind(parse_scene(kCell + "[physical_map]\n")), PanelKind::physical_map);
  EXPECT_EQ(truncation_use(PanelKind::physical_map), TruncationUse::analysis);
  for (const auto& [table, name] :
       {std::pair{"colour = 1\n", "physical_map.colour"},
        // 2.8 Pa s is not a plausible viscosity as a bare number (mPa s meant): refused with the range.
        std::pair{"viscosity = [2.8, 50.0]\n", "physical_map.viscosity: viscosity = 2.8 (a bare number"},
        std::pair{"viscosity = [\"50 mPa s\", \"1 mPa s\"]\n", "physical_map.viscosity"},
        std::pair{"viscosity = [\"1 mPa s\"]\n", "physical_map.viscosity must be [min, max]"},
        std::pair{"shear_rate = [10, 10]\n", "physical_map.shear_rate"},
        std::pair{"shear_rate = [1e-9, 10]\n", "physical_map.shear_rate: shear_rate = 1e-09"},
        std::pair{"shear_rate = [\"1 m\", 10]\n", "physical_map.shear_rate"},
        std::pair{"viscosities = 0\n", "physical_map.viscosities"},
        std::pair{"viscosity = [0.01, 0.01]\nviscosities = 2\n", "physical_map.viscosities"},
        std::pair{"samples_per_decade = 0\n", "physical_map.samples_per_decade"},
        std::pair{"rtol = 1.0\n", "physical_map.rtol"}, std::pair{"onset = 1\n", "physical_map.onset"},
        std::pair{"spreads = \"all\"\n", "physical_map.spreads"}}) {
    const std::string m =
        expect_invalid([&] { (void)physical_map_panel(parse_scene(kCell + "[physical_map]\n" + table)); });
    EXPECT_NE(m.find(name), std::string::npos) << table << ": " << m;
  }
}

// The page's tables say what the map holds: a boundary found as its rate, one outside the range on its side, a
// failing assumption as NO with how far off, each observation with its source and the sentence it rests on.
TEST(PhysicalMapTable, PageSaysWhatTheMapHolds) {
  PhysicalMap map;
  map.min_rate = 0.1;
  map.max_rate = 1e5;
  map.onset = true;
  PhysicalMapColumn c;
  c.viscosity = 0.025;
  c.tumbling_to_swinging.found = true;
  c.tumbling_to_swinging.rate = 8;
  c.onset[0].side = "below";
  c.onset[0].l = 4;
  c.onset[1].side = "above";
  map.columns = {c};
  map.assumptions = {{"quasi-spherical expansion", "Delta", 4.28, 1, false, "m1"},
                     {"Stokes flow", "Re", 1e-3, 0.1, true, "m2"}};
  PublishedObservation o;
  o.source = "Abkarian2007";
  o.observation = "swinging";
  o.kind = "stress";
  o.stress = 0.1;
  o.precision = "order";
  o.reference = "PRL 98";
  o.basis = "of the order of 0.1 Pa";
  const PhysicalMapPage page = physical_map_page(map, {o}, "data/experiments.csv");
  ASSERT_EQ(page.tables.size(), 3u);
  const std::vector<std::string>& row = page.tables[0].rows.at(0);
  ASSERT_EQ(row.size(), 7u);
  EXPECT_EQ(row[0], "25");
  EXPECT_EQ(row[3], "8 1/s");
  EXPECT_EQ(row[4], "0.2");  // eta_ex gamma = 0.025 Pa s x 8/s
  EXPECT_EQ(row[5].rfind("below 0.1 1/s", 0), 0u) << row[5];
  EXPECT_NE(row[5].find("l = 4"), std::string::npos) << row[5];
  EXPECT_EQ(row[6].rfind("above 1e+05 1/s", 0), 0u) << row[6];
  const std::vector<std::string>& seen = page.tables[1].rows.at(0);
  EXPECT_EQ(seen[0], "Abkarian2007");
  EXPECT_EQ(seen[2], "shear stress eta_ex gamma = 0.1 Pa (order of magnitude)");
  EXPECT_EQ(seen[4], "of the order of 0.1 Pa");
  EXPECT_EQ(page.tables[2].rows.at(0)[4], "NO");
  EXPECT_NE(page.tables[2].rows.at(0)[5].find("4.3 times the bound"), std::string::npos);
  EXPECT_EQ(page.tables[2].rows.at(1)[4], "yes");
  // Without the onset searched its columns are left out rather than shown empty.
  map.onset = false;
  EXPECT_EQ(physical_map_page(map, {o}, "").tables[0].rows.at(0).size(), 5u);
}

// A one-viscosity physical-map panel end to end: the page lists the boundaries, the observations and the assumption
// checks, and the boundary drawn is a true crossing: independently of the search, the reduced regime tumbles at the
// bracket's lower end and does not at its upper end.
TEST(PanelReport, PhysicalMapBuildsItsPageAndItsBoundaryIsACrossing) {
  const std::string text = kCell +
                           "[physical_map]\nviscosity = [\"25 mPa s\", \"25 mPa s\"]\nviscosities = 1\n"
                           "shear_rate = [\"0.1/s\", \"1000/s\"]\nsamples_per_decade = 1\nrtol = 0.1\nonset = false\n";
  const SceneFile sf = parse_scene(text);
  const fs::path parent = test::fresh_dir("panels_test", "physical_map");
  ReportOptions ro;
  ro.output = (parent / "panel").string();
  PanelOptions po;
  po.threads = 1;
  const PanelReportResult r = build_panel_report(sf, po, ro);
  EXPECT_EQ(r.kind, PanelKind::physical_map);
  const fs::path dir = parent / "panel";
  for (const char* f : {"index.html", "README.md", "report.json", "scene.toml", "physical_map.json",
                        "fig_physical_map.png", "fig_physical_map.svg"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  const std::string html = read_file((dir / "index.html").string());
  for (const char* seen : {"Published observations drawn over the map", "Abkarian2007", "of the order of 0.1 Pa",
                           "Lanotte2016", "quasi-spherical expansion", "Boundaries per outer viscosity"})
    EXPECT_NE(html.find(seen), std::string::npos) << seen;
  const nlohmann::json drawn = nlohmann::json::parse(read_file((dir / "physical_map.json").string()));
  const nlohmann::json& t = drawn.at("columns").at(0).at("tumbling_to_swinging");
  ASSERT_TRUE(t.at("found").get<bool>()) << t.dump();
  EXPECT_GE(drawn.at("experiments").size(), 3u);
  const double lo = t.at("bracket").at(0).get<double>(), hi = t.at("bracket").at(1).get<double>();
  EXPECT_EQ(hi, t.at("shear_rate").get<double>());
  EXPECT_LE(hi / lo - 1, 0.1);
  auto regime = [&](double rate) {
    Scene s = sf.scene;
    s.beta = std::acos(0.0);
    set_parameter(s, SceneParameter::shear_rate, rate);
    return reduced_regime(s).regime;
  };
  EXPECT_EQ(regime(lo), Regime::tumbling);
  EXPECT_NE(regime(hi), Regime::tumbling);
}

TEST(PanelReport, SceneWithoutPanelTableIsRefused) {
  const SceneFile sf = parse_scene(kBase);
  ReportOptions ro;
  ro.output = (test::fresh_dir("panels_test", "none") / "x").string();
  const std::string m = expect_invalid([&] { (void)build_panel_report(sf, {}, ro); });
  EXPECT_NE(m.find("no panel table"), std::string::npos) << m;
  PanelOptions bad;
  bad.threads = -1;
  const std::string m2 = expect_invalid([&] { (void)build_panel_report(sf, bad, ro); });
  EXPECT_NE(m2.find("threads"), std::string::npos) << m2;
}

}  // namespace
}  // namespace rbcstab

// Figure labels write a parameter with its symbol from the parameter table, and scientific notation as mathematics:
// a caption such as Fig. 6's "delta = 10^{-10}" is the table's symbol and this rule, not text typed in the figure.
TEST(ParameterLabels, TexValueUsesTheTableSymbolAndPowersOfTen) {
  EXPECT_EQ(rbcstab::detail::tex_value(rbcstab::SceneParameter::delta, 1e-10), "$\\delta = 10^{-10}$");
  EXPECT_EQ(rbcstab::detail::tex_value(rbcstab::SceneParameter::delta, 1e-3), "$\\delta = 0.001$");
  EXPECT_EQ(rbcstab::detail::tex_value(rbcstab::SceneParameter::lambda, 2.5e6), "$\\lambda = 2.5 \\times 10^{6}$");
  EXPECT_EQ(rbcstab::detail::tex_value(rbcstab::SceneParameter::alpha, 50), "$\\alpha = 50$");
  EXPECT_EQ(rbcstab::detail::tex_value(rbcstab::SceneParameter::Delta, -INFINITY), "$\\Delta = -\\infty$");
  EXPECT_EQ(rbcstab::detail::tex_value(rbcstab::SceneParameter::lnC, -1e-5), "$\\ln \\mathcal{C} = -10^{-5}$");
}
