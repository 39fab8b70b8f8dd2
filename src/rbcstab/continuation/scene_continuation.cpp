#include "rbcstab/continuation/scene_continuation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/event_curve.hpp"
#include "rbcstab/continuation/fold_curve.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/hopf_curve.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/ns_curve.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

namespace {

constexpr std::array<std::pair<CurveKind, SpecialPointType>, 7> kCurves{{{CurveKind::LP, SpecialPointType::LP},
                                                                         {CurveKind::BP, SpecialPointType::BP},
                                                                         {CurveKind::HB, SpecialPointType::HB},
                                                                         {CurveKind::LPC, SpecialPointType::LPC},
                                                                         {CurveKind::PD, SpecialPointType::PD},
                                                                         {CurveKind::NS, SpecialPointType::NS},
                                                                         {CurveKind::UZ, SpecialPointType::UZ}}};

using Values = std::vector<MeasureValue>;
using Measure = std::function<Values(const Eigen::VectorXd& x, double p)>;

// ---- the measures of a point, in the order of measure_names / curve_measure_names ----

Values polar_values(const Eigen::VectorXd& x) {  // of (Re z, Im z, w), the first three unknowns
  const PolarState s = polar(x.head(3));
  return {s.r, s.Psi};
}

template <class State>  // ModalState, FullEquilibriumState
Values modal_values(const State& st) {
  Values v{st.r, st.Psi, st.sigma};
  for (double D : st.Delta_l) v.emplace_back(D);
  return v;
}

Values equilibrium_values(const ReducedEquilibriumProblem&, const Eigen::VectorXd& x, double) { return polar_values(x); }
Values equilibrium_values(const ModalEquilibriumProblem& pr, const Eigen::VectorXd& x, double p) {
  return modal_values(pr.observe(x, p));
}
Values equilibrium_values(const FullEquilibriumProblem& pr, const Eigen::VectorXd& x, double p) {
  return modal_values(pr.observe(x, p));
}

// winding, kind, trivial_multiplier (NaN when the system conserves no norm).
void append_cycle_values(Values& v, const OrbitSummary& s, const Floquet& f) {
  v.emplace_back(s.winding);
  v.emplace_back(to_string(s.kind));
  v.emplace_back(f.trivial ? *f.trivial : std::nan(""));
}

Values orbit_values(const PeriodicOrbitProblem& pr, const ReducedForcedSystem&, const Eigen::VectorXd& X, double p) {
  const OrbitSummary s = pr.summary(X, p);
  Values v{s.r0, s.Psi0, s.r_min, s.r_max, s.Psi_min, s.Psi_max};
  append_cycle_values(v, s, pr.floquet(X, p));
  return v;
}
Values orbit_values(const PeriodicOrbitProblem& pr, const ModalForcedSystem& sys, const Eigen::VectorXd& X, double p) {
  Values v = modal_values(sys.observe(0.0, pr.state_at_zero(X), p));
  append_cycle_values(v, pr.summary(X, p), pr.floquet(X, p));
  return v;
}

MeasuredBranch measured(Branch b, std::vector<std::string> names, StabilityKind spectrum_kind, const Measure& measure) {
  MeasuredBranch m;
  m.spectrum_kind = spectrum_kind;
  m.measure_names = std::move(names);
  auto row = [&](const Eigen::VectorXd& x, double p) {
    Values v = measure(x, p);
    if (v.size() != m.measure_names.size())
      throw std::logic_error("measures: " + std::to_string(v.size()) + " values for " +
                             std::to_string(m.measure_names.size()) + " names");
    return v;
  };
  for (const BranchPoint& pt : b.points) m.point_measures.push_back(row(pt.x, pt.p));
  for (const SpecialPoint& sp : b.special_points) m.special_measures.push_back(row(sp.x, sp.p));
  m.branch = std::move(b);
  return m;
}

// ---- the problem of each kind: its start and its measures ----

StartPoint given_start(StartMethod method, Eigen::VectorXd x, double p) {
  StartPoint s;
  s.method = method;
  s.x = std::move(x);
  s.p = p;
  return s;
}

// Newton at fixed p from `guess`; `what` names the solution sought in the failure message.
StartPoint newton_start(const ContinuationProblem& problem, StartMethod method, const Eigen::VectorXd& guess, double p,
                        const std::string& what, const std::string& hint = "try a longer --relax-T") {
  const NewtonResult r = solve_fixed_parameter(problem, guess, p);
  StartPoint s = given_start(method, r.x, p);
  s.newton = true;
  s.converged = r.converged;
  s.iterations = r.iterations;
  s.residual_norm = r.residual_norm;
  if (!r.converged) {
    std::ostringstream m;
    m << "no " << what << " (Newton residual " << r.residual_norm << " after " << r.iterations
      << " iterations); " << hint;
    s.message = m.str();
  }
  return s;
}

class SceneProblem {
 public:
  virtual ~SceneProblem() = default;
  virtual const ContinuationProblem& problem() const = 0;
  virtual StartPoint start(const BranchSpec& spec) const = 0;
  virtual Values measures(const Eigen::VectorXd& x, double p) const = 0;
  virtual std::vector<UserEvent> events() const { return {}; }
  virtual const char* solution_name() const { return "equilibrium"; }
};

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
  return newton_start(pr, StartMethod::ellipsoidal, pr.ellipsoidal_state(p0), p0, "full-model equilibrium near the ellipsoid");
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
  Orbit(const Scene& scene, ContinuationParameter q, const OrbitOptions& options) : sys_(scene, q), pr_(sys_, options) {}
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
    StartPoint s = newton_start(pr_, StartMethod::relaxed, pr_.shooting_guess(r.x, p0), p0,
                                std::is_same_v<System, ModalForcedSystem> ? "periodic orbit near the relaxed modal state"
                                                                          : "periodic orbit near the relaxed state");
    s.relaxation_periods = static_cast<int>(std::ceil(spec.relax_T / (2 * M_PI))) + r.periods;
    s.periodicity_defect = r.defect;
    s.periodicity_tol = spec.relax_tol;
    s.relaxed = r.converged;
    std::ostringstream m;
    m << std::setprecision(4);
    if (!r.failure.empty())
      m << "the relaxation failed after " << s.relaxation_periods << " periods (" << r.failure << ")";
    else if (!r.converged)
      m << "the relaxation reached its bound of " << spec.relax_max_periods << " periods after relax_T with periodicity defect "
        << r.defect << " > " << spec.relax_tol << " (a slow transient, or an attractor that is not periodic)";
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

std::unique_ptr<SceneProblem> make_problem(const BranchSpec& spec, const Scene& scene) {
  switch (spec.kind) {
    case ProblemKind::equilibrium:
      return std::make_unique<Equilibrium<ReducedEquilibriumProblem>>(scene, spec.parameter);
    case ProblemKind::modal: return std::make_unique<Equilibrium<ModalEquilibriumProblem>>(scene, spec.parameter);
    case ProblemKind::full: return std::make_unique<Equilibrium<FullEquilibriumProblem>>(scene, spec.parameter);
    case ProblemKind::orbit: return std::make_unique<Orbit<ReducedForcedSystem>>(scene, spec.parameter, spec.orbit);
    case ProblemKind::modal_orbit: return std::make_unique<Orbit<ModalForcedSystem>>(scene, spec.parameter, spec.orbit);
  }
  throw std::logic_error("unknown problem kind");
}

// The start of a branch: a restart's given state, solved by Newton at fixed p, else the kind's start.
StartPoint start_of(const SceneProblem& sp, const BranchSpec& spec, const Scene& scene) {
  if (!spec.start_state) return sp.start(spec);
  const Eigen::Index n = sp.problem().dimension();
  if (spec.start_state->size() != n || !spec.start_state->allFinite())
    throw InvalidArgument("start_state", "start_state has " + std::to_string(spec.start_state->size()) +
                                             " entries: must be " + std::to_string(n) +
                                             " finite numbers (the problem's unknowns for --kind " + to_string(spec.kind) + ")");
  return newton_start(sp.problem(), StartMethod::restart, *spec.start_state, get_parameter(scene, spec.parameter),
                      "solution near the labelled point's state", "the labelled point is not a solution of this problem");
}

// Labels along the branch from `next`: each point that is an end or a label_every-th point, then the
// special points that follow it. Returns the next free label.
int label_branch(MeasuredBranch& m, int label_every, int next) {
  const auto& pts = m.branch.points;
  const auto& sps = m.branch.special_points;
  m.point_labels.assign(pts.size(), 0);
  m.special_labels.assign(sps.size(), 0);
  std::size_t j = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (!m.point_type(k).empty() || (label_every > 0 && k % static_cast<std::size_t>(label_every) == 0))
      m.point_labels[k] = next++;
    for (; j < sps.size() && sps[j].after_index <= k; ++j) m.special_labels[j] = next++;
  }
  for (; j < sps.size(); ++j) m.special_labels[j] = next++;
  return next;
}

