#pragma once
// The truncation L a simulation runs at. The scene's L (default 10, as the paper) fixes the physical scene: the
// perturbation seeds every l = 3..L, and a larger L is another scene. A run may drop seeded modes (run at a
// smaller L) only when a check after that run shows they did not matter; otherwise the scene's L is run.
//
// Modes that start with zero area stay at zero exactly (no l >= 3 source when the stress-free shape has no
// l >= 3 content), and a seeded mode l obeys d ln Delta_l/dt = 2 Upsilon_l(sigma(t)) exactly. A dropped mode
// acts on the kept ones only through the area it holds: sigma = -N/D sums Upsilon_l Delta_l over every mode
// (model/tension.hpp).
//  - A priori (choose_truncation): the candidate is the smallest L keeping every mode whose growth predicted
//    along the reduced transient, Delta_l(t) = delta_l exp(2 G_l(t)) with G_l(t) = t Upsilon_l(<sigma_R>_t)
//    (analysis/predictors.hpp), gains more than tolerance * Delta (and every mode the scene sets explicitly).
//    It ignores the seeded modes' feedback on sigma and transients between its checkpoints.
//  - A posteriori (run_and_check): from the candidate run's own sigma(t), read at every accepted step, each
//    dropped mode's Delta_l(t) follows in closed form; it must stay below delta_l + tolerance * Delta at every t
//    (bounded between steps), and the tension the scene would have with the dropped modes' area must differ from
//    the run's by at most tolerance * max_t |sigma| at every step. Otherwise the scene's L is run instead
//    (simulate_truncated).
#include <functional>
#include <string>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct TruncationOptions {
  double tolerance = 1e-4;     // in (0, 1): area gain (relative to Delta) a dropped mode may take from the kept ones,
                               // and the tension change (relative to max_t |sigma|) their area may cause
  int L_max = 40;              // in [3, kMaxL]: largest L choose_truncation considers (the policy passes the
                               // scene's L; 40: the reference of the truncation study)
  int checkpoints = 32;        // in [1, 10000]: times T k/K where G_l(t) is evaluated, so that a mode that grows
                               // and decays again before T still counts
  PredictorOptions predictor;  // the reduced run (its integrator tolerances)
  void validate() const;       // throws InvalidArgument naming the field
};

struct TruncationChoice {
  int L = 10;
  std::string reason;              // one line for the user: the rule and what decided it
  std::vector<double> G_max;       // index l - 3 for l = 3..L_max: max over the checkpoints of G_l(t)
  std::vector<double> log_gain;    // index l - 3: ln(delta_l (exp(2 G_max) - 1) / Delta), -inf-free: -1e300 if no gain
  double dropped_seeded_area = 0;  // sum of delta_l for l = L+1..L_max: the area the candidate run does not hold
  DomainStatus status = DomainStatus::ok;  // outside_domain: the reduced run failed, L = L_max (conservative)
  IntegrationCounters counters;
};

TruncationChoice choose_truncation(const Scene& scene, const TruncationOptions& options = {});
// The reduced transient the rule reads: over [0, scene.T] at options.checkpoints, with options.predictor's
// integrator. The finite-horizon predictor can share it (finite_horizon_growth(scene, transient)).
ReducedTransient truncation_transient(const Scene& scene, const TruncationOptions& options = {});
ReducedTransient truncation_transient(const ValidScene& scene, const TruncationOptions& options = {});
// The rule from that transient: bit for bit choose_truncation(scene, options). Throws
// InvalidArgument("transient", ...) if it is another scene's or has another horizon or checkpoint count.
TruncationChoice choose_truncation(const Scene& scene, const ReducedTransient& transient,
                                   const TruncationOptions& options = {});

// How a computation uses L; it decides whether the automatic choice applies when no L was given.
enum class TruncationUse {
  simulation,   // one scene simulated over [0, T] (simulate, summary, report, post, shape): the candidate of
                // choose_truncation, checked after its run (simulate_truncated)
  grid,         // many scenes at one L (diagram, trace, the Fig. 6e table): the automatic choice is per scene
  analysis,     // modes l = 2..L with no simulation horizon (thresholds, modal and full continuation, floquet)
  measurement,  // a benchmark measures at the L it is given
  reduced,      // the reduced system (l = 2 only): L is not used
};

