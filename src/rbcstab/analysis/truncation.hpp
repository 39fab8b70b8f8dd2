#pragma once
// The truncation L a scene needs. Modes that start with zero area stay at zero exactly
// (no l >= 3 source when the stress-free shape is ellipsoidal), so L only decides which seeded modes exist.
// A dropped mode l > L affects the kept ones in two ways only:
//  - its seeded area delta_l: a stable mode returns it to l = 2 (bookkeeping, not dynamics: an L run with
//    Delta raised by the dropped seeded area reproduces the larger-L run; tests/analysis/truncation_test.cpp);
//  - its area gain max_t [Delta_l(t) - delta_l], which it would take from the kept modes.
// The rule bounds the second by the finite-horizon predictor: along the reduced transient,
// Delta_l(t) = delta_l exp(2 G_l(t)) with G_l(t) = t Upsilon_l(<sigma_R>_t) (analysis/predictors.hpp), so the
// chosen L is the smallest that keeps every mode with predicted gain delta_l (exp(2 max_t G_l(t)) - 1) above
// tolerance * Delta (and every mode the scene sets explicitly).
#include <string>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct TruncationOptions {
  double tolerance = 1e-4;  // in (0, 1): area gain (relative to Delta) a dropped mode may take from the kept ones;
                            // 1e-4 moves sigma(T) by ~4e-6 relative (measured: ~0.04 per unit area)
  int L_max = 40;           // in [3, kMaxL]: largest L considered (the reference of the truncation study)
  int checkpoints = 32;     // in [1, 10000]: times T k/K where G_l(t) is evaluated, so that a mode that grows
                            // and decays again before T still counts
  PredictorOptions predictor;  // the reduced run (its integrator tolerances)
  void validate() const;       // throws InvalidArgument naming the field
};

struct TruncationChoice {
  int L = 10;
  std::string reason;             // one line for the user: the rule and what decided it
  std::vector<double> G_max;      // index l - 3 for l = 3..L_max: max over the checkpoints of G_l(t)
  std::vector<double> log_gain;   // index l - 3: ln(delta_l (exp(2 G_max) - 1) / Delta), -inf-free: -1e300 if no gain
  double dropped_seeded_area = 0; // sum of delta_l for l = L+1..L_max: returned to l = 2 in an L_max run
  DomainStatus status = DomainStatus::ok;  // outside_domain: the reduced run failed, L = L_max (conservative)
  IntegrationCounters counters;
};

TruncationChoice choose_truncation(const Scene& scene, const TruncationOptions& options = {});
// The reduced transient the rule reads: over [0, scene.T] at options.checkpoints, with options.predictor's
// integrator. The finite-horizon predictor can share it (finite_horizon_growth(scene, transient)).
ReducedTransient truncation_transient(const Scene& scene, const TruncationOptions& options = {});
// The rule from that transient: bit for bit choose_truncation(scene, options). Throws
// InvalidArgument("transient", ...) if it is another scene's or has another horizon or checkpoint count.
TruncationChoice choose_truncation(const Scene& scene, const ReducedTransient& transient,
                                   const TruncationOptions& options = {});

// How a computation uses L; it decides whether the automatic choice applies when no L was given.
enum class TruncationUse {
  simulation,   // one scene simulated over [0, T] (simulate, summary, report, post, shape): choose_truncation
  grid,         // many scenes at one L (diagram, trace, the Fig. 6e table): the automatic choice is per scene
  analysis,     // modes l = 2..L with no simulation horizon (thresholds, modal and full continuation, floquet)
  measurement,  // a benchmark measures at the L it is given
  reduced,      // the reduced system (l = 2 only): L is not used
};

struct TruncationDecision {
  int L = 10;
  std::string reason;  // one line: "L = 4: ..." (the JSON key "L_reason")
};

// The one truncation policy of every command that takes a scene. An L given by a flag or the scene file is kept
// and the reason says which; otherwise a simulation gets the automatic choice and every other use keeps the
// scene's L with the reason the automatic choice does not apply. The reduced use keeps L and says it is unused.
// transient (optional): the scene's truncation_transient, read by the automatic choice instead of a run of its
// own, so that the finite-horizon predictor can share it.
TruncationDecision resolve_truncation(const Scene& scene, Origin L_origin, TruncationUse use,
                                      const TruncationOptions& options = {}, const ReducedTransient* transient = nullptr);

// resolve_truncation applied to a scene file (its L's origin): sets scene.L and L_reason, then validates the scene.
// Every front end (the command line, the Python module) calls this once per scene it runs.
void apply_truncation(SceneFile& file, TruncationUse use, const ReducedTransient* transient = nullptr);

}  // namespace rbcstab
