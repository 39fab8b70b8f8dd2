// rbcstab continue: maps flags to a BranchSpec, CurveSpec or RestartRequest; the library decides
// (continuation/scene_continuation.hpp: scene_run, continue_run, restart), renders (branch_io.hpp) and saves and
// loads (branch_file.hpp).
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/continuation/bifurcation_diagram.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/scene_continuation.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
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
  OrbitOptions orbit;
  // The tunable options (tunable_options.hpp) by name, as given; their flags by name.
  std::map<std::string, double> tuned;
  std::map<std::string, CLI::Option*> o_tuned;
  std::vector<std::string> monitors, stops;  // --monitor, --stop-at
  bool json = false;
  std::string csv;
  bool switch_at_bp = false;
  bool allow_unstable_start = false;
  // --curve: the two-parameter curve of the point-th special point of this type, in (parameter, parameter2).
  std::string curve;
  std::string parameter2;
  double p2_min = -INFINITY, p2_max = INFINITY;
  int point = 1;
  std::string save;     // branch file (--diagram: the tree, its branch files beside it)
  int diagram = -1;     // --diagram DEPTH: the whole diagram (bifurcation_diagram.hpp)
  std::string journal;  // --diagram: the journal's prefix (default: --save's path)
  bool no_journal = false;
  int label_every = 10;
  std::string measures;  // text table: comma-separated measure names
  // A restart: the run in this branch file, from label N (--label) or switching at BP label N (--switch-at).
  std::string restart;
  std::string label, switch_at;  // a label's number or TYPE[:l=L][:m=M] (resolve_label)
  // Flags a restart takes from the command line only when given (else from the file).
  ProgressOutput progress;
  CLI::Option *o_kind{}, *o_parameter{}, *o_min{}, *o_max{}, *o_direction{}, *o_max_points{}, *o_label_every{},
      *o_relax_T{}, *o_label{}, *o_switch_at{};
  bool given(const std::string& name) const { return o_tuned.at(name)->count() > 0; }
  // The tunable options given, set on the engine and the orbit options.
  void tune(ContinuationOptions& e, OrbitOptions& orbit_options) const {
    for (const TunableOption& t : tunable_options())
      if (given(t.name)) {
        t.check(tuned.at(t.name));  // before the integer ones are cast
        t.set(e, orbit_options, tuned.at(t.name));
      }
  }
};

// --help for a tunable option: its line, range and default.
std::string tunable_help(const TunableOption& t) {
  return std::string(t.help) + "; " + t.range() + " (default " + format_value(t.default_value()) + ")";
}

// Every output rendered first (a rendering error writes nothing), then the CSV and branch files, then JSON
// or text.
void print(const ContinueOptions& o, const std::string& L_reason, const ContinuationRun& r) {
  const std::string csv = o.csv.empty() ? "" : to_csv(r);
  const std::string file = o.save.empty() ? "" : branch_file_json(r).dump(1) + "\n";
  const std::string out =
      o.json ? to_json(r, L_reason).dump(2) + "\n" : to_text(r, TableOptions::from_list(o.measures));
  std::vector<OutputFile> files;
  if (!o.csv.empty()) files.push_back({o.csv, csv, "--csv"});
  if (!o.save.empty()) files.push_back({o.save, file, "--save"});
  write_files_atomic(files);
  std::cout << out;
}

void print(const ContinueOptions& o, const std::string&, const BifurcationDiagram& d) {
  for (const std::string& why : d.rejected) std::cerr << "rbcstab: warning: " << why << "\n";
  if (!o.save.empty()) save_diagram(o.save, d, "--save");
  std::cout << (o.json ? to_json(d).dump(2) + "\n" : to_text(d));
}

template <class Run>
int report(const ContinueOptions& o, const std::string& L_reason, const Run& r) {
  const RunOutcome out = outcome(r);
  if (!out.note.empty()) std::cerr << "rbcstab: note: " << out.note << "\n";
  if (out.has_output) print(o, L_reason, r);
  if (out.failure.empty()) return kOk;
  std::cerr << "rbcstab: " << out.failure << "\n";
  return kRunFailed;
}

