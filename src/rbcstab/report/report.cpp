#include "rbcstab/report/report.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <random>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/simulation_io.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/detail/parameter_labels.hpp"
#include "rbcstab/report/detail/provenance.hpp"
#include "rbcstab/report/detail/report_pages.hpp"
#include "rbcstab/report/detail/staging.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

#ifndef RBCSTAB_REPORT_SOURCE_PYTHON_DIR
#define RBCSTAB_REPORT_SOURCE_PYTHON_DIR ""
#endif

extern char** environ;

namespace rbcstab {

namespace fs = std::filesystem;

namespace {

bool has_script(const fs::path& dir) {
  std::error_code ec;
  return !dir.empty() && fs::is_regular_file(dir / kReportScript, ec);
}

// The figures' title: the scene's name, then its parameters in the parameter table's symbols (mathtext).
std::string figure_title(const Scene& s) {
  std::string t = s.name + ":";
  for (SceneParameter q : {SceneParameter::lambda, SceneParameter::Delta, SceneParameter::Delta0, SceneParameter::B,
                           SceneParameter::C, SceneParameter::beta})
    t += (q == SceneParameter::lambda ? " " : ", ") + detail::tex_value(q, get_parameter(s, q));
  return t;
}

// Every parameter's TeX symbol by name, for the labels the drawing script writes.
nlohmann::json parameter_symbols() {
  nlohmann::json j = nlohmann::json::object();
  for (const ParameterRow& row : parameter_table()) j[row.name] = row.symbol;
  return j;
}

std::string grid_csv(const ShapeGrid& g) {
  std::ostringstream ss;
  ss << "i,j,theta,phi,rho,x,y,z\n";
  for (int i = 0; i <= g.n_theta; ++i)
    for (int j = 0; j <= g.n_phi; ++j) {
      const double th = g.theta[std::size_t(i)], ph = g.phi[std::size_t(j)], r = g.at(i, j);
      ss << i << ',' << j << ',' << csv_number(th) << ',' << csv_number(ph) << ',' << csv_number(r) << ','
         << csv_number(r * std::sin(th) * std::cos(ph)) << ',' << csv_number(r * std::sin(th) * std::sin(ph)) << ','
         << csv_number(r * std::cos(th)) << '\n';
    }
  return ss.str();
}

}  // namespace

int run_process(const std::vector<std::string>& args, const std::string& log_path) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const char* log = log_path.empty() ? "/dev/null" : log_path.c_str();
  posix_spawn_file_actions_addopen(&actions, 1, log, O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0].c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

namespace detail {
std::string log_tail(const std::string& path, std::size_t n) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  return s.size() > n ? "..." + s.substr(s.size() - n) : s;
}

// Built by append: GCC 12 warns falsely on chained literal + string.
// ".<name><tag><pid>-<random>": the pid lets a later run remove the folders of a killed one.
std::string hidden_sibling_name(const fs::path& target, const char* tag) {
  std::random_device rd;
  std::ostringstream suffix;
  suffix << std::hex << rd() << rd();
  return staging_prefix(target.filename().string(), tag).append(suffix.str());
}

fs::path output_target(const std::string& output, bool overwrite) {
  const fs::path out = fs::absolute(output).lexically_normal();
  const fs::path target = out.has_filename() ? out : out.parent_path();
  std::error_code ec;
  if (fs::exists(target, ec) && !overwrite)
    throw InvalidArgument("output", "output: " + target.string() + " exists; pass --overwrite to replace it");
  if (!fs::is_directory(target.parent_path(), ec))
    throw ReportError("output: parent folder " + target.parent_path().string() + " does not exist");
  return target;
}

void publish_folder(const fs::path& tmp, const fs::path& target) {
  std::error_code ec;
  if (fs::exists(target, ec)) {  // --overwrite: swap, then remove the old folder
    const fs::path old = target.parent_path() / hidden_sibling_name(target, ".old-");
    fs::rename(target, old);
    fs::rename(tmp, target);
    fs::remove_all(old, ec);
  } else {
    fs::rename(tmp, target);
  }
}

double oscillation_period(const std::vector<double>& t, const std::vector<double>& x) {
  const std::size_t n = t.size();
  if (n < 5 || x.size() != n) return 0;
  double lo = x[n / 2], hi = lo;
  for (std::size_t k = n / 2; k < n; ++k) {
    lo = std::min(lo, x[k]);
    hi = std::max(hi, x[k]);
  }
  if (!(hi - lo > 1e-6 * std::max(1.0, std::abs(hi)))) return 0;  // flat: steady state
  // Interior maxima in the second half that reach the upper third of the swing (no ripples).
  std::vector<double> peaks;
  for (std::size_t k = std::max<std::size_t>(1, n / 2); k + 1 < n; ++k)
    if (x[k] > x[k - 1] && x[k] >= x[k + 1] && x[k] > lo + (hi - lo) * 2 / 3) peaks.push_back(t[k]);
  if (peaks.size() < 3) return 0;
  return (peaks.back() - peaks.front()) / double(peaks.size() - 1);
}
}  // namespace detail

