#pragma once
// Module-private: labelling a branch and finding a run's branches and last label (branch_labels.cpp); a
// branch, its switched branch and a curve read them to number after one another.
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_measures.hpp"

namespace rbcstab::detail {

// Labels along the branch from `next`: each point that is an end or a label_every-th point, then the
// special points that follow it. Returns the next free label.
int label_branch(MeasuredBranch& m, int label_every, int next);
// Branch 1 of a run (the primary or the one-parameter branch) or 2 (the switched branch or the curve);
// nullptr if the run has no such branch.
const MeasuredBranch* branch_of(const ContinuationRun& run, int b);
int run_last_label(const SceneBranch& r);
int run_last_label(const ContinuationRun& run);

}  // namespace rbcstab::detail
