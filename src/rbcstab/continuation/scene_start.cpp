// How a scene branch starts: the kind's start (its SceneProblem's, scene_problem.cpp) or a restart's given
// state solved by Newton at fixed p, then its certified stability; an orbit certified unstable is refused.
#include "rbcstab/continuation/scene_start.hpp"

#include <iomanip>
#include <sstream>
#include <string>
#include <utility>

#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::assessed_start;
using detail::make_problem;
using detail::newton_start;
using detail::SceneProblem;

// The start of a branch: a restart's given state, solved by Newton at fixed p, else the kind's start.
StartPoint start_of(const SceneProblem& sp, const BranchSpec& spec, const Scene& scene) {
  if (!spec.start_state) return sp.start(spec);
  const Eigen::Index n = sp.problem().dimension();
  if (spec.start_state->size() != n || !spec.start_state->allFinite())
    throw InvalidArgument("start_state", "start_state has " + std::to_string(spec.start_state->size()) +
                                             " entries: must be " + std::to_string(n) +
                                             " finite numbers (the problem's unknowns for --kind " +
                                             to_string(spec.kind) + ")");
  return newton_start(sp.problem(), StartMethod::restart, *spec.start_state,
                      spec.start_parameter ? *spec.start_parameter : get_parameter(scene, spec.parameter),
                      "solution near the labelled point's state",
                      "the labelled point is not a solution of this problem");
}

}  // namespace

namespace detail {

StartPoint given_start(StartMethod method, Eigen::VectorXd x, double p) {
  StartPoint s;
  s.method = method;
  s.x = std::move(x);
  s.p = p;
  return s;
}

StartPoint newton_start(const ContinuationProblem& problem, StartMethod method, const Eigen::VectorXd& guess, double p,
                        const std::string& what, const std::string& hint) {
  const NewtonResult r = solve_fixed_parameter(problem, guess, p);
  StartPoint s = given_start(method, r.x, p);
  s.newton = true;
  s.converged = r.converged;
  s.iterations = r.iterations;
  s.residual_norm = r.residual_norm;
  if (!r.converged) {
    std::ostringstream m;
    m << "no " << what << " (Newton residual " << r.residual_norm << " after " << r.iterations << " iterations); "
      << hint;
    s.message = m.str();
  }
  return s;
}

StartPoint assessed_start(const SceneProblem& sp, const BranchSpec& spec, const Scene& scene) {
  StartPoint s = start_of(sp, spec, scene);
  if (!s.converged) return s;
  const ContinuationProblem& pr = sp.problem();
  StabilityCertificate c;
  try {
    // Equilibria whose start the engine's Newton polishes: solved here for the reading only (x stays).
    Eigen::VectorXd x = s.x;
    if (!s.newton) {
      const NewtonResult n = solve_fixed_parameter(pr, s.x, s.p, spec.engine.newton_tol);
      if (!n.converged) return s;  // the engine reports the failure
      x = n.x;
    }
    c = certify_solution(pr, x, s.p, spec.engine.newton_tol);
    s.n_unstable = count_unstable(pr.spectrum(x, s.p), pr.stability_kind(), spec.engine.stability_tol);
  } catch (const InvalidArgument&) {
    return s;  // the start lies outside the problem's domain: the engine reports it (outside_domain)
  }
  s.stable = s.n_unstable == 0;
  s.stability = c.stability;
  s.margin = c.margin;
  s.margin_error = c.margin_error;
  s.uncertain_because = c.uncertain_because;
  if (c.stability == Stability::stable) return s;
  const bool orbit = is_orbit(spec.kind);
  std::ostringstream m;
  m << std::setprecision(6) << "the start at " << to_string(spec.parameter) << " = " << s.p << " is ";
  if (c.stability == Stability::unstable)
    m << "an unstable " << sp.solution_name() << " (" << s.n_unstable << " unstable "
      << (orbit ? "multipliers, max |mu| = " : "eigenvalues, max Re = ") << (orbit ? 1 - c.margin : -c.margin)
      << ", margin " << c.margin << " +- " << std::setprecision(2) << c.margin_error << ")";
  else
    m << "of uncertain stability (" << sp.solution_name() << ", margin " << c.margin << " within its error "
      << std::setprecision(2) << c.margin_error << ")";
  s.refused = orbit && c.stability == Stability::unstable && !spec.allow_unstable_start && !spec.start_state;
  if (s.refused)
    m << std::setprecision(3) << " (Newton from the scene's state after " << s.relaxation_periods
      << " periods, periodicity defect " << s.periodicity_defect
      << "): perturbations leave it, so a simulation does not show it. Pass --allow-unstable-start to continue "
         "from it, or relax longer (--relax-T) to start on an attracting orbit";
  else if (c.stability == Stability::unstable)
    m << (orbit ? ": continued from it (allowed)" : ": continued from it");
  s.message = s.message.empty() ? m.str() : m.str() + "; " + s.message;
  return s;
}

}  // namespace detail

StartPoint find_start(const BranchSpec& spec) {
  spec.validate();
  const Scene scene = problem_scene_of(spec);
  return assessed_start(*make_problem(spec, scene), spec, scene);
}

}  // namespace rbcstab
