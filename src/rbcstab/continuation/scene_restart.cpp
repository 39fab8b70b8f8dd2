// Restarts from a labelled point of a run (AUTO's IRS): the spec a label gives, a branch from it, a switch
// at a labelled BP and a labelled special point's curve.
#include "rbcstab/continuation/scene_restart.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <variant>

#include "rbcstab/continuation/detail/branch_labels.hpp"
#include "rbcstab/continuation/detail/scene_curve.hpp"
#include "rbcstab/continuation/detail/scene_problem.hpp"
#include "rbcstab/continuation/detail/scene_switch.hpp"
#include "rbcstab/continuation/orbit_switch.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::branch_of;
using detail::curve_header;
using detail::make_problem;
using detail::require_switchable;
using detail::run_last_label;
using detail::switch_options;
using detail::switch_with;
using detail::trace_curve;

// The one-parameter run: the branch, or the branch a curve started from (its spec and problem scene).
const SceneBranch& one_parameter_run(const ContinuationRun& run) {
  if (const SceneCurve* c = std::get_if<SceneCurve>(&run)) return c->one;
  return std::get<SceneBranch>(run);
}

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
  for (const auto& [name, v] : c.tuned) {
    const TunableOption& t = tunable_option(name);
    t.check(v);
    if (std::string_view(t.name) == "segments" && v != s.orbit.segments)
      throw InvalidArgument(t.name, std::string(t.name) + " = " + format_value(v) +
                                        " cannot change on a restart (the run's: " + std::to_string(s.orbit.segments) +
                                        "): an orbit's labelled state lies on the run's mesh of shooting segments");
    t.set(s.engine, s.orbit, v);
  }
  if (c.monitors) s.monitors = *c.monitors;
  if (c.max_points) s.engine.max_points = *c.max_points;
  if (c.label_every) s.label_every = *c.label_every;
  s.switch_at_bp = c.switch_at_bp;
}

}  // namespace

void RestartRequest::validate() const {
  if (label > 0 && switch_at > 0) throw InvalidArgument("switch_at", "--switch-at and --label cannot be combined");
  if (label <= 0 && switch_at <= 0)
    throw InvalidArgument(
        "label", "--restart needs --label N (the labelled point to start from) or --switch-at N (a BP's label)");
  if (switch_at > 0 && curve) throw InvalidArgument("switch_at", "--switch-at and --curve cannot be combined");
}

