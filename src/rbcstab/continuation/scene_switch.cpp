// Switching at a BP of a scene branch: the BP a run switches at (first_bp_met) and the branch bifurcating
// there, continued and labelled after the branch it switched from.
#include "rbcstab/continuation/detail/scene_switch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "rbcstab/continuation/detail/branch_labels.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::label_branch;
using detail::make_problem;
using detail::measure_branch;
using detail::require_switchable;
using detail::run_last_label;
using detail::switch_options;
using detail::switch_with;

}  // namespace

namespace detail {

void require_switchable(ProblemKind kind, const std::string& flag) {
  if (kind == ProblemKind::orbit)
    throw InvalidArgument(flag, "--" + std::string(flag == "switch_at" ? "switch-at" : "switch-at-bp") +
                                    " is available for --kind equilibrium, modal and full (and modal-orbit), not "
                                    "orbit: the reduced in-plane orbit has no BP (its nontrivial multipliers are a "
                                    "conjugate pair of one modulus)");
}

SwitchedBranch switch_with(const SceneProblem& sp, const SceneBranch& from, const MeasuredBranch& on, int k,
                           const BranchSwitchOptions& options, int first_label) {
  require_switchable(from.spec.kind);
  require(k >= 1, "bp", k, "an integer >= 1 (the k-th BP of the branch)");
  SwitchedBranch s;
  s.bp_number = k;
  const Branch& b = on.branch;
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP, k);
  if (!bp) {
    const auto n = std::count_if(b.special_points.begin(), b.special_points.end(),
                                 [](const SpecialPoint& p) { return p.type == SpecialPointType::BP; });
    s.message = n == 0 ? "--switch-at-bp: the branch has no BP (branch point) to switch at"
                       : "--switch-at-bp: the branch has " + std::to_string(n) + " BP(s), no BP number " +
                             std::to_string(k) + " to switch at";
    Branch none;
    none.parameter_names = sp.problem().parameter_names();
    s.branch = measure_branch(sp, from, std::move(none));
    return s;
  }
  s.bp_label = on.special_labels.at(static_cast<std::size_t>(bp - b.special_points.data()));
  // The run's monitors label (or stop) the switched branch too.
  BranchSwitchOptions o = options;
  for (UserEvent& e :
       monitor_events(sp, measure_names(from.spec.kind, from.problem_scene.L), from.spec.monitors, bp->x, bp->p))
    o.continuation.events.push_back(std::move(e));
  BranchSwitchResult sw = switch_branch(sp.problem(), b, *bp, o);
  s.switched = sw.switched;
  s.message = sw.message;
  s.branch = measure_branch(sp, from, std::move(sw.branch));
  label_branch(s.branch, from.spec.label_every, first_label);
  return s;
}

BranchSwitchOptions switch_options(const SceneBranch& from) {
  BranchSwitchOptions o;
  o.continuation = from.spec.engine;
  return o;
}

}  // namespace detail

int first_bp_met(const Branch& b, Direction direction) {
  int k = 0, best = 0;
  double best_s = std::numeric_limits<double>::infinity();
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type != SpecialPointType::BP) continue;
    ++k;
    if (direction != Direction::both) return k;  // the branch runs from its start
    // Arclength from the start: that of the bracketing point nearer the start plus the distance to it.
    const BranchPoint& a = b.points.at(sp.after_index);
    const BranchPoint& c = b.points.at(sp.after_index + 1);
    const BranchPoint& near = a.arclength >= 0 ? a : c;
    Eigen::VectorXd d(sp.x.size() + 1);
    d << sp.x - near.x, sp.p - near.p;
    const double s = std::abs(near.arclength) + d.norm();
    if (s < best_s) best_s = s, best = k;
  }
  return best;
}

SwitchedBranch switch_at_bp(const SceneBranch& from, int k) { return switch_at_bp(from, k, switch_options(from)); }

SwitchedBranch switch_at_bp(const SceneBranch& from, int k, const BranchSwitchOptions& options) {
  require_switchable(from.spec.kind);
  return switch_with(*make_problem(from.spec, from.problem_scene), from, from.branch, k, options,
                     run_last_label(from) + 1);
}

}  // namespace rbcstab