// The start with its certified stability; an orbit certified unstable is refused unless allowed.
// A restart from a labelled state is the user's explicit choice: reported, never refused.
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

MeasuredBranch measure_branch(const SceneProblem& sp, const SceneBranch& r, Branch b) {
  return measured(std::move(b), measure_names(r.spec.kind, r.problem_scene.L), sp.problem().stability_kind(),
                  [&](const Eigen::VectorXd& x, double p) { return sp.measures(x, p); });
}

// The modal orbit's BPs (a mode's multiplier crossing 1, a_l -> -a_l) switch like equilibria
// (switch_branch is generic). The reduced in-plane orbit has none: its period map is a Moebius map, whose
// two nontrivial multipliers k, conj(k) share |k| = exp(int Upsilon_2 dt); a multiplier 1 needs |k| = 1, an
// elliptic map under which every orbit is neutral.
void require_switchable(ProblemKind kind, const std::string& flag = "switch_at_bp") {
  if (kind == ProblemKind::orbit)
    throw InvalidArgument(flag, "--" + std::string(flag == "switch_at" ? "switch-at" : "switch-at-bp") +
                                    " is available for --kind equilibrium, modal and full (and modal-orbit), not "
                                    "orbit: the reduced in-plane orbit has no BP (its nontrivial multipliers are a "
                                    "conjugate pair of one modulus)");
}

// The branch bifurcating at the k-th BP of `on` (a branch of from's problem), labelled from first_label.
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
  BranchSwitchResult sw = switch_branch(sp.problem(), b, *bp, options);
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

// ---- curves ----

using CurveMeasure = std::function<Values(const Eigen::VectorXd& X, double p1, double p2)>;

// What every curve run shares: its start, engine options and output names.
struct CurveRun {
  const SpecialPoint& sp;
  double p2_0;
  const ContinuationOptions& engine;
  std::vector<std::string> names;

  MeasuredBranch trace(const ContinuationProblem& curve, const Eigen::VectorXd& X0, const CurveMeasure& values) const {
    Branch c = continue_branch(curve, X0, p2_0, engine);
    return measured(std::move(c), names, curve.stability_kind(), [&](const Eigen::VectorXd& X, double p2) {
      return values(X, curve.parameter_values(X, p2)[0], p2);
    });
  }
};

// Equilibrium curves over any level's two-parameter problem; the first n unknowns of a curve point are
// the state.
template <class P>
MeasuredBranch equilibrium_curve(const CurveRun& run, CurveSystem system, const SceneTwoParameterProblem<P>& base) {
  const Eigen::Index n = base.dimension();
  const CurveMeasure values = [&](const Eigen::VectorXd& X, double p1, double p2) {
    return equilibrium_values(base.at(p2), X.head(n), p1);
  };
  if (system == CurveSystem::fold) {
    const FoldCurveProblem curve(base, run.sp, run.p2_0);
    return run.trace(curve, curve.start(), values);
  }
  if (system == CurveSystem::branch_point) {
    const BranchPointCurveProblem curve(base, run.sp, run.p2_0);
    return run.trace(curve, curve.start(), values);
  }
  const HopfCurveProblem curve(base, run.sp, run.p2_0);
  return run.trace(curve, curve.start(), [&](const Eigen::VectorXd& X, double p1, double p2) {
    Values v = values(X, p1, p2);
    v.emplace_back(curve.omega(X));
    return v;
  });
}