ContinuationRun restart(const ContinuationRun& run, const RestartRequest& q) {
  q.validate();
  if (q.switch_at > 0) return switch_at_label(run, q.switch_at, q.changes);
  if (q.curve) return restart_curve(run, q.label, *q.curve, q.changes);
  return restart(run, q.label, q.changes);
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
  // The point's own value of the parameter continued in, when it is one of the point's parameters.
  for (std::size_t i = 0; i < values.size(); ++i)
    if (continuation_parameter_from_string(m.branch.parameter_names.at(i)) == s.parameter)
      s.start_parameter = values[i];
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
                                           "(--label " +
                                           std::to_string(label) + ") and switch at that branch's BP");
  if (lp.type == to_string(SpecialPointType::HB) && lp.special) {
    // The orbit switch's own verdict: the l >= 3 onset's rotating waves (named with the BP whose branch carries
    // them), a multiple Hopf point named with its pairs, or not supported for this problem kind (orbit_switch.hpp).
    const MeasuredBranch& m = *branch_of(run, lp.branch);
    const OrbitSwitchResult o =
        switch_at(make_problem(ctx.spec, ctx.problem_scene)->problem(), m.branch, m.branch.special_points[lp.index]);
    const std::string bp = o.rotating_wave_of < 0
                               ? ""
                               : ". For the branch that carries them switch at label " +
                                     std::to_string(m.special_labels.at(static_cast<std::size_t>(o.rotating_wave_of))) +
                                     " (the BP).";
    throw InvalidArgument("switch_at", what + " is an HB: " + o.message + bp);
  }
  if (lp.type == to_string(SpecialPointType::PD) && lp.special)
    throw InvalidArgument("switch_at", what + " is a PD: " + detail::kScenePeriodDoublingRefusal);
  if (lp.type != to_string(SpecialPointType::BP)) {
    std::string bps;
    for (const LabelledPoint& p : labelled_points(run))
      if (p.type == to_string(SpecialPointType::BP) && !(std::holds_alternative<SceneCurve>(run) && p.branch == 2))
        bps += (bps.empty() ? "" : ", ") + std::to_string(p.label);
    throw InvalidArgument("switch_at",
                          what + " is " + (lp.type.empty() ? "a regular point" : "a point of type " + lp.type) +
                              ", not a BP (branch point): " +
                              (bps.empty() ? "this run has no BP" : "the BP labels of this run are " + bps));
  }
  if (changes.parameter && *changes.parameter != ctx.spec.parameter)
    throw InvalidArgument("parameter", "parameter = " + to_string(*changes.parameter) + " cannot switch at " + what +
                                           ": a switch continues the branch's own parameter, " +
                                           to_string(ctx.spec.parameter));
  SceneBranch r;
  r.spec = ctx.spec;
  r.spec.switch_at_bp = false;
  apply_changes(r.spec, changes);
  set_domain_bounds(r.spec.engine, r.spec.parameter, r.spec.engine.p_min, r.spec.engine.p_max);
  r.spec.engine.validate();
  r.spec.orbit.validate();
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
  const int k =
      static_cast<int>(std::count_if(r.branch.branch.special_points.begin(),
                                     r.branch.branch.special_points.begin() + static_cast<std::ptrdiff_t>(lp.index) + 1,
                                     [](const SpecialPoint& p) { return p.type == SpecialPointType::BP; }));
  r.switched =
      switch_with(*make_problem(r.spec, r.problem_scene), r, r.branch, k, switch_options(r), run_last_label(run) + 1);
  return r;
}

SceneCurve restart_curve(const ContinuationRun& run, int label, const CurveSpec& curve, const RestartChanges& changes) {
  const LabelledPoint lp = find_label(run, label);
  const SceneBranch& ctx = one_parameter_run(run);
  if (changes.parameter && *changes.parameter != ctx.spec.parameter)
    throw InvalidArgument("parameter", "parameter = " + to_string(*changes.parameter) +
                                           " cannot continue the curve of label " + std::to_string(label) +
                                           ": it is a special point in " + to_string(ctx.spec.parameter) +
                                           ", the curve's first parameter");
  const SpecialPointType type = special_point_type(curve.type);
  const std::string T = to_string(curve.type);
  const SceneCurve* on = std::get_if<SceneCurve>(&run);
  const bool curve_point = on && lp.branch == 2;
  if (curve_point ? on->spec.type != curve.type : lp.type != T)
    throw InvalidArgument("label", "label = " + std::to_string(label) + " is " +
                                       (curve_point       ? "a point of a " + to_string(on->spec.type) + " curve"
                                        : lp.type.empty() ? "a regular point"
                                                          : "a point of type " + lp.type) +
                                       ": --curve " + T + " starts from a point of type " + T + " or a point of a " +
                                       T + " curve");
  SceneBranch one;
  // The curve leaves its first parameter free (the run's bounds in it bounded the branch the curve
  // started from, not the curve): a point of the curve outside them is still a start for it.
  RestartChanges free_p1 = changes;
  if (curve_point && !changes.p_min) free_p1.p_min = -std::numeric_limits<double>::infinity();
  if (curve_point && !changes.p_max) free_p1.p_max = std::numeric_limits<double>::infinity();
  one.spec = restart_spec(run, label, free_p1);
  one.problem_scene = one.spec.scene;
  one.start.method = StartMethod::restart;
  one.start.x = *one.spec.start_state;
  one.start.p = start_value(one.spec);
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
    sp.name = on->start.name;  // a UZ curve's event (its point's own type name otherwise)
    sp.status = LocationStatus::located;
    sp.p = one.start.p;
    sp.parameters = {sp.p};
    sp.eigenvalue = curve_point_critical(*on, lp);
  }
  sp.x = one.start.x;
  trace_curve(r, sp, 1);
  return r;
}

}  // namespace rbcstab
