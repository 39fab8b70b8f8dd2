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

namespace rbcstab {

namespace {

// Strings of the kinds, in the order the messages list them.
constexpr std::array<std::pair<ProblemKind, const char*>, 5> kKinds{{{ProblemKind::equilibrium, "equilibrium"},
                                                                     {ProblemKind::orbit, "orbit"},
                                                                     {ProblemKind::modal, "modal"},
                                                                     {ProblemKind::modal_orbit, "modal-orbit"},
                                                                     {ProblemKind::full, "full"}}};
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
                        const std::string& what) {
  const NewtonResult r = solve_fixed_parameter(problem, guess, p);
  StartPoint s = given_start(method, r.x, p);
  s.newton = true;
  s.converged = r.converged;
  s.iterations = r.iterations;
  s.residual_norm = r.residual_norm;
  if (!r.converged) {
    std::ostringstream m;
    m << "no " << what << " (Newton residual " << r.residual_norm << " after " << r.iterations
      << " iterations); try a longer --relax-T";
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
  StartPoint start(const BranchSpec& spec) const override {
    const double p0 = sys_.start_parameter();
    if constexpr (std::is_same_v<System, ModalForcedSystem>)
      return newton_start(pr_, StartMethod::relaxed, pr_.shooting_guess(sys_.relaxed_state(spec.scene, spec.relax_T), p0),
                          p0, "periodic orbit near the relaxed modal state");
    else
      return newton_start(pr_, StartMethod::relaxed, pr_.shooting_guess(sys_.relaxed_state(spec.relax_T), p0), p0,
                          "periodic orbit near the relaxed state");
  }
  Values measures(const Eigen::VectorXd& X, double p) const override { return orbit_values(pr_, sys_, X, p); }
  std::vector<UserEvent> events() const override { return {pr_.transition_event()}; }

 private:
  System sys_;  // before pr_, which refers to it
  PeriodicOrbitProblem pr_;
};

// The scene the problem is built from: a modal orbit's Delta is the simulated scene's total excess area.
Scene problem_scene_of(const BranchSpec& spec) {
  return spec.kind == ProblemKind::modal_orbit ? total_area_scene(spec.scene) : spec.scene;
}

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

MeasuredBranch measure_branch(const SceneProblem& sp, const SceneBranch& r, Branch b) {
  return measured(std::move(b), measure_names(r.spec.kind, r.problem_scene.L), sp.problem().stability_kind(),
                  [&](const Eigen::VectorXd& x, double p) { return sp.measures(x, p); });
}

void require_switchable(ProblemKind kind) {
  if (is_orbit(kind))
    throw InvalidArgument("switch_at_bp",
                          "--switch-at-bp is available for --kind equilibrium, modal and full, not orbit or modal-orbit");
}

SwitchedBranch switch_with(const SceneProblem& sp, const SceneBranch& from, int k, const BranchSwitchOptions& options) {
  require_switchable(from.spec.kind);
  require(k >= 1, "bp", k, "an integer >= 1 (the k-th BP of the branch)");
  SwitchedBranch s;
  s.bp_number = k;
  const Branch& b = from.branch.branch;
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
  BranchSwitchResult sw = switch_branch(sp.problem(), b, *bp, options);
  s.switched = sw.switched;
  s.message = sw.message;
  s.branch = measure_branch(sp, from, std::move(sw.branch));
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

// The symmetry-breaking BP curve of modal equilibria (mode l = critical_mode of the start): the
// ellipsoidal l = 2 block plus Upsilon_l(sigma) = 0, six unknowns, exact.
MeasuredBranch modal_bp_curve(const CurveRun& run, const Scene& scene, ContinuationParameter q1, ContinuationParameter q2,
                              const SceneTwoParameterProblem<ModalEquilibriumProblem>& base) {
  const ModalBranchPointCurve curve(scene, q1, q2, critical_mode(base.at(run.p2_0), run.sp.x, run.sp.p));
  return run.trace(curve, curve.start(run.sp.x, run.sp.p), [&](const Eigen::VectorXd& X, double p1, double p2) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(base.dimension());  // every a_l = 0 on the ellipsoidal branch
    x.head(5) = X.head(5);
    return equilibrium_values(base.at(p2), x, p1);
  });
}

}  // namespace

// ---- kinds and names ----

std::string to_string(ProblemKind kind) {
  for (const auto& [k, name] : kKinds)
    if (k == kind) return name;
  return "?";
}

ProblemKind problem_kind_from_string(const std::string& name) {
  for (const auto& [k, n] : kKinds)
    if (name == n) return k;
  throw InvalidArgument("kind", "kind = '" + name + "' is not available: must be equilibrium, orbit, modal, modal-orbit or full");
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

std::string to_string(CurveSystem system) {
  switch (system) {
    case CurveSystem::fold: return "fold";
    case CurveSystem::hopf: return "hopf";
    case CurveSystem::period_doubling: return "period_doubling";
    case CurveSystem::neimark_sacker: return "neimark_sacker";
    case CurveSystem::branch_point: return "branch_point";
    case CurveSystem::modal_branch_point: return "modal_branch_point";
    case CurveSystem::ellipsoidal_orbit_branch_point: return "ellipsoidal_orbit_branch_point";
    case CurveSystem::event: return "event";
  }
  return "?";
}

std::string to_string(StartMethod method) { return method == StartMethod::relaxed ? "relaxed" : "ellipsoidal"; }

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

// ---- specs ----

void set_domain_bounds(ContinuationOptions& engine, ContinuationParameter q, double lo, double hi) {
  const bool beta = q == ContinuationParameter::beta;
  engine.p_min = ((q == ContinuationParameter::lambda || beta) && lo < 0) ? 0.0 : lo;
  engine.p_max = (beta && hi > M_PI) ? M_PI : hi;
}

void BranchSpec::validate() const {
  if (switch_at_bp) require_switchable(kind);
  if (is_orbit(kind)) orbit.validate();
  const ModelLevel level = model_level(kind);
  if (scene.model != ModelLevel::automatic && scene.model != level)
    throw InvalidArgument("model", "model = " + to_string(scene.model) + " is not available for --kind " +
                                       to_string(kind) + ": must be " + to_string(level) + " (or auto)");
  require(std::isfinite(relax_T) && relax_T >= 0, "relax_T", relax_T, "a finite number >= 0");
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

StartPoint find_start(const BranchSpec& spec) {
  spec.validate();
  return make_problem(spec, problem_scene_of(spec))->start(spec);
}

SceneBranch continue_scene(const BranchSpec& spec) {
  spec.validate();
  SceneBranch r;
  r.spec = spec;
  set_domain_bounds(r.spec.engine, spec.parameter, spec.engine.p_min, spec.engine.p_max);
  r.problem_scene = problem_scene_of(spec);
  const auto sp = make_problem(r.spec, r.problem_scene);
  r.start = sp->start(r.spec);
  Branch b;
  if (r.start.converged) {
    ContinuationOptions engine = r.spec.engine;
    for (UserEvent& e : sp->events()) engine.events.push_back(std::move(e));
    b = continue_branch(sp->problem(), r.start.x, r.start.p, engine);
  } else {
    b.parameter_names = sp->problem().parameter_names();
    b.status = ContinuationStatus::start_failed;
    b.message = r.start.message;
  }
  r.branch = measure_branch(*sp, r, std::move(b));
  if (spec.switch_at_bp) r.switched = switch_with(*sp, r, 1, switch_options(r));
  return r;
}

SwitchedBranch switch_at_bp(const SceneBranch& from, int k) { return switch_at_bp(from, k, switch_options(from)); }

SwitchedBranch switch_at_bp(const SceneBranch& from, int k, const BranchSwitchOptions& options) {
  require_switchable(from.spec.kind);
  return switch_with(*make_problem(from.spec, from.problem_scene), from, k, options);
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
  SceneCurve r;
  r.spec = spec;
  r.one = one;
  const ContinuationParameter q1 = one.spec.parameter, q2 = *spec.parameter2;
  ContinuationOptions engine = one.spec.engine;
  engine.events.clear();  // the one-parameter events read the one-parameter state
  set_domain_bounds(engine, q2, spec.p2_min, spec.p2_max);
  engine.direction = Direction::both;
  r.spec.p2_min = engine.p_min;
  r.spec.p2_max = engine.p_max;
  if (!one.start.converged) {
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
  if (sp->status != LocationStatus::located) {
    r.message = "--curve " + T + ": special point " + sp->name + " at " + b.parameter_names.front() + " = " +
                std::to_string(sp->p) + " was not located (" + to_string(sp->status) + "); its curve needs an exact start";
    return r;
  }
  r.start = *sp;
  const Scene scene = with_parameter(one.problem_scene, q1, sp->p);  // the curve's start
  r.start_p2 = get_parameter(scene, q2);
  r.system = curve_system(one.spec.kind, spec.type, scene, q1, q2, *sp, spec.symmetric_tol);
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
  r.started = true;
  return r;
}

bool ended_normally(ContinuationStatus status) {
  return status == ContinuationStatus::completed || status == ContinuationStatus::outside_domain;
}

}  // namespace rbcstab
