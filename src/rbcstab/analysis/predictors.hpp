#pragma once
// The reduced-model runs the stability verdicts consume (the verdicts themselves, and the predict() that
// combines them, live in rbcstab::verdict):
//  - the time average of sigma_R on the reduced attractor (a long ReducedModel run);
//  - the reduced transient over [0, T] from the scene's own initial state, integrated once and shared by the
//    finite-horizon predictor G_l(T) = int_0^T Upsilon_l(sigma_R(t)) dt (the linear prediction
//    Delta_l(T)/Delta_l(0) = exp(2 G_l(T))) and the truncation rule (analysis/truncation.hpp);
//  - the regime of the reduced (ellipsoidal) dynamics: rolling, tank-treading, swinging, oscillating out of plane or
//    tumbling.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/quadrature.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct PredictorOptions {
  IntegratorOptions integrator = default_integrator();  // reduced runs: 3 unknowns, tight tolerances are cheap
  double transient = 500;  // skipped before the time average of sigma_R (the reduced relaxation time is O(10-100))
  double window = 2000;    // averaging window: many periods of any in-plane orbit (periods are O(2 pi))
  double average_tolerance = 1e-3;  // |mean(first half) - mean(second half)| <= tol (1 + |mean|) => converged
  double out_of_plane_r0 = 1e-4;    // r0 below this counts as out of plane (beta = 1e-3 gives r0 ~ 9e-7)
  double regime_sample_dt =
      0.05;               // in (0, window/2]: Psi sampling over the regime window: far below the rotation period 2 pi
  void validate() const;  // throws InvalidArgument naming the field
  static IntegratorOptions default_integrator();
};

// Time average of sigma_R over [transient, transient + window] along the ReducedModel trajectory from the
// scene's own initial state.
struct SigmaAverage {
  Quantity mean;  // outside_domain if the run failed or the halves disagree
  double first_half = 0, second_half = 0;
  IntegrationCounters counters;
};
SigmaAverage time_averaged_sigma_R(const Scene& scene, const PredictorOptions& options = {});

// The reduced transient over [0, T] from the scene's own initial state: int_0^t sigma_R at the checkpoints
// t_k = T k/K (k = 1..K). It depends on the parameters and beta only (the reduced model holds l = 2 alone, whose
// initial state ignores L and the l >= 3 seeds), so one run serves the truncation rule at L_max and the
// finite-horizon predictor at the chosen L. The integrator steps to every checkpoint: runs with different K
// agree to the integration error, not bit for bit.
struct ReducedTransient {
  Parameters parameters;  // of the scene it was integrated for
  double beta = 0;
  double T = 0;                        // the requested horizon
  int checkpoints = 1;                 // K
  std::vector<double> t, integral;     // checkpoints reached, int_0^{t_k} sigma_R there
  double t_end = 0, integral_end = 0;  // T on success, else where the run stopped; the integral there
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
  IntegrationCounters counters;
  bool of(const Scene& scene) const;       // integrated for this scene's parameters and beta (any T, L, seeds)
  bool of_flow(const Scene& scene) const;  // the same up to B (see transient_at_B)
  // What the reduced flow depends on: lambda, Delta, Delta0, C and beta (not B, T, L or the seeds).
  static std::array<double, 5> flow(const Parameters& p, double beta);
};
// checkpoints in [1, 10000]; options: its integrator.
ReducedTransient reduced_transient(const ValidScene& scene, double T, int checkpoints = 1,
                                   const PredictorOptions& options = {});
ReducedTransient reduced_transient(const Scene& scene, double T, int checkpoints = 1,
                                   const PredictorOptions& options = {});
// The system of that run: the scene's ReducedModel with int_0^t sigma_R appended as state 3.
class ReducedIntegralSystem {
 public:
  explicit ReducedIntegralSystem(const ValidScene& scene);
  ReducedIntegralSystem(const ReducedIntegralSystem&) = delete;  // the quadrature refers to model_
  ReducedIntegralSystem& operator=(const ReducedIntegralSystem&) = delete;
  const System& system() const { return with_integral_; }

 private:
  ReducedModel model_;
  WithQuadratures with_integral_;
};
// The run behind it, stopped at `times` (increasing, in (0, ...)): t and integral at each time reached, t_end and
// integral_end where it ended, status and counters; T and checkpoints are left to the caller.
ReducedTransient reduced_integrals(const ValidScene& scene, std::span<const double> times,
                                   const PredictorOptions& options = {});

// The transient of a scene that differs from the transient's only in B, without a run: the reduced flow holds no B
// (mu = Upsilon_2(sigma_R) is fixed by the area balance of the l = 2 mode, whose other coefficients hold none), and
// sigma_R = Upsilon_2^{-1}(mu) is affine in mu, so int sigma_R dt maps through the two affine laws exactly (to
// rounding). A diagram with B on an axis integrates one transient per value of the other axis. Throws
// InvalidArgument("transient", ...) if the flow differs (of_flow).
ReducedTransient transient_at_B(const ReducedTransient& transient, const Scene& scene);

// G_l(T) for l = 2..L (index l - 2) along the reduced transient over [0, T]; also the mean sigma_R over [0, T].
struct FiniteHorizon {
  double T = 0;
  double mean_sigma_R = 0;
  std::vector<double> G;  // index l - 2
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
  IntegrationCounters counters;
};
// From a transient of the scene (throws InvalidArgument("transient", ...) if it is another scene's); T = its T.
FiniteHorizon finite_horizon_growth(const Scene& scene, const ReducedTransient& transient);
FiniteHorizon finite_horizon_growth(const ValidScene& scene, const ReducedTransient& transient);
// The same on its own run with one checkpoint (T only).
FiniteHorizon finite_horizon_growth(const Scene& scene, double T, const PredictorOptions& options = {});

enum class Regime { rolling, tank_treading, swinging, oscillating_out_of_plane, tumbling, undetermined };
template <>
struct EnumTable<Regime> {
  static constexpr EnumName<Regime> entries[] = {
      {Regime::rolling, "rolling"},   {Regime::tank_treading, "tank-treading"},
      {Regime::swinging, "swinging"}, {Regime::oscillating_out_of_plane, "oscillating-out-of-plane"},
      {Regime::tumbling, "tumbling"}, {Regime::undetermined, "undetermined"}};
};
struct RegimeResult {
  Regime regime = Regime::undetermined;
  std::string reason;
  double Psi_range = 0, r_range = 0;  // over the regime window (transient .. transient + window)
};
// rolling: out-of-plane steady state (the paper's deformed rolling); tank_treading: in-plane steady state;
// swinging: from an in-plane start Psi oscillates with no net rotation (the paper's swinging, Sec. IV);
// oscillating_out_of_plane: the same oscillation from an out-of-plane start, where swinging (an in-plane
// motion) is the wrong name; tumbling: Psi decreases without bound.
RegimeResult reduced_regime(const Scene& scene, const PredictorOptions& options = {});
RegimeResult reduced_regime(const ValidScene& scene, const PredictorOptions& options = {});

// r0 = |z0| of the scene's stress-free l = 2 shape (0 out of plane, sqrt(3)/2 in plane).
double stress_free_r0(const Scene& scene);
double stress_free_r0(const ValidScene& scene);

}  // namespace rbcstab
