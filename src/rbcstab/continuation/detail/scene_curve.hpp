#pragma once
// Module-private: starting and tracing a special point's curve (scene_curve.cpp), shared by continue_curve and
// restart_curve.
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"

namespace rbcstab::detail {

// A curve's result before it runs: its spec (bounds as run) and the branch it starts from.
SceneCurve curve_header(const SceneBranch& one, const CurveSpec& spec);
// Continues r's curve from sp, a special point of r.one's problem (x its state, p the first parameter's
// value), labelled from first_label; a point that was not located is a reason, not a start.
void trace_curve(SceneCurve& r, const SpecialPoint& sp, int first_label);

}  // namespace rbcstab::detail