// Cycle curves: one code path for the reduced and the modal forced systems. The curve unknowns start
// with the shooting state (the NS curve's are (X, p1, kappa = cos theta)); r, Psi are those of (z, w).
MeasuredBranch cycle_curve(const CurveRun& run, CurveSystem system, const ForcedSystem2& forced,
                           const OrbitOptions& options) {
  const CurveMeasure values = [](const Eigen::VectorXd& X, double, double) { return polar_values(X); };
  const OrbitTwoParameterProblem base(forced, options);
  switch (system) {
    case CurveSystem::fold: {
      const FoldCurveProblem curve(base, run.sp, run.p2_0);
      return run.trace(curve, curve.start(), values);
    }
    case CurveSystem::branch_point: {
      // A BP of cycles (e.g. the modal orbit's symmetry-breaking a_l -> -a_l pitchfork off the ellipsoidal
      // orbit): the generic BP system over the shooting problem (2 n + 2 unknowns, central-difference Jacobian).
      const BranchPointCurveProblem curve(base, run.sp, run.p2_0);
      return run.trace(curve, curve.start(), values);
    }
    case CurveSystem::neimark_sacker: {
      const NeimarkSackerCurveProblem curve(forced, options, run.sp, run.p2_0);
      return run.trace(curve, curve.start(), values);
    }
    case CurveSystem::event: {
      // The only event of orbit branches is the swinging <-> tumbling transition (Orbit::events).
      if (run.sp.name != kTransitionEventName)
        throw InvalidArgument("curve", "--curve UZ: the UZ point '" + run.sp.name + "' has no smooth event form");
      const OrbitPassageEvent event(base, run.sp.name);
      const EventCurveProblem curve(base, event, run.sp, run.p2_0);
      return run.trace(curve, curve.start(), [](const Eigen::VectorXd& X, double, double) {
        Values v = polar_values(X);
        v.emplace_back(X[X.size() - 1]);  // t_passage, the event's auxiliary unknown
        return v;
      });
    }
    default: {
      const PeriodDoublingCurveProblem curve(base, run.sp, run.p2_0);
      return run.trace(curve, curve.start(), values);
    }
  }
}

// The BP curve of the in-plane ellipsoidal modal orbit: the Z2-reduced system (reduced shooting +
// sigma_bar = sigma_l^c, 3 N + 1 unknowns, cost independent of L), mode l the one whose Upsilon_l(sigma_bar)
// is closest to 0 at the start.
MeasuredBranch ellipsoidal_orbit_bp_curve(const CurveRun& run, const Scene& scene, ContinuationParameter q1,
                                          ContinuationParameter q2, const OrbitOptions& options) {
  const ModalOrbitBranchPointCurve probe(scene, q1, q2, 3, options);
  const Eigen::VectorXd X0 = probe.start_from_modal(run.sp.x, run.sp.p);
  const Eigen::Index n = X0.size() - 1;
  const int l = ellipsoidal_orbit_critical_mode(probe.parameters(run.sp.p, run.p2_0), scene.L,
                                                probe.sigma_bar(X0.head(n), run.sp.p, run.p2_0));
  const ModalOrbitBranchPointCurve curve(scene, q1, q2, l, options);
  return run.trace(curve, X0, [&](const Eigen::VectorXd& X, double p1, double p2) {
    Values v = polar_values(X);
    v.emplace_back(curve.sigma_bar(X.head(n), p1, p2));
    v.emplace_back(l);
    return v;
  });
}

// The modal equilibrium (n unknowns) at a point X of ModalBranchPointCurve: its five l = 2 coordinates,
// every a_l = 0 (the ellipsoidal branch).
Eigen::VectorXd ellipsoidal_modal_state(const Eigen::VectorXd& X, Eigen::Index n) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  x.head(5) = X.head(5);
  return x;
}

// The modal orbit's shooting unknowns (segments of 5 + L - 2: Re z, Im z, w, Re v~, Im v~, a_3 .. a_L) at a
// point X of ModalOrbitBranchPointCurve (the reduced shooting unknowns, 3 per segment, then p1): v~ and
// every a_l are 0 on the ellipsoidal orbit (the inverse of start_from_modal).
Eigen::VectorXd ellipsoidal_orbit_state(const Eigen::VectorXd& X, int L, int segments) {
  const Eigen::Index nm = 5 + (L - 2);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(segments * nm);
  for (Eigen::Index j = 0; j < segments; ++j) x.segment(j * nm, 3) = X.segment(3 * j, 3);
  return x;
}

// The symmetry-breaking BP curve of modal equilibria (mode l = critical_mode of the start): the
// ellipsoidal l = 2 block plus Upsilon_l(sigma) = 0, six unknowns, exact.
MeasuredBranch modal_bp_curve(const CurveRun& run, const Scene& scene, ContinuationParameter q1, ContinuationParameter q2,
                              const SceneTwoParameterProblem<ModalEquilibriumProblem>& base) {
  const ModalBranchPointCurve curve(scene, q1, q2, critical_mode(base.at(run.p2_0), run.sp.x, run.sp.p));
  return run.trace(curve, curve.start(run.sp.x, run.sp.p), [&](const Eigen::VectorXd& X, double p1, double p2) {
    return equilibrium_values(base.at(p2), ellipsoidal_modal_state(X, base.dimension()), p1);
  });
}

// ---- runs and their labels ----

// Branch 1 of a run (the primary or the one-parameter branch) or 2 (the switched branch or the curve);
// nullptr if the run has no such branch.
const MeasuredBranch* branch_of(const ContinuationRun& run, int b) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run)) return b == 1 ? &c->one.branch : &c->curve;
  const SceneBranch& r = std::get<SceneBranch>(run);
  if (b == 1) return &r.branch;
  return r.switched ? &r.switched->branch : nullptr;
}

// The one-parameter run: the branch, or the branch a curve started from (its spec and problem scene).
const SceneBranch& one_parameter_run(const ContinuationRun& run) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run)) return c->one;
  return std::get<SceneBranch>(run);
}

int run_last_label(const SceneBranch& r) {
  return std::max(r.branch.last_label(), r.switched ? r.switched->branch.last_label() : 0);
}

int run_last_label(const ContinuationRun& run) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run)) return std::max(run_last_label(c->one), c->curve.last_label());
  return run_last_label(std::get<SceneBranch>(run));
}

