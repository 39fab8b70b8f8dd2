// rbcstab trace: the stability boundary in a parameter plane as curves traced by continuation
// (--criterion asymptotic: mu_l = Upsilon_l(<sigma_R>) = 0; finite-horizon: G_l(T) = 0), one record per
// curve piece with its mode, plus the corners where the mode changes; CSV and JSON. With --diagram
// FILE.json (an `rbcstab diagram` output of the same plane) it also measures every predictor's agreement
// with the simulations.
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct TraceCliOptions {
  SceneOptions scene;
  PlaneFlags plane;
  TraceOptions trace;
  std::string out = "trace", diagram, criterion = "asymptotic", method = "auto";
  int threads = 1;
  bool json = false;
  ProgressOutput progress;
};

int run(const TraceCliOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::grid);
  const DiagramSpec spec = plane_spec(sf, o.plane.choice());
  TraceOptions to = o.trace;
  to.criterion = trace_criterion_from_string(o.criterion);
  to.method = trace_method_from_string(o.method);
  to.on_progress = o.progress.callback("trace:", "criterion evaluations");
  const TraceResult t = trace_boundary(sf.scene, spec, to);

  nlohmann::json doc = trace_json(sf, spec, to, t);
  if (!o.diagram.empty())
    doc["agreement"] = trace_agreement_json(parse_json_text(read_file(o.diagram), o.diagram, "diagram"), o.diagram,
                                            spec, to, o.threads);
  write_files_atomic({{o.out + ".csv", trace_csv(spec, t), "--out"}, {o.out + ".json", doc.dump(1) + "\n", "--out"}});
  for (const std::string& line : trace_summary_lines(t, doc, o.out)) std::cerr << "rbcstab: " << line << "\n";
  if (o.json) std::cout << trace_brief_json(doc, o.out).dump(2) << "\n";
  return kOk;
}

Runner add_trace(CLI::App& app) {
  auto o = std::make_shared<TraceCliOptions>();
  o->scene.add_to(app);
  o->plane.add_to(app, false);
  app.add_option("--criterion", o->criterion, "asymptotic | finite-horizon")->capture_default_str();
  app.add_option("--method", o->method,
                 "auto: on ln B planes the finite-horizon and in-plane asymptotic boundaries in closed form in B (one "
                 "reduced transient or periodic orbit per value of the other axis), the rest by continuation; "
                 "continuation: continuation on every plane")
      ->check(CLI::IsMember(enum_names<TraceMethod>()))
      ->capture_default_str();
  app.add_option("--horizon", o->trace.T, "finite-horizon T, >= 0 (0: the scene's T)")
      ->check(non_negative())
      ->capture_default_str();
  add_integer(app, "--lines", o->trace.lines, 0, 10000,
              "interior lines (x fixed) searched for starting points besides the edges");
  add_integer(app, "--samples", o->trace.samples, 2, 1000000, "brackets per edge or line when searching for starts");
  app.add_option("--max-step", o->trace.max_step, "continuation step cap in the unit square (curve resolution), > 0")
      ->capture_default_str();
  add_integer(app, "--threads", o->threads, 0, 4096, "threads for the per-point predictor verdicts of --diagram",
              " (0: all cores)");
  app.add_option("--diagram", o->diagram, "diagram JSON of the same plane: measure the criterion's agreement")
      ->check(CLI::ExistingFile);
  app.add_option("--out", o->out, "output prefix: PREFIX.csv and PREFIX.json")
      ->check(output_name())
      ->capture_default_str();
  app.add_flag("--json", o->json, "print one JSON object on stdout (output files, pieces, corners, agreement)");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterTrace{"trace", "Trace the stability boundary of a parameter plane as curves", add_trace,
                                     42};
}  // namespace

}  // namespace rbcstab::cli