// --restart FILE: from --label N (a branch in --parameter, or with --curve that point's curve) or
// --switch-at N. The scene, kind and segments are the file's.
int run_restart(const ContinueOptions& o, const std::optional<CurveSpec>& curve) {
  // The flags' combination checked before the file is read; the labels resolved in the file's run.
  RestartRequest q{o.o_label->count() > 0 ? 1 : 0, o.o_switch_at->count() > 0 ? 1 : 0, curve, {}};
  q.validate();
  const std::string from_file = "--restart takes the scene from the branch file: ";
  if (!o.scene.scene_path.empty()) throw InvalidArgument("restart", from_file + "--scene cannot change it");
  for (const std::string& flag : o.scene.given_flags())
    throw InvalidArgument("restart", from_file + flag + " cannot change it");
  if (o.o_relax_T->count() > 0)
    throw InvalidArgument("restart", "--restart continues the file's states: --relax-T cannot change");
  const ContinuationRun run = load_branch(o.restart);
  if (q.label > 0) q.label = resolve_label(run, o.label, "label");
  if (q.switch_at > 0) q.switch_at = resolve_label(run, o.switch_at, "switch_at");
  RestartChanges& ch = q.changes;
  if (o.o_kind->count() > 0) ch.kind = problem_kind_from_string(o.kind);
  if (o.o_parameter->count() > 0) ch.parameter = continuation_parameter_from_string(o.parameter);
  if (o.o_min->count() > 0) ch.p_min = o.p_min;
  if (o.o_max->count() > 0) ch.p_max = o.p_max;
  if (o.o_direction->count() > 0) ch.direction = direction_from_string(o.direction);
  for (const TunableOption& t : tunable_options())
    if (o.given(t.name)) ch.tuned[t.name] = o.tuned.at(t.name);
  if (!o.monitors.empty() || !o.stops.empty()) ch.monitors = parse_monitors(o.monitors, o.stops);
  if (o.o_max_points->count() > 0) ch.max_points = o.engine.max_points;
  if (o.o_label_every->count() > 0) ch.label_every = o.label_every;
  ch.switch_at_bp = o.switch_at_bp;
  return report(o, saved_run_L_reason(run), restart(run, q));
}

int run(const ContinueOptions& o) {
  std::optional<CurveSpec> curve;
  if (!o.curve.empty())
    curve = curve_spec(o.curve, o.parameter2, o.p2_min, o.p2_max, o.point, "--min2", "--max2");
  else if (!o.parameter2.empty())
    throw InvalidArgument("parameter2", "--parameter2 needs --curve LP|BP|HB|LPC|PD|NS|UZ");
  if (!o.restart.empty()) return run_restart(o, curve);
  if (o.o_label->count() > 0 || o.o_switch_at->count() > 0)
    throw InvalidArgument(o.o_label->count() > 0 ? "label" : "switch_at",
                          std::string(o.o_label->count() > 0 ? "--label" : "--switch-at") +
                              " needs --restart FILE (the branch file that holds the label)");
  BranchSpec spec;
  spec.kind = problem_kind_from_string(o.kind);
  SceneFile file = o.scene.read();
  spec.parameter = continuation_parameter_from_string(o.parameter);
  spec.engine = o.engine;
  spec.orbit = o.orbit;
  o.tune(spec.engine, spec.orbit);
  spec.monitors = parse_monitors(o.monitors, o.stops);
  spec.engine.on_progress = o.progress.callback("continue:", "points (this direction)");
  spec.engine.p_min = o.p_min;
  spec.engine.p_max = o.p_max;
  spec.engine.direction = direction_from_string(o.direction);
  spec.relax_T = o.relax_T;
  spec.switch_at_bp = o.switch_at_bp;
  spec.label_every = o.label_every;
  spec.allow_unstable_start = o.allow_unstable_start;
  const SceneRun sr = scene_run(std::move(file), spec, curve, "--min", "--max");
  if (!curve) TableOptions::from_list(o.measures).validate(measure_names(sr.spec.kind, sr.spec.scene.L));
  const std::string journal = o.no_journal         ? ""
                              : !o.journal.empty() ? o.journal + ".journal"
                              : o.save.empty()     ? ""
                                                   : o.save + ".journal";
  if (o.diagram >= 0)
    return report(
        o, sr.L_reason,
        bifurcation_diagram({.start = sr.spec, .depth = o.diagram, .journal = journal, .stop = StopOnSignal().flag()}));
  return report(o, sr.L_reason, continue_run(sr));
}

