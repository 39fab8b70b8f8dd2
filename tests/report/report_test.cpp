// End to end: a report for a small scene builds, its PNGs have the declared pixel sizes, its VTK
// reads back, and the data behind each figure equals an independent run of the same scene.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/report/detail/provenance.hpp"
#include "rbcstab/report/report.hpp"
#include "report/png_size.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {
namespace fs = std::filesystem;

using test_support::png_size;

std::vector<std::vector<double>> read_csv_rows(const fs::path& path, std::vector<std::string>* header = nullptr) {
  std::istringstream in(read_file(path.string()));
  std::string line;
  std::getline(in, line);
  if (header) {
    std::stringstream hs(line);
    std::string h;
    while (std::getline(hs, h, ',')) header->push_back(h);
  }
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ls, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

SceneFile small_scene(double beta) {
  SceneFile sf;
  sf.scene.name = "small";
  sf.scene.L = 4;
  sf.scene.T = 6;
  sf.scene.dt = 0.5;
  sf.scene.beta = beta;
  sf.scene.delta = 1e-3;
  sf.options.tail_window = 2;
  return sf;
}

ReportOptions small_options(const fs::path& out) {
  ReportOptions o;
  o.output = out.string();
  o.shape = {12, 24};
  o.frame_shape = {8, 16};
  o.frames = 4;
  return o;
}

// Removes a test folder when the test ends.
struct Cleanup {
  fs::path path;
  ~Cleanup() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

bool has_leftovers(const fs::path& parent) {
  for (const auto& e : fs::directory_iterator(parent))
    if (e.path().filename().string().rfind(".", 0) == 0) return true;
  return false;
}

// One report build shared by the checks below (ctest runs every TEST in its own process, so the
// checks are one TEST to build the report once).
struct Built {
  fs::path parent_;
  SceneFile scene_;
  ReportResult result_;
};

void check_figures(const Built& b) {
  const auto& parent_ = b.parent_;
  const fs::path out = parent_ / "out";
  const auto manifest = nlohmann::json::parse(read_file((out / "report.json").string()));
  const auto drawn = nlohmann::json::parse(read_file((out / "figures.json").string()));
  ASSERT_GE(manifest.at("figures").size(), 5u);
  // The stamp: on the page and in the manifest, hashing the scene.toml the folder holds.
  const detail::Provenance stamp = detail::provenance_from_json(manifest.at("provenance"));
  EXPECT_EQ(stamp.scene_hash,
            detail::make_provenance({read_file((out / "scene.toml").string())}, "scene.toml").scene_hash);
  EXPECT_NE(read_file((out / "index.html").string()).find(detail::provenance_html(stamp)), std::string::npos);
  std::size_t checked = 0;
  for (const auto& f : manifest.at("figures")) {
    const fs::path png = out / f.at("png").get<std::string>();
    ASSERT_TRUE(fs::exists(png)) << png;
    EXPECT_GT(fs::file_size(png), 1000u) << png;  // a blank PNG of this size is still > 1 kB; see colour check
    const auto [w, h] = png_size(png);
    EXPECT_EQ(w, f.at("size_px")[0].get<int>()) << png;
    EXPECT_EQ(h, f.at("size_px")[1].get<int>()) << png;
    ++checked;
  }
  EXPECT_EQ(checked, 5u);
  // The GIF exists (python3-pil is a dependency of python3-matplotlib in Debian) and is a GIF.
  const std::string gif = read_file((out / "animation.gif").string());
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  // Every drawn file is linked from index.html and README.md.
  const std::string html = read_file((out / "index.html").string());
  const std::string md = read_file((out / "README.md").string());
  std::size_t vectors = 0;
  for (const auto& d : drawn) {
    if (!d.contains("svg")) continue;  // the shaded shape and its animation frames: PNG only
    const std::string svg = d.at("svg");
    EXPECT_NE(read_file((out / svg).string()).find("<svg"), std::string::npos) << svg;
    EXPECT_NE(html.find("<a href=\"" + svg + "\""), std::string::npos) << svg;  // a click opens it
    ++vectors;
  }
  EXPECT_EQ(vectors, 3u);  // Figs. 2 and 3: reduced dynamics, excess areas, tension
  for (const auto& d : drawn) {
    const std::string file = d.at("file");
    if (file.ends_with(".png")) {
      EXPECT_NE(html.find("src=\"" + file + "\""), std::string::npos) << file;
      EXPECT_NE(md.find("](" + file + ")"), std::string::npos) << file;
    }
  }
  // The per-mode table lists l = 2, 3, 4 in numeric order.
  const auto table = md.find("## Excess area per mode");
  ASSERT_NE(table, std::string::npos);
  const auto row2 = md.find("\n| 2 | ", table), row3 = md.find("\n| 3 | ", table), row4 = md.find("\n| 4 | ", table);
  EXPECT_NE(row2, std::string::npos);
  EXPECT_LT(row2, row3);
  EXPECT_LT(row3, row4);
  EXPECT_FALSE(has_leftovers(parent_));
}

// The trajectory behind Figs. 2/3 equals an independent simulate() of the same scene (deterministic,
// written with 17 digits: exact), and the reduced companion equals a reduced-level run.
void check_trajectories(const Built& b) {
  const auto& parent_ = b.parent_;
  const auto& scene_ = b.scene_;
  const SimulationResult again = simulate(scene_.scene, scene_.options);
  std::vector<std::string> header;
  const auto rows = read_csv_rows(parent_ / "out" / "trajectory.csv", &header);
  const Trajectory& tr = again.trajectory;
  ASSERT_EQ(rows.size(), tr.rows());
  ASSERT_EQ(header.size(), std::size_t(1 + 3 + 3 + 1));  // t, Delta_2..4, sigma, r, Psi, integrated
  for (std::size_t row = 0; row < rows.size(); ++row) {
    ASSERT_EQ(rows[row].size(), header.size());
    ASSERT_EQ(rows[row][7], tr.integrated(row) ? 1.0 : 0.0);
    EXPECT_EQ(rows[row][0], tr.time(row));
    if (!tr.integrated(row)) continue;  // a skipped sample: its fields are empty
    const std::size_t k = tr.sample(row);
    for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(rows[row][1 + j], tr.Delta_l[k][j]);
    EXPECT_EQ(rows[row][4], tr.sigma[k]);
    EXPECT_EQ(rows[row][5], tr.r[k]);
    EXPECT_EQ(rows[row][6], tr.Psi[k]);
  }
  Scene reduced = scene_.scene;
  reduced.model = ModelLevel::reduced;
  reduced.L = 2;
  const SimulationResult red = simulate(reduced, scene_.options);
  const auto rrows = read_csv_rows(parent_ / "out" / "reduced_trajectory.csv");
  const Trajectory& rt = red.trajectory;
  ASSERT_EQ(rrows.size(), rt.rows());
  for (std::size_t row = 0; row < rrows.size(); ++row) {
    ASSERT_EQ(rrows[row].size(), 6u);  // t, Delta_2, sigma, r, Psi, integrated
    if (!rt.integrated(row)) continue;
    const std::size_t k = rt.sample(row);
    EXPECT_EQ(rrows[row][2], rt.sigma[k]);
    EXPECT_EQ(rrows[row][3], rt.r[k]);
    EXPECT_EQ(rrows[row][4], rt.Psi[k]);
  }
  // Thresholds behind the sigma_l^c lines.
  const auto th = nlohmann::json::parse(read_file((parent_ / "out" / "thresholds.json").string()));
  const double alpha = scene_.scene.parameters.alpha();
  for (int l = 2; l <= 4; ++l) EXPECT_EQ(th.at("sigma_c").at(std::to_string(l)).get<double>(), sigma_c(l, alpha));
  EXPECT_NEAR(th.at("sigma_star").get<double>(), -4 * std::sqrt(alpha), 1e-14 * std::sqrt(alpha));
}

// The shape files: VTK read back has the mesh's counts, and every point sits at the radius
// rebuilt from an independent run's final state (same amplitudes, evaluated pointwise).
void check_shape_files(const Built& b) {
  const auto& parent_ = b.parent_;
  const auto& scene_ = b.scene_;
  const SimulationResult again = simulate(scene_.scene, scene_.options);
  const InitialState init = initial_state(scene_.scene);
  const auto system = make_system(scene_.scene.parameters, init, again.level.level);
  const ModeAmplitudes f = system->amplitudes(again.t_reached, again.y_final);

  std::istringstream in(read_file((parent_ / "out" / "shape_T.vtk").string()));
  std::string line, word, type;
  for (int k = 0; k < 4; ++k) std::getline(in, line);
  EXPECT_EQ(line, "DATASET POLYDATA");
  std::size_t n = 0, m = 0, size = 0;
  in >> word >> n >> type;
  ASSERT_EQ(word, "POINTS");
  EXPECT_EQ(n, 2u + 11u * 24u);  // poles + (n_theta - 1) rings of n_phi points
  std::vector<std::array<double, 3>> pts(n);
  for (auto& p : pts) in >> p[0] >> p[1] >> p[2];
  in >> word >> m >> size;
  ASSERT_EQ(word, "POLYGONS");
  EXPECT_EQ(m, 2u * 24u * 11u);
  EXPECT_EQ(size, 4 * m);
  for (const auto& p : pts) {
    const double rho = std::hypot(p[0], p[1], p[2]);
    const double theta = std::acos(std::clamp(p[2] / rho, -1.0, 1.0)), phi = std::atan2(p[1], p[0]);
    // Same amplitudes to the last bit; the angles recovered from Cartesian points cost ~1e-15.
    EXPECT_NEAR(rho, shape_radius(f, theta, phi), 1e-12);
  }
  // The grid CSV behind the shape figure holds the same radii.
  const auto rows = read_csv_rows(parent_ / "out" / "shape_T.csv");
  ASSERT_EQ(rows.size(), 13u * 25u);
  for (const auto& r : rows) EXPECT_NEAR(r[4], shape_radius(f, r[2], r[3]), 1e-14);
  // The animation's last frame is the shape at T from a separate integration on the frame grid:
  // the two runs differ by the integrator's tolerance (rtol 1e-8) and the float storage (1e-7).
  const auto anim = nlohmann::json::parse(read_file((parent_ / "out" / "animation.json").string()));
  const auto& last = anim.at("rho").back();
  const auto& th = anim.at("theta");
  const auto& ph = anim.at("phi");
  ASSERT_EQ(last.size(), th.size() * ph.size());
  EXPECT_EQ(anim.at("t").back().get<double>(), scene_.scene.T);
  for (std::size_t i = 0; i < th.size(); ++i)
    for (std::size_t j = 0; j < ph.size(); ++j)
      EXPECT_NEAR(last[i * ph.size() + j].get<double>(), shape_radius(f, th[i].get<double>(), ph[j].get<double>()),
                  1e-6);
}

// The convergence table of report.json: its 2T change equals an independent run at 2T, and the page shows it.
void check_convergence(const Built& b) {
  const fs::path out = b.parent_ / "out";
  const auto c = nlohmann::json::parse(read_file((out / "report.json").string())).at("convergence");
  ASSERT_TRUE(c.at("checked").get<bool>());
  ASSERT_TRUE(b.result_.convergence.run.has_value());
  EXPECT_EQ(c.at("flagged").get<std::size_t>(), b.result_.convergence.run->flagged());
  // The reduced companion: 2T and rtol/100 only, its 2T change that of an independent run of the companion.
  ASSERT_TRUE(b.result_.convergence.reduced.has_value());
  const auto& rc = c.at("reduced_companion");
  ASSERT_EQ(rc.at("runs").size(), 2u);
  Scene companion_twice = reduced_scene(b.scene_.scene);
  companion_twice.T *= 2;
  const SimulationResult companion = simulate(reduced_scene(b.scene_.scene), b.scene_.options),
                         companion_2T = simulate(companion_twice, b.scene_.options);
  std::size_t compared = 0;
  for (const auto& row : rc.at("rows"))
    if (row.at("quantity") == "r_final") {
      EXPECT_EQ(row.at("changes").at("2T").get<double>(), companion_2T.r_final - companion.r_final);
      ++compared;
    }
  EXPECT_EQ(compared, 1u);
  Scene twice = b.scene_.scene;
  twice.T *= 2;
  const SimulationResult base = simulate(b.scene_.scene, b.scene_.options), r = simulate(twice, b.scene_.options);
  bool found = false;
  for (const auto& row : c.at("rows"))
    if (row.at("quantity") == "sigma_final") {
      found = true;
      EXPECT_EQ(row.at("changes").at("2T").get<double>(), r.sigma_final - base.sigma_final);
    }
  EXPECT_TRUE(found);
  const std::string html = read_file((out / "index.html").string());
  EXPECT_NE(html.find("Convergence runs"), std::string::npos);
  EXPECT_NE(html.find("change rtol/100"), std::string::npos);
}

TEST(ReportEndToEnd, SmallInPlaneSceneBuildsAndItsDataReproduceTheFigures) {
  Built b;
  b.parent_ = test::fresh_dir("report_test", "e2e");
  const Cleanup cleanup{b.parent_};
  b.scene_ = small_scene(1.5707963267948966);
  b.result_ = build_report(b.scene_, small_options(b.parent_ / "out"));
  EXPECT_EQ(b.result_.run.status, IntegrationStatus::success);
  check_figures(b);
  check_trajectories(b);
  check_shape_files(b);
  check_convergence(b);
}

// The animation window: period of a sampled oscillation, none for a steady or monotonic signal.
TEST(OscillationPeriod, FindsThePeriodOfASampledSignal) {
  std::vector<double> t, swing, steady, ramp;
  for (int k = 0; k <= 2000; ++k) {
    t.push_back(0.05 * k);
    swing.push_back(0.9 + 0.05 * std::sin(2 * std::numbers::pi * t.back() / 6.3) + 0.001 * std::sin(7.0 * t.back()));
    steady.push_back(0.5 + 0.3 * std::exp(-t.back()));
    ramp.push_back(-t.back());
  }
  // Maxima located to one sample (0.05), averaged over ~8 periods: error < 0.05 / 7.
  EXPECT_NEAR(detail::oscillation_period(t, swing), 6.3, 0.01);
  EXPECT_EQ(detail::oscillation_period(t, steady), 0);
  EXPECT_EQ(detail::oscillation_period(t, ramp), 0);
  EXPECT_EQ(detail::oscillation_period({0, 1}, {0, 1}), 0);
}

TEST(ReportFailures, MissingPythonFailsCleanly) {
  const fs::path parent = test::fresh_dir("report_test", "nopython");
  const Cleanup cleanup{parent};
  ReportOptions o = small_options(parent / "out");
  o.python = (parent / "no-such-python3").string();
  EXPECT_THROW(build_report(small_scene(0.001), o), ReportError);
  o.python = "/bin/false";  // runs, but cannot import matplotlib
  EXPECT_THROW(build_report(small_scene(0.001), o), ReportError);
  EXPECT_FALSE(fs::exists(parent / "out"));
  EXPECT_FALSE(has_leftovers(parent));
}

TEST(ReportFailures, FailingPlotScriptLeavesNothing) {
  const fs::path parent = test::fresh_dir("report_test", "badscript");
  const Cleanup cleanup{parent};
  const fs::path scripts = parent / "scripts";
  fs::create_directories(scripts);
  // Writes a file into the report folder, then fails: the half-written folder must vanish.
  write_file_atomic((scripts / "rbcstab_report.py").string(),
                    "import sys, os\nopen(os.path.join(sys.argv[2], 'half.png'), 'w').write('x')\nsys.exit(7)\n");
  ReportOptions o = small_options(parent / "out");
  o.script_dir = scripts.string();
  try {
    build_report(small_scene(0.001), o);
    ADD_FAILURE() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("exit 7"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(parent / "out"));
  EXPECT_FALSE(has_leftovers(parent));
}

TEST(ReportFailures, ExistingOutputNeedsOverwriteAndBadOptionsAreNamed) {
  const fs::path parent = test::fresh_dir("report_test", "exists");
  const Cleanup cleanup{parent};
  fs::create_directories(parent / "out");
  ReportOptions o = small_options(parent / "out");
  try {
    build_report(small_scene(0.001), o);
    ADD_FAILURE() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "output");
  }
  o.frames = 1;
  try {
    build_report(small_scene(0.001), o);
    ADD_FAILURE() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "frames");
  }
}

// The hook figures (phase diagram, Fig. 6e, bifurcation, physical map) drawn from the script's synthetic data.
TEST(ReportHooks, SelftestDrawsHookFiguresOfTheDeclaredSize) {
  const fs::path dir = test::fresh_dir("report_test", "hooks");
  const Cleanup cleanup{dir};
  const std::string script = find_script_dir("") + "/rbcstab_report.py";
  const std::string cmd =
      "/usr/bin/python3 '" + script + "' selftest '" + dir.string() + "' > '" + (dir / "log.txt").string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << read_file((dir / "log.txt").string());
  const std::map<std::string, std::pair<int, int>> expected{
      {"fig_phase_diagram.png", {900, 750}},
      {"fig_delta2_theory.png", {750, 750}},
      {"fig_bifurcation.png", {900, 675}},
      {"fig_bifurcation_continue.png", {900, 675}},  // from the layout of `rbcstab continue --json`
      {"fig_physical_map.png", {900, 700}}};
  for (const auto& [file, size] : expected) EXPECT_EQ(png_size(dir / file), size) << file;
}

// amplitudes_at: at t = 0 the scene's initial amplitudes (exact: no step taken); at T the state of
// an independent simulate() (different output grids: agreement to the integrator's tolerance).
TEST(AmplitudesAt, StartsAtTheSceneAndEndsAtTheSimulation) {
  const SceneFile sf = small_scene(0.4);
  const AmplitudeSeries a = amplitudes_at(sf, {0.0, 2.5, sf.scene.T});
  ASSERT_EQ(a.status, IntegrationStatus::success);
  ASSERT_EQ(a.t.size(), 3u);
  const InitialState init = initial_state(sf.scene);
  for (int l = 2; l <= sf.scene.L; ++l)
    for (int m = -l; m <= l; ++m) EXPECT_NEAR(std::abs(a.f[0].at(l, m) - init.f.at(l, m)), 0, 1e-15) << l << ' ' << m;
  const SimulationResult r = simulate(sf.scene, sf.options);
  const auto system = make_system(sf.scene.parameters, init, r.level.level);
  const ModeAmplitudes fT = system->amplitudes(r.t_reached, r.y_final);
  for (int l = 2; l <= sf.scene.L; ++l)
    for (int m = -l; m <= l; ++m) EXPECT_NEAR(std::abs(a.f[2].at(l, m) - fT.at(l, m)), 0, 1e-6) << l << ' ' << m;
  EXPECT_THROW(amplitudes_at(sf, {1.0, 0.5}), InvalidArgument);
  EXPECT_THROW(amplitudes_at(sf, {sf.scene.T + 1}), InvalidArgument);
}

// The paper-figure scenes this module owns load, validate, and hold the panels' parameters.
TEST(PaperScenes, Fig2Fig3Fig6ScenesLoadWithThePapersParameters) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(RBCSTAB_SCENES_DIR)) {
    const std::string name = e.path().filename().string();
    if (!(name.starts_with("fig2_") || name.starts_with("fig3_") || name.starts_with("fig6_"))) continue;
    const SceneFile sf = load_scene(e.path().string());
    EXPECT_NO_THROW(sf.scene.validate()) << name;
    const Parameters& p = sf.scene.parameters;
    EXPECT_EQ(p.C, 0.04) << name;  // every Fig. 2, 3, 6 panel: C = 0.04, Delta0 = 0.01 (captions)
    EXPECT_EQ(p.Delta0, 0.01) << name;
    const bool in_plane = name.find("_ip") != std::string::npos;
    EXPECT_EQ(sf.scene.beta, in_plane ? 1.5707963267948966 : 0.001) << name;
    EXPECT_EQ(sf.scene.name + ".toml", name);
    if (!name.starts_with("fig2_")) {  // Figs. 3, 6: L = 10, B = 2, Delta = 1, T = 500
      EXPECT_EQ(sf.scene.L, 10) << name;
      EXPECT_EQ(p.B, 2.0) << name;
      EXPECT_EQ(p.Delta, 1.0) << name;
      EXPECT_EQ(sf.scene.T, 500.0) << name;
    } else {
      EXPECT_EQ(sf.scene.model, ModelLevel::reduced) << name;
      EXPECT_EQ(p.lambda, 5.0) << name;
    }
    ++count;
  }
  EXPECT_EQ(count, 4 + 2 + 8);
}

