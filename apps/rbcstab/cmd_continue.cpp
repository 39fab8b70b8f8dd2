// rbcstab continue: an equilibrium branch (reduced system, modal or full model) or a periodic-orbit branch
// (reduced or modal) in one parameter, or a special point's curve in two, with its special points
// (AUTO-07p labels), as CSV and/or one JSON object. The library decides (continuation/scene_continuation.hpp)
// and renders (continuation/branch_io.hpp); this file maps flags to a BranchSpec and prints.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "checks.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/scene_continuation.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ContinueOptions {
  SceneOptions scene;
  std::string kind = "equilibrium";
  std::string parameter = "lambda";
  double p_min = -INFINITY, p_max = INFINITY;
  std::string direction = "both";
  ContinuationOptions engine;
  double relax_T = 200;
  OrbitOptions orbit;  // --segments
  bool json = false;
  std::string csv;
  bool switch_at_bp = false;
  // --curve: the two-parameter curve of the point-th special point of this type, in (parameter, parameter2).
  std::string curve;
  std::string parameter2;
  double p2_min = -INFINITY, p2_max = INFINITY;
  int point = 1;
};

// The same for a branch and a curve: CSV, then JSON or text.
template <class Result>
void print(const ContinueOptions& o, const Result& r) {
  if (!o.csv.empty()) write_file_atomic(o.csv, to_csv(r));
  if (o.json) {
    const nlohmann::json j = to_json(r);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << to_text(r);
  }
}

int report(const ContinueOptions& o, const SceneBranch& r) {
  if (!r.start.converged) {
    std::cerr << "rbcstab: " << r.start.message << "\n";
    return kRunFailed;
  }
  print(o, r);
  if (r.switched && !r.switched->switched) {
    std::cerr << "rbcstab: branch switching failed: " << r.switched->message << "\n";
    return kRunFailed;
  }
  const Branch& b = r.branch.branch;
  if (!ended_normally(b.status)) {
    std::cerr << "rbcstab: continuation stopped: " << to_string(b.status) << ": " << b.message << "\n";
    return kRunFailed;
  }
  return kOk;
}

int report(const ContinueOptions& o, const SceneCurve& r) {
  if (!r.started) {
    std::cerr << "rbcstab: " << r.message << "\n";
    return kRunFailed;
  }
  print(o, r);
  const Branch& c = r.curve.branch;
  if (!ended_normally(c.status)) {
    std::cerr << "rbcstab: curve continuation stopped: " << to_string(c.status) << ": " << c.message << "\n";
    return kRunFailed;
  }
  return kOk;
}

// --parameter2 by name (the message names the flag).
ContinuationParameter parameter2(const std::string& name) {
  try {
    return continuation_parameter_from_string(name);
  } catch (const InvalidArgument&) {
    throw InvalidArgument("parameter2", "parameter2 = '" + name +
                                            "' is not a continuation parameter: must be one of lambda, Delta, "
                                            "Delta0, B, C, Lambda, S, beta");
  }
}

int run(const ContinueOptions& o) {
  BranchSpec spec;
  spec.kind = problem_kind_from_string(o.kind);
  std::optional<CurveSpec> curve;
  if (!o.curve.empty()) {
    curve.emplace();
    curve->type = curve_kind_from_string(o.curve);
    if (!o.parameter2.empty()) curve->parameter2 = parameter2(o.parameter2);
    curve->p2_min = o.p2_min;
    curve->p2_max = o.p2_max;
    curve->point = o.point;
  } else if (!o.parameter2.empty()) {
    throw InvalidArgument("parameter2", "--parameter2 needs --curve LP|BP|HB|LPC|PD|NS|UZ");
  }
  SceneFile sf = o.scene.resolve();
  if (o.scene.o_beta->count() == 0 && o.scene.scene_path.empty()) sf.scene.beta = default_beta(spec.kind);
  spec.scene = sf.scene;
  spec.parameter = continuation_parameter_from_string(o.parameter);
  spec.engine = o.engine;
  spec.engine.p_min = o.p_min;
  spec.engine.p_max = o.p_max;
  spec.engine.direction = o.direction == "forward"    ? Direction::forward
                          : o.direction == "backward" ? Direction::backward
                                                      : Direction::both;
  spec.relax_T = o.relax_T;
  spec.orbit = o.orbit;
  spec.switch_at_bp = o.switch_at_bp;
  if (curve) return report(o, continue_curve(spec, *curve));
  return report(o, continue_scene(spec));
}
}  // namespace

