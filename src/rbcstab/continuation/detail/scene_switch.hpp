#pragma once
// Module-private: switching at a BP of a scene branch (scene_switch.cpp), shared by continue_scene, switch_at_bp
// and switch_at_label.
#include <string>

#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"

namespace rbcstab::detail {

// The modal orbit's BPs (a mode's multiplier crossing 1, a_l -> -a_l) switch like equilibria
// (switch_branch is generic). The reduced in-plane orbit has none: its period map is a Moebius map, whose
// two nontrivial multipliers k, conj(k) share |k| = exp(int Upsilon_2 dt); a multiplier 1 needs |k| = 1, an
// elliptic map under which every orbit is neutral.
void require_switchable(ProblemKind kind, const std::string& flag = "switch_at_bp");
// The branch bifurcating at the k-th BP of `on` (a branch of from's problem), labelled from first_label.
SwitchedBranch switch_with(const SceneProblem& sp, const SceneBranch& from, const MeasuredBranch& on, int k,
                           const BranchSwitchOptions& options, int first_label);
BranchSwitchOptions switch_options(const SceneBranch& from);

// Why a scene's PD is not switched at (the diagram's not_available outcome, --switch-at's refusal): the doubled
// orbit is a PeriodicOrbitProblem of its own (2 periods) that the scene kinds, measures and branch files do not
// describe. This model's reduced orbits have no PD at all (above).
inline constexpr const char* kScenePeriodDoublingRefusal =
    "the doubled orbit of a scene's PD (2 periods) has no scene kind, measures or branch file yet "
    "(switch_at_period_doubling does it for a PeriodicOrbitProblem in C++)";

}  // namespace rbcstab::detail