struct TruncationDecision {
  int L = 10;
  std::string reason;  // one line: "L = 4: ..." (the JSON key "L_reason")
  bool check = false;  // L is a candidate below the scene's L: only a run and its check can confirm it
};

// The one truncation policy of every command that takes a scene, before any run. An L given by a flag or the
// scene file is kept and the reason says which; otherwise a simulation gets the candidate of choose_truncation
// with L_max = scene.L (never above the scene's L; check = true when below it), and every other use keeps the
// scene's L with the reason the automatic choice does not apply. The reduced use keeps L and says it is unused.
// transient (optional): the scene's truncation_transient, read by the automatic choice instead of a run of its
// own, so that the finite-horizon predictor can share it.
TruncationDecision resolve_truncation(const Scene& scene, Origin L_origin, TruncationUse use,
                                      const TruncationOptions& options = {},
                                      const ReducedTransient* transient = nullptr);

// The scene run at L_candidate in [2, scene.L) (the kept modes keep the scene's seeds) and the check of the
// dropped modes l = L_candidate+1..scene.L against that run's sigma(t) (TruncationCheck, io/scene_file.hpp;
// check.L_run = L_candidate when it passed, else scene.L: the caller reruns). The building block of
// simulate_truncated, public so that tests can read the check of any candidate.
struct CheckedRun {
  SimulationResult run;  // at L_candidate
  TruncationCheck check;
};
CheckedRun run_and_check(const Scene& scene, int L_candidate, const SimulationOptions& options = {},
                         const TruncationOptions& truncation = {});

// The policy for one scene simulated over [0, T], and its run: resolve_truncation; a candidate below the scene's
// L is run and checked (run_and_check) and kept if it passes, else the scene's L is run. Sets file.scene.L to the
// L run, file.L_reason, and file.truncation_check when a candidate was checked. Every front end that simulates
// one scene calls this. The candidate and the run at the scene's L are `run_full` (empty: simulate), which
// verdict's simulate_scene makes certified: the check reads sigma(t) at every accepted step, and over periods a
// certified run skipped it bounds the dropped modes from the orbit's tension (EarlyTermination::sigma_integral
// and the range of sigma over a period on each side of the skip).
// `valid` (validated(file), io) refers to file.scene and stays valid: the L set is the scene's or a checked one.
// Without a `transient`, the automatic choice reads `transient_run(valid, options)`: the scene's transient over
// [0, T] at options.checkpoints (empty: truncation_transient; verdict's simulate_scene: certified_transient,
// which stops integrating once the reduced run is certified on its attractor).
using SceneRunner = std::function<SimulationResult(const ValidScene&, const SimulationOptions&)>;
using TransientRunner = std::function<ReducedTransient(const ValidScene&, const TruncationOptions&)>;
SimulationResult simulate_truncated(SceneFile& file, const SimulationOptions& options,
                                    const ReducedTransient* transient = nullptr, const SceneRunner& run_full = {},
                                    const TransientRunner& transient_run = {});
SimulationResult simulate_truncated(SceneFile& file, const ValidScene& valid, const SimulationOptions& options,
                                    const ReducedTransient* transient = nullptr, const SceneRunner& run_full = {},
                                    const TransientRunner& transient_run = {});

// The policy applied to a scene file (its L's origin) for a front end that integrates the scene itself: sets
// scene.L, L_reason (and for a simulation, by simulate_truncated without a trajectory, truncation_check), then
// validates the scene. A simulation's L is then the one whose run was checked. run_candidate, transient_run: as
// simulate_truncated's run_full and transient_run (verdict's apply_scene_truncation makes both certified).
void apply_truncation(SceneFile& file, TruncationUse use, const ReducedTransient* transient = nullptr,
                      const SceneRunner& run_candidate = {}, const TransientRunner& transient_run = {});
// The same for a file already checked (valid = validated(file)), which stays valid: the L set is checked alone.
void apply_truncation(SceneFile& file, const ValidScene& valid, TruncationUse use,
                      const ReducedTransient* transient = nullptr, const SceneRunner& run_candidate = {},
                      const TransientRunner& transient_run = {});

}  // namespace rbcstab
