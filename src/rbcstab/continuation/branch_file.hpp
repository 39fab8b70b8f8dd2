#pragma once
// Branch files: a run (scene_continuation.hpp) saved with everything a restart needs, and loaded back
// validated, so that restart / switch_at_label / restart_curve can start from any of its labels (AUTO's
// b- and s-files in one JSON). A file is the run's JSON (branch_io.hpp) plus
//   "format": "rbcstab-branch", "version": 1;
//   in every branch object (the run's, "switched_branch", a curve's "one_parameter_branch"): "spectrum"
//   ("eigenvalues" or "multipliers"), per point "x" (the full state: the problem's unknowns; a curve's
//   points: the curve system's), "p" (the free parameter), "arclength", "newton_iterations", per special
//   point "x", "p", "after_index", "test_value", "eigenvalue"; "switched_branch" also "bp_number";
//   "spec": {"scene" (TOML, io/scene_file.hpp), "kind", "parameter", "engine" (every number of
//   ContinuationOptions, the direction by name, unbounded limits null), "relax_T", "orbit", "label_every",
//   "switch_at_bp", "start_state" (null, or a restart's start), "monitor" and "stop_at" (the monitors' texts,
//   NAME=V1,V2,...; absent when none)};
//   "start": the start point (method, p, newton, converged, iterations, residual_norm, message);
//   a curve: "curve_spec" {"type", "parameter2", "p2_min", "p2_max", "point", "symmetric_tol"},
//   "curve_start" (the special point it started from, with "x", "p", "eigenvalue"), "start_p2",
//   "started", "curve_message".
// A number stored as null (a measure or spectral value that is not finite) reads back as NaN; x, p,
// parameters and arclength must be finite.
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/continuation/branch_labels.hpp"

namespace rbcstab {

inline constexpr const char* kBranchFileFormat = "rbcstab-branch";
inline constexpr int kBranchFileVersion = 1;

nlohmann::json branch_file_json(const ContinuationRun& run);
// The file's "spec": everything of a BranchSpec but its functions (progress, stop, a function monitor).
nlohmann::json branch_spec_json(const BranchSpec& spec);
// Writes branch_file_json(run) atomically (io/files.hpp); throws std::runtime_error naming the path.
void save_branch(const std::string& path, const ContinuationRun& run);

// The run a branch file holds. Every key is checked (format, version, kinds and names, sizes of every
// state against the problem's dimension, finite numbers, labels positive and unique); anything else
// throws InvalidArgument(name, "name = 'source' ...") naming the key and its value: a file that is not a
// branch file, a truncated file, a newer version.
ContinuationRun parse_branch_file(const std::string& text, const std::string& source,
                                  const std::string& name = "restart");
// The same from the file's JSON, parsed already (a diagram journal's record holds it).
ContinuationRun parse_branch_json(const nlohmann::json& file, const std::string& source,
                                  const std::string& name = "restart");
ContinuationRun load_branch(const std::string& path, const std::string& name = "restart");

}  // namespace rbcstab
