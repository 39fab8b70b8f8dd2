#pragma once
// Scene files (TOML). Keys are the paper's symbols; docs/scenes.md lists them with their ranges.
#include <string>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct SceneFile {
  Scene scene;
  SimulationOptions options;  // the [integrator] table
};

// Parses TOML text; unknown keys, wrong types and out-of-range values throw InvalidArgument naming
// the key (as "table.key") and the allowed range.
SceneFile parse_scene(const std::string& toml_text, const std::string& source_name = "scene");
SceneFile load_scene(const std::string& path);
// Whether the TOML text sets run.L (when it does not, the CLI chooses L: analysis/truncation.hpp).
bool scene_sets_L(const std::string& toml_text, const std::string& source_name = "scene");
// The scene and options as TOML (round-trips through parse_scene).
std::string to_toml(const SceneFile& file);

}  // namespace rbcstab