#ifdef RBCSTAB_CLI
// The CLI's exit codes: 3 when python/matplotlib is missing (nothing written), 2 for an existing folder.
TEST(ReportCli, ExitCodes) {
  const fs::path parent = test::fresh_dir("report_test", "cli");
  const Cleanup cleanup{parent};
  const std::string base = std::string(RBCSTAB_CLI) + " report --T 2 --L 3 --frames 2 --shape-resolution 6 ";
  const std::string quiet = " > /dev/null 2>&1";
  int rc =
      std::system((base + "--python /nonexistent/python3 --output '" + (parent / "a").string() + "'" + quiet).c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 3);
  EXPECT_FALSE(fs::exists(parent / "a"));
  // --no-convergence is a flag of its own (an unknown one would exit 2 before python is looked for).
  rc = std::system(
      (base + "--no-convergence --python /nonexistent/python3 --output '" + (parent / "a").string() + "'" + quiet)
          .c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 3);
  fs::create_directories(parent / "b");
  rc = std::system((base + "--output '" + (parent / "b").string() + "'" + quiet).c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  rc = std::system((base + "--frames 1 --output '" + (parent / "c").string() + "'" + quiet).c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  EXPECT_FALSE(has_leftovers(parent));
}

// rbcstab shape: the t = 0 VTK holds the scene's initial shape (closed form through shape_radius).
TEST(ShapeCli, WritesTheInitialShapeAtTimeZero) {
  const fs::path parent = test::fresh_dir("report_test", "shapecli");
  const Cleanup cleanup{parent};
  const std::string stem = (parent / "cell").string();
  const int rc = std::system((std::string(RBCSTAB_CLI) +
                              " shape --T 2 --L 3 --beta 0.7 --at 0 --at 2 --resolution 8 "
                              "--format vtk --format ply --output '" +
                              stem + "' > /dev/null 2>&1")
                                 .c_str());
  ASSERT_EQ(WEXITSTATUS(rc), 0);
  EXPECT_TRUE(fs::exists(stem + "_t2.vtk"));
  EXPECT_TRUE(fs::exists(stem + "_t2.ply"));
  Scene s;
  s.T = 2;
  s.L = 3;
  s.beta = 0.7;
  const ModeAmplitudes f0 = initial_state(s).f;
  std::istringstream in(read_file(stem + "_t0.vtk"));
  std::string line, word, type;
  for (int k = 0; k < 4; ++k) std::getline(in, line);
  std::size_t n = 0;
  in >> word >> n >> type;
  ASSERT_EQ(n, 2u + 7u * 16u);
  for (std::size_t k = 0; k < n; ++k) {
    double x = 0, y = 0, z = 0;
    in >> x >> y >> z;
    const double rho = std::hypot(x, y, z);
    EXPECT_NEAR(rho, shape_radius(f0, std::acos(std::clamp(z / rho, -1.0, 1.0)), std::atan2(y, x)), 1e-12);
  }
}
#endif

}  // namespace
}  // namespace rbcstab
