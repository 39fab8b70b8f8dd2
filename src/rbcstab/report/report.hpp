#pragma once
// A self-contained report folder for one scene: the run (and its reduced companion), the data
// behind every figure (CSV/JSON), the shape at T (VTK, VTP, PLY), figures drawn by matplotlib
// (python/rbcstab_report.py), index.html and README.md. The folder appears whole or not at all.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/report/convergence.hpp"
#include "rbcstab/report/shape.hpp"
#include "rbcstab/verdict/shear_rate.hpp"

namespace rbcstab {

// Python or matplotlib missing, the plotting script failing, or the folder not writable.
// Derives from std::runtime_error, which the CLI maps to exit code 3 (output error).
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A table of plain-text cells a panel adds to its page (header, then rows of as many cells).
struct ReportTable {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct ReportOptions {
  std::string output;                       // folder to create (its parent must exist)
  bool overwrite = false;                   // replace an existing folder; otherwise refuse (never merge)
  std::string python = "/usr/bin/python3";  // Debian's python3 with python3-matplotlib
  std::string script_dir;                   // folder of rbcstab_report.py; empty: find_script_dir("")
  ShapeGridOptions shape{64, 128};          // the rendered / exported shape at T
  ShapeGridOptions frame_shape{32, 64};     // coarser grid per animation frame (keeps animation.json ~1 MB)
  int frames = 60;                          // animation frames (GIF), uniform in [T - frame_window, T]
  double frame_window = 0;        // 0: auto (one period of r(t) at the end if the run oscillates, else [0, T])
  bool reduced_companion = true;  // also run the reduced level (Fig. 2 r, Psi; Fig. 3 sigma_R)
  ShearRateSearchOptions shear_rate_search;  // a physical scene: the thresholds' search (summary's)
  ConvergenceOptions convergence;            // the run's numbers re-measured under each refinement (convergence.hpp)
  // Hooks for data other modules produce; drawn when given (formats in docs/report.md).
  std::string phase_diagram;      // CSV with columns x, y, l_Delta (+ optional overlay JSON beside it)
  std::string delta2_comparison;  // CSV with columns Delta2_theory, Delta2_simulation[, alpha]
  std::string bifurcation;  // a branch JSON (continuation/branch_io.hpp), drawn by plot_spec (bifurcation_plot.hpp)
  std::string bifurcation_x, bifurcation_y;  // its axes ("": plot_spec's defaults)
  std::string physical_map;                  // a physical-map JSON (verdict_io.hpp: to_json with the observations)
  // Figure panels (phase diagram, Fig. 6e, bifurcation; report/panels.hpp): no run of the scene itself,
  // whose time-dependent figures would mean nothing there; only the hooks are drawn (at least one is needed).
  bool run_scene = true;
  std::vector<std::string> attachments;  // files copied in as they are (the raw data behind a panel)
  std::string panel_summary;             // panel reports: what was computed, shown under the title
  std::vector<std::pair<std::string, std::string>> panel_facts;  // panel reports: rows of the "Panel" table
  std::vector<ReportTable> panel_tables;                         // panel reports: more tables, after "Panel"
  std::string figure_title;                                      // panel reports: title drawn above the hook figures
  std::string scene_toml;  // panel reports: the scene file as read (its panel table kept) for scene.toml
  // Each step as it starts ("running the scene", "drawing the figures"), for progress; the runs themselves
  // report through the scene's SimulationOptions::on_progress.
  std::function<void(const std::string& step)> on_step;
  void validate() const;  // throws InvalidArgument naming the field
};

struct ReportResult {
  SimulationResult run;  // the scene as given
  bool has_reduced = false;
  SimulationResult reduced;        // model = reduced, perturbations dropped
  std::vector<std::string> files;  // relative to the output folder
  std::vector<std::string> warnings;
  ShapeGrid shape;                                        // rho at the end of the run
  std::vector<ShearRateThreshold> shear_rate_thresholds;  // a physical scene: per orientation (else empty)
  ReportConvergence convergence;                          // empty: not asked for, or the run stopped before T
  double seconds = 0;
};

// The amplitudes f_{l,m}(t) at increasing times in [0, T], from the level and initial state
// simulate() uses for the scene. A failed integration keeps the samples before it, with its status.
struct AmplitudeSeries {
  std::vector<double> t;
  std::vector<ModeAmplitudes> f;
  LevelChoice level;
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
};
AmplitudeSeries amplitudes_at(const SceneFile& scene, const std::vector<double>& times);

namespace detail {
// Mean spacing of the maxima of x(t) over the second half of the samples (maxima reaching the
// upper third of the swing); 0 when x is flat there or has fewer than 3 such maxima.
double oscillation_period(const std::vector<double>& t, const std::vector<double>& x);
}  // namespace detail

// `rbcstab shape`: the scene's shape at each time (sorted, repeats dropped; none: T) on the grid, in each format
// (vtk, vtp, ply, csv) as STEM.<format>, or STEM_t<time>.<format> for several times. The files are returned for
// the caller to write as one set (write_files_atomic; `flag` names the stem in its messages) with what they hold.
struct ShapeExportOptions {
  std::string stem;
  std::vector<double> times;
  std::vector<std::string> formats{"vtk"};
  ShapeGridOptions grid;
};
struct ShapeExportRun {
  ShapeExport result;
  std::vector<OutputFile> files;
};
ShapeExportRun export_shapes(const SceneFile& scene, const ShapeExportOptions& options, const std::string& flag = "");

// The drawing script of reports and bifurcation plots, in the folder find_script_dir gives.
inline constexpr const char* kReportScript = "rbcstab_report.py";

// The running program's path (/proc/self/exe; "" if unknown): an installed tool finds its data beside it.
std::string executable_path();

// Where rbcstab_report.py lives: $RBCSTAB_DATA_DIR[/python], then <exe>/../share/rbcstab/python
// (installed), then the source tree this library was built from. Empty if none holds the script.
std::string find_script_dir(const std::string& executable_path);

// Runs args[0] with args (no shell), stdout and stderr appended to log_path ("" discards them);
// returns the exit status, or -1 if the program could not be started or did not exit normally.
int run_process(const std::vector<std::string>& args, const std::string& log_path);

// Throws ReportError with a remedy unless `python` runs and imports matplotlib (Agg backend).
void check_python(const std::string& python);
// A benchmark's figure PREFIX.png from PREFIX.csv by `script` (in the folder find_script_dir("") gives, run by
// /usr/bin/python3, its output in PREFIX.plot.log). Throws ReportError ("<figure> failed: see <log>") when it fails.
void draw_csv_figure(const std::string& script, const std::string& prefix, const std::string& title,
                     const std::string& figure);

// Runs the scene and writes the report. Bad input throws InvalidArgument; missing python,
// failed plotting or unwritable output throw ReportError, leaving no partial folder. A failed
// integration still yields a report (figures up to t_reached) with its status stated.
ReportResult build_report(const SceneFile& scene, const ReportOptions& options);

}  // namespace rbcstab
