// rbcstab floquet: leading Floquet multipliers of the full model along the orbit a scene relaxes to
// (scene_floquet_multipliers: relax at the scene's level, embed in the full model, ARPACK on the
// monodromy action; rosenbrock variational integration for the full level from --implicit-from-L).
// The scene's --T, --dt, --stepper, --rtol and --atol do not apply: the relaxation (rk8pd, rtol 1e-11)
// and the variational integration use their own tight tolerances (docs/continuation.md).
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/continuation/monodromy.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct FloquetOptions {
  SceneOptions scene;
  SceneFloquetOptions floquet;
  bool json = false;
};

int run(const FloquetOptions& o) {
  // ARPACK names this field "tol"; checked here so that the message names the flag --arpack-tol.
  require(std::isfinite(o.floquet.arpack.tol) && o.floquet.arpack.tol >= 0 && o.floquet.arpack.tol < 1, "arpack_tol",
          o.floquet.arpack.tol, "[0, 1)");
  const SceneFile sf = o.scene.resolve(TruncationUse::analysis);
  const SceneFloquetResult r = scene_floquet_multipliers(sf.scene, o.floquet);
  const Eigen::VectorXcd& mu = r.floquet.arpack.eigenvalues;
  if (o.json) {
    nlohmann::json j;
    j["status"] = to_string(r.status);
    if (!r.message.empty()) j["message"] = r.message;
    j["parameters"] = to_json(sf.scene.parameters);
    j["beta"] = sf.scene.beta;
    put_truncation(j, sf);
    j["n"] = r.dimension;
    j["relax_level"] = to_string(r.relax_level);
    j["relax_periods"] = o.floquet.relax_periods;
    j["t0"] = r.t0;
    j["period"] = r.period;
    j["periodicity_defect"] = number_or_null(r.periodicity_defect);
    j["stepper"] = to_string(r.stepper);
    j["integrations"] = r.floquet.integrations;
    j["steps"] = r.floquet.counters.steps;
    nlohmann::json list = nlohmann::json::array();
    for (Eigen::Index i = 0; i < mu.size(); ++i)
      list.push_back({{"re", number_or_null(mu(i).real())},
                      {"im", number_or_null(mu(i).imag())},
                      {"abs", number_or_null(std::abs(mu(i)))}});
    j["multipliers"] = list;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << std::setprecision(8) << "full model L = " << sf.scene.L << " (n = " << r.dimension << "), relaxed "
              << o.floquet.relax_periods << " periods at the " << to_string(r.relax_level) << " level, period "
              << r.period << ", periodicity defect " << r.periodicity_defect << ", " << to_string(r.stepper) << ", "
              << r.floquet.integrations << " actions: " << to_string(r.status) << "\n";
    for (Eigen::Index i = 0; i < mu.size(); ++i)
      std::cout << "  mu = " << mu(i).real() << (mu(i).imag() < 0 ? " - " : " + ") << std::abs(mu(i).imag())
                << "i  |mu| = " << std::abs(mu(i)) << "\n";
  }
  if (r.status != SceneFloquetStatus::converged) {
    std::cerr << "rbcstab: " << to_string(r.status) << ": " << r.message << "\n";
    return kRunFailed;
  }
  return kOk;
}
}  // namespace

static Runner add_floquet(CLI::App& app) {
  auto o = std::make_shared<FloquetOptions>();
  o->scene.add_to(app);
  app.add_option("--relax-periods", o->floquet.relax_periods,
                 "forcing periods simulated at the scene's level before the monodromy (default 30)");
  app.add_option("--max-periodicity-defect", o->floquet.max_periodicity_defect,
                 "largest periodicity defect |y(t0+T) - y(t0)|/|y(t0)| of the relaxed state accepted as an orbit "
                 "(default 1e-6; larger: exit 1 without multipliers; inf: any state)");
  app.add_option("--k", o->floquet.arpack.k, "number of leading multipliers (default 12)");
  app.add_option("--arpack-tol", o->floquet.arpack.tol, "ARPACK's relative Ritz tolerance (default 1e-10)");
  app.add_option("--implicit-from-L", o->floquet.monodromy.implicit_from_L,
                 "use the rosenbrock variational integration for L >= this (default 40; 0: never)");
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"floquet", "Leading Floquet multipliers of the full model along a scene's orbit",
                                add_floquet, 33};
}  // namespace

}  // namespace rbcstab::cli
