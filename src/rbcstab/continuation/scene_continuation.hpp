#pragma once
// Continuation of a scene: the typed entry points behind `rbcstab continue` and the report's
// [continuation] panel. A BranchSpec names what to continue (the problem kind, the free parameter, its
// bounds, the engine options); continue_scene picks the problem and its start, continues the branch and
// measures every point by name; continue_curve continues a special point's curve in a second parameter
// (choosing the curve system); switch_at_bp follows the branch bifurcating at a BP. Every point a user
// may restart from carries a label (AUTO's LAB); restart, switch_at_label and restart_curve start again
// from a labelled point of a run (branch_file.hpp saves and loads runs). Results are plain data;
// branch_io.hpp renders them (JSON, CSV, text).
#include "rbcstab/continuation/dense.hpp"
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/parameters.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

// What is continued: equilibria of the reduced system, of the modal model or of the full model, or
// periodic orbits of the forced in-plane reduced system or modal model.
enum class ProblemKind { equilibrium, modal, full, orbit, modal_orbit };
template <>
struct EnumTable<ProblemKind> {  // in the order messages list the kinds
  static constexpr EnumName<ProblemKind> entries[] = {{ProblemKind::equilibrium, "equilibrium"},
                                                      {ProblemKind::orbit, "orbit"},
                                                      {ProblemKind::modal, "modal"},
                                                      {ProblemKind::modal_orbit, "modal-orbit"},
                                                      {ProblemKind::full, "full"}};
};
ProblemKind problem_kind_from_string(const std::string& name);  // throws InvalidArgument("kind", ...)
ModelLevel model_level(ProblemKind kind);                       // reduced, modal or full
bool is_orbit(ProblemKind kind);
// How the truncation policy treats a kind's L: the reduced kinds do not use it; modal and full equilibria
// and modal orbits are analyses with no simulation horizon (resolve_truncation).
TruncationUse truncation_use(ProblemKind kind);
// The rest shape's orientation a kind needs when the user gives none: equilibria need an autonomous
// system (rest shape out of plane, 0), periodic orbits a forced one (in plane, pi/2).
double default_beta(ProblemKind kind);

// direction_from_string throws InvalidArgument("direction", ...) naming the allowed directions.
Direction direction_from_string(const std::string& name);

// The curve of a special point in two parameters: LP, BP, HB of equilibria; LPC, PD, NS, BP of orbits;
// UZ: a user event's zero set (orbits: the swinging <-> tumbling transition, event_curve.hpp).
enum class CurveKind { LP, BP, HB, LPC, PD, NS, UZ };
std::string to_string(CurveKind kind);
CurveKind curve_kind_from_string(const std::string& name);  // throws InvalidArgument("curve", ...)
SpecialPointType special_point_type(CurveKind kind);

// The system that continues a curve: the fold (LP, LPC), Hopf and period-doubling minimal augmentations,
// the Neimark-Sacker system, the generic 2n + 2 branch-point system, and the two symmetry-reduced BP
// systems: ModalBranchPointCurve (modal equilibria) and ModalOrbitBranchPointCurve (Z2-reduced, the
// in-plane ellipsoidal modal orbit); event: F = 0 plus the event's smooth form (EventCurveProblem).
enum class CurveSystem {
  fold,
  hopf,
  period_doubling,
  neimark_sacker,
  branch_point,
  modal_branch_point,
  ellipsoidal_orbit_branch_point,
  event
};
template <>
struct EnumTable<CurveSystem> {
  static constexpr EnumName<CurveSystem> entries[] = {
      {CurveSystem::fold, "fold"},
      {CurveSystem::hopf, "hopf"},
      {CurveSystem::period_doubling, "period_doubling"},
      {CurveSystem::neimark_sacker, "neimark_sacker"},
      {CurveSystem::branch_point, "branch_point"},
      {CurveSystem::modal_branch_point, "modal_branch_point"},
      {CurveSystem::ellipsoidal_orbit_branch_point, "ellipsoidal_orbit_branch_point"},
      {CurveSystem::event, "event"}};
};

