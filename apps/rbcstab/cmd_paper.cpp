// rbcstab paper: every figure of the paper, composed as the paper composes it, with its claims checked.
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/report/paper.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/report/report_io.hpp"

namespace rbcstab::cli {

namespace {
struct PaperCliOptions {
  PaperOptions paper;
  bool quiet = false;
  bool json = false;
  ProgressOutput progress;
};

int run(PaperCliOptions& o) {
  PaperOptions p = o.paper;
  if (p.script_dir.empty()) p.script_dir = find_script_dir(executable_path());
  if (p.scene_dir.empty()) p.scene_dir = find_scene_dir(executable_path());
  if (o.progress.enabled())
    p.on_step = [](const std::string& step, int k, int n) {
      std::cerr << "rbcstab: paper: " << (k > 0 ? "[" + std::to_string(k) + "/" + std::to_string(n) + "] " : "  ")
                << step << "\n";
    };
  p.on_progress = o.progress.grid("rbcstab: paper:   ");
  const StopOnSignal interrupt;
  p.stop = interrupt.flag();
  const PaperResult r = build_paper(p);
  if (!r.complete) {
    std::cerr << "rbcstab: interrupted: the paper was not finished and nothing was written\n";
    return kRunFailed;
  }
  std::cout << (o.json ? paper_json(p, r).dump(2) + "\n" : paper_text(p, r));
  if (r.failed_runs) {
    std::cerr << "rbcstab: " << r.failed_runs << " run(s) did not reach T; the page shows them\n";
    return kRunFailed;
  }
  return kOk;
}

Runner add_paper(CLI::App& app) {
  auto o = std::make_shared<PaperCliOptions>();
  PaperOptions& p = o->paper;
  app.add_option("--output,-o", p.output,
                 "folder to create (index.html, the figures, their data); its parent must exist")
      ->required();
  app.add_flag("--overwrite", p.overwrite, "replace an existing output folder (swapped in whole at the end)");
  app.add_flag("--quick", p.quick, "coarse grids: 12 x 12 phase diagrams and a 3 x 2 Fig. 6e grid per lambda");
  add_integer(app, "--threads", p.threads, 0, 4096, "worker threads for the runs and diagram points",
              " (0: all cores)");
  app.add_option("--python", p.python, "python3 interpreter with matplotlib (Debian python3-matplotlib)")
      ->capture_default_str();
  app.add_option("--data-dir", p.script_dir,
                 "folder holding paper_draw.py (default: $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python)");
  app.add_option("--scene-dir", p.scene_dir,
                 "folder holding the paper's scene files (default: $RBCSTAB_DATA_DIR/scenes, "
                 "<prefix>/share/rbcstab/scenes, the source tree)");
  app.add_flag("--quiet", o->quiet, "no progress on stderr");
  o->progress.add_flags(app, &o->quiet);
  app.add_flag("--json", o->json, "print one JSON object (counts, failed claims) on stdout");
  app.footer(
      "Exit codes: 0 ok (failed claims are reported, not an error), 1 a run stopped early or interrupted, "
      "2 invalid input, 3 output error (python3/matplotlib missing, plotting failed: nothing is left behind).");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterPaper{
    "paper", "Compute and draw every figure of the paper with its claims checked (one HTML page)", add_paper, 61};
}  // namespace

}  // namespace rbcstab::cli
