#pragma once
// JSON, text and CSV views of one scene file's simulation, shared by the command line and any other front end.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

// to_json(r) with the scene's parameters, the integrator (stepper, rtol, atol) and the truncation (L, L_reason).
nlohmann::json simulation_json(const SceneFile& file, const SimulationResult& r);
// One line (model, status, l_Delta, sigma(T), drift, steps), then the truncation reason, then the early
// termination when the run stopped early.
std::string simulation_text(const SceneFile& file, const SimulationResult& r);
// t, Delta_2..Delta_L, sigma, r, Psi, integrated on the sampling grid, round-trip digits; a sample a certified
// early stop skipped has empty fields and integrated = 0 (Trajectory).
std::string trajectory_csv(const SimulationResult& r);

}  // namespace rbcstab