static Runner add_continue(CLI::App& app) {
  auto o = std::make_shared<ContinueOptions>();
  o->scene.add_to(app);
  app.add_option("--kind", o->kind,
                 "what to continue: equilibrium (reduced system, out-of-plane rest shape), modal (modal-model "
                 "equilibria with every Delta_l, out-of-plane rest shape: the ellipsoidal branch and its BPs where "
                 "Upsilon_l(sigma) = 0) or orbit (periodic orbits "
                 "of the forced in-plane reduced system: swinging/tumbling, Floquet multipliers, LPC/PD/NS, UZ "
                 "swing_tumble) or modal-orbit (periodic orbits of the forced modal model relaxed from the scene, "
                 "e.g. the in-plane post-instability state, with every Delta_l) or full (full-model equilibria, "
                 "L <= 16, for stress-free shapes with l >= 3 content, initial.rest_delta_l in a scene file; "
                 "beta = 0 or C = inf)")
      ->capture_default_str();
  app.add_option("--segments", o->orbit.segments, "orbit: number of multiple-shooting segments")->capture_default_str();
  app.add_flag("--switch-at-bp", o->switch_at_bp,
               "equilibrium, modal, full: also continue the branch that bifurcates at the first BP (modal: the "
               "post-instability state); JSON key switched_branch, CSV rows with branch = switched");
  app.add_option("--parameter", o->parameter,
                 "free parameter: lambda, Delta, Delta0, B, C, Lambda, S or beta (the rest shape's orientation, "
                 "[0, pi]; equilibria exist only at beta = 0 unless Delta0 = 0 or C = inf)")
      ->capture_default_str();
  app.add_option("--min", o->p_min,
                 "lower bound of the free parameter (the branch ends there exactly; default: none, 0 for lambda and beta)");
  app.add_option("--max", o->p_max, "upper bound of the free parameter (the branch ends there exactly; default: none, pi for beta)");
  app.add_option("--direction", o->direction, "forward (parameter increasing), backward or both")
      ->check(CLI::IsMember({"forward", "backward", "both"}))
      ->capture_default_str();
  app.add_option("--step", o->engine.initial_step, "first arclength step, > 0")->check(positive())->capture_default_str();
  app.add_option("--max-step", o->engine.max_step, "largest arclength step, > 0")->check(positive())->capture_default_str();
  app.add_option("--max-points", o->engine.max_points, "points per direction, integer >= 2")->check(CLI::Range(2, 100000000))->capture_default_str();
  app.add_option("--relax-T", o->relax_T,
                 "relaxation time that gives the start state from the scene's shape, > 0 (orbits: rounded up to a "
                 "multiple of 2 pi)")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--curve", o->curve,
                 "continue the curve of a special point of the one-parameter branch in (--parameter, --parameter2): "
                 "LP, BP, HB (equilibrium, modal, full; modal BP: the symmetry-breaking curve Upsilon_l(sigma) = 0) or LPC, "
                 "PD, NS, BP (orbit, modal-orbit; BP: the generic BP system over the shooting problem, e.g. the "
                 "modal orbit's symmetry-breaking BPs) or UZ (orbit, modal-orbit: the swinging <-> tumbling "
                 "transition, the orbit passing through r = 0, as a curve); default: none (one-parameter run)")
      ->check(CLI::IsMember({"LP", "BP", "HB", "LPC", "PD", "NS", "UZ"}));
  app.add_option("--parameter2", o->parameter2,
                 "--curve: second free parameter (lambda, Delta, Delta0, B, C, Lambda, S or beta; independent of "
                 "--parameter: not Lambda with Delta or lambda, not S with C or Delta0)");
  app.add_option("--min2", o->p2_min, "--curve: lower bound of --parameter2 (the curve ends there exactly; default: none)");
  app.add_option("--max2", o->p2_max, "--curve: upper bound of --parameter2 (the curve ends there exactly; default: none)");
  app.add_option("--point", o->point, "--curve: start from the K-th located special point of that type, integer >= 1")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  app.add_flag("--json", o->json, "print one JSON object (branch, special_points) on stdout");
  app.add_option("--csv", o->csv, "write the branch as CSV to this file");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"continue", "Continue an equilibrium or periodic-orbit branch in one parameter (LP/BP/HB, LPC/PD/NS), or a special point's curve in two",
                                add_continue, 40};
}  // namespace

}  // namespace rbcstab::cli