// "its labels are 1 to 12" or the list.
std::string label_list(const std::vector<LabelledPoint>& all) {
  if (all.empty()) return "it has no labels";
  bool contiguous = true;
  for (std::size_t i = 0; i < all.size(); ++i) contiguous = contiguous && all[i].label == static_cast<int>(i) + 1;
  if (contiguous) return "its labels are 1 to " + std::to_string(all.size());
  std::string list;
  for (const LabelledPoint& p : all) list += (list.empty() ? "" : ", ") + std::to_string(p.label);
  return "its labels are " + list;
}

}  // namespace

Eigen::Index problem_dimension(const SceneBranch& r) { return make_problem(r.spec, r.problem_scene)->problem().dimension(); }

// Every curve system's unknowns start with the state, except the symmetry-reduced BP systems, which hold
// only its l = 2 part.
Eigen::VectorXd curve_point_state(const SceneCurve& c, const Eigen::VectorXd& X) {
  const Eigen::Index n = problem_dimension(c.one);
  const int L = c.one.problem_scene.L, N = c.one.spec.orbit.segments;
  Eigen::Index need = n + 1;
  if (c.system == CurveSystem::modal_branch_point) need = 6;
  if (c.system == CurveSystem::ellipsoidal_orbit_branch_point) need = 3 * N + 1;
  if (X.size() < need)
    throw InvalidArgument("x", "a point of the " + to_string(c.system) + " curve has " + std::to_string(X.size()) +
                                   " unknowns: must be at least " + std::to_string(need));
  if (c.system == CurveSystem::modal_branch_point) return ellipsoidal_modal_state(X, n);
  if (c.system == CurveSystem::ellipsoidal_orbit_branch_point) return ellipsoidal_orbit_state(X, L, N);
  return X.head(n);
}

namespace {

// The state x of a labelled point: its own (a point of a one-parameter branch) or that of the problem
// its curve augments.
Eigen::VectorXd labelled_state(const ContinuationRun& run, const LabelledPoint& lp) {
  const MeasuredBranch& m = *branch_of(run, lp.branch);
  const Eigen::VectorXd& x = lp.special ? m.branch.special_points[lp.index].x : m.branch.points[lp.index].x;
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run); c && lp.branch == 2) return curve_point_state(*c, x);
  return x;
}

// The critical eigenvalue (HB: i omega) or multiplier (NS: e^{i theta}) at a point of a Hopf or NS curve.
std::complex<double> curve_point_critical(const SceneCurve& c, const LabelledPoint& lp) {
  const MeasuredBranch& m = c.curve;
  if (c.system == CurveSystem::hopf) {
    const auto& row = lp.special ? m.special_measures.at(lp.index) : m.point_measures.at(lp.index);
    for (std::size_t i = 0; i < m.measure_names.size(); ++i)
      if (m.measure_names[i] == "omega") return {0.0, std::get<double>(row.at(i))};
  }
  if (c.system == CurveSystem::neimark_sacker) {
    const Eigen::VectorXd& X = lp.special ? m.branch.special_points[lp.index].x : m.branch.points[lp.index].x;
    return std::polar(1.0, std::acos(std::clamp(X[X.size() - 1], -1.0, 1.0)));  // unknowns (X, p1, cos theta)
  }
  return {};
}

void apply_changes(BranchSpec& s, const RestartChanges& c) {
  if (c.kind && *c.kind != s.kind)
    throw InvalidArgument("kind", "kind = " + to_string(*c.kind) + " is not the kind of the run restarted from, " +
                                      to_string(s.kind) + ": a restart continues the run's problem");
  if (c.parameter && *c.parameter != s.parameter) {
    s.parameter = *c.parameter;
    s.engine.p_min = -std::numeric_limits<double>::infinity();
    s.engine.p_max = std::numeric_limits<double>::infinity();
  }
  if (c.p_min) s.engine.p_min = *c.p_min;
  if (c.p_max) s.engine.p_max = *c.p_max;
  if (c.direction) s.engine.direction = *c.direction;
  if (c.initial_step) s.engine.initial_step = *c.initial_step;
  if (c.max_step) s.engine.max_step = *c.max_step;
  if (c.max_points) s.engine.max_points = *c.max_points;
  if (c.label_every) s.label_every = *c.label_every;
  s.switch_at_bp = c.switch_at_bp;
}

// A curve's result before it runs: its spec (bounds as run) and the branch it starts from.
SceneCurve curve_header(const SceneBranch& one, const CurveSpec& spec) {
  SceneCurve r;
  r.spec = spec;
  r.one = one;
  ContinuationOptions bounds;
  set_domain_bounds(bounds, *spec.parameter2, spec.p2_min, spec.p2_max);
  r.spec.p2_min = bounds.p_min;
  r.spec.p2_max = bounds.p_max;
  return r;
}

// Continues r's curve from sp, a special point of r.one's problem (x its state, p the first parameter's
// value), labelled from first_label; a point that was not located is a reason, not a start.
void trace_curve(SceneCurve& r, const SpecialPoint& sp, int first_label) {
  const SceneBranch& one = r.one;
  const ContinuationParameter q1 = one.spec.parameter, q2 = *r.spec.parameter2;
  if (sp.status != LocationStatus::located) {
    r.message = "--curve " + to_string(r.spec.type) + ": special point " + sp.name + " at " + to_string(q1) + " = " +
                std::to_string(sp.p) + " was not located (" + to_string(sp.status) + "); its curve needs an exact start";
    return;
  }
  ContinuationOptions engine = one.spec.engine;
  engine.events.clear();  // the one-parameter events read the one-parameter state
  engine.p_min = r.spec.p2_min;
  engine.p_max = r.spec.p2_max;
  engine.direction = Direction::both;
  r.start = sp;
  const Scene scene = with_parameter(one.problem_scene, q1, sp.p);  // the curve's start
  r.start_p2 = get_parameter(scene, q2);
  r.system = curve_system(one.spec.kind, r.spec.type, scene, q1, q2, sp, r.spec.symmetric_tol);
  const CurveRun run{r.start, r.start_p2, engine, curve_measure_names(one.spec.kind, r.system, scene.L)};
  switch (one.spec.kind) {
    case ProblemKind::orbit: r.curve = cycle_curve(run, r.system, ReducedForcedSystem2(scene, q1, q2), one.spec.orbit); break;
    case ProblemKind::modal_orbit:
      r.curve = r.system == CurveSystem::ellipsoidal_orbit_branch_point
                    ? ellipsoidal_orbit_bp_curve(run, scene, q1, q2, one.spec.orbit)
                    : cycle_curve(run, r.system, ModalForcedSystem2(scene, q1, q2), one.spec.orbit);
      break;
    case ProblemKind::modal: {
      const SceneTwoParameterProblem<ModalEquilibriumProblem> base(scene, q1, q2);
      r.curve = r.system == CurveSystem::modal_branch_point ? modal_bp_curve(run, scene, q1, q2, base)
                                                            : equilibrium_curve(run, r.system, base);
      break;
    }
    case ProblemKind::full:
      // The generic systems (BP: the 2n + 2 system, e.g. an unforced mode's Z2 pitchfork).
      r.curve = equilibrium_curve(run, r.system, SceneTwoParameterProblem<FullEquilibriumProblem>(scene, q1, q2));
      break;
    case ProblemKind::equilibrium:
      r.curve = equilibrium_curve(run, r.system, SceneTwoParameterProblem<ReducedEquilibriumProblem>(scene, q1, q2));
      break;
  }
  label_branch(r.curve, one.spec.label_every, first_label);
  r.started = true;
}

}  // namespace

