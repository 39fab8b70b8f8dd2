#pragma once
// Continuation of a scene: the typed entry points behind `rbcstab continue` and the report's
// [continuation] panel. A BranchSpec names what to continue (the problem kind, the free parameter, its
// bounds, the engine options); continue_scene picks the problem and its start, continues the branch and
// measures every point by name; continue_curve continues a special point's curve in a second parameter
// (choosing the curve system); switch_at_bp follows the branch bifurcating at a BP. Every point a user
// may restart from carries a label (AUTO's LAB); restart, switch_at_label and restart_curve start again
// from a labelled point of a run (branch_file.hpp saves and loads runs). Results are plain data;
// branch_io.hpp renders them (JSON, CSV, text).
//
// This header includes all of it; each part has its own:
//   scene_kinds.hpp     ProblemKind, CurveKind, CurveSystem and their names
//   scene_measures.hpp  the measures of a point by name; MeasuredBranch
//   branch_spec.hpp     BranchSpec, the free parameter's bounds
//   scene_start.hpp     StartPoint, find_start
//   scene_branch.hpp    SceneBranch, continue_scene; SwitchedBranch, switch_at_bp
//   scene_curve.hpp     CurveSpec, curve_system, SceneCurve, continue_curve
//   branch_labels.hpp   ContinuationRun, its labelled points
//   scene_restart.hpp   restart, switch_at_label, restart_curve
//   scene_run.hpp       scene_run, continue_run, curve_spec, outcome
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_restart.hpp"
#include "rbcstab/continuation/scene_run.hpp"
#include "rbcstab/continuation/scene_start.hpp"
