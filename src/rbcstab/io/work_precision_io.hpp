#pragma once
// CSV, JSON and text views of a work-precision table (integrate/work_precision.hpp), shared by the command line
// (`rbcstab bench work-precision`) and any other front end. A missing number is an empty CSV field, a JSON null
// with "<key>_reason", "n/a" in text.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/integrate/work_precision.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

// level, stepper, rtol, status, counters, seconds, error_Delta, error_sigma, l_Delta, verdict_changed: one row each.
std::string work_precision_csv(const WorkPrecisionTable& t);
// {scene, reference: {level, stepper, rtol, status, reason, Delta_final, l_Delta, sigma_final, spread_vs_modal},
// rows, L, L_reason}.
nlohmann::json work_precision_json(const SceneFile& file, const WorkPrecisionTable& t);
// The reference, then one aligned line per row.
std::string work_precision_text(const WorkPrecisionTable& t);

}  // namespace rbcstab