// A named measure of a point: a number, an integer (winding, mode) or a label (orbit kind).
using MeasureValue = std::variant<double, int, std::string>;

// The measures of a point of a branch of `kind` (L: the scene's truncation), in output order:
//   equilibrium: r, Psi;  modal, full: r, Psi, sigma, Delta_2 ... Delta_L;
//   orbit: r, Psi (t = 0), r_min, r_max, Psi_min, Psi_max, winding, kind, trivial_multiplier;
//   modal_orbit: r, Psi, sigma, Delta_2 ... Delta_L (t = 0), winding, kind, trivial_multiplier.
std::vector<std::string> measure_names(ProblemKind kind, int L);
// The measures of a point of a curve continued by `system` from a branch of `kind`: an equilibrium's
// measures (plus omega on a Hopf curve); for orbits r, Psi at t = 0 (plus sigma_bar, mode on the
// ellipsoidal-orbit BP curve; t_passage on the event curve: the time of the passage through z = 0,
// continuous along the curve, not reduced mod 2 pi).
std::vector<std::string> curve_measure_names(ProblemKind kind, CurveSystem system, int L);
// Whether a measure is a CSV column: not trivial_multiplier, a check of the shooting (1 up to rounding)
// rather than a property of the orbit, which JSON carries.
bool is_csv_measure(std::string_view name);

// A branch (or curve) and its points' measures: what every rendering and plot reads. The points keep
// their parameters, full state x, spectrum and stability (Branch); measures are aligned with measure_names.
struct MeasuredBranch {
  Branch branch;
  StabilityKind spectrum_kind = StabilityKind::eigenvalues;  // eigenvalues or Floquet multipliers
  std::vector<std::string> measure_names;
  std::vector<std::vector<MeasureValue>> point_measures;    // [k]: of branch.points[k]
  std::vector<std::vector<MeasureValue>> special_measures;  // [k]: of branch.special_points[k]
  // Labels (AUTO's LAB): positive integers, unique over a run (a branch, its switched branch, a curve and
  // the branch it started from), on every special point, on the two ends of the branch and on every
  // label_every-th point counted from the first; 0: an unlabelled point. Numbered along the branch.
  std::vector<int> point_labels;    // [k]: of branch.points[k]
  std::vector<int> special_labels;  // [k]: of branch.special_points[k]
  // The label of point k / special point k (0 when unlabelled or labels were never assigned).
  int point_label(std::size_t k) const;
  int special_label(std::size_t k) const;
  // "EP" for the first and the last point of the branch, "" for a regular point.
  std::string point_type(std::size_t k) const;
  int last_label() const;  // the largest label, 0 if none
  // The measure `name` of point k; throws InvalidArgument("measure", ...) for an unknown name.
  const MeasureValue& measure(std::size_t k, std::string_view name) const;
  // The same as a number (integers converted); throws InvalidArgument("measure", ...) for a label.
  double number(std::size_t k, std::string_view name) const;
};

