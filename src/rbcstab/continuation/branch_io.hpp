#pragma once
// The one rendering of continuation results (scene_continuation.hpp): the Branch JSON schema shared by
// `rbcstab continue --json`, the branch files (branch_file.hpp), the report's bifurcation panel and later
// bindings, CSV tables and the text summary with its table of labelled points.
//
// JSON of a branch: {"branch": [points], "special_points": [...], "status", "message", "counters"}; each
// point holds its parameter(s) by name, its measures by name (measure_names), "label" (an integer, null
// for an unlabelled point), "type" ("EP" at the two ends, "" otherwise), "stable", "n_unstable", the certified
// "stability" ("stable", "unstable" or "uncertain"), "margin", "margin_error" and its spectrum as [re, im]
// pairs ("eigenvalues" or "multipliers"); each special point "type", "name", "label", its parameter(s) and
// measures, "critical" (HB, PD, NS: the crossing eigenvalue or multiplier), "bracket", "precision", "status",
// "unstable_before", "unstable_after", "stability", "margin", "margin_error". A scene's branch adds "kind",
// "level", "free_parameter", "parameters" (the scene's), "beta", "segments" (orbits), "start" (StartPoint:
// "method", "p", "converged", "stable", "n_unstable", "refused", "message", the stability keys and for orbits
// "relaxation_periods", "periodicity_defect", "periodicity_tol", "relaxed") and "switched_branch" (the same
// schema plus "switched" and "bp_label", the label of the BP it switched at); a curve adds "curve": {"type",
// "parameters", "start", "one_parameter_points", "system"}, "one_parameter_branch" (the branch schema: the
// branch the curve started from, labelled first) and its "free_parameter" is the second parameter.
//
// CSV: the parameter(s), "branch" (primary / switched: kinds that can switch), the CSV measures
// (is_csv_measure), "stable", "n_unstable", for one-parameter branches "max_Re_eig" or
// "max_abs_multiplier", then "label" and "type"; one row per point and per special point, in order along
// the branch (a special point's stability columns are empty: its unstable count changes there); 17
// significant digits.
//
// Text: the summary (points, range, status, one line per special point, the switch), then AUTO's b-file
// table: one row per labelled point with BR (1: the primary or one-parameter branch, 2: the switched
// branch or the curve), PT (the point's index in "branch"; a special point k+ lies between points k and
// k + 1), TY, LAB, the parameter(s), the chosen measures and the stability.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_start.hpp"

namespace rbcstab {

// A point's spectrum under its JSON key ("eigenvalues" or "multipliers"), and its most unstable value,
// max Re(lambda) or max |mu|, under its CSV column ("max_Re_eig" or "max_abs_multiplier").
std::string spectrum_key(StabilityKind kind);
std::string most_unstable_key(StabilityKind kind);
double most_unstable(const Eigen::VectorXcd& spectrum, StabilityKind kind);

nlohmann::json to_json(const MeasuredBranch& branch);
// How a branch started (every StartPoint field; the relaxation keys for orbits only).
nlohmann::json to_json(const StartPoint& start, bool orbit);
nlohmann::json to_json(const SceneBranch& result);
nlohmann::json to_json(const SceneCurve& result);
nlohmann::json to_json(const ContinuationRun& run);
// What `rbcstab continue --json` prints: to_json(run) with its truncation, "L" and "L_reason".
nlohmann::json to_json(const ContinuationRun& run, const std::string& L_reason);

std::string to_csv(const SceneBranch& result);
std::string to_csv(const SceneCurve& result);
std::string to_csv(const ContinuationRun& run);

// The measures of the text table: none given -> those of r, Psi, sigma, Delta_2, omega, sigma_bar, mode,
// r_min, r_max, kind the branch has, in that order.
struct TableOptions {
  std::vector<std::string> measures;
  // Throws InvalidArgument("measures", ...) for a name not in `available`.
  void validate(const std::vector<std::string>& available) const;
  // The measures of a comma-separated list ("r,Psi,sigma"; the empty text: none, the default table). An empty
  // name ("r,,Psi", "r,") throws InvalidArgument("measures", ...).
  static TableOptions from_list(const std::string& comma_separated);
};

std::string to_text(const SceneBranch& result, const TableOptions& table = {});
std::string to_text(const SceneCurve& result, const TableOptions& table = {});
std::string to_text(const ContinuationRun& run, const TableOptions& table = {});

}  // namespace rbcstab
