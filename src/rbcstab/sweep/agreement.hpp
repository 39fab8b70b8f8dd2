#pragma once
// Agreement of every predictor with a simulated diagram: for each predictor the fraction
// of grid points whose verdict (stable / unstable) and mode match the simulation, and where the
// disagreements sit (distance to that predictor's boundary in grid steps, S, alpha / alpha_*^init).
// Predictors (verdict; mode when unstable):
//   asymptotic      mu_l = Upsilon_l(<sigma_R>) > 0 for some l in [3, L]; the surviving mode (verdict
//   asymptotic_verdict) finite_horizon  G_l(T) > 0 for some l; argmax Delta_l(0)(exp(2 G_l) - 1) (verdict
//   finite_horizon_prediction) l_star          l_* >= 2.5 (alpha >= (35/8)^2); round(l_*) (the paper's l -> l+1 lines
//   at l_* = l + 1/2) alpha_init      alpha > alpha_*^init (sigma_R(0) < sigma_*: unstable at the start); round(l_*)
//   large_S         <sigma_R^-+> (S >> 1 closed forms) < sigma_* and l_* >= 2.5, i.e. C < C_*^-+ (or
//                   lambda > lambda_*^-); round(l_*). Not classified where the closed form is outside its domain.
#include <memory>
#include <string>
#include <vector>

#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab {

struct Disagreement {
  std::size_t index = 0;
  Verdict simulated = Verdict::stable;
  int l_simulated = 2;
  bool predicted_unstable = false;
  int l_predicted = 2;
  double distance_steps = 0;         // to the predictor's boundary, in grid steps (inf when it has none on the plane)
  double S = 0;                      // the point's S (small S: far from the paper's S >> 1 regime)
  double alpha_over_alpha_init = 0;  // near 1: the initial-tension criterion competes (0 if alpha_init undefined)
};

struct Agreement {
  std::string predictor;                  // asymptotic | finite_horizon | l_star | alpha_init | large_S
  std::string description;                // its verdict rule
  std::string boundary;                   // what distance_steps is measured to
  std::size_t points = 0;                 // finished simulated points the predictor classifies (failed ones excluded)
  std::size_t not_classified = 0;         // finished points outside the predictor's domain
  std::size_t verdict_matches = 0;        // stable/unstable agree
  std::size_t mode_matches = 0;           // verdict agrees and, if unstable, l agrees
  std::size_t unstable_matches = 0;       // both call the point unstable
  std::size_t unstable_mode_matches = 0;  // both unstable with the same l (the mode the predictor names)
  std::vector<Disagreement> verdict_disagreements;
  std::size_t beyond_one_step = 0;  // verdict disagreements farther than one grid step from the boundary
  std::size_t small_S = 0;          // verdict disagreements with S < 10 (outside the S >> 1 regime)
  std::size_t near_alpha_init = 0;  // verdict disagreements with |alpha/alpha_*^init - 1| < 0.25
  std::size_t boundary_pieces = 0, boundary_corners = 0;  // of the traced boundary (0 for analytic lines)
  std::string note;                                       // e.g. why the boundary could not be traced
};

struct AgreementOptions {
  bool finite_horizon = true;         // one reduced run over [0, T] per point (~0.1-1 ms each)
  bool trace = true;                  // trace the asymptotic boundary for the distances (~10 ms out of plane)
  bool trace_in_plane = true;         // trace in-plane scenes too (periodic-orbit averages: on the App. E ln B x ln C
                                      // planes in closed form in B, ~0.3-0.5 s; by continuation ~2-5 s)
  bool trace_finite_horizon = false;  // also trace the finite-horizon boundary (ln B planes in closed form in B, one
                                      // reduced run per value of the other axis: ~0.05-1 s; by continuation one per
                                      // evaluation, ~1-20 s); else its distances are to the asymptotic one
  int threads = 1;                    // per-point predictor verdicts in parallel (results do not depend on it)
  TraceOptions trace_options;         // for the traced boundaries (criterion is set per predictor); its orbit options
                                      // also serve the per-point asymptotic verdicts (in plane: one orbit per flow,
                                      // solved at the base scene's B and mapped to each point's B)
  // The asymptotic boundary of this plane when the caller has traced it already (trace_boundary with
  // trace_options and TraceCriterion::asymptotic, as a report draws it): used instead of tracing it again.
  std::shared_ptr<const TraceResult> asymptotic_boundary;
  PredictorOptions predictor;  // per-point verdicts (analysis defaults: verdicts need no 1e-12 smoothness)
  void validate() const;
};

// One entry per predictor, in the order above.
std::vector<Agreement> predictor_agreements(const Scene& base, const DiagramSpec& spec,
                                            const std::vector<PointResult>& points,
                                            const AgreementOptions& options = {});

// The asymptotic predictor alone, with distances to a given traced boundary.
Agreement asymptotic_agreement(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                               const TraceResult& boundary);

}  // namespace rbcstab