namespace {
struct Frames {
  std::vector<double> t;
  std::vector<ShapeGrid> grids;
  IntegrationStatus status = IntegrationStatus::success;
};

// Shapes along the run on the frame grid.
Frames shape_frames(const SceneFile& sf, const ReportOptions& o, double window) {
  const double t0 = std::max(0.0, sf.scene.T - window);
  std::vector<double> grid;
  for (int k = 0; k < o.frames; ++k) grid.push_back(t0 + (sf.scene.T - t0) * k / (o.frames - 1));
  grid.back() = sf.scene.T;
  const AmplitudeSeries series = amplitudes_at(sf, grid);
  Frames f;
  f.t = series.t;
  for (const auto& a : series.f) f.grids.push_back(shape_on_grid(a, o.frame_shape));
  f.status = series.status;
  return f;
}

std::string animation_json(const Frames& f) {
  nlohmann::json j;
  j["t"] = f.t;
  if (!f.grids.empty()) {
    j["theta"] = f.grids[0].theta;
    j["phi"] = f.grids[0].phi;
  }
  nlohmann::json rho = nlohmann::json::array();
  for (const auto& g : f.grids) {
    std::vector<double> v(g.rho.size());
    // 7 significant digits: far below a pixel, keeps the file small.
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = std::stod(std::to_string(float(g.rho[k])));
    rho.push_back(v);
  }
  j["rho"] = rho;
  j["layout"] = "rho[frame][i * len(phi) + j]";
  return j.dump();
}

nlohmann::json figure(const std::string& kind, const std::string& png, int w, int h, std::vector<std::string> data,
                      const std::string& caption) {
  return {{"kind", kind}, {"png", png}, {"size_px", {w, h}}, {"data", data}, {"caption", caption}};
}

// Copies a hook's data file into the report (and an overlay JSON beside a phase diagram).
std::string import_hook(const std::string& src, const fs::path& dir, const std::string& name) {
  const std::string text = read_file(src);  // InvalidArgument("file") if unreadable
  write_file_atomic((dir / name).string(), text);
  return name;
}

// A hook CSV the plotting script can draw: a header (the first line not starting with '#') holding, for each
// entry of `columns`, one of its names, at least `min_columns` columns, and a data row. Checked before anything
// runs, so a wrong file is bad input named by its flag rather than a failure inside the script.
void require_hook_csv(const std::string& path, const std::string& name,
                      const std::vector<std::vector<std::string>>& columns, std::size_t min_columns) {
  std::istringstream in(read_file(path, name));
  std::string line, header;
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (header.empty())
      header = line;
    else
      ++rows;
  }
  std::vector<std::string> names;
  std::istringstream h(header);
  for (std::string c; std::getline(h, c, ',');) names.push_back(c);
  std::string wanted;
  bool ok = names.size() >= min_columns;
  for (const auto& alternatives : columns) {
    std::string any;
    bool found = false;
    for (const std::string& c : alternatives) {
      any += (any.empty() ? "" : " or ") + c;
      found = found || std::find(names.begin(), names.end(), c) != names.end();
    }
    wanted += (wanted.empty() ? "" : ", ") + any;
    ok = ok && found;
  }
  const std::string shown = header.size() > 80 ? header.substr(0, 80) + "..." : header;
  const std::string what = name + " = '" + path + "' ";
  if (!ok)
    throw InvalidArgument(name, what + "is not a CSV of at least " + std::to_string(min_columns) + " columns with " +
                                    wanted + ": its header is '" + shown + "'");
  if (rows == 0) throw InvalidArgument(name, what + "has a header but no data rows");
}

