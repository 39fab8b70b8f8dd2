// rbcstab simulate: one scene, JSON summary and optional trajectory CSV.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct SimulateOptions {
  SceneOptions scene;
  bool json = false;
  std::string trajectory;
};

std::string trajectory_csv(const SimulationResult& r) {
  std::ostringstream ss;
  ss << std::setprecision(17);
  ss << "t";
  for (int l = 2; l <= r.L; ++l) ss << ",Delta_" << l;
  ss << ",sigma,r,Psi\n";
  const Trajectory& tr = r.trajectory;
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    ss << tr.t[k];
    for (double d : tr.Delta_l[k]) ss << ',' << d;
    ss << ',' << tr.sigma[k] << ',' << tr.r[k] << ',' << tr.Psi[k] << '\n';
  }
  return ss.str();
}

int run(const SimulateOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::simulation);
  const SimulationResult r = simulate(sf.scene, sf.options);
  if (!o.trajectory.empty()) write_file_atomic(o.trajectory, trajectory_csv(r), "--trajectory");
  for (const auto& w : r.warnings) std::cerr << "rbcstab: warning: " << w << "\n";
  if (o.json) {
    nlohmann::json j = to_json(r);
    j["parameters"] = to_json(sf.scene.parameters);
    j["stepper"] = to_string(sf.options.integrator.stepper);
    j["rtol"] = sf.options.integrator.rtol;
    j["atol"] = sf.options.integrator.atol;
    put_truncation(j, sf);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << std::setprecision(6) << "model " << to_string(r.level.level) << ", status " << to_string(r.status)
              << ", l_Delta = " << r.l_Delta << ", sigma(T) = " << r.sigma_final
              << ", drift = " << r.excess_area_drift << ", steps = " << r.counters.steps << "\n"
              << sf.L_reason << "\n";
  }
  if (r.status != IntegrationStatus::success) {
    std::cerr << "rbcstab: run stopped at t = " << r.t_reached << ": " << r.reason << "\n";
    return kRunFailed;
  }
  return kOk;
}
}  // namespace

static Runner add_simulate(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  app.add_option("--trajectory", o->trajectory, "write t, Delta_2..Delta_L, sigma, r, Psi on the sampling grid to this CSV");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"simulate", "Integrate a scene and report the excess-area redistribution", add_simulate, 20};
}  // namespace

}  // namespace rbcstab::cli