// A one-parameter branch from a scene.
struct BranchSpec {
  Scene scene;  // every parameter but the free one; modal_orbit: the scene that is simulated to relax
  ProblemKind kind = ProblemKind::equilibrium;
  ContinuationParameter parameter = ContinuationParameter::lambda;
  // Steps, tolerances, detection; p_min/p_max bound the free parameter (landed on exactly; lambda's and
  // beta's closed domain edges replace bounds beyond them) and the branch runs both ways by default.
  ContinuationOptions engine = [] {
    ContinuationOptions o;
    o.direction = Direction::both;
    return o;
  }();
  double relax_T = 200;       // relaxation that gives the start state (orbits: rounded up to a multiple of 2 pi)
  // Orbits: after relax_T, whole forcing periods are relaxed in chunks until the periodicity defect
  // |x(2 pi k) - x(2 pi (k - 1))|_2 (a unit-norm state) is below relax_tol or relax_max_periods more
  // have run; Newton then solves the orbit from there. Near an attracting orbit with leading multiplier
  // rho the distance to it is ~ defect / (1 - |rho|): 4e-5 at the default for |rho| = 0.977 (the
  // in-plane orbit at Lambda = 1.2, S = 200), 4e-4 for 0.9976 (S = 2000), well inside Newton's reach.
  double relax_tol = 1e-6;
  int relax_max_periods = 20000;
  // An orbit start certified unstable (not what the scene relaxes to) is refused (StartPoint::refused:
  // the branch is not continued) unless this is set. An unstable equilibrium start is reported only
  // (the modal and full kinds start on the symmetric branch by design, stable or not).
  bool allow_unstable_start = false;
  OrbitOptions orbit;         // orbit, modal_orbit: the shooting
  // Also follow the branch bifurcating at the first BP met from the start in the continuation direction
  // (direction both: the BP nearest the start in arclength, first_bp_met).
  bool switch_at_bp = false;
  int label_every = 10;  // label every N-th point (AUTO's NPR); 0: only the ends and the special points
  // A restart (restart_spec): the problem's unknowns at the scene's value of the free parameter replace
  // the kind's start, and the scene is the problem's scene as it is (modal_orbit: not rescaled to the
  // total excess area, which it already is).
  std::optional<Eigen::VectorXd> start_state;
  // Throws InvalidArgument naming the field: switch_at_bp for kinds that cannot switch, the orbit
  // options, the scene's model level against the kind (model), relax_T, relax_tol, relax_max_periods,
  // label_every, the engine options,
  // and a start value (the scene's parameter) outside the bounds (min).
  void validate() const;
};

// The bounds the engine uses for parameter q from the requested [lo, hi]: lambda >= 0 and beta in
// [0, pi] are closed domain edges, landed on exactly instead of failing beyond them.
void set_domain_bounds(ContinuationOptions& engine, ContinuationParameter q, double lo, double hi);
// A requested bound (lo_name, hi_name: the flags or keys that gave them) beyond a closed edge is a mistake, not
// a wish to stop there: InvalidArgument naming it, its value and the domain. An infinite bound (none) passes.
void require_bounds_in_domain(ContinuationParameter q, double lo, double hi, const std::string& lo_name,
                              const std::string& hi_name);

// How a branch starts from its scene. equilibrium: the scene relaxed for relax_T (on the stable branch
// when one attracts it); modal: the ellipsoidal equilibrium's closed form; full: the closed form without
// stress-free l >= 3 content, else the scene relaxed by the full model (Newton from the ellipsoid may land
// on an unstable member of the unfolded pitchfork); orbits: the relaxed state's shooting guess. Full and
// orbits are then solved by Newton at fixed parameter; the other kinds leave that to the engine's start.
enum class StartMethod { relaxed, ellipsoidal, restart };  // restart: BranchSpec::start_state
template <>
struct EnumTable<StartMethod> {
  static constexpr EnumName<StartMethod> entries[] = {
      {StartMethod::relaxed, "relaxed"}, {StartMethod::ellipsoidal, "ellipsoidal"}, {StartMethod::restart, "restart"}};
};
struct StartPoint {
  StartMethod method = StartMethod::relaxed;
  Eigen::VectorXd x;  // the problem's unknowns (orbits: the shooting vector)
  double p = 0;       // the free parameter's start value
  bool newton = false;      // Newton at fixed p solved x (full, orbits)
  bool converged = true;    // false: no solution near the start state; message says which
  int iterations = 0;
  double residual_norm = 0;
  // Orbits: the relaxation before Newton (BranchSpec::relax_tol).
  int relaxation_periods = 0;  // forcing periods relaxed in all (relax_T's and the adaptive ones)
  double periodicity_defect = std::numeric_limits<double>::quiet_NaN();  // of the last period relaxed
  double periodicity_tol = std::numeric_limits<double>::quiet_NaN();     // spec.relax_tol
  bool relaxed = false;        // the defect fell below the tolerance within relax_max_periods
  // The solution's stability at the start (equilibria: after Newton at fixed p from x), certified as
  // every branch point is (certify_solution); stable and n_unstable as BranchPoint's.
  bool stable = true;
  int n_unstable = 0;
  Stability stability = Stability::uncertain;
  double margin = std::numeric_limits<double>::quiet_NaN();
  double margin_error = std::numeric_limits<double>::quiet_NaN();
  bool refused = false;  // an orbit certified unstable without spec.allow_unstable_start: not continued
  // Why it failed or was refused; else a note (an unstable or uncertain start, a relaxation that
  // reached its bound), or empty.
  std::string message;
};
StartPoint find_start(const BranchSpec& spec);  // validates spec

