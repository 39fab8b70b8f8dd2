// rbcstab report: run a scene and write a self-contained report folder (figures, data, shapes).
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/report/report_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ReportCliOptions {
  SceneOptions scene;
  ReportOptions report;
  int n_theta = 64;
  bool no_reduced = false, json = false;
  PanelOptions panel;
  std::vector<std::string> counts;  // checks.hpp counts_of
  std::string shear_rate_range;     // LO,HI (1/s): the threshold search of a physical scene
  bool quiet = false;
  ProgressOutput progress;
};

// A scene file with a panel table ([diagram], [fig6e], [continuation], [physical_map]): compute it, then draw it.
int run_panel(ReportCliOptions& o, const SceneFile& sf, ReportOptions& ro) {
  if (const std::vector<long long> counts = counts_of(o.counts); !counts.empty()) {
    o.panel.nx = int(counts[0]);
    o.panel.ny = int(counts[1]);
  }
  o.panel.on_progress = o.progress.grid("rbcstab: report: ");
  const StopOnSignal interrupt;
  o.panel.stop = interrupt.flag();
  const PanelReportResult r = build_panel_report(sf, o.panel, ro);
  if (!r.complete) {
    std::cerr << "rbcstab: interrupted: the panel was not finished and no report was written\n";
    return kRunFailed;
  }
  std::cout << (o.json ? panel_report_json(sf, ro, r).dump(2) + "\n" : panel_report_text(ro, r));
  if (r.failed) {
    std::cerr << "rbcstab: " << r.failed << " run(s) of the panel did not finish (status " << r.status
              << "); the report shows them as failed\n";
    return kRunFailed;
  }
  return kOk;
}

int run(ReportCliOptions& o) {
  SceneFile sf = o.scene.read();
  const PanelKind kind = panel_kind(sf);
  apply_scene_truncation(sf, truncation_use(kind));
  ReportOptions ro = o.report;
  ro.shape = {o.n_theta, 2 * o.n_theta};
  ro.reduced_companion = !o.no_reduced;
  if (ro.script_dir.empty()) ro.script_dir = find_script_dir(executable_path());
  if (kind != PanelKind::none) return run_panel(o, sf, ro);
  // The scene's runs only: a panel's points run on worker threads.
  sf.options.on_progress = o.progress.callback("report: run at t =", "");
  if (o.progress.enabled()) ro.on_step = [&o](const std::string& step) { o.progress.step("report: " + step); };
  if (!o.counts.empty() || o.panel.threads != 0)
    throw InvalidArgument("--counts", "--counts and --threads apply to a scene with a [diagram] table only");
  ro.shear_rate_search = shear_rate_search(sf.scene, o.shear_rate_range, "--shear-rate-range");
  const ReportResult r = build_report(sf, ro);
  for (const auto& w : r.warnings) std::cerr << "rbcstab: warning: " << w << "\n";
  std::cout << (o.json ? report_json(sf, ro, r).dump(2) + "\n" : report_text(ro, r));
  const std::vector<std::string> failures = report_failures(sf, r);
  for (const std::string& f : failures) std::cerr << "rbcstab: " << f << "\n";
  return failures.empty() ? kOk : kRunFailed;
}

Runner add_report(CLI::App& app) {
  auto o = std::make_shared<ReportCliOptions>();
  o->scene.add_to(app);
  ReportOptions& r = o->report;
  app.add_option("--output,-o", r.output,
                 "report folder to create (index.html, README.md, figures, data); its parent must exist")
      ->required();
  app.add_flag("--overwrite", r.overwrite, "replace an existing output folder (swapped in whole at the end)");
  add_shear_rate_range(app, o->shear_rate_range);
  app.add_option("--python", r.python, "python3 interpreter with matplotlib (Debian python3-matplotlib)")
      ->capture_default_str();
  add_integer(app, "--frames", r.frames, 2, 2000, "animation frames");
  app.add_option("--frame-window", r.frame_window,
                 "animate the last W time units [T - W, T], >= 0; 0 = auto: one period of r(t) at the end if the run "
                 "oscillates (swinging, tumbling), else the whole run")
      ->check(non_negative())
      ->capture_default_str();
  add_integer(app, "--shape-resolution", o->n_theta, 2, 4096,
              "polar grid points n_theta of the exported and rendered shape (n_phi = 2 n_theta)");
  app.add_flag("!--no-convergence", r.convergence.enabled, "skip re-running with L+2, 2T, delta/10, rtol/100");
  app.add_flag("--no-reduced", o->no_reduced,
               "skip the reduced-system companion run (Fig. 2 r, Psi from the l = 2 block only)");
  app.add_option("--phase-diagram", r.phase_diagram,
                 "also draw this phase-diagram CSV (x, y, l_Delta; overlay curves from the .json beside it)");
  app.add_option("--delta2-comparison", r.delta2_comparison,
                 "also draw this CSV of Delta2_theory, Delta2_simulation[, alpha, lambda] (Fig. 6e)");
  app.add_option("--bifurcation", r.bifurcation,
                 "also draw this branch JSON (`rbcstab continue --json` or a --save branch file) as a bifurcation "
                 "diagram, as `rbcstab plot` does (docs/plot.md)");
  app.add_option("--bifurcation-x", r.bifurcation_x,
                 "--bifurcation: the x axis, a parameter or measure (default: the free parameter; curves: p1)");
  app.add_option("--bifurcation-y", r.bifurcation_y,
                 "--bifurcation: the y axis, a parameter or measure (default: Psi for reduced-system equilibria, "
                 "r_max for orbits, r otherwise; curves: p2)");
  app.add_option("--data-dir", r.script_dir,
                 "folder holding rbcstab_report.py (default: $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python)");
  add_integer(app, "--threads", o->panel.threads, 0, 4096, "[diagram] scenes: worker threads for the grid",
              " (0: all cores)");
  add_counts(app, o->counts,
             "[diagram] scenes: override the grid's nx,ny (or NxM), integers in [1, 1000000], for a quick look "
             "(default: the scene's counts)");
  add_integer(app, "--trace-lines", o->panel.trace.lines, 0, 10000,
              "[diagram] scenes: interior lines (x fixed) searched for starts of the traced boundary besides the "
              "plane's edges");
  app.add_flag("--quiet", o->quiet, "no progress on stderr");
  o->progress.add_flags(app, &o->quiet);
  app.add_flag("--json", o->json, "print one JSON object (files, summaries) on stdout");
  app.footer(
      "Exit codes: 0 ok, 1 a run stopped early (report still written), 2 invalid input, 3 output error "
      "(python3/matplotlib missing, plotting failed, folder not writable: nothing is left behind).");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterReport{
    "report", "Run a scene or a figure panel ([diagram], [fig6e], [continuation], [physical_map]) into a report",
    add_report, 60};
}  // namespace

}  // namespace rbcstab::cli
