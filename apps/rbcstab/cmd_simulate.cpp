// rbcstab simulate: one scene, JSON summary and optional trajectory CSV.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/io/simulation_io.hpp"
#include "rbcstab/verdict/certified_run.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct SimulateOptions {
  SceneOptions scene;
  bool json = false;
  std::string trajectory;
  ProgressOutput progress;
};

int run(const SimulateOptions& o) {
  SceneFile sf = o.scene.read_unchecked();  // simulate_scene checks it
  sf.options.trajectory_text = !o.trajectory.empty();
  sf.options.on_progress = o.progress.callback("simulate: t =", "");
  const SimulationResult r = simulate_scene(sf, sf.options);
  if (!o.trajectory.empty()) write_file_atomic(o.trajectory, trajectory_csv(r), "--trajectory");
  for (const auto& w : r.warnings) std::cerr << "rbcstab: warning: " << w << "\n";
  if (o.json)
    std::cout << simulation_json(sf, r).dump(2) << "\n";
  else
    std::cout << simulation_text(sf, r);
  if (r.status != IntegrationStatus::success) {
    std::cerr << "rbcstab: run stopped at t = " << r.t_reached << ": " << run_reason(r, sf.scene.parameters) << "\n";
    return kRunFailed;
  }
  return kOk;
}

Runner add_simulate(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  app.add_option("--trajectory", o->trajectory,
                 "write t, Delta_2..Delta_L, sigma, r, Psi on the sampling grid to this CSV");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterSimulate{"simulate", "Integrate a scene and report the excess-area redistribution",
                                        add_simulate, 20};
}  // namespace

}  // namespace rbcstab::cli
