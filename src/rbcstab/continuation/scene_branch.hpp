#pragma once
// A one-parameter branch continued from a scene (SceneBranch, continue_scene) and the branch bifurcating
// at one of its BPs (SwitchedBranch, switch_at_bp; scene_switch.cpp).
#include <optional>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_start.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// The branch that bifurcates at a BP of a branch.
struct SwitchedBranch {
  bool switched = false;  // false: message says why (no such BP, not a simple BP, corrector failed)
  std::string message;
  int bp_number = 1;      // the k-th BP of the branch it switched from
  int bp_label = 0;       // that BP's label (0: none)
  MeasuredBranch branch;  // labelled after the branch it switched from
};

struct SceneBranch {
  BranchSpec spec;      // as run: the engine's bounds set by set_domain_bounds
  Scene problem_scene;  // the problem's scene (modal_orbit: spec.scene with its total excess area as Delta)
  StartPoint start;
  MeasuredBranch branch;                   // status start_failed (no points) when the start did not converge
  std::optional<SwitchedBranch> switched;  // spec.switch_at_bp: at the first BP met (first_bp_met)
};

// The number k (find_special_point) of the first BP of b met from its start, continued in `direction`:
// the first along the branch for forward and backward, the one nearest the start in arclength for both.
// 0 if b has no BP.
int first_bp_met(const Branch& b, Direction direction);

// Validates spec, finds the start and continues the branch (orbits with the swing_tumble UZ event).
SceneBranch continue_scene(const BranchSpec& spec);

// The branch bifurcating at the k-th BP of `from` (equilibrium, modal, full), continued with
// from.spec.engine or options.continuation. Throws InvalidArgument("switch_at_bp", ...) for kinds that
// cannot switch and ("bp", ...) for k < 1.
SwitchedBranch switch_at_bp(const SceneBranch& from, int k = 1);
SwitchedBranch switch_at_bp(const SceneBranch& from, int k, const BranchSwitchOptions& options);

// The number of unknowns of a branch's problem (its spec on its problem scene).
Eigen::Index problem_dimension(const SceneBranch& r);

}  // namespace rbcstab