// The bifurcation hook's diagram, decided before anything runs (bad input names the report's flags).
std::optional<PlotSpec> bifurcation_plot(const ReportOptions& o) {
  if (o.bifurcation.empty()) return std::nullopt;
  PlotOptions po;
  po.x = o.bifurcation_x;
  po.y = o.bifurcation_y;
  po.title = o.figure_title;
  try {
    return plot_spec({read_plot_input(o.bifurcation)}, po);
  } catch (const InvalidArgument& e) {
    if (e.parameter() != "x" && e.parameter() != "y") throw;
    throw InvalidArgument("bifurcation_" + e.parameter(), std::string("bifurcation_") + e.what());
  }
}

// The figures of the hooks (phase diagram, Fig. 6e, bifurcation), their data copied into `dir`.
void add_hook_figures(const ReportOptions& o, const std::optional<PlotSpec>& bifurcation, const fs::path& dir,
                      std::vector<std::string>& files, nlohmann::json& figs) {
  std::error_code ec;
  auto titled = [&](nlohmann::json f) {
    if (!o.figure_title.empty()) f["title"] = o.figure_title;
    return f;
  };
  if (!o.phase_diagram.empty()) {
    std::vector<std::string> data{import_hook(o.phase_diagram, dir, "phase_diagram.csv")};
    const fs::path overlay = fs::path(o.phase_diagram).replace_extension(".json");
    if (fs::is_regular_file(overlay, ec))
      data.push_back(import_hook(overlay.string(), dir, "phase_diagram_overlay.json"));
    files.insert(files.end(), data.begin(), data.end());
    figs.push_back(titled(figure("phase_diagram", "fig_phase_diagram.png", 900, 750, data,
                                 "Phase diagram coloured by $l_Delta$ with the traced boundaries and analytic lines")));
  }
  if (!o.delta2_comparison.empty()) {
    const std::string d = import_hook(o.delta2_comparison, dir, "delta2_comparison.csv");
    files.push_back(d);
    figs.push_back(titled(figure("delta2_comparison", "fig_delta2_theory.png", 750, 750, {d},
                                 "Fig. 6e-type: post-instability $~Delta_2$ from theory against the simulated mean")));
  }
  if (bifurcation) {
    const std::string d = import_hook(o.bifurcation, dir, "bifurcation.json");
    write_file_atomic((dir / "bifurcation_plot.json").string(), to_json(*bifurcation).dump(1) + "\n");
    files.insert(files.end(), {d, "bifurcation_plot.json"});
    figs.push_back(titled(figure("bifurcation", "fig_bifurcation.png", 900, 675, {"bifurcation_plot.json", d},
                                 "Bifurcation diagram: " + bifurcation->y.name + " against " + bifurcation->x.name +
                                     "; stable solid, unstable dashed, uncertain dotted; special points marked "
                                     "with their type and label (bifurcation_plot.json: what was drawn)")));
  }

  if (!o.physical_map.empty()) {
    const std::string d = import_hook(o.physical_map, dir, "physical_map.json");
    files.push_back(d);
    figs.push_back(titled(figure("physical_map", "fig_physical_map.png", 900, 700, {d},
                                 "Physical phase diagram: the regime boundaries over outer viscosity and shear rate, "
                                 "their bands, and the published observations (physical_map.json: what was drawn)")));
  }
  for (const std::string& a : o.attachments) files.push_back(import_hook(a, dir, fs::path(a).filename().string()));
}

