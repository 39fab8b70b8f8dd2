// The curve of a special point of a scene branch in a second parameter: the system that continues it
// (curve_system), its start and trace over each kind's two-parameter problem, and the state of the problem
// it augments at a curve point (curve_point_state).
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/detail/branch_labels.hpp"
#include "rbcstab/continuation/detail/scene_curve.hpp"
#include "rbcstab/continuation/detail/scene_measures.hpp"
#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/continuation/event_curve.hpp"
#include "rbcstab/continuation/fold_curve.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/hopf_curve.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/ns_curve.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::curve_header;
using detail::equilibrium_values;
using detail::measured;
using detail::polar_values;
using detail::run_last_label;
using detail::trace_curve;
using detail::Values;

using CurveMeasure = std::function<Values(const Eigen::VectorXd& X, double p1, double p2)>;

// What every curve run shares: its start, engine options and output names.
struct CurveRun {
  const SpecialPoint& sp;
  double p2_0;
  const ContinuationOptions& engine;
  std::vector<std::string> names;
  const std::vector<Monitor>& monitors;  // over the curve's two parameters and its measures

  MeasuredBranch trace(const ContinuationProblem& curve, const Eigen::VectorXd& X0, const CurveMeasure& values) const {
    const detail::Measure measure = [&](const Eigen::VectorXd& X, double p2) {
      return values(X, curve.parameter_values(X, p2)[0], p2);
    };
    ContinuationOptions e = engine;
    const detail::MonitoredPoint point{
        curve.parameter_names(),
        [&curve](const Eigen::VectorXd& X, double p2) { return curve.parameter_values(X, p2); }, names, measure};
    for (UserEvent& ev : detail::monitor_events(point, monitors, X0, p2_0)) e.events.push_back(std::move(ev));
    Branch c = continue_branch(curve, X0, p2_0, e);
    return measured(std::move(c), names, curve.stability_kind(), measure);
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
MeasuredBranch modal_bp_curve(const CurveRun& run, const Scene& scene, ContinuationParameter q1,
                              ContinuationParameter q2, const SceneTwoParameterProblem<ModalEquilibriumProblem>& base) {
  const ModalBranchPointCurve curve(scene, q1, q2, critical_mode(base.at(run.p2_0), run.sp.x, run.sp.p));
  return run.trace(curve, curve.start(run.sp.x, run.sp.p), [&](const Eigen::VectorXd& X, double p1, double p2) {
    return equilibrium_values(base.at(p2), ellipsoidal_modal_state(X, base.dimension()), p1);
  });
}

}  // namespace

namespace detail {

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

void trace_curve(SceneCurve& r, const SpecialPoint& sp, int first_label) {
  const SceneBranch& one = r.one;
  const ContinuationParameter q1 = one.spec.parameter, q2 = *r.spec.parameter2;
  if (sp.status != LocationStatus::located) {
    r.message = "--curve " + to_string(r.spec.type) + ": special point " + sp.name + " at " + to_string(q1) + " = " +
                std::to_string(sp.p) + " was not located (" + to_string(sp.status) +
                "); its curve needs an exact start";
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
  const CurveRun run{r.start, r.start_p2, engine, curve_measure_names(one.spec.kind, r.system, scene.L),
                     one.spec.monitors};
  switch (one.spec.kind) {
    case ProblemKind::orbit:
      r.curve = cycle_curve(run, r.system, ReducedForcedSystem2(scene, q1, q2), one.spec.orbit);
      break;
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

}  // namespace detail

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

void CurveSpec::validate(const BranchSpec& branch) const {
  const bool orbit = is_orbit(branch.kind);
  // UZ: the events of a branch are those of its kind; only orbit branches carry one (swing_tumble).
  const bool cycle_curve =
      type == CurveKind::LPC || type == CurveKind::PD || type == CurveKind::NS || type == CurveKind::UZ;
  if (orbit != cycle_curve && !(orbit && type == CurveKind::BP))
    throw InvalidArgument("curve", "curve = " + to_string(type) + " is not available for --kind " +
                                       to_string(branch.kind) + ": must be " +
                                       (orbit ? "LPC, PD, NS, BP or UZ" : "LP, BP or HB"));
  if (!parameter2) throw InvalidArgument("parameter2", "--curve needs --parameter2 (the second free parameter)");
  if (branch.switch_at_bp) throw InvalidArgument("switch_at_bp", "--switch-at-bp and --curve cannot be combined");
  require_independent(branch.parameter, *parameter2, "parameter2");
  if (!(p2_min < p2_max))
    throw InvalidArgument("min2", "min2 = " + std::to_string(p2_min) + " must be < max2 = " + std::to_string(p2_max));
  require(point >= 1 && point <= kCurvePointLimit, "point", point, integer_range(1, kCurvePointLimit));
  require(std::isfinite(symmetric_tol) && symmetric_tol >= 0, "symmetric_tol", symmetric_tol, "a finite number >= 0");
}

CurveSystem curve_system(ProblemKind kind, CurveKind type, const Scene& scene, ContinuationParameter q1,
                         ContinuationParameter q2, const SpecialPoint& start, double symmetric_tol) {
  switch (type) {
    case CurveKind::LP:
    case CurveKind::LPC:
      return CurveSystem::fold;
    case CurveKind::HB:
      return CurveSystem::hopf;
    case CurveKind::PD:
      return CurveSystem::period_doubling;
    case CurveKind::NS:
      return CurveSystem::neimark_sacker;
    case CurveKind::UZ:
      return CurveSystem::event;
    case CurveKind::BP:
      break;
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
  // The monitors are the curve's: the branch it starts from has none (their UZ points would mix with the
  // points a UZ curve starts from).
  BranchSpec plain = branch;
  plain.monitors.clear();
  SceneBranch one = continue_scene(plain);
  one.spec.monitors = branch.monitors;
  return continue_curve(one, curve);
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

}  // namespace rbcstab
