#pragma once
// The one rendering of continuation results (scene_continuation.hpp): the Branch JSON schema shared by
// `rbcstab continue --json`, the report's bifurcation panel and later bindings, CSV tables and the text
// summary.
//
// JSON of a branch: {"branch": [points], "special_points": [...], "status", "message", "counters"}; each
// point holds its parameter(s) by name, its measures by name (measure_names), "stable", "n_unstable",
// the certified "stability" ("stable", "unstable" or "uncertain"), "margin", "margin_error" and its
// spectrum as [re, im] pairs ("eigenvalues" or "multipliers"); each special point "type",
// "name", its parameter(s) and measures, "critical" (HB, PD, NS: the crossing eigenvalue or multiplier),
// "bracket", "precision", "status", "unstable_before", "unstable_after", "stability", "margin",
// "margin_error". A scene's branch adds "kind", "level", "free_parameter", "parameters" (the scene's),
// "beta", "segments" (orbits), "start" (StartPoint: "method", "p", "converged", "stable", "n_unstable",
// "refused", "message", the stability keys and for orbits "relaxation_periods", "periodicity_defect",
// "periodicity_tol", "relaxed") and "switched_branch" (the same schema plus "switched"); a curve adds "curve": {"type", "parameters",
// "start", "one_parameter_points", "system"} and its "free_parameter" is the second parameter.
//
// CSV: the parameter(s), "branch" (primary / switched: kinds that can switch), the CSV measures
// (is_csv_measure), "stable", "n_unstable" and, for one-parameter branches, "max_Re_eig" or
// "max_abs_multiplier"; 17 significant digits.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/continuation/scene_continuation.hpp"

namespace rbcstab {

nlohmann::json to_json(const MeasuredBranch& branch);
nlohmann::json to_json(const SceneBranch& result);
nlohmann::json to_json(const SceneCurve& result);

std::string to_csv(const SceneBranch& result);
std::string to_csv(const SceneCurve& result);

// A few lines: the points and the range covered, the status, one line per special point.
std::string to_text(const SceneBranch& result);
std::string to_text(const SceneCurve& result);

}  // namespace rbcstab
