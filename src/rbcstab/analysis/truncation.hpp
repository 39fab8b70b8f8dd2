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
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct TruncationOptions {
  double tolerance = 1e-4;  // in (0, 1): area gain (relative to Delta) a dropped mode may take from the kept ones;
                            // 1e-4 moves sigma(T) by ~4e-6 relative (measured: ~0.04 per unit area)
  int L_max = 40;           // in [3, 100]: largest L considered (the reference of the truncation study)
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

}  // namespace rbcstab
