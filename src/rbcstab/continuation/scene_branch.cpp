// A one-parameter branch from a scene: its problem, start, branch, measures and labels, and the branch
// switched to at its first BP when asked.
#include "rbcstab/continuation/scene_branch.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "rbcstab/continuation/detail/branch_labels.hpp"
#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/continuation/detail/scene_switch.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

namespace {

using detail::assessed_start;
using detail::label_branch;
using detail::make_problem;
using detail::measure_branch;
using detail::switch_options;
using detail::switch_with;

}  // namespace

SceneBranch continue_scene(const BranchSpec& spec) {
  spec.validate();
  SceneBranch r;
  r.spec = spec;
  set_domain_bounds(r.spec.engine, spec.parameter, spec.engine.p_min, spec.engine.p_max);
  r.problem_scene = problem_scene_of(spec);
  const auto sp = make_problem(r.spec, r.problem_scene);
  r.start = assessed_start(*sp, r.spec, r.problem_scene);
  // An in-range input so extreme that the start overflows (lambda = 1e308) is a failed start, not bad input.
  const bool nonfinite_guess = r.start.converged && !r.start.x.allFinite();
  if (nonfinite_guess || (r.start.newton && !std::isfinite(r.start.residual_norm))) {
    r.start.converged = false;
    r.start.message = "the start state is " + nonfinite_reason(r.problem_scene.parameters);
  }
  Branch b;
  if (r.start.converged && !r.start.refused) {
    ContinuationOptions engine = r.spec.engine;
    for (UserEvent& e : sp->events()) engine.events.push_back(std::move(e));
    for (UserEvent& e :
         detail::monitor_events(*sp, measure_names(spec.kind, r.problem_scene.L), spec.monitors, r.start.x, r.start.p))
      engine.events.push_back(std::move(e));
    b = continue_branch(sp->problem(), r.start.x, r.start.p, engine);
  } else {
    b.parameter_names = sp->problem().parameter_names();
    b.status = ContinuationStatus::start_failed;
    b.message = r.start.message;
  }
  r.branch = measure_branch(*sp, r, std::move(b));
  const int next = label_branch(r.branch, spec.label_every, 1);
  if (spec.switch_at_bp)
    r.switched = switch_with(*sp, r, r.branch, std::max(1, first_bp_met(r.branch.branch, r.spec.engine.direction)),
                             switch_options(r), next);
  return r;
}

}  // namespace rbcstab