// ---- kinds and names ----

ProblemKind problem_kind_from_string(const std::string& name) {
  if (const auto kind = try_from_string<ProblemKind>(name)) return *kind;
  const std::vector<std::string>& names = enum_names<ProblemKind>();
  std::string allowed;
  for (std::size_t i = 0; i < names.size(); ++i)
    allowed += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  throw InvalidArgument("kind", "kind = '" + name + "' is not available: must be " + allowed);
}

ModelLevel model_level(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::full: return ModelLevel::full;
    case ProblemKind::modal:
    case ProblemKind::modal_orbit: return ModelLevel::modal;
    default: return ModelLevel::reduced;
  }
}

bool is_orbit(ProblemKind kind) { return kind == ProblemKind::orbit || kind == ProblemKind::modal_orbit; }

double default_beta(ProblemKind kind) { return is_orbit(kind) ? M_PI / 2 : 0.0; }

TruncationUse truncation_use(ProblemKind kind) {
  return model_level(kind) == ModelLevel::reduced ? TruncationUse::reduced : TruncationUse::analysis;
}

std::string to_string(CurveKind kind) { return to_string(special_point_type(kind)); }

CurveKind curve_kind_from_string(const std::string& name) {
  for (const auto& [k, type] : kCurves)
    if (name == to_string(type)) return k;
  throw InvalidArgument("curve", "curve = '" + name + "' is not a curve: must be LP, BP, HB, LPC, PD, NS or UZ");
}

SpecialPointType special_point_type(CurveKind kind) {
  for (const auto& [k, type] : kCurves)
    if (k == kind) return type;
  throw std::logic_error("unknown curve kind");
}

std::vector<std::string> measure_names(ProblemKind kind, int L) {
  std::vector<std::string> names{"r", "Psi"};
  if (model_level(kind) != ModelLevel::reduced) {
    names.emplace_back("sigma");
    for (int l = 2; l <= L; ++l) names.push_back("Delta_" + std::to_string(l));
  }
  if (kind == ProblemKind::orbit) names.insert(names.end(), {"r_min", "r_max", "Psi_min", "Psi_max"});
  if (is_orbit(kind)) names.insert(names.end(), {"winding", "kind", "trivial_multiplier"});
  return names;
}

std::vector<std::string> curve_measure_names(ProblemKind kind, CurveSystem system, int L) {
  if (is_orbit(kind)) {
    std::vector<std::string> names{"r", "Psi"};
    if (system == CurveSystem::ellipsoidal_orbit_branch_point) names.insert(names.end(), {"sigma_bar", "mode"});
    if (system == CurveSystem::event) names.emplace_back("t_passage");
    return names;
  }
  std::vector<std::string> names = measure_names(kind, L);
  if (system == CurveSystem::hopf) names.emplace_back("omega");
  return names;
}

bool is_csv_measure(std::string_view name) { return name != "trivial_multiplier"; }

const MeasureValue& MeasuredBranch::measure(std::size_t k, std::string_view name) const {
  for (std::size_t i = 0; i < measure_names.size(); ++i)
    if (measure_names[i] == name) return point_measures.at(k).at(i);
  std::string list;
  for (const auto& n : measure_names) list += (list.empty() ? "" : ", ") + n;
  throw InvalidArgument("measure", "measure = '" + std::string(name) + "' is not a measure of this branch: must be one of " + list);
}

double MeasuredBranch::number(std::size_t k, std::string_view name) const {
  const MeasureValue& v = measure(k, name);
  if (const double* d = std::get_if<double>(&v)) return *d;
  if (const int* i = std::get_if<int>(&v)) return *i;
  throw InvalidArgument("measure", "measure = '" + std::string(name) + "' is a label, not a number");
}

int MeasuredBranch::point_label(std::size_t k) const { return k < point_labels.size() ? point_labels[k] : 0; }

int MeasuredBranch::special_label(std::size_t k) const { return k < special_labels.size() ? special_labels[k] : 0; }

std::string MeasuredBranch::point_type(std::size_t k) const {
  return k == 0 || k + 1 == branch.points.size() ? to_string(SpecialPointType::EP) : "";
}

int MeasuredBranch::last_label() const {
  int m = 0;
  for (int l : point_labels) m = std::max(m, l);
  for (int l : special_labels) m = std::max(m, l);
  return m;
}

Direction direction_from_string(const std::string& name) { return from_string<Direction>(name, "direction"); }

// ---- specs ----

namespace {
// lambda >= 0 and beta in [0, pi] are closed edges a branch lands on; other domains are open.
bool has_closed_edges(ContinuationParameter q) {
  return q == ContinuationParameter::lambda || q == ContinuationParameter::beta;
}
}  // namespace

void set_domain_bounds(ContinuationOptions& engine, ContinuationParameter q, double lo, double hi) {
  engine.p_min = lo;
  engine.p_max = hi;
  if (!has_closed_edges(q)) return;
  const Domain d = continuation_domain(q, Parameters{});  // neither domain depends on the other parameters
  engine.p_min = std::max(lo, d.lo);
  engine.p_max = std::min(hi, d.hi);
}

