// rbcstab floquet: leading Floquet multipliers of the full model along the orbit a scene relaxes to
// (scene_floquet_multipliers: relax at the scene's level, embed in the full model, ARPACK on the
// monodromy action; rosenbrock variational integration for the full level from --implicit-from-L).
// The scene's --T, --dt, --stepper, --rtol and --atol do not apply: the relaxation (rk8pd, rtol 1e-11)
// and the variational integration use their own tight tolerances (docs/continuation.md).
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "rbcstab/continuation/floquet_io.hpp"
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
  if (o.json) {
    nlohmann::json j = floquet_json(sf.scene, o.floquet, r);
    put_truncation(j, sf);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << floquet_text(sf.scene, o.floquet, r);
  }
  if (r.status != SceneFloquetStatus::converged) {
    std::cerr << "rbcstab: " << to_string(r.status) << ": " << r.message << "\n";
    return kRunFailed;
  }
  return kOk;
}

Runner add_floquet(CLI::App& app) {
  auto o = std::make_shared<FloquetOptions>();
  o->scene.add_to(app);
  app.add_option(
      "--relax-periods", o->floquet.relax_periods,
      "forcing periods simulated at the scene's level before the monodromy, an integer in [0, 1000000] (default 30)");
  app.add_option("--max-periodicity-defect", o->floquet.max_periodicity_defect,
                 "largest periodicity defect |y(t0+T) - y(t0)|/|y(t0)| of the relaxed state accepted as an orbit "
                 "> 0 (default 1e-6; larger: exit 1 without multipliers; inf: any state)");
  app.add_option("--k", o->floquet.arpack.k,
                 "number of leading multipliers, an integer in [1, n - 2] with n the state dimension (default 12)");
  app.add_option("--arpack-tol", o->floquet.arpack.tol, "ARPACK's relative Ritz tolerance, in [0, 1) (default 1e-10)");
  app.add_option("--implicit-from-L", o->floquet.monodromy.implicit_from_L,
                 "use the rosenbrock variational integration for L >= this, an integer >= 0 (default 40; 0: never)");
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterFloquet{"floquet", "Leading Floquet multipliers of the full model along a scene's orbit",
                                       add_floquet, 33};
}  // namespace

}  // namespace rbcstab::cli