// Draws the figures listed in the manifest (report.json, already in tmp), writes the pages and renames
// tmp into place (swapping out an existing folder under --overwrite).
void draw_and_publish(const ReportOptions& o, const nlohmann::json& manifest, const fs::path& tmp,
                      const fs::path& target, std::vector<std::string>& files) {
  std::error_code ec;
  const std::string log = (tmp / "plot.log").string();
  if (o.on_step) o.on_step("drawing the figures with " + o.python);
  const int rc =
      run_process({o.python, (fs::path(o.script_dir) / kReportScript).string(), "report", tmp.string()}, log);
  if (rc != 0)
    throw ReportError("the plotting script failed (exit " + std::to_string(rc) + "): " + detail::log_tail(log, 1500));
  files.push_back("plot.log");
  const nlohmann::json drawn = nlohmann::json::parse(read_file((tmp / "figures.json").string()));
  for (const auto& f : drawn) {
    files.push_back(f.at("file").get<std::string>());
    if (f.contains("svg")) files.push_back(f.at("svg").get<std::string>());
  }
  files.push_back("figures.json");
  for (const auto& [name, text] : {std::pair{"README.md", detail::report_markdown(manifest, drawn)},
                                   std::pair{"index.html", detail::report_html(manifest, drawn)}}) {
    write_file_atomic((tmp / name).string(), text);
    files.push_back(name);
  }
  detail::publish_folder(tmp, target);
}

// A figure-panel report: the scene as given, the hooks' data and figures, the attachments.
ReportResult build_panel_folder(const SceneFile& sf, const ReportOptions& o, const std::optional<PlotSpec>& bifurcation,
                                const fs::path& target, std::chrono::steady_clock::time_point start) {
  if (o.phase_diagram.empty() && o.delta2_comparison.empty() && o.bifurcation.empty() && o.physical_map.empty())
    throw InvalidArgument("run_scene",
                          "run_scene = false (a figure panel) needs a phase diagram, a Fig. 6e table, "
                          "a bifurcation or a physical map to draw");
  ReportResult res;
  detail::in_staging_folder(target, [&](const fs::path& tmp) {
    const std::string scene_text = o.scene_toml.empty() ? to_toml(sf) : o.scene_toml;
    write_file_atomic((tmp / "scene.toml").string(), scene_text);
    res.files.push_back("scene.toml");
    nlohmann::json figs = nlohmann::json::array();
    add_hook_figures(o, bifurcation, tmp, res.files, figs);
    nlohmann::json manifest;
    manifest["scene"] = to_json(sf.scene);
    put_truncation(manifest, sf);
    manifest["title"] = figure_title(sf.scene);
    manifest["symbols"] = parameter_symbols();
    manifest["parameters"] = to_json(sf.scene.parameters);
    nlohmann::json panel;
    panel["summary"] = o.panel_summary;
    panel["facts"] = nlohmann::json::array();
    for (const auto& [k, v] : o.panel_facts) panel["facts"].push_back({k, v});
    panel["tables"] = nlohmann::json::array();
    for (const ReportTable& t : o.panel_tables)
      panel["tables"].push_back({{"title", t.title}, {"header", t.header}, {"rows", t.rows}});
    manifest["panel"] = panel;
    manifest["provenance"] = detail::provenance_json(detail::make_provenance({scene_text}, "scene.toml"));
    manifest["warnings"] = nlohmann::json::array();
    manifest["figures"] = figs;
    write_file_atomic((tmp / "report.json").string(), manifest.dump(2) + "\n");
    res.files.push_back("report.json");
    draw_and_publish(o, manifest, tmp, target, res.files);
  });
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}
}  // namespace

std::string executable_path() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : p.string();
}

