// rbcstab diagram: a phase diagram by direct simulation over two parameter axes (paper Fig. 4,
// Fig. 5, Appendix E) with threads, shards, MPI ranks and a resumable journal; writes
// PREFIX.csv and PREFIX.json atomically, progress with rate and ETA on stderr.
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_document.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/mpi.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct DiagramCliOptions {
  SceneOptions scene;
  PlaneFlags plane;
  std::string out = "diagram", journal, shard = "0/1", schedule = "dynamic";
  int threads = 0;
  bool no_seconds = false, quiet = false, no_journal = false, json = false;
  bool no_finite_horizon_agreement = false;
  double sync_interval = 1.0;
  ProgressOutput progress;
};

int run(const DiagramCliOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::grid);
  const DiagramSpec spec = plane_spec(sf, o.plane.choice());

  MpiSession mpi;  // a no-op unless started by mpirun (and built with MPI)
  DiagramOptions ro;
  ro.threads = o.threads;
  ro.dynamic_schedule = o.schedule == "dynamic";
  ro.shard = mpi.shard(shard_from_string(o.shard));
  ro.sync_interval = o.sync_interval;
  const std::string suffix = shard_suffix(ro.shard);
  const std::string prefix = mpi.size() > 1 ? o.out : o.out + suffix;
  if (!o.no_journal) ro.journal = (o.journal.empty() ? o.out : o.journal) + suffix + ".journal";
  const bool show = !o.quiet && mpi.rank() == 0;
  if (show) ro.on_progress = o.progress.grid("rbcstab: ", true);
  const StopOnSignal interrupt;
  ro.stop = interrupt.flag();

  DiagramRun r = run_diagram(sf.scene, sf.options, spec, ro);
  for (const std::string& why : r.rejected) std::cerr << "rbcstab: warning: " << why << "\n";
  if (mpi.size() > 1) r = mpi.gather(r, spec);
  if (mpi.rank() != 0) return r.complete ? kOk : kRunFailed;
  if (!r.complete) {
    std::cerr << "rbcstab: " << diagram_run_text(r, prefix) << "\n";
    return kRunFailed;
  }
  const DiagramOutputOptions oo{!o.no_seconds};
  const Shard out_shard = mpi.size() > 1 ? Shard{} : ro.shard;
  const std::string csv = diagram_csv(spec, r.points, oo);
  AgreementOptions ao;
  ao.threads = o.threads;
  ao.finite_horizon = !o.no_finite_horizon_agreement;
  const nlohmann::json doc = diagram_document(sf, spec, r.points, out_shard, oo, ao);
  write_files_atomic({{prefix + ".csv", csv, "--out"}, {prefix + ".json", doc.dump(1) + "\n", "--out"}});
  if (o.json) std::cout << diagram_brief_json(sf, r, prefix).dump(2) << "\n";
  if (show) std::cerr << "rbcstab: " << diagram_run_text(r, prefix) << "\n";
  return count_verdicts(r.points).failed ? kRunFailed : kOk;
}

Runner add_diagram(CLI::App& app) {
  auto o = std::make_shared<DiagramCliOptions>();
  o->scene.add_to(app);
  o->plane.add_to(app, true);
  add_integer(app, "--threads", o->threads, 0, 4096, "worker threads", " (0: all cores)");
  app.add_option("--schedule", o->schedule, "point scheduling over threads")
      ->check(CLI::IsMember({"dynamic", "static"}))
      ->capture_default_str();
  app.add_option("--shard", o->shard,
                 "k/n with 0 <= k < n: compute only the points with index % n == k (job arrays; then rbcstab merge)")
      ->capture_default_str();
  app.add_option("--out", o->out, "output prefix: PREFIX.csv, PREFIX.json (shards: PREFIX.shardKofN.*)")
      ->check(output_name())
      ->capture_default_str();
  app.add_option("--journal", o->journal, "checkpoint journal prefix (default: the output prefix; file PREFIX.journal)")
      ->check(output_name());
  app.add_flag("--no-journal", o->no_journal, "no checkpoint journal (no resume)");
  app.add_option("--sync-interval", o->sync_interval, "fdatasync the journal at most this often [s], >= 0")
      ->capture_default_str();
  app.add_flag("--no-seconds", o->no_seconds,
               "omit per-point wall-clock seconds: outputs identical byte for byte across runs");
  app.add_flag("--quiet", o->quiet, "no progress and no closing summary on stderr");
  o->progress.add_flags(app, &o->quiet);
  app.add_flag("--no-finite-horizon-agreement", o->no_finite_horizon_agreement,
               "skip the finite-horizon predictor in the agreement block (one reduced run per point, ~1 ms each)");
  app.add_flag("--json", o->json, "print one JSON object on stdout (output files, point counts by verdict, seconds)");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterDiagram{"diagram", "Phase diagram by direct simulation over two parameter axes",
                                       add_diagram, 40};
}  // namespace

}  // namespace rbcstab::cli
