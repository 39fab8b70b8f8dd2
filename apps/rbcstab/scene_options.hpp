#pragma once
// Scene flags shared by every subcommand that runs a scene: --scene FILE plus per-symbol overrides.
#include <CLI/CLI.hpp>
#include <string>

#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {
struct ReducedTransient;  // analysis/predictors.hpp
}  // namespace rbcstab

namespace rbcstab::cli {

struct SceneOptions {
  std::string scene_path;
  Scene flags;  // values given on the command line (only the ones with count() > 0 apply)
  std::string model = "auto", stepper = "rk8pd";
  double rtol = 1e-8, atol = 1e-12;
  CLI::Option *o_lambda{}, *o_Delta{}, *o_Delta0{}, *o_B{}, *o_C{}, *o_beta{}, *o_delta{}, *o_L{}, *o_T{}, *o_dt{},
      *o_model{}, *o_stepper{}, *o_rtol{}, *o_atol{};
  std::vector<std::string> delta_l, rest_delta_l;  // "l=value"
  CLI::Option *o_delta_l{}, *o_rest_delta_l{};

  void add_to(CLI::App& app);
  // The default scene (paper Fig. 3, out of plane), then the scene file, then the flags.
  SceneFile resolve() const;
  // resolve(), then, unless --L or the file's run.L gave L, the smallest L meeting the truncation tolerance
  // (choose_truncation, docs/benchmarks.md "Automatic L"); the choice and its reason land in L_reason.
  // transient (optional): receives the scene's truncation_transient, which the rule then reads, so that the
  // finite-horizon predictor can share the run.
  SceneFile resolve_with_default_L(std::string& L_reason, ReducedTransient* transient = nullptr) const;
};

}  // namespace rbcstab::cli