AmplitudeSeries amplitudes_at(const SceneFile& sf, const std::vector<double>& times) {
  const Scene& s = sf.scene;
  s.validate();
  sf.options.validate();
  for (std::size_t k = 0; k < times.size(); ++k)
    require(std::isfinite(times[k]) && times[k] >= 0 && times[k] <= s.T && (k == 0 || times[k] > times[k - 1]), "t",
            times[k], "increasing times in [0, T]");
  const InitialState init = initial_state(s);
  AmplitudeSeries out;
  out.level = choose_level(s, init);
  const auto system = make_system(s.parameters, init, out.level.level);
  const std::vector<double> y0 = system->initial_state();
  const IntegrationResult ir =
      integrate(*system, y0, 0.0, times, sf.options.integrator, [&](double t, std::span<const double> y) {
        out.t.push_back(t);
        out.f.push_back(system->amplitudes(t, y));
      });
  out.status = ir.status;
  out.reason = ir.reason;
  return out;
}

void ReportOptions::validate() const {
  if (output.empty()) throw InvalidArgument("output", "output: a folder path is required");
  shape.validate();
  frame_shape.validate();
  convergence.validate();
  require(frames >= 2 && frames <= 2000, "frames", frames, "an integer in [2, 2000]");
  require(std::isfinite(frame_window) && frame_window >= 0, "frame_window", frame_window, "finite and >= 0 (0: auto)");
  if (python.empty()) throw InvalidArgument("python", "python: an interpreter path is required");
  for (const auto& [name, axis] :
       {std::pair{"bifurcation_x", &bifurcation_x}, std::pair{"bifurcation_y", &bifurcation_y}})
    if (!axis->empty() && bifurcation.empty())
      throw InvalidArgument(name, std::string(name) + " = '" + *axis + "' needs a bifurcation file to draw");
}

std::string find_script_dir(const std::string& executable_path) {
  if (const char* env = std::getenv("RBCSTAB_DATA_DIR"); env && *env) {
    for (const fs::path& p : {fs::path(env) / "python", fs::path(env)})
      if (has_script(p)) return p.string();
  }
  if (!executable_path.empty()) {
    const fs::path exe_dir = fs::path(executable_path).parent_path();
    if (has_script(exe_dir / ".." / "share" / "rbcstab" / "python"))
      return fs::weakly_canonical(exe_dir / ".." / "share" / "rbcstab" / "python").string();
  }
  if (has_script(RBCSTAB_REPORT_SOURCE_PYTHON_DIR)) return RBCSTAB_REPORT_SOURCE_PYTHON_DIR;
  return "";
}

void check_python(const std::string& python) {
  std::error_code ec;
  if (!fs::exists(python, ec))
    throw ReportError("python: " + python +
                      " not found; the report draws its figures with python3 and matplotlib "
                      "(Debian: apt-get install python3-matplotlib) or pass --python PATH");
  const int rc = run_process({python, "-c", "import matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot"}, "");
  if (rc != 0)
    throw ReportError("python: " + python + " cannot import matplotlib (exit " + std::to_string(rc) +
                      "); install python3-matplotlib (Debian) or pass --python PATH to an interpreter that has it");
}

