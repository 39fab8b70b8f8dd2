// rbcstab thresholds: the paper's instability thresholds for a scene, each with its domain, beside the exact
// finite-S out-of-plane criterion and the asymptotic and finite-horizon predictions (no modal simulation).
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "rbcstab/verdict/verdict_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ThresholdsOptions {
  SceneOptions scene;
  bool json = false;
  bool exact_C_star = false;
};

int run(const ThresholdsOptions& o) {
  SceneFile sf = o.scene.read_unchecked();
  const ValidScene valid = validated(sf);  // the one check, for the truncation and the report
  apply_truncation(sf, valid, TruncationUse::analysis);
  const ThresholdReport t = threshold_report(valid, o.exact_C_star);
  if (o.json)
    std::cout << thresholds_json(sf, t).dump(2) << "\n";
  else
    std::cout << thresholds_text(sf, t);
  return kOk;
}

Runner add_thresholds(CLI::App& app) {
  auto o = std::make_shared<ThresholdsOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  app.add_flag("--exact-C-star", o->exact_C_star,
               "also solve sigma_R(exact equilibrium) = sigma_* for C over the paper's range [e^-5.5, e^2]");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterThresholds{
    "thresholds", "Instability thresholds and predicted unstable modes of a scene (no simulation)", add_thresholds, 30};
}  // namespace

}  // namespace rbcstab::cli
