#pragma once
// JSON views of results (nlohmann::json). Non-finite numbers become null with a note beside them.
#include <nlohmann/json.hpp>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

nlohmann::json to_json(const Parameters& p);  // the parameter table's material rows: inputs, then Lambda, S, alpha
nlohmann::json to_json(const Scene& s);
nlohmann::json to_json(const SimulationResult& r);
// {"2": v[0], "3": v[1], ...}
nlohmann::json by_mode(const std::vector<double>& values_from_l2);
// "L" and "L_reason" (why that L: SceneFile::L_reason), which every JSON output of a scene carries.
void put_truncation(nlohmann::json& j, const SceneFile& file);
void put_truncation(nlohmann::json& j, int L, const std::string& L_reason);
// A double, or null when not finite.
nlohmann::json number_or_null(double v);

}  // namespace rbcstab