Runner add_continue(CLI::App& app) {
  auto o = std::make_shared<ContinueOptions>();
  o->scene.add_to(app);
  o->o_kind = app.add_option("--kind", o->kind,
                             "what to continue: equilibrium (reduced system), modal, full (L <= 16: stress-free l >= 3 "
                             "content), orbit (in-plane reduced orbits) or modal-orbit (docs/continuation.md)")
                  ->capture_default_str();
  app.add_flag("--switch-at-bp", o->switch_at_bp,
               "equilibrium, modal, full, modal-orbit: also continue the branch that bifurcates at the first BP met "
               "from the start in the continuation direction (--direction both: the BP nearest the start in "
               "arclength; modal: the post-instability state); JSON key switched_branch, CSV rows with branch = "
               "switched");
  app.add_flag("--allow-unstable-start", o->allow_unstable_start,
               "orbit, modal-orbit: continue even when the orbit found at the start is unstable (by default that is "
               "refused with exit 1: the scene does not relax to it)");
  o->o_parameter = app.add_option("--parameter", o->parameter,
                                  "free parameter: " + continuation_parameter_list() +
                                      " (beta: the rest shape's orientation, [0, pi])")
                       ->capture_default_str();
  o->o_min =
      app.add_option(
             "--min", o->p_min,
             "lower bound of the free parameter (the branch ends there exactly; default: none, 0 for lambda and beta)")
          ->check(number_text("within the parameter's domain"));
  o->o_max =
      app.add_option("--max", o->p_max,
                     "upper bound of the free parameter (the branch ends there exactly; default: none, pi for beta)")
          ->check(number_text("within the parameter's domain"));
  o->o_direction = app.add_option("--direction", o->direction, "forward (parameter increasing), backward or both")
                       ->check(CLI::IsMember({"forward", "backward", "both"}))
                       ->capture_default_str();
  // Steps, tolerances and the orbits' discretisation: one flag per tunable option, its range from the table
  // (the library checks the value and names the option).
  for (const TunableOption& t : tunable_options())
    o->o_tuned[t.name] = app.add_option(t.flag, o->tuned[t.name], tunable_help(t))
                             ->check(t.integer ? integer_text(t.range()) : number_text(t.range()))
                             ->type_name(t.integer ? "INT" : "FLOAT");
  app.add_option("--monitor", o->monitors,
                 "label a UZ point where a parameter or a measure of the branch (--curve: the curve) reaches each "
                 "value: NAME=V1,V2,... (e.g. Delta_2=0.5,0.8; repeatable; the point is named NAME=V); --restart: "
                 "--monitor/--stop-at replace the file's, 'none' drops them")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--stop-at", o->stops,
                 "end the branch (each direction) where a parameter or a measure reaches VALUE: NAME=VALUE "
                 "(repeatable: the first reached ends it; status completed, message 'stopped at NAME=VALUE')")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  o->o_max_points =
      app.add_option("--max-points", o->engine.max_points, "points per direction, " + integer_range(2, kMaxPointsLimit))
          ->check(integer_in(2, kMaxPointsLimit))
          ->capture_default_str();
  o->o_relax_T =
      app.add_option("--relax-T", o->relax_T,
                     "relaxation time that gives the start state from the scene's shape, > 0 (orbits: rounded up to a "
                     "multiple of 2 pi)")
          ->check(positive())
          ->capture_default_str();
  app.add_option(
         "--curve", o->curve,
         "continue the curve of a special point of the one-parameter branch in (--parameter, --parameter2): "
         "LP, BP, HB (equilibrium, modal, full; modal BP: the symmetry-breaking curve Upsilon_l(sigma) = 0) or LPC, "
         "PD, NS, BP (orbit, modal-orbit; BP: the generic BP system over the shooting problem, e.g. the "
         "modal orbit's symmetry-breaking BPs) or UZ (orbit, modal-orbit: the swinging <-> tumbling "
         "transition, the orbit passing through r = 0, as a curve); default: none (one-parameter run)")
      ->check(CLI::IsMember({"LP", "BP", "HB", "LPC", "PD", "NS", "UZ"}));
  app.add_option("--parameter2", o->parameter2,
                 "--curve: second free parameter (" + continuation_parameter_list() + "), independent of --parameter");
  app.add_option("--min2", o->p2_min,
                 "--curve: lower bound of --parameter2 (the curve ends there exactly; default: none)")
      ->check(number_text("within --parameter2's domain"));
  app.add_option("--max2", o->p2_max,
                 "--curve: upper bound of --parameter2 (the curve ends there exactly; default: none)")
      ->check(number_text("within --parameter2's domain"));
  app.add_option("--point", o->point,
                 "--curve: start from the K-th located point of that type, " + integer_range(1, kCurvePointLimit))
      ->check(integer_in(1, kCurvePointLimit))
      ->capture_default_str();
  app.add_flag("--json", o->json, "print one JSON object (branch, special_points) on stdout");
  app.add_option("--csv", o->csv, "write the branch as CSV to this file");
  app.add_option("--save", o->save,
                 "write a branch file (the JSON plus every point's state and what a restart needs) to this file");
  o->o_label_every =
      app.add_option("--label-every", o->label_every,
                     "label every N-th point of a branch (AUTO's NPR), " + integer_range(0, kLabelEveryLimit) +
                         "; special points and the two ends are always labelled")
          ->check(integer_in(0, kLabelEveryLimit))
          ->capture_default_str();
  app.add_option("--measures", o->measures,
                 "text output: the measures of the labelled-point table, comma-separated (e.g. r,Psi,sigma); "
                 "default: r, Psi, sigma, Delta_2, omega, sigma_bar, mode, r_min, r_max, kind as the branch has them");
  app.add_option("--restart", o->restart,
                 "continue from a labelled point of this branch file (--save): with --label N in --parameter (default: "
                 "the file's) or, with --curve, that point's curve; or --switch-at N. Scene and kind are the file's");
  o->o_label = app.add_option("--label", o->label,
                              "--restart: the label to start from, an integer in [1, 1000000000], or the one special "
                              "point of a type and mode, TYPE[:l=L][:m=M] (e.g. BP:l=3: the BP of mode l = 3)");
  o->o_switch_at = app.add_option("--switch-at", o->switch_at,
                                  "--restart: switch onto the other branch at the BP with this label (equilibrium, "
                                  "modal, full, modal-orbit), an integer in [1, 1000000000] or BP:l=L[:m=M]; at an "
                                  "HB or PD label: exit 2 saying why no orbit branch starts there");
  app.add_option("--diagram", o->diagram,
                 "the whole bifurcation diagram to this depth, " + integer_range(0, 20) +
                     ": every branch from every BP (both halves), recursively; HB, PD, NS listed with why they "
                     "are not followed; "
                     "--save F: the tree F and its branch files F.b1.json, ...")
      ->check(integer_in(0, 20))
      ->excludes("--csv", "--curve", "--restart", "--switch-at-bp");
  app.add_option("--journal", o->journal,
                 "--diagram: checkpoint journal prefix, file PREFIX.journal (default: --save's "
                 "path, F.journal): a run stopped and run again resumes from it")
      ->needs("--diagram");
  app.add_flag("--no-journal", o->no_journal, "--diagram: no checkpoint journal (no resume)")
      ->needs("--diagram")
      ->excludes("--journal");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterContinue{"continue",
                                        "Continue an equilibrium or periodic-orbit branch in one parameter (LP/BP/HB, "
                                        "LPC/PD/NS), or a special point's curve in two",
                                        add_continue,
                                        40,
                                        {{"initial_step", "--step"}, {"p_min", "--min"}, {"p_max", "--max"}}};
}  // namespace

}  // namespace rbcstab::cli