// The scene the problem is built from: a modal orbit's Delta is the simulated scene's total excess area
// (spec.scene as it is for a restart).
Scene problem_scene_of(const BranchSpec& spec);

// The branch that bifurcates at a BP of a branch.
struct SwitchedBranch {
  bool switched = false;  // false: message says why (no such BP, not a simple BP, corrector failed)
  std::string message;
  int bp_number = 1;      // the k-th BP of the branch it switched from
  int bp_label = 0;       // that BP's label (0: none)
  MeasuredBranch branch;  // labelled after the branch it switched from
};

struct SceneBranch {
  BranchSpec spec;      // as run: the engine's bounds set by set_domain_bounds
  Scene problem_scene;  // the problem's scene (modal_orbit: spec.scene with its total excess area as Delta)
  StartPoint start;
  MeasuredBranch branch;  // status start_failed (no points) when the start did not converge
  std::optional<SwitchedBranch> switched;  // spec.switch_at_bp: at the first BP met (first_bp_met)
};

// The number k (find_special_point) of the first BP of b met from its start, continued in `direction`:
// the first along the branch for forward and backward, the one nearest the start in arclength for both.
// 0 if b has no BP.
int first_bp_met(const Branch& b, Direction direction);

// Validates spec, finds the start and continues the branch (orbits with the swing_tumble UZ event).
SceneBranch continue_scene(const BranchSpec& spec);

// The branch bifurcating at the k-th BP of `from` (equilibrium, modal, full), continued with
// from.spec.engine or options.continuation. Throws InvalidArgument("switch_at_bp", ...) for kinds that
// cannot switch and ("bp", ...) for k < 1.
SwitchedBranch switch_at_bp(const SceneBranch& from, int k = 1);
SwitchedBranch switch_at_bp(const SceneBranch& from, int k, const BranchSwitchOptions& options);

// The curve of the point-th located special point of type `type` of a one-parameter branch, in
// (branch parameter, parameter2) with parameter2 free, both directions, the branch's engine options
// (without its events) and [p2_min, p2_max] as bounds (set_domain_bounds).
struct CurveSpec {
  CurveKind type = CurveKind::LP;
  std::optional<ContinuationParameter> parameter2;  // required; independent of the branch's parameter
  double p2_min = -std::numeric_limits<double>::infinity(), p2_max = std::numeric_limits<double>::infinity();
  int point = 1;
  // A BP of a modal orbit whose v~ and every a_l are below this (max norm) lies on the in-plane
  // ellipsoidal orbit, which the Z2-reduced system continues: those entries are exactly 0 there on a
  // continued branch (an invariant subspace), while an orbit with l >= 3 content has them O(1).
  double symmetric_tol = 1e-8;
  // Throws InvalidArgument naming the field: the type against the branch's kind (curve), parameter2
  // (missing, or coupled to the branch's parameter), min2 >= max2, point < 1, switch_at_bp set.
  void validate(const BranchSpec& branch) const;
};

