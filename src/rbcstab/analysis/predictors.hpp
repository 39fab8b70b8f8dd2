#pragma once
// Three predictors of a scene's verdict, cheapest first (docs/theory.md):
//  (a) asymptotic: mu_l = Upsilon_l(<sigma_R>) on the reduced attractor (the exact equilibrium for an
//      out-of-plane scene, else a converged time average of sigma_R along a long ReducedModel run);
//  (b) finite horizon: G_l(T) = int_0^T Upsilon_l(sigma_R(t)) dt along the reduced transient from the scene's
//      own initial state, the linear prediction Delta_l(T)/Delta_l(0) = exp(2 G_l(T));
//  (c) the nonlinear modal simulation (simulate()).
// Also the regime of the reduced (ellipsoidal) dynamics: rolling, tank-treading, swinging or tumbling.
#include <string>
#include <vector>

#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct PredictorOptions {
  IntegratorOptions integrator = default_integrator();  // reduced runs: 3 unknowns, tight tolerances are cheap
  double transient = 500;     // skipped before the time average of sigma_R (the reduced relaxation time is O(10-100))
  double window = 2000;       // averaging window: many periods of any in-plane orbit (periods are O(2 pi))
  double average_tolerance = 1e-3;  // |mean(first half) - mean(second half)| <= tol (1 + |mean|) => converged
  double out_of_plane_r0 = 1e-4;    // r0 below this counts as out of plane (beta = 1e-3 gives r0 ~ 9e-7)
  double regime_sample_dt = 0.05;   // in (0, window/2]: Psi sampling over the regime window: far below the rotation period 2 pi
  void validate() const;            // throws InvalidArgument naming the field
  static IntegratorOptions default_integrator();
};

// Time average of sigma_R over [transient, transient + window] along the ReducedModel trajectory from the
// scene's own initial state.
struct SigmaAverage {
  Quantity mean;               // outside_domain if the run failed or the halves disagree
  double first_half = 0, second_half = 0;
  IntegrationCounters counters;
};
SigmaAverage time_averaged_sigma_R(const Scene& scene, const PredictorOptions& options = {});

// G_l(T) for l = 2..L (index l - 2) along the reduced transient over [0, T]; also the mean sigma_R over [0, T].
struct FiniteHorizon {
  double T = 0;
  double mean_sigma_R = 0;
  std::vector<double> G;       // index l - 2
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
  IntegrationCounters counters;
};
FiniteHorizon finite_horizon_growth(const Scene& scene, double T, const PredictorOptions& options = {});

enum class Regime { rolling, tank_treading, swinging, tumbling, undetermined };
template <>
struct EnumTable<Regime> {
  static constexpr EnumName<Regime> entries[] = {
      {Regime::rolling, "rolling"}, {Regime::tank_treading, "tank-treading"}, {Regime::swinging, "swinging"},
      {Regime::tumbling, "tumbling"}, {Regime::undetermined, "undetermined"}};
};
struct RegimeResult {
  Regime regime = Regime::undetermined;
  std::string reason;
  double Psi_range = 0, r_range = 0;  // over the regime window (transient .. transient + window)
};
// rolling: out-of-plane steady state (the paper's deformed rolling); tank_treading: in-plane steady state;
// swinging: Psi oscillates with no net rotation; tumbling: Psi decreases without bound.
RegimeResult reduced_regime(const Scene& scene, const PredictorOptions& options = {});

struct ModePrediction {
  std::string predictor;      // "asymptotic", "finite_horizon", "simulation"
  std::vector<int> unstable;  // l in [3, L] predicted (or seen) to grow
  int l_Delta = 2;            // predicted argmax_l [Delta_l(T) - Delta_l(0)]
  std::vector<double> rate;   // index l - 2: mu_l (asymptotic), G_l(T) (finite horizon), ln(X_l/Delta_l(0))/2 (simulation)
  DomainStatus status = DomainStatus::ok;
  std::string reason;
};

struct ScenePrediction {
  Quantity sigma_R_asymptotic;          // <sigma_R> on the attractor
  std::string asymptotic_source;        // "exact out-of-plane equilibrium" or "time average ..."
  bool out_of_plane = false;
  OutOfPlaneEquilibrium equilibrium;    // filled when out_of_plane
  FiniteHorizon horizon;
  ModePrediction asymptotic, finite_horizon, simulation;
  RegimeResult regime;
};
// The finite-horizon predictor's verdict from G_l(T): the modes with G_l > 0, and l_Delta = the argmax of the
// linear excess-area growth Delta_l(0) (exp(2 G_l) - 1) (status outside_domain when the reduced run stopped).
ModePrediction finite_horizon_prediction(const Scene& scene, const FiniteHorizon& horizon);

// (a) and (b) for the scene; (c) from a simulation result of the same scene (pass nullptr to skip it).
ScenePrediction predict(const Scene& scene, const SimulationResult* simulated, const PredictorOptions& options = {});

// r0 = |z0| of the scene's stress-free l = 2 shape (0 out of plane, sqrt(3)/2 in plane).
double stress_free_r0(const Scene& scene);

}  // namespace rbcstab
