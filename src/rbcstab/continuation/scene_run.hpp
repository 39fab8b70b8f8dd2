#pragma once
// A run as a front end asks for it (`rbcstab continue`, the Python module): a fresh run from a scene file
// (scene_run, continue_run), a curve by names (curve_spec), and how a run ended (outcome, run_L).
#include <optional>
#include <string>

#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

// The curve of the point-th located special point of type `type` in (the branch's parameter, parameter2):
// the type and parameter2 by name (InvalidArgument "curve" / "parameter2" listing the allowed names; an
// empty parameter2 stays unset, which CurveSpec::validate refuses), the bounds neither NaN nor beyond
// parameter2's closed domain edges (require_bounds_in_domain), named min2_name / max2_name in messages.
CurveSpec curve_spec(const std::string& type, const std::string& parameter2, double p2_min, double p2_max,
                     int point = 1, const std::string& min2_name = "min2", const std::string& max2_name = "max2");

// A fresh run (not a restart) from a scene file.
struct SceneRun {
  // spec.scene is the file's scene with the kind's truncation (apply_truncation) and, when the file leaves
  // beta at its default, the kind's default beta (default_beta).
  BranchSpec spec;
  std::optional<CurveSpec> curve;  // set: the curve of a special point of the branch instead of the branch
  std::string L_reason;            // why spec.scene.L (put_truncation)
};
// `spec` as given but its scene taken from `file` (as read: L as given); the bounds spec.engine.p_min/p_max
// neither NaN nor beyond the parameter's closed domain edges, named min_name / max_name in messages.
SceneRun scene_run(SceneFile file, BranchSpec spec, std::optional<CurveSpec> curve = {},
                   const std::string& min_name = "min", const std::string& max_name = "max");
// continue_curve(run.spec, *run.curve), or continue_scene(run.spec) without a curve.
ContinuationRun continue_run(const SceneRun& run);
// Why a run restarted from a saved run (or loaded from a branch file) has its L: the saved scene's.
std::string saved_run_L_reason(const ContinuationRun& run);

// A branch that ends at a stop condition or on the edge of its parameter's domain has ended normally.
bool ended_normally(ContinuationStatus status);

// How a run ended, for a front end: whether it has output to show (a start that failed or was refused has
// none), a note (an unstable equilibrium start), and why it failed ("" when it did not): a failed start, a
// failed switch, or a branch or curve that stopped before a normal end.
struct RunOutcome {
  bool has_output = true;
  std::string note;
  std::string failure;
};
RunOutcome outcome(const SceneBranch& run);
RunOutcome outcome(const SceneCurve& run);
RunOutcome outcome(const ContinuationRun& run);
// The truncation L of a run's scene (a curve: that of the branch it starts from).
int run_L(const SceneBranch& run);
int run_L(const SceneCurve& run);
int run_L(const ContinuationRun& run);

}  // namespace rbcstab