// Which system continues the curve of `start` (a special point of a branch of `kind` in q1, with the
// problem's scene at the start: parameter q1 set to start.p): BP of modal equilibria -> the symmetry-
// breaking ModalBranchPointCurve; BP of a modal orbit on the ellipsoidal orbit (v~ = 0, a_l = 0 within
// symmetric_tol, an untilted rest shape, beta fixed) -> the Z2-reduced system; any other BP -> generic.
CurveSystem curve_system(ProblemKind kind, CurveKind type, const Scene& scene, ContinuationParameter q1,
                         ContinuationParameter q2, const SpecialPoint& start, double symmetric_tol = 1e-8);

struct SceneCurve {
  CurveSpec spec;      // as run: the bounds set by set_domain_bounds
  SceneBranch one;     // the one-parameter branch the curve starts from
  bool started = false;  // false: no start (the branch's start failed, or no located point); message says why
  std::string message;
  SpecialPoint start;  // the special point of `one`
  double start_p2 = 0;   // parameter2 at the start (the scene's value)
  CurveSystem system = CurveSystem::fold;
  MeasuredBranch curve;  // points carry (parameter, parameter2)
};

// Validates both specs (before any work), runs the branch, then its curve.
SceneCurve continue_curve(const BranchSpec& branch, const CurveSpec& curve);
// The curve from a branch already run (no re-run; its switched branch, if any, does not matter).
SceneCurve continue_curve(const SceneBranch& one, const CurveSpec& curve);

// ---- restart from a labelled point (AUTO's IRS) ----

// A run whose labelled points a restart starts from: a one-parameter branch (with its switched branch)
// or a curve (with the one-parameter branch it started from).
using ContinuationRun = std::variant<SceneBranch, SceneCurve>;

// A labelled point of a run and where it lies.
struct LabelledPoint {
  int label = 0;
  std::string type;     // "" or "EP" for a point of a branch, else the special point's type ("BP", "UZ", ...)
  int branch = 1;       // 1: the primary (a curve run: the one-parameter) branch; 2: the switched branch or the curve
  bool special = false;   // a special point (index into special_points) or a point (index into points)
  std::size_t index = 0;
};
// The number of unknowns of a branch's problem (its spec on its problem scene).
Eigen::Index problem_dimension(const SceneBranch& r);
// The state of the problem a curve augments (c.one's) at a point X of the curve (c.curve's unknowns);
// throws InvalidArgument("x", ...) when X is too short for the curve's system.
Eigen::VectorXd curve_point_state(const SceneCurve& c, const Eigen::VectorXd& X);

// Every labelled point of a run, in label order.
std::vector<LabelledPoint> labelled_points(const ContinuationRun& run);
// Throws InvalidArgument("label", ...) listing the run's labels when it has no such label.
LabelledPoint find_label(const ContinuationRun& run, int label, const std::string& flag = "label");

// What a restart changes in the run's spec; unset fields keep the run's values (the bounds: the run's when
// the parameter is the run's, none otherwise).
struct RestartChanges {
  std::optional<ProblemKind> kind;  // not a change: when set, it must be the run's (else InvalidArgument("kind"))
  std::optional<ContinuationParameter> parameter;  // default: the run's (a curve run: its first parameter)
  std::optional<double> p_min, p_max;
  std::optional<Direction> direction;
  std::optional<double> initial_step, max_step;
  std::optional<std::size_t> max_points;
  std::optional<int> label_every;
  bool switch_at_bp = false;
};

