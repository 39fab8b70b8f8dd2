#pragma once
// Restarts from a labelled point of a run (AUTO's IRS): a branch (restart), a switch at a labelled BP
// (switch_at_label) or a special point's curve (restart_curve), and the request that picks one.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/monitors.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"

namespace rbcstab {

// What a restart changes in the run's spec; unset fields keep the run's values (the bounds: the run's when
// the parameter is the run's, none otherwise).
struct RestartChanges {
  std::optional<ProblemKind> kind;  // not a change: when set, it must be the run's (else InvalidArgument("kind"))
  std::optional<ContinuationParameter> parameter;  // default: the run's (a curve run: its first parameter)
  std::optional<double> p_min, p_max;
  std::optional<Direction> direction;
  // Tunable options by name (tunable_options.hpp: steps, Newton, location, the orbits' integration), each
  // checked against its range. segments cannot change (an orbit's labelled state lies on the run's mesh):
  // InvalidArgument("segments", ...) for another number.
  std::map<std::string, double> tuned;
  std::optional<std::size_t> max_points;
  std::optional<int> label_every;
  bool switch_at_bp = false;
  // Set: these replace the run's monitors and stops (empty: drops them); unset: the run's are kept.
  std::optional<std::vector<Monitor>> monitors;
};

// The spec that continues from label `label` of `run`: the run's kind, engine and orbit options, its
// problem scene with the labelled point's parameter values (a curve point: both) and the point's state as
// start_state (a curve point: the state of the problem the curve augments), the changes applied.
// Throws InvalidArgument("label", ...) for a label the run does not have, and as BranchSpec::validate.
BranchSpec restart_spec(const ContinuationRun& run, int label, const RestartChanges& changes = {});
// continue_scene(restart_spec(...)): labels from 1.
SceneBranch restart(const ContinuationRun& run, int label, const RestartChanges& changes = {});
// The run's branch that holds the BP labelled `label` (its labels kept) with the branch bifurcating there
// as its switched branch (labelled after the run's labels), continued with the run's options and the
// changes. Throws InvalidArgument("switch_at", ...) unless the label is a BP of a one-parameter branch,
// ("parameter", ...) for a parameter other than the branch's.
SceneBranch switch_at_label(const ContinuationRun& run, int label, const RestartChanges& changes = {});
// The curve of the special point labelled `label` (or of a point of a curve of the same type) in
// (the run's parameter, curve.parameter2); curve.point is ignored. Throws InvalidArgument("label", ...)
// for a point of another type, ("parameter", ...) for a parameter other than the run's, and as
// CurveSpec::validate.
SceneCurve restart_curve(const ContinuationRun& run, int label, const CurveSpec& curve,
                         const RestartChanges& changes = {});
// One restart request, as `rbcstab continue --restart` takes it: from label (a branch, or with curve that
// point's curve) or a switch at the BP labelled switch_at. validate() names the flags of a bad combination.
struct RestartRequest {
  int label = 0, switch_at = 0;
  std::optional<CurveSpec> curve;
  RestartChanges changes;
  void validate() const;
};
ContinuationRun restart(const ContinuationRun& run, const RestartRequest& request);

}  // namespace rbcstab