void require_bounds_in_domain(ContinuationParameter q, double lo, double hi, const std::string& lo_name,
                              const std::string& hi_name) {
  if (!has_closed_edges(q)) return;
  const Domain d = continuation_domain(q, Parameters{});
  const std::string range = d.text() + ", " + to_string(q) + "'s continuation domain";
  require(std::isinf(lo) || d.contains(lo), lo_name, lo, range);
  require(std::isinf(hi) || d.contains(hi), hi_name, hi, range);
}

void BranchSpec::validate() const {
  if (switch_at_bp) require_switchable(kind);
  if (is_orbit(kind)) orbit.validate();
  const ModelLevel level = model_level(kind);
  if (scene.model != ModelLevel::automatic && scene.model != level)
    throw InvalidArgument("model", "model = " + to_string(scene.model) + " is not available for --kind " +
                                       to_string(kind) + ": must be " + to_string(level) + " (or auto)");
  require(std::isfinite(relax_T) && relax_T >= 0, "relax_T", relax_T, "a finite number >= 0");
  require(label_every >= 0, "label_every", label_every, "an integer >= 0 (0: label only the ends and special points)");
  require(std::isfinite(relax_tol) && relax_tol > 0 && relax_tol <= 1, "relax_tol", relax_tol,
          "(0, 1] (the periodicity defect of a unit-norm state)");
  require(relax_max_periods >= 1 && relax_max_periods <= 10000000, "relax_max_periods", relax_max_periods,
          "an integer in [1, 1e7]");
  ContinuationOptions e = engine;
  set_domain_bounds(e, parameter, engine.p_min, engine.p_max);
  // Every branch starts at the scene's value (modal_orbit: its total excess area's scene).
  const double p_start = get_parameter(problem_scene_of(*this), parameter);
  if (!(p_start >= e.p_min && p_start <= e.p_max)) {
    std::ostringstream m;
    m << std::setprecision(10) << "the branch starts at the scene's " << to_string(parameter) << " = " << p_start
      << ", outside [--min, --max] = [" << e.p_min << ", " << e.p_max << "]: widen the range or change the scene";
    throw InvalidArgument("min", m.str());
  }
  e.validate();
}

void CurveSpec::validate(const BranchSpec& branch) const {
  const bool orbit = is_orbit(branch.kind);
  // UZ: the events of a branch are those of its kind; only orbit branches carry one (swing_tumble).
  const bool cycle_curve = type == CurveKind::LPC || type == CurveKind::PD || type == CurveKind::NS || type == CurveKind::UZ;
  if (orbit != cycle_curve && !(orbit && type == CurveKind::BP))
    throw InvalidArgument("curve", "curve = " + to_string(type) + " is not available for --kind " + to_string(branch.kind) +
                                       ": must be " + (orbit ? "LPC, PD, NS, BP or UZ" : "LP, BP or HB"));
  if (!parameter2) throw InvalidArgument("parameter2", "--curve needs --parameter2 (the second free parameter)");
  if (branch.switch_at_bp) throw InvalidArgument("switch_at_bp", "--switch-at-bp and --curve cannot be combined");
  require_independent(branch.parameter, *parameter2, "parameter2");
  if (!(p2_min < p2_max))
    throw InvalidArgument("min2", "min2 = " + std::to_string(p2_min) + " must be < max2 = " + std::to_string(p2_max));
  require(point >= 1, "point", point, "an integer >= 1");
  require(std::isfinite(symmetric_tol) && symmetric_tol >= 0, "symmetric_tol", symmetric_tol, "a finite number >= 0");
}

// ---- entry points ----

Scene problem_scene_of(const BranchSpec& spec) {
  return spec.kind == ProblemKind::modal_orbit && !spec.start_state ? total_area_scene(spec.scene) : spec.scene;
}

StartPoint find_start(const BranchSpec& spec) {
  spec.validate();
  const Scene scene = problem_scene_of(spec);
  return assessed_start(*make_problem(spec, scene), spec, scene);
}

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

SwitchedBranch switch_at_bp(const SceneBranch& from, int k) { return switch_at_bp(from, k, switch_options(from)); }

SwitchedBranch switch_at_bp(const SceneBranch& from, int k, const BranchSwitchOptions& options) {
  require_switchable(from.spec.kind);
  return switch_with(*make_problem(from.spec, from.problem_scene), from, from.branch, k, options, run_last_label(from) + 1);
}

CurveSystem curve_system(ProblemKind kind, CurveKind type, const Scene& scene, ContinuationParameter q1,
                         ContinuationParameter q2, const SpecialPoint& start, double symmetric_tol) {
  switch (type) {
    case CurveKind::LP:
    case CurveKind::LPC: return CurveSystem::fold;
    case CurveKind::HB: return CurveSystem::hopf;
    case CurveKind::PD: return CurveSystem::period_doubling;
    case CurveKind::NS: return CurveSystem::neimark_sacker;
    case CurveKind::UZ: return CurveSystem::event;
    case CurveKind::BP: break;
  }
  if (kind == ProblemKind::modal) return CurveSystem::modal_branch_point;
  if (kind != ProblemKind::modal_orbit || q1 == ContinuationParameter::beta || q2 == ContinuationParameter::beta ||
      !ModalOrbitBranchPointCurve::has_untilted_rest_shape(scene))
    return CurveSystem::branch_point;
  // The first segment's state (Re z, Im z, w, Re v~, Im v~, a_3 .. a_L): on the ellipsoidal orbit all but
  // the first three vanish.
  const Eigen::Index nm = 5 + (scene.L - 2);
  return start.x.segment(3, nm - 3).cwiseAbs().maxCoeff() <= symmetric_tol ? CurveSystem::ellipsoidal_orbit_branch_point
                                                                            : CurveSystem::branch_point;
}

SceneCurve continue_curve(const BranchSpec& branch, const CurveSpec& curve) {
  branch.validate();
  curve.validate(branch);
  return continue_curve(continue_scene(branch), curve);
}

