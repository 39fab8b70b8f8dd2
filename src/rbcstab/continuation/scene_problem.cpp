// The problem of each kind behind a scene branch: its construction (make_problem), its own start (equilibria:
// the relaxed state or the closed form; orbits: relaxation, then Newton) and its measures.
#include "rbcstab/continuation/detail/scene_problem.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
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

// The (l, m) of each unknown: none for the reduced system (its unknowns are the l = 2 block's only, no BP
// of another mode exists), (Re z, Im z, w, Re v, Im v, a_3..a_L) for the modal level, x_{l,m} for the full.
std::vector<detail::ShapeMode> modes_of(const ReducedEquilibriumProblem&) { return {}; }
std::vector<detail::ShapeMode> modes_of(const ModalEquilibriumProblem& pr) {
  std::vector<detail::ShapeMode> out{{2, 2}, {2, 2}, {2, 0}, {2, 1}, {2, 1}};
  for (int l = 3; l <= pr.L(); ++l) out.push_back({l, -1});  // a_l: the amplitude of every m of mode l
  return out;
}
std::vector<detail::ShapeMode> modes_of(const FullEquilibriumProblem& pr) {
  std::vector<detail::ShapeMode> out(static_cast<std::size_t>(pr.dimension()));
  for (int l = 2; l <= pr.L(); ++l)
    for (int m = 0; m <= l; ++m)
      for (int k = 0; k < (m == 0 ? 1 : 2); ++k)
        out[static_cast<std::size_t>(FullEquilibriumProblem::index(l, m) + k)] = {l, m};
  return out;
}

// Equilibria of one level (Problem: ReducedEquilibriumProblem, ModalEquilibriumProblem, FullEquilibriumProblem).
template <class Problem>
class Equilibrium final : public SceneProblem {
 public:
  Equilibrium(const Scene& scene, ContinuationParameter q) : pr_(scene, q) {}
  const ContinuationProblem& problem() const override { return pr_; }
  StartPoint start(const BranchSpec& spec) const override { return equilibrium_start(pr_, spec); }
  Values measures(const Eigen::VectorXd& x, double p) const override { return equilibrium_values(pr_, x, p); }
  std::vector<detail::ShapeMode> unknown_modes() const override { return modes_of(pr_); }

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

void identify_mode(const ContinuationProblem& problem, const std::vector<ShapeMode>& modes, SpecialPoint& sp,
                   const Branch* branch) {
  sp.mode_l.reset();
  sp.mode_m.reset();
  if (modes.empty() || static_cast<Eigen::Index>(modes.size()) != sp.x.size() || !sp.x.allFinite()) return;
  Eigen::MatrixXd J;
  problem.jacobian(sp.x, sp.p, J);
  if (!J.allFinite()) return;
  Eigen::EigenSolver<Eigen::MatrixXd> es(J);
  if (es.info() != Eigen::Success) return;
  const std::complex<double> target = sp.type == SpecialPointType::HB ? sp.eigenvalue : std::complex<double>(0.0);
  Eigen::Index k = 0;
  (es.eigenvalues().array() - target).abs().minCoeff(&k);
  // An HB whose pair coincides with another eigenvalue on the axis (at Delta0 = 0 the l = 2, m = 1 pair stays at
  // +-i/2, where the l = 3, m = 1 pair crosses): the nearest eigenvalue may be the one that does not cross. The
  // crossing one is off the axis at the neighbouring branch point on the side with more unstable eigenvalues:
  // the nearest to the pair there among those with Re > 1e-6 (1 + |lambda|).
  const double tol = 1e-6 * (1 + std::abs(target));
  const auto near_target = ((es.eigenvalues().array() - target).abs() <= tol).count();
  if (sp.type == SpecialPointType::HB && near_target > 1 && branch && sp.after_index + 1 < branch->points.size()) {
    const BranchPoint& side = branch->points[sp.after_index + (sp.unstable_after > sp.unstable_before ? 1 : 0)];
    Eigen::MatrixXd Js;
    problem.jacobian(side.x, side.p, Js);
    if (!Js.allFinite()) return;
    Eigen::EigenSolver<Eigen::MatrixXd> es_side(Js);
    if (es_side.info() != Eigen::Success) return;
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < es_side.eigenvalues().size(); ++i) {
      const std::complex<double> z = es_side.eigenvalues()[i];
      if (!(z.real() > 1e-6 * (1 + std::abs(z)))) continue;
      if (best < 0 || std::abs(z - target) < std::abs(es_side.eigenvalues()[best] - target)) best = i;
    }
    if (best < 0) return;  // no crossing eigenvalue to tell them apart: no mode reported
    es = std::move(es_side);
    k = best;
  }
  const Eigen::VectorXd w = es.eigenvectors().col(k).cwiseAbs2();
  const double total = w.sum();
  std::map<int, double> by_l;
  std::map<std::pair<int, int>, double> by_lm;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    by_l[modes[i].l] += w[static_cast<Eigen::Index>(i)];
    if (modes[i].m >= 0) by_lm[{modes[i].l, modes[i].m}] += w[static_cast<Eigen::Index>(i)];
  }
  constexpr double dominant = 0.9;
  for (const auto& [l, weight] : by_l)
    if (weight >= dominant * total) sp.mode_l = l;
  for (const auto& [lm, weight] : by_lm)
    if (weight >= dominant * total && sp.mode_l == lm.first) sp.mode_m = lm.second;
}

MeasuredBranch measure_branch(const SceneProblem& sp, const SceneBranch& r, Branch b) {
  if (const std::vector<ShapeMode> modes = sp.unknown_modes(); !modes.empty())
    for (SpecialPoint& s : b.special_points)
      if (s.type == SpecialPointType::BP || s.type == SpecialPointType::HB) identify_mode(sp.problem(), modes, s, &b);
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
