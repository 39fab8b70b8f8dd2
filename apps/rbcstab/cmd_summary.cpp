// rbcstab summary: the main job, a readable account of one scene.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/verdict/verdict_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct SummaryOptions {
  SceneOptions scene;
  bool json = false;
  std::string shear_rate_range;  // LO,HI (1/s): the threshold search of a physical scene
  ProgressOutput progress;
};

int run(const SummaryOptions& o) {
  SceneFile sf = o.scene.read_unchecked();  // run_summary checks it
  sf.options.on_progress = o.progress.callback("summary: t =", "");
  const ShearRateSearchOptions search = shear_rate_search(sf.scene, o.shear_rate_range, "--shear-rate-range");
  const SummaryRun s = run_summary(std::move(sf), search);
  if (o.json)
    std::cout << summary_json(s.file, s.run, s.prediction).dump(2) << "\n";
  else
    std::cout << summary_text(s.file, s.run, s.prediction);
  return s.run.status == IntegrationStatus::success ? kOk : kRunFailed;
}

Runner add_summary(CLI::App& app) {
  auto o = std::make_shared<SummaryOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout (the keys of simulate --json, then the analysis)");
  add_shear_rate_range(app, o->shear_rate_range);
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterSummary{
    "summary", "The main job: a readable summary of a scene (default: the paper's Fig. 3 case)", add_summary, 10};
}  // namespace

}  // namespace rbcstab::cli