SceneCurve continue_curve(const SceneBranch& one, const CurveSpec& spec) {
  BranchSpec branch = one.spec;
  branch.switch_at_bp = false;  // a branch already run with its switched branch still has curves
  spec.validate(branch);
  SceneCurve r = curve_header(one, spec);
  if (!one.start.converged || one.start.refused) {
    r.message = one.start.message;
    return r;
  }
  // The point-th special point of the type, located: the curve systems start from an exact point.
  const Branch& b = one.branch.branch;
  const SpecialPointType type = special_point_type(spec.type);
  const std::string T = to_string(spec.type);
  const SpecialPoint* sp = find_special_point(b, type, spec.point);
  if (!sp) {
    const auto n = std::count_if(b.special_points.begin(), b.special_points.end(),
                                 [&](const SpecialPoint& p) { return p.type == type; });
    r.message = "--curve " + T + ": no located " + T + " point number " + std::to_string(spec.point) +
                ": the one-parameter branch has " + std::to_string(n) + " " + T + " point(s); widen --min/--max";
    return r;
  }
  trace_curve(r, *sp, run_last_label(one) + 1);
  return r;
}

bool ended_normally(ContinuationStatus status) {
  return status == ContinuationStatus::completed || status == ContinuationStatus::outside_domain;
}

void RestartRequest::validate() const {
  if (label > 0 && switch_at > 0) throw InvalidArgument("switch_at", "--switch-at and --label cannot be combined");
  if (label <= 0 && switch_at <= 0)
    throw InvalidArgument("label", "--restart needs --label N (the labelled point to start from) or --switch-at N (a BP's label)");
  if (switch_at > 0 && curve) throw InvalidArgument("switch_at", "--switch-at and --curve cannot be combined");
}

ContinuationRun restart(const ContinuationRun& run, const RestartRequest& q) {
  q.validate();
  if (q.switch_at > 0) return switch_at_label(run, q.switch_at, q.changes);
  if (q.curve) return restart_curve(run, q.label, *q.curve, q.changes);
  return restart(run, q.label, q.changes);
}

RunOutcome outcome(const SceneBranch& r) {
  RunOutcome o;
  if (!r.start.converged || r.start.refused) return {false, "", r.start.message};
  o.note = r.start.message;
  const Branch& b = r.branch.branch;
  if (r.switched && !r.switched->switched)
    o.failure = "branch switching failed: " + r.switched->message;
  else if (!ended_normally(b.status))
    o.failure = "continuation stopped: " + to_string(b.status) + ": " + b.message;
  return o;
}

RunOutcome outcome(const SceneCurve& r) {
  RunOutcome o;
  if (!r.started) return {false, "", r.message};
  const Branch& c = r.curve.branch;
  if (!ended_normally(c.status)) o.failure = "curve continuation stopped: " + to_string(c.status) + ": " + c.message;
  return o;
}

RunOutcome outcome(const ContinuationRun& run) {
  return std::visit([](const auto& r) { return outcome(r); }, run);
}

int run_L(const SceneBranch& r) { return r.spec.scene.L; }
int run_L(const SceneCurve& r) { return r.one.spec.scene.L; }
int run_L(const ContinuationRun& run) {
  return std::visit([](const auto& r) { return run_L(r); }, run);
}

// ---- restart ----

std::vector<LabelledPoint> labelled_points(const ContinuationRun& run) {
  std::vector<LabelledPoint> out;
  for (int b = 1; b <= 2; ++b) {
    const MeasuredBranch* m = branch_of(run, b);
    if (!m) continue;
    for (std::size_t k = 0; k < m->branch.points.size(); ++k)
      if (const int l = m->point_label(k)) out.push_back({l, m->point_type(k), b, false, k});
    for (std::size_t k = 0; k < m->branch.special_points.size(); ++k)
      if (const int l = m->special_label(k)) out.push_back({l, to_string(m->branch.special_points[k].type), b, true, k});
  }
  std::sort(out.begin(), out.end(), [](const LabelledPoint& a, const LabelledPoint& b) { return a.label < b.label; });
  return out;
}

LabelledPoint find_label(const ContinuationRun& run, int label, const std::string& flag) {
  const std::vector<LabelledPoint> all = labelled_points(run);
  for (const LabelledPoint& p : all)
    if (p.label == label) return p;
  throw InvalidArgument(flag, flag + " = " + std::to_string(label) + " is not a label of this run: " + label_list(all));
}

BranchSpec restart_spec(const ContinuationRun& run, int label, const RestartChanges& changes) {
  const LabelledPoint lp = find_label(run, label);
  const SceneBranch& ctx = one_parameter_run(run);
  BranchSpec s = ctx.spec;
  s.scene = ctx.problem_scene;
  const MeasuredBranch& m = *branch_of(run, lp.branch);
  const std::vector<double>& values =
      lp.special ? m.branch.special_points[lp.index].parameters : m.branch.points[lp.index].parameters;
  for (std::size_t i = 0; i < values.size(); ++i)
    s.scene = with_parameter(s.scene, continuation_parameter_from_string(m.branch.parameter_names.at(i)), values[i]);
  s.start_state = labelled_state(run, lp);
  s.switch_at_bp = false;
  apply_changes(s, changes);
  s.validate();
  return s;
}

SceneBranch restart(const ContinuationRun& run, int label, const RestartChanges& changes) {
  return continue_scene(restart_spec(run, label, changes));
}

