#pragma once
// One command per paper figure panel. A scene file with a panel table is a figure panel:
//   [diagram]       a phase diagram by simulation (sweep/diagram_table.hpp; Figs. 4, 5, Appendix E), drawn
//                   with the traced boundary (out-of-plane scenes) and the paper's analytic lines on top;
//   [fig6e]         the Fig. 6e table (sweep/fig6e.hpp): Delta~2 against the simulated mean;
//   [continuation]  an equilibrium branch of the reduced system (continue_scene, as `rbcstab continue`), drawn
//                   as a bifurcation diagram (stable solid, unstable dashed, special points labelled);
//   [physical_map]  the physical phase diagram of the scene's cell (verdict/physical_map.hpp) with the published
//                   observations (data/experiments.csv) drawn over it and the assumption checks listed.
// build_panel_report computes the panel's data and hands it to build_report's hooks.
#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/io/experiments.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/fig6e.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/physical_map.hpp"

namespace rbcstab {

enum class PanelKind { none, diagram, fig6e, continuation, physical_map };  // names: the scene file's panel tables
template <>
struct EnumTable<PanelKind> {
  static constexpr EnumName<PanelKind> entries[] = {{PanelKind::none, "none"},
                                                    {PanelKind::diagram, "diagram"},
                                                    {PanelKind::fig6e, "fig6e"},
                                                    {PanelKind::continuation, "continuation"},
                                                    {PanelKind::physical_map, "physical_map"}};
};
// The panel table the scene file holds: none, or exactly one (two throw InvalidArgument("scene", ...)).
PanelKind panel_kind(const SceneFile& scene);
// How the panel uses the truncation L (resolve_truncation): the grids of [diagram] and [fig6e] run every scene
// at one L, [continuation] continues the reduced system; no panel: the scene's simulation.
TruncationUse truncation_use(PanelKind kind);

// [fig6e]: lambda = [1, 5], B = [1, ..., 10], C = [0.01, ...] (each optional: Fig6eOptions' defaults, the
// paper's grid). Delta, Delta0, beta, delta, L, T and the integrator come from the scene, so the table
// runs what the scene says (a scene without the table: the paper's grid). Unknown keys and bad values throw
// InvalidArgument naming "fig6e.<key>".
Fig6eOptions fig6e_options(const SceneFile& scene);
// "# ..." comment, then lambda,B,C,alpha,ln_alpha,l_s,l_Delta,Delta2_tilde,Delta2_tilde_integer,Delta2_bar,ratio,
// ratio_integer; n/a where a quantity is outside its domain (stable run, failed run). Also `post --fig6e`.
std::string fig6e_csv(const Fig6eOptions& options, const std::vector<Fig6eRow>& rows);

// [continuation]: parameter (lambda Delta Delta0 B C Lambda S), min, max, direction (forward backward both),
// measure (r or Psi: the y axis), step, max_step, max_points, relax_T. Unknown keys and bad values throw
// InvalidArgument naming "continuation.<key>".
struct ContinuationPanel {
  ContinuationParameter parameter = ContinuationParameter::lambda;
  std::string measure = "Psi";    // the tank-treading angle shows the fold at Lambda = 1; r is 1 on that branch
  double relax_T = 200;           // relaxation that gives the start state (as `rbcstab continue --relax-T`)
  ContinuationOptions engine;     // p_min, p_max, direction, steps; validated by continue_branch
  std::vector<Monitor> monitors;  // monitor = ["NAME=V1,V2"], stop_at = ["NAME=V"]
};
ContinuationPanel continuation_panel(const SceneFile& scene);
// The panel's branch: reduced-system equilibria from the scene, as `rbcstab continue` (same start, bounds).
BranchSpec branch_spec(const ContinuationPanel& panel, const Scene& scene);
// The Branch JSON of `rbcstab continue --json` (continuation/branch_io.hpp) plus "measure", the quantity
// rbcstab_report.py draws against the parameter.
nlohmann::json bifurcation_json(const SceneBranch& branch, const std::string& measure);

// [physical_map]: viscosity = [min, max] and shear_rate = [min, max] (each item a number in SI -- Pa s, 1/s --
// within the quantity's plausible range, or a text with a unit: "1 mPa s", "0.1/s"), viscosities,
// samples_per_decade, rtol, onset (true/false), spreads ("none" or "healthy": healthy_cell_spreads); the rest as
// PhysicalMapOptions' defaults. Unknown keys and bad values throw InvalidArgument naming "physical_map.<key>".
struct PhysicalMapPanel {
  PhysicalMapOptions options;  // threads and progress: the caller's
  bool healthy_spreads = false;
};
PhysicalMapPanel physical_map_panel(const SceneFile& scene);
// What the page shows beside the figure, from the map and the observations drawn over it: the facts (rows of the
// "Panel" table) and three tables -- the boundaries per viscosity, the observations with their sources and the
// sentence each rests on, and the assumption checks with how far each is off.
struct PhysicalMapPage {
  std::vector<std::pair<std::string, std::string>> facts;
  std::vector<ReportTable> tables;
};
PhysicalMapPage physical_map_page(const PhysicalMap& map, const std::vector<PublishedObservation>& observed,
                                  const std::string& experiments_file);

// The phase diagram's overlay {"axes": {"x", "y"}, "curves": [{"label", "x", "y", "style", "color"}]}: the
// axes' TeX labels (tex_symbol: the parameter table's symbols), the traced boundary pieces (solid black, one
// legend entry per mode) and the analytic lines (dashed / dotted; C_*^± red).
nlohmann::json phase_overlay_json(const DiagramSpec& spec, const std::vector<TraceCurve>& boundary,
                                  const std::vector<Overlay>& lines);

struct PanelOptions {
  int threads = 0;     // diagram worker threads; 0 = all cores (the points are independent)
  int nx = 0, ny = 0;  // > 0: override the scene's [diagram] counts (a quick look at a coarse grid)
  TraceOptions trace;  // the traced boundary (criterion, start search, step cap)
  std::function<void(const Progress&)> on_progress;  // diagram progress (called on the calling thread)
  const std::atomic<bool>* stop = nullptr;           // set to stop a diagram early (then nothing is drawn)
  void validate() const;                             // names the field
};

struct PanelReportResult {
  PanelKind kind = PanelKind::none;
  ReportResult report;
  bool complete = true;    // false: the panel's computation did not finish (diagram stopped) and no folder was written
  std::size_t failed = 0;  // diagram points or Fig. 6e rows whose run did not reach T; a branch that was lost
  std::string status;      // continuation: the branch status; otherwise "success" or "failed runs"
  double compute_seconds = 0;                              // the panel's computation (drawing excluded)
  std::vector<std::pair<std::string, std::string>> facts;  // also shown on the report's "Panel" table
};

// Runs the panel of a scene file holding a panel table and writes its report folder (options.output); the
// folder's scene.toml is the file as read (scene.text). Throws InvalidArgument for bad input
// (InvalidArgument("scene", ...) if the file holds no panel table), ReportError when drawing or writing fails,
// as build_report.
PanelReportResult build_panel_report(const SceneFile& scene, const PanelOptions& panel, const ReportOptions& options);

}  // namespace rbcstab
