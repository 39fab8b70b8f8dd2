// rbcstab report: run a scene and write a self-contained report folder (figures, data, shapes).
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/report.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ReportCliOptions {
  SceneOptions scene;
  ReportOptions report;
  int n_theta = 64;
  bool no_reduced = false;
  bool json = false;
};

std::string executable_path() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : p.string();
}

int run(ReportCliOptions& o) {
  std::string L_reason;
  const SceneFile sf = o.scene.resolve_with_default_L(L_reason);
  ReportOptions ro = o.report;
  ro.shape = {o.n_theta, 2 * o.n_theta};
  ro.reduced_companion = !o.no_reduced;
  if (ro.script_dir.empty()) ro.script_dir = find_script_dir(executable_path());
  const ReportResult r = build_report(sf, ro);
  for (const auto& w : r.warnings) std::cerr << "rbcstab: warning: " << w << "\n";
  if (o.json) {
    nlohmann::json j;
    j["output"] = ro.output;
    j["files"] = r.files;
    j["summary"] = to_json(r.run);
    if (r.has_reduced) j["reduced_summary"] = to_json(r.reduced);
    j["shape"] = {{"rho_min", r.shape.rho_min}, {"rho_max", r.shape.rho_max}};
    j["seconds"] = r.seconds;
    j["L"] = sf.scene.L;
    j["L_reason"] = L_reason;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << "report written to " << ro.output << " (" << r.files.size() << " files, open index.html); l_Delta = "
              << r.run.l_Delta << ", status " << to_string(r.run.status) << "\n";
  }
  const bool failed = r.run.status != IntegrationStatus::success ||
                      (r.has_reduced && r.reduced.status != IntegrationStatus::success);
  if (failed) {
    std::cerr << "rbcstab: a run stopped early (" << r.run.reason << (r.has_reduced ? " / " + r.reduced.reason : "")
              << "); the report shows it up to t_reached\n";
    return kRunFailed;
  }
  return kOk;
}
}  // namespace

static Runner add_report(CLI::App& app) {
  auto o = std::make_shared<ReportCliOptions>();
  o->scene.add_to(app);
  ReportOptions& r = o->report;
  app.add_option("--output,-o", r.output, "report folder to create (index.html, README.md, figures, data); its parent must exist")
      ->required();
  app.add_flag("--overwrite", r.overwrite, "replace an existing output folder (swapped in whole at the end)");
  app.add_option("--python", r.python, "python3 interpreter with matplotlib (Debian python3-matplotlib)")
      ->capture_default_str();
  app.add_option("--frames", r.frames, "animation frames, integer in [2, 2000]")->capture_default_str();
  app.add_option("--frame-window", r.frame_window,
                 "animate the last W time units [T - W, T], >= 0; 0 = auto: one period of r(t) at the end if the run "
                 "oscillates (swinging, tumbling), else the whole run")
      ->capture_default_str();
  app.add_option("--shape-resolution", o->n_theta,
                 "polar grid points n_theta of the exported and rendered shape (n_phi = 2 n_theta), in [2, 4096]")
      ->capture_default_str();
  app.add_flag("--no-reduced", o->no_reduced, "skip the reduced-system companion run (Fig. 2 r, Psi from the l = 2 block only)");
  app.add_option("--phase-diagram", r.phase_diagram,
                 "also draw this phase-diagram CSV (x, y, l_Delta; overlay curves from the .json beside it)");
  app.add_option("--delta2-comparison", r.delta2_comparison,
                 "also draw this CSV of Delta2_theory, Delta2_simulation[, alpha, lambda] (Fig. 6e)");
  app.add_option("--bifurcation", r.bifurcation, "also draw this bifurcation-diagram JSON (branches, stability, points)");
  app.add_option("--data-dir", r.script_dir,
                 "folder holding rbcstab_report.py (default: $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python)");
  app.add_flag("--json", o->json, "print one JSON object (files, summaries) on stdout");
  app.footer("Exit codes: 0 ok, 1 a run stopped early (report still written), 2 invalid input, 3 output error "
             "(python3/matplotlib missing, plotting failed, folder not writable: nothing is left behind).");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"report", "Run a scene and write a report folder: figures, data, 3-D shapes",
                                add_report, 60};
}  // namespace

}  // namespace rbcstab::cli
