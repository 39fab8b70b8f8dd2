#pragma once
// JSON and text views of a scene's Floquet multipliers (scene_floquet_multipliers), shared by the command line
// and any other front end.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/continuation/monodromy.hpp"

namespace rbcstab {

// Status, the scene's parameters and beta, the relaxation and monodromy diagnostics and the multipliers
// ({re, im, abs}, largest first); the caller adds the truncation (put_truncation).
nlohmann::json floquet_json(const Scene& scene, const SceneFloquetOptions& options, const SceneFloquetResult& r);
// One line of diagnostics, then one line per multiplier.
std::string floquet_text(const Scene& scene, const SceneFloquetOptions& options, const SceneFloquetResult& r);

}  // namespace rbcstab
