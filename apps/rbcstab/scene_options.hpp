#pragma once
// Scene flags shared by every subcommand that runs a scene: --scene FILE plus one flag per scene key that has
// one (io's scene_flags(): the parameter table's stored parameters, L, T, dt, model, stepper, rtol, atol and
// the per-mode perturbations), the [physical] keys' unit flags (--shear-rate, ...), and --full-horizon, which sets
// the scene key run.full_horizon.
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/verdict/shear_rate.hpp"

namespace rbcstab::cli {

// --shear-rate-range LO,HI (summary, report): the shear-rate threshold search of a physical scene
// (shear_rate_search, verdict/shear_rate.hpp).
void add_shear_rate_range(CLI::App& app, std::string& text);

struct SceneOptions {
  std::string scene_path;

  void add_to(CLI::App& app);  // the options bind to this object: it must not move afterwards
  // The default scene (paper Fig. 3, out of plane), then the scene file, then the flags; SceneFile::origins
  // records which. L as they give it.
  SceneFile read() const;
  // read(), then the truncation policy for this use (apply_truncation): scene.L and L_reason.
  SceneFile resolve(TruncationUse use) const;
  // The scene flags given on the command line, by name (e.g. "--lambda").
  std::vector<std::string> given_flags() const;

 private:
  struct Flag {
    const SceneKey* key = nullptr;
    CLI::Option* option = nullptr;
  };
  std::vector<Flag> flags_;
  // The values CLI11 parses into, by scene key path (std::map: the references stay valid).
  std::map<std::string, double> numbers_;
  std::map<std::string, long long> integers_;
  std::map<std::string, std::string> names_;
  std::map<std::string, std::vector<std::string>> modes_;
  std::map<std::string, bool> booleans_;
  bool full_horizon_ = false;
  CLI::Option* full_horizon_option_ = nullptr;
};

}  // namespace rbcstab::cli
