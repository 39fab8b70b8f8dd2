// rbcstab summary: the main job, a readable account of one scene.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/verdict/verdict_io.hpp"
#include "progress.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct SummaryOptions {
  SceneOptions scene;
  bool json = false;
  ProgressOutput progress;
};

int run(const SummaryOptions& o) {
  const SceneOptions& so = o.scene;
  ReducedTransient transient;  // integrated once: the truncation rule and the finite-horizon predictor read it
  SceneFile sf = so.resolve(TruncationUse::simulation, &transient);
  sf.options.on_progress = o.progress.callback("summary: t =", "");
  const SimulationResult r = simulate(sf.scene, sf.options);
  const ScenePrediction prediction = predict(sf.scene, transient, &r);
  if (o.json)
    std::cout << summary_json(sf, r, prediction).dump(2) << "\n";
  else
    std::cout << summary_text(sf, r, prediction);
  return r.status == IntegrationStatus::success ? kOk : kRunFailed;
}
}  // namespace

static Runner add_summary(CLI::App& app) {
  auto o = std::make_shared<SummaryOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout (the keys of simulate --json, then the analysis)");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"summary", "The main job: a readable summary of a scene (default: the paper's Fig. 3 case)", add_summary, 10};
}  // namespace

}  // namespace rbcstab::cli