ReportResult build_report(const SceneFile& sf, const ReportOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  options.validate();
  sf.scene.validate();
  sf.options.validate();
  ReportOptions o = options;
  if (o.script_dir.empty()) o.script_dir = find_script_dir("");
  if (!has_script(o.script_dir))
    throw ReportError("script_dir: " + std::string(kReportScript) + " not found (looked in '" + o.script_dir +
                      "', $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python); set RBCSTAB_DATA_DIR");
  check_python(o.python);

  const fs::path target = detail::output_target(o.output, o.overwrite);
  std::error_code ec;
  for (const std::string* hook : {&o.phase_diagram, &o.delta2_comparison, &o.bifurcation, &o.physical_map})
    if (!hook->empty() && !fs::is_regular_file(*hook, ec))
      throw InvalidArgument("file", "data file '" + *hook + "' not found");
  // The script's readers (rbcstab_report.py: plot_phase_diagram, plot_delta2_comparison) take these columns.
  if (!o.phase_diagram.empty()) require_hook_csv(o.phase_diagram, "phase_diagram", {{"l_Delta"}}, 3);
  if (!o.delta2_comparison.empty())
    require_hook_csv(o.delta2_comparison, "delta2_comparison",
                     {{"Delta2_theory", "Delta2_tilde"}, {"Delta2_simulation", "Delta2_bar"}}, 2);
  for (const std::string& a : o.attachments)
    if (!fs::is_regular_file(a, ec)) throw InvalidArgument("file", "data file '" + a + "' not found");
  const std::optional<PlotSpec> bifurcation = bifurcation_plot(o);
  if (!o.run_scene) return build_panel_folder(sf, o, bifurcation, target, start);

  ReportResult res;
  SimulationOptions run_options = sf.options;
  run_options.trajectory_text = true;  // trajectory.csv: counted by simulate's memory bound
  if (o.on_step) o.on_step("running the scene to T = " + format_value(sf.scene.T));
  res.run = simulate(sf.scene, run_options);
  res.warnings = res.run.warnings;
  // The companion adds nothing when the scene itself runs at the reduced level.
  if (o.reduced_companion && res.run.level.level != ModelLevel::reduced) {
    if (o.on_step) o.on_step("running the reduced companion");
    res.reduced = simulate(reduced_scene(sf.scene), run_options);
    res.has_reduced = true;
  }
  if (o.convergence.enabled) {
    if (o.on_step) o.on_step("checking convergence: the scene again with L + 2, 2T, delta/10, rtol/100");
    const Scene companion = reduced_scene(sf.scene);
    res.convergence = report_convergence(sf.scene, sf.options, res.run, res.has_reduced ? &companion : nullptr,
                                         res.has_reduced ? &res.reduced : nullptr, o.convergence);
    if (const std::size_t n = res.convergence.flagged())
      res.warnings.push_back(std::to_string(n) +
                             " reported number(s) moved by more than their tolerance under a "
                             "refinement (see the Convergence table)");
  }
  // Animate one period of r(t) at the end when the run oscillates (swinging, tumbling: the GIF then
  // loops seamlessly and the strip shows one cycle), else the whole run.
  double window = o.frame_window;
  if (window == 0) {
    const double period = detail::oscillation_period(res.run.trajectory.t, res.run.trajectory.r);
    window = period > 0 ? std::min(sf.scene.T, period) : sf.scene.T;
  }
  // A physical scene: the shear rates at which the cell first turns unstable, per orientation (as summary).
  if (sf.scene.physical) {
    if (o.on_step) o.on_step("searching the shear-rate thresholds");
    res.shear_rate_thresholds = shear_rate_thresholds(sf.scene, o.shear_rate_search);
  }
  if (o.on_step) o.on_step("computing " + std::to_string(o.frames) + " animation frames");
  const Frames frames = shape_frames(sf, o, window);
  res.shape = shape_on_grid(final_amplitudes(sf.scene, res.run), o.shape);
  if (res.shape.rho_min <= 0)
    res.warnings.push_back("the shape is not star-shaped (min rho = " + format_value(res.shape.rho_min) +
                           "): Delta is beyond the quasi-spherical expansion; the mesh folds over itself");

  // Everything is written into a hidden sibling folder, renamed into place at the end.
  detail::in_staging_folder(target, [&](const fs::path& tmp) {
    auto put = [&](const std::string& name, const std::string& text) {
      write_file_atomic((tmp / name).string(), text);
      res.files.push_back(name);
    };
    const Parameters& p = sf.scene.parameters;
    const double alpha = p.alpha();
    nlohmann::json thresholds;
    thresholds["alpha"] = number_or_null(alpha);
    thresholds["sigma_star"] = number_or_null(-4 * std::sqrt(alpha));  // Pi = 2 sqrt(alpha) (Eq. inst)
    thresholds["l_star"] = number_or_null((-1 + std::sqrt(1 + 8 * std::sqrt(alpha))) / 2);
    nlohmann::json sc;
    for (int l = 2; l <= sf.scene.L; ++l) sc[std::to_string(l)] = number_or_null(sigma_c(l, alpha));
    thresholds["sigma_c"] = sc;
    thresholds["note"] = "mode l grows iff sigma < sigma_c[l] = -(Pi + 4 alpha/Pi), Pi = l(l+1)";
    explain_nulls(thresholds, nonfinite_reason(p));

    put("scene.toml", to_toml(sf));
    put("trajectory.csv", trajectory_csv(res.run));
    if (res.has_reduced) put("reduced_trajectory.csv", trajectory_csv(res.reduced));
    put("thresholds.json", thresholds.dump(2) + "\n");
    put("shape_T.csv", grid_csv(res.shape));
    const SurfaceMesh mesh = surface_mesh(res.shape);
    const std::string title = "rbcstab shape of scene " + sf.scene.name + " at t = " + format_value(res.run.t_reached);
    put("shape_T.vtk", to_vtk_legacy(mesh, title));
    put("shape_T.vtp", to_vtk_xml(mesh));
    put("shape_T.ply", to_ply(mesh, title));
    put("animation.json", animation_json(frames));

    const bool in_plane = std::abs(std::cos(sf.scene.beta)) < 0.5;
    // Times stay in model units; a physical scene's captions say what that unit is in seconds.
    const std::string t_unit =
        sf.scene.physical
            ? " ($t$ in units of $1/gamma$ = " + format_value(cell_numbers(*sf.scene.physical).time_unit) + " s)"
            : "";
    nlohmann::json figs = nlohmann::json::array();
    figs.push_back(figure(
        "reduced_dynamics", "fig_reduced_r_Psi.png", 1200, 450,
        res.has_reduced ? std::vector<std::string>{"reduced_trajectory.csv", "trajectory.csv"}
                        : std::vector<std::string>{"trajectory.csv"},
        std::string(res.has_reduced ? "Fig. 2-type: ellipsoidal amplitude $r(t)$ and angle $Psi(t)$, reduced system "
                                      "($l = 2$ only, perturbations dropped) and the $l = 2$ block of this run"
                                    : "Fig. 2-type: ellipsoidal amplitude $r(t)$ and angle $Psi(t)$ of this run "
                                      "(reduced level)") +
            t_unit));
    figs.push_back(figure("excess_areas", "fig_excess_areas.png", 900, 600, {"trajectory.csv"},
                          "Fig. 3b/c-type: excess area per mode $Delta_l(t)$, $l$ = 2..$L$ (log scale)" + t_unit));
    figs.push_back(figure("tension", "fig_tension.png", 900, 600,
                          res.has_reduced
                              ? std::vector<std::string>{"trajectory.csv", "thresholds.json", "reduced_trajectory.csv"}
                              : std::vector<std::string>{"trajectory.csv", "thresholds.json"},
                          "Fig. 3d/e-type: membrane tension $sigma(t)$, the reduced system's $sigma_R(t)$, and the "
                          "critical tensions $sigma_l^c$ of the modes that can grow" +
                              t_unit));
    nlohmann::json shape_fig =
        figure("shape", "fig_shape_T.png", 750, 750, {"shape_T.csv"},
               std::string("Fig. 6-inset-type: the shape at $t$ = ") + format_value(res.run.t_reached) +
                   ", coloured by the distance from the origin $rho$ (" +
                   (in_plane ? "in-plane start" : "out-of-plane start") + ")");
    shape_fig["t"] = res.run.t_reached;
    figs.push_back(shape_fig);
    nlohmann::json anim = figure(
        "animation", "fig_animation_strip.png", 1500, 375, {"animation.json"},
        "Shape over $t$ in [" + format_value(sf.scene.T - window) + ", " + format_value(sf.scene.T) +
            "] (frames of animation.gif" + (window < sf.scene.T ? ": one period of r(t), so the GIF loops" : "") +
            "), seen from above the shear plane (flow along $x$, gradient along $y$)" + t_unit);
    anim["gif"] = "animation.gif";
    anim["gif_size_px"] = {400, 400};
    figs.push_back(anim);
    add_hook_figures(o, bifurcation, tmp, res.files, figs);
    nlohmann::json manifest;
    manifest["scene"] = to_json(sf.scene);
    put_truncation(manifest, sf);
    manifest["title"] = figure_title(sf.scene);
    manifest["symbols"] = parameter_symbols();
    manifest["parameters"] = to_json(p);
    manifest["provenance"] = detail::provenance_json(detail::make_provenance({to_toml(sf)}, "scene.toml"));
    manifest["summary"] = to_json(res.run, p);
    manifest["summary"].erase("trajectory");
    if (res.has_reduced) {
      manifest["reduced_summary"] = to_json(res.reduced, p);
      manifest["reduced_summary"].erase("trajectory");
    }
    manifest["thresholds"] = thresholds;
    manifest["convergence"] = convergence_json(res.convergence, o.convergence);
    put_physical(manifest, sf.scene);
    if (sf.scene.physical) manifest["shear_rate_thresholds"] = to_json(res.shear_rate_thresholds);
    manifest["shape"] = {{"t", res.run.t_reached},       {"rho_min", res.shape.rho_min}, {"rho_max", res.shape.rho_max},
                         {"n_theta", res.shape.n_theta}, {"n_phi", res.shape.n_phi},     {"in_plane", in_plane}};
    manifest["frames"] = {{"count", frames.t.size()}, {"status", to_string(frames.status)}, {"window", window}};
    manifest["warnings"] = res.warnings;
    manifest["figures"] = figs;
    explain_nulls(manifest,
                  res.run.status == IntegrationStatus::success ? nonfinite_reason(p) : run_reason(res.run, p));
    put("report.json", manifest.dump(2) + "\n");
    draw_and_publish(o, manifest, tmp, target, res.files);
  });
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

ShapeExportRun export_shapes(const SceneFile& sf, const ShapeExportOptions& options, const std::string& flag) {
  std::vector<double> times = options.times.empty() ? std::vector<double>{sf.scene.T} : options.times;
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  options.grid.validate();
  const AmplitudeSeries series = amplitudes_at(sf, times);
  ShapeExportRun out{{series.level.level, series.status, series.reason, {}}, {}};
  for (std::size_t k = 0; k < series.t.size(); ++k) {
    const ShapeGrid g = shape_on_grid(series.f[k], options.grid);
    const SurfaceMesh mesh = surface_mesh(g);
    std::ostringstream stem;
    stem << options.stem;
    if (times.size() > 1) stem << "_t" << series.t[k];
    const std::string title = "rbcstab shape of scene " + sf.scene.name + " at t = " + format_value(series.t[k]);
    for (const auto& f : options.formats) {
      const std::string path = stem.str() + "." + f;
      const std::string text = f == "vtk"   ? to_vtk_legacy(mesh, title)
                               : f == "vtp" ? to_vtk_xml(mesh)
                               : f == "ply" ? to_ply(mesh, title)
                                            : to_csv(g);
      out.files.push_back({path, text, flag});
      out.result.files.push_back({series.t[k], path, g.rho_min, g.rho_max});
    }
  }
  return out;
}

void draw_csv_figure(const std::string& script, const std::string& prefix, const std::string& title,
                     const std::string& figure) {
  check_python("/usr/bin/python3");
  const std::string dir = find_script_dir("");
  if (dir.empty()) throw ReportError("cannot find the plotting scripts (set RBCSTAB_DATA_DIR)");
  const std::string log = prefix + ".plot.log";
  if (run_process({"/usr/bin/python3", dir + "/" + script, prefix + ".csv", prefix + ".png", title}, log) != 0)
    throw ReportError(figure + " failed: see " + log);
}

}  // namespace rbcstab