// The spec that continues from label `label` of `run`: the run's kind, engine and orbit options, its
// problem scene with the labelled point's parameter values (a curve point: both) and the point's state as
// start_state (a curve point: the state of the problem the curve augments), the changes applied.
// Throws InvalidArgument("label", ...) for a label the run does not have, and as BranchSpec::validate.
BranchSpec restart_spec(const ContinuationRun& run, int label, const RestartChanges& changes = {});
// continue_scene(restart_spec(...)): labels from 1.
SceneBranch restart(const ContinuationRun& run, int label, const RestartChanges& changes = {});
// The run's branch that holds the BP labelled `label` (its labels kept) with the branch bifurcating there
// as its switched branch (labelled after the run's labels), continued with the run's options and the
// changes. Throws InvalidArgument("switch_at", ...) unless the label is a BP of a one-parameter branch,
// ("parameter", ...) for a parameter other than the branch's.
SceneBranch switch_at_label(const ContinuationRun& run, int label, const RestartChanges& changes = {});
// The curve of the special point labelled `label` (or of a point of a curve of the same type) in
// (the run's parameter, curve.parameter2); curve.point is ignored. Throws InvalidArgument("label", ...)
// for a point of another type, ("parameter", ...) for a parameter other than the run's, and as
// CurveSpec::validate.
SceneCurve restart_curve(const ContinuationRun& run, int label, const CurveSpec& curve,
                         const RestartChanges& changes = {});
// One restart request, as `rbcstab continue --restart` takes it: from label (a branch, or with curve that
// point's curve) or a switch at the BP labelled switch_at. validate() names the flags of a bad combination.
struct RestartRequest {
  int label = 0, switch_at = 0;
  std::optional<CurveSpec> curve;
  RestartChanges changes;
  void validate() const;
};
ContinuationRun restart(const ContinuationRun& run, const RestartRequest& request);

// ---- a run as a front end asks for it (`rbcstab continue`, the Python module) ----

// The curve of the point-th located special point of type `type` in (the branch's parameter, parameter2):
// the type and parameter2 by name (InvalidArgument "curve" / "parameter2" listing the allowed names; an
// empty parameter2 stays unset, which CurveSpec::validate refuses), the bounds neither NaN nor beyond
// parameter2's closed domain edges (require_bounds_in_domain), named min2_name / max2_name in messages.
CurveSpec curve_spec(const std::string& type, const std::string& parameter2, double p2_min, double p2_max,
                     int point = 1, const std::string& min2_name = "min2", const std::string& max2_name = "max2");

// A fresh run (not a restart) from a scene file.
struct SceneRun {
  // spec.scene is the file's scene with the kind's truncation (apply_truncation) and, when the file leaves
  // beta at its default, the kind's default beta (default_beta).
  BranchSpec spec;
  std::optional<CurveSpec> curve;  // set: the curve of a special point of the branch instead of the branch
  std::string L_reason;            // why spec.scene.L (put_truncation)
};
// `spec` as given but its scene taken from `file` (as read: L as given); the bounds spec.engine.p_min/p_max
// neither NaN nor beyond the parameter's closed domain edges, named min_name / max_name in messages.
SceneRun scene_run(SceneFile file, BranchSpec spec, std::optional<CurveSpec> curve = {},
                   const std::string& min_name = "min", const std::string& max_name = "max");
// continue_curve(run.spec, *run.curve), or continue_scene(run.spec) without a curve.
ContinuationRun continue_run(const SceneRun& run);
// Why a run restarted from a saved run (or loaded from a branch file) has its L: the saved scene's.
std::string saved_run_L_reason(const ContinuationRun& run);

// A branch that ends at a stop condition or on the edge of its parameter's domain has ended normally.
bool ended_normally(ContinuationStatus status);

// How a run ended, for a front end: whether it has output to show (a start that failed or was refused has
// none), a note (an unstable equilibrium start), and why it failed ("" when it did not): a failed start, a
// failed switch, or a branch or curve that stopped before a normal end.
struct RunOutcome {
  bool has_output = true;
  std::string note;
  std::string failure;
};
RunOutcome outcome(const SceneBranch& run);
RunOutcome outcome(const SceneCurve& run);
RunOutcome outcome(const ContinuationRun& run);
// The truncation L of a run's scene (a curve: that of the branch it starts from).
int run_L(const SceneBranch& run);
int run_L(const SceneCurve& run);
int run_L(const ContinuationRun& run);

}  // namespace rbcstab
