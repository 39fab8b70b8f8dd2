// The problem of each kind behind a scene branch: its construction (make_problem), its own start (equilibria:
// the relaxed state or the closed form; orbits: relaxation, then Newton) and its measures.
#include "rbcstab/continuation/detail/scene_problem.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_start.hpp"
#include "rbcstab/core/constants.hpp"

namespace rbcstab {

namespace {

using detail::equilibrium_values;
using detail::given_start;
using detail::make_problem;
using detail::newton_start;
using detail::orbit_values;
using detail::SceneProblem;
using detail::Values;

// The start of each level's equilibria (StartMethod in the header says why).
StartPoint equilibrium_start(const ReducedEquilibriumProblem& pr, const BranchSpec& spec) {
  return given_start(StartMethod::relaxed, pr.relaxed_state(spec.relax_T), pr.start_parameter());
}
StartPoint equilibrium_start(const ModalEquilibriumProblem& pr, const BranchSpec&) {
  const double p0 = pr.start_parameter();
  return given_start(StartMethod::ellipsoidal, pr.ellipsoidal_state(p0), p0);  // the engine's Newton polishes it
}
StartPoint equilibrium_start(const FullEquilibriumProblem& pr, const BranchSpec& spec) {
  const double p0 = pr.start_parameter();
  const auto& rest = pr.scene().rest_delta_l;
  if (std::any_of(rest.begin(), rest.end(), [](const auto& kv) { return kv.second > 0; }))
    return newton_start(pr, StartMethod::relaxed, pr.relaxed_state(spec.relax_T), p0,
                        "full-model equilibrium near the relaxed state");
  return newton_start(pr, StartMethod::ellipsoidal, pr.ellipsoidal_state(p0), p0,
                      "full-model equilibrium near the ellipsoid");
}

// Equilibria of one level (Problem: ReducedEquilibriumProblem, ModalEquilibriumProblem, FullEquilibriumProblem).
template <class Problem>
class Equilibrium final : public SceneProblem {
 public:
  Equilibrium(const Scene& scene, ContinuationParameter q) : pr_(scene, q) {}
  const ContinuationProblem& problem() const override { return pr_; }
  StartPoint start(const BranchSpec& spec) const override { return equilibrium_start(pr_, spec); }
  Values measures(const Eigen::VectorXd& x, double p) const override { return equilibrium_values(pr_, x, p); }

 private:
  Problem pr_;
};

// Orbits of the forced reduced system or modal model (System: ReducedForcedSystem, ModalForcedSystem).
template <class System>
class Orbit final : public SceneProblem {
 public:
  Orbit(const Scene& scene, ContinuationParameter q, const OrbitOptions& options)
      : sys_(scene, q), pr_(sys_, options) {}
  const ContinuationProblem& problem() const override { return pr_; }
  // The scene relaxed for relax_T, then period by period to relax_tol (PeriodicOrbitProblem::relax), then Newton.
  StartPoint start(const BranchSpec& spec) const override {
    const double p0 = sys_.start_parameter();
    Eigen::VectorXd x0;
    if constexpr (std::is_same_v<System, ModalForcedSystem>) {
      std::string failure;
      x0 = sys_.relaxed_state(spec.scene, spec.relax_T, spec.orbit.poll, 1e-11, &failure);
      if (!failure.empty()) {
        StartPoint s = given_start(StartMethod::relaxed, x0, p0);
        s.converged = false;
        s.message = "the relaxing simulation failed: " + failure;
        return s;
      }
    } else {
      x0 = sys_.relaxed_state(spec.relax_T, spec.orbit.poll);
    }
    const OrbitRelaxation r = pr_.relax(x0, p0, spec.relax_tol, spec.relax_max_periods);
    StartPoint s =
        newton_start(pr_, StartMethod::relaxed, pr_.shooting_guess(r.x, p0), p0,
                     std::is_same_v<System, ModalForcedSystem> ? "periodic orbit near the relaxed modal state"
                                                               : "periodic orbit near the relaxed state");
    s.relaxation_periods = static_cast<int>(std::ceil(spec.relax_T / (2 * kPi))) + r.periods;
    s.periodicity_defect = r.defect;
    s.periodicity_tol = spec.relax_tol;
    s.relaxed = r.converged;
    std::ostringstream m;
    m << std::setprecision(4);
    if (!r.failure.empty())
      m << "the relaxation failed after " << s.relaxation_periods << " periods (" << r.failure << ")";
    else if (!r.converged)
      m << "the relaxation reached its bound of " << spec.relax_max_periods
        << " periods after relax_T with periodicity defect " << r.defect << " > " << spec.relax_tol
        << " (a slow transient, or an attractor that is not periodic)";
    if (!m.str().empty()) s.message = s.message.empty() ? m.str() : s.message + "; " + m.str();
    return s;
  }
  Values measures(const Eigen::VectorXd& X, double p) const override { return orbit_values(pr_, sys_, X, p); }
  std::vector<UserEvent> events() const override { return {pr_.transition_event()}; }
  const char* solution_name() const override { return "periodic orbit"; }

 private:
  System sys_;  // before pr_, which refers to it
  PeriodicOrbitProblem pr_;
};

}  // namespace

namespace detail {

std::unique_ptr<SceneProblem> make_problem(const BranchSpec& spec, const Scene& scene) {
  switch (spec.kind) {
    case ProblemKind::equilibrium:
      return std::make_unique<Equilibrium<ReducedEquilibriumProblem>>(scene, spec.parameter);
    case ProblemKind::modal:
      return std::make_unique<Equilibrium<ModalEquilibriumProblem>>(scene, spec.parameter);
    case ProblemKind::full:
      return std::make_unique<Equilibrium<FullEquilibriumProblem>>(scene, spec.parameter);
    case ProblemKind::orbit:
      return std::make_unique<Orbit<ReducedForcedSystem>>(scene, spec.parameter, spec.orbit);
    case ProblemKind::modal_orbit:
      return std::make_unique<Orbit<ModalForcedSystem>>(scene, spec.parameter, spec.orbit);
  }
  throw std::logic_error("unknown problem kind");
}

MeasuredBranch measure_branch(const SceneProblem& sp, const SceneBranch& r, Branch b) {
  return measured(std::move(b), measure_names(r.spec.kind, r.problem_scene.L), sp.problem().stability_kind(),
                  [&](const Eigen::VectorXd& x, double p) { return sp.measures(x, p); });
}

}  // namespace detail

Eigen::Index problem_dimension(const SceneBranch& r) {
  return make_problem(r.spec, r.problem_scene)->problem().dimension();
}

Scene problem_scene_of(const BranchSpec& spec) {
  return spec.kind == ProblemKind::modal_orbit && !spec.start_state ? total_area_scene(spec.scene) : spec.scene;
}

}  // namespace rbcstab