SceneBranch switch_at_label(const ContinuationRun& run, int label, const RestartChanges& changes) {
  const LabelledPoint lp = find_label(run, label, "switch_at");
  const SceneBranch& ctx = one_parameter_run(run);
  require_switchable(ctx.spec.kind, "switch_at");
  const std::string what = "switch_at = " + std::to_string(label);
  if (std::holds_alternative<SceneCurve>(run) && lp.branch == 2)
    throw InvalidArgument("switch_at", what + " is a point of the " + to_string(std::get<SceneCurve>(run).spec.type) +
                                           " curve, not a BP of a one-parameter branch: restart a branch from it "
                                           "(--label " + std::to_string(label) + ") and switch at that branch's BP");
  if (lp.type != to_string(SpecialPointType::BP)) {
    std::string bps;
    for (const LabelledPoint& p : labelled_points(run))
      if (p.type == to_string(SpecialPointType::BP) && !(std::holds_alternative<SceneCurve>(run) && p.branch == 2))
        bps += (bps.empty() ? "" : ", ") + std::to_string(p.label);
    throw InvalidArgument("switch_at", what + " is " + (lp.type.empty() ? "a regular point" : "a point of type " + lp.type) +
                                           ", not a BP (branch point): " +
                                           (bps.empty() ? "this run has no BP" : "the BP labels of this run are " + bps));
  }
  if (changes.parameter && *changes.parameter != ctx.spec.parameter)
    throw InvalidArgument("parameter", "parameter = " + to_string(*changes.parameter) + " cannot switch at " + what +
                                           ": a switch continues the branch's own parameter, " + to_string(ctx.spec.parameter));
  SceneBranch r;
  r.spec = ctx.spec;
  r.spec.switch_at_bp = false;
  apply_changes(r.spec, changes);
  set_domain_bounds(r.spec.engine, r.spec.parameter, r.spec.engine.p_min, r.spec.engine.p_max);
  r.spec.engine.validate();
  r.problem_scene = ctx.problem_scene;
  r.start = ctx.start;
  r.branch = *branch_of(run, lp.branch);
  const SpecialPoint& bp = r.branch.branch.special_points[lp.index];
  if (!(bp.p >= r.spec.engine.p_min && bp.p <= r.spec.engine.p_max)) {
    std::ostringstream m;
    m << std::setprecision(10) << what << " lies at " << to_string(r.spec.parameter) << " = " << bp.p
      << ", outside [--min, --max] = [" << r.spec.engine.p_min << ", " << r.spec.engine.p_max << "]";
    throw InvalidArgument("min", m.str());
  }
  const int k = static_cast<int>(std::count_if(r.branch.branch.special_points.begin(),
                                               r.branch.branch.special_points.begin() + static_cast<std::ptrdiff_t>(lp.index) + 1,
                                               [](const SpecialPoint& p) { return p.type == SpecialPointType::BP; }));
  r.switched = switch_with(*make_problem(r.spec, r.problem_scene), r, r.branch, k, switch_options(r), run_last_label(run) + 1);
  return r;
}

SceneCurve restart_curve(const ContinuationRun& run, int label, const CurveSpec& curve, const RestartChanges& changes) {
  const LabelledPoint lp = find_label(run, label);
  const SceneBranch& ctx = one_parameter_run(run);
  if (changes.parameter && *changes.parameter != ctx.spec.parameter)
    throw InvalidArgument("parameter", "parameter = " + to_string(*changes.parameter) + " cannot continue the curve of label " +
                                           std::to_string(label) + ": it is a special point in " + to_string(ctx.spec.parameter) +
                                           ", the curve's first parameter");
  const SpecialPointType type = special_point_type(curve.type);
  const std::string T = to_string(curve.type);
  const SceneCurve* on = std::get_if<SceneCurve>(&run);
  const bool curve_point = on && lp.branch == 2;
  if (curve_point ? on->spec.type != curve.type : lp.type != T)
    throw InvalidArgument("label", "label = " + std::to_string(label) + " is " +
                                       (curve_point ? "a point of a " + to_string(on->spec.type) + " curve"
                                                    : lp.type.empty() ? "a regular point" : "a point of type " + lp.type) +
                                       ": --curve " + T + " starts from a point of type " + T + " or a point of a " + T +
                                       " curve");
  SceneBranch one;
  one.spec = restart_spec(run, label, changes);
  one.problem_scene = one.spec.scene;
  one.start.method = StartMethod::restart;
  one.start.x = *one.spec.start_state;
  one.start.p = get_parameter(one.problem_scene, one.spec.parameter);
  one.branch.measure_names = measure_names(one.spec.kind, one.problem_scene.L);
  one.branch.branch.parameter_names = {to_string(one.spec.parameter)};
  curve.validate(one.spec);
  SceneCurve r = curve_header(one, curve);
  const MeasuredBranch& m = *branch_of(run, lp.branch);
  SpecialPoint sp = lp.special ? m.branch.special_points[lp.index] : SpecialPoint{};
  if (curve_point) {
    // A point of a curve is a located point of its type at the curve's value of the second parameter.
    sp = SpecialPoint{};
    sp.type = type;
    sp.name = T;
    sp.status = LocationStatus::located;
    sp.p = one.start.p;
    sp.parameters = {sp.p};
    sp.eigenvalue = curve_point_critical(*on, lp);
  }
  sp.x = one.start.x;
  trace_curve(r, sp, 1);
  return r;
}

// ---- a run as a front end asks for it ----

CurveSpec curve_spec(const std::string& type, const std::string& parameter2, double p2_min, double p2_max, int point,
                     const std::string& min2_name, const std::string& max2_name) {
  CurveSpec c;
  c.type = curve_kind_from_string(type);
  if (!parameter2.empty()) {
    try {
      c.parameter2 = continuation_parameter_from_string(parameter2);
    } catch (const InvalidArgument& e) {
      // The table's message ("parameter = 'x' is not ...: must be one of ...") names the second parameter.
      const std::string message = e.what();
      throw InvalidArgument("parameter2", "parameter2" + message.substr(e.parameter().size()));
    }
  }
  if (c.parameter2) require_bounds_in_domain(*c.parameter2, p2_min, p2_max, min2_name, max2_name);
  require(!std::isnan(p2_min), min2_name, p2_min, "a number (-inf: no bound)");
  require(!std::isnan(p2_max), max2_name, p2_max, "a number (inf: no bound)");
  c.p2_min = p2_min;
  c.p2_max = p2_max;
  c.point = point;
  return c;
}

SceneRun scene_run(SceneFile file, BranchSpec spec, std::optional<CurveSpec> curve, const std::string& min_name,
                   const std::string& max_name) {
  apply_truncation(file, truncation_use(spec.kind));
  if (file.origin("initial.beta") == Origin::default_value) file.scene.beta = default_beta(spec.kind);
  spec.scene = file.scene;
  require_bounds_in_domain(spec.parameter, spec.engine.p_min, spec.engine.p_max, min_name, max_name);
  require(!std::isnan(spec.engine.p_min), min_name, spec.engine.p_min, "a number (-inf: no bound)");
  require(!std::isnan(spec.engine.p_max), max_name, spec.engine.p_max, "a number (inf: no bound)");
  return {std::move(spec), std::move(curve), file.L_reason};
}

ContinuationRun continue_run(const SceneRun& run) {
  if (run.curve) return continue_curve(run.spec, *run.curve);
  return continue_scene(run.spec);
}

std::string saved_run_L_reason(const ContinuationRun& run) {
  return "L = " + std::to_string(run_L(run)) + ": the branch file's scene (--restart)";
}

}  // namespace rbcstab
