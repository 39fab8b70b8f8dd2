#pragma once
// The three verdicts of a scene, cheapest first, and predict() that combines them:
//  (a) asymptotic: mu_l = Upsilon_l(<sigma_R>) on the reduced attractor (verdict/asymptotic.hpp: the exact
//      out-of-plane equilibrium, the attracting periodic orbit's period average, or a converged time average);
//  (b) finite horizon: G_l(T) = int_0^T Upsilon_l(sigma_R(t)) dt along the reduced transient from the scene's
//      own initial state (analysis finite_horizon_growth), the linear prediction Delta_l(T)/Delta_l(0) = exp(2 G_l(T));
//  (c) the nonlinear modal simulation (simulate()).
// Also the regime of the reduced (ellipsoidal) dynamics (analysis reduced_regime).
#include <string>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/verdict/asymptotic.hpp"
#include "rbcstab/verdict/shear_rate.hpp"

namespace rbcstab {

struct ModePrediction {
  std::string predictor;      // "asymptotic", "finite_horizon", "simulation"
  std::vector<int> unstable;  // l in [3, L] predicted (or seen) to grow
  int l_Delta = 2;            // predicted argmax_l [Delta_l(T) - Delta_l(0)]
  std::vector<double>
      rate;  // index l - 2: mu_l (asymptotic), G_l(T) (finite horizon), ln(X_l/Delta_l(0))/2 (simulation)
  DomainStatus status = DomainStatus::ok;
  std::string reason;
};

// (a) from <sigma_R>: the modes with mu_l > 0, and l_Delta = the surviving mode (asymptotic_verdict): once
// modes grow, sigma rises until only the mode with the largest sigma_l^c stays and takes the area.
ModePrediction asymptotic_prediction(const Scene& scene, const AsymptoticSigma& sigma);
// (b) from G_l(T): the modes with G_l > 0, and l_Delta = the argmax of the linear excess-area growth
// Delta_l(0) (exp(2 G_l) - 1) (status outside_domain when the reduced run stopped).
ModePrediction finite_horizon_prediction(const Scene& scene, const FiniteHorizon& horizon);
// (c) from a simulation: the modes whose area grew (tail mean if oscillating, else at T) and its l_Delta;
// nullptr: outside_domain ("no simulation supplied").
ModePrediction simulation_prediction(const SimulationResult* simulated);

struct ScenePrediction {
  Quantity sigma_R_asymptotic;        // <sigma_R> on the attractor
  std::string asymptotic_source;      // which source gave it, in words
  AsymptoticSigma asymptotic_sigma;   // the source and its diagnostics
  bool out_of_plane = false;          // the stress-free shape is out of plane (is_out_of_plane)
  OutOfPlaneEquilibrium equilibrium;  // filled when out_of_plane
  FiniteHorizon horizon;
  ModePrediction asymptotic, finite_horizon, simulation;
  RegimeResult regime;
  // A physical scene's first unstable shear rate out of plane and in plane (filled by run_summary; empty else).
  std::vector<ShearRateThreshold> shear_rate_thresholds;
};

// (a), (b) and (c) for the scene: (b) from the scene's reduced transient over [0, T] (one checkpoint; the
// summary passes the transient it shares with the truncation rule), (c) from a simulation result of the same
// scene (pass nullptr to skip it).
ScenePrediction predict(const Scene& scene, const SimulationResult* simulated, const PredictorOptions& options = {},
                        const OrbitAverageOptions& orbit = {});
ScenePrediction predict(const ValidScene& scene, const SimulationResult* simulated,
                        const PredictorOptions& options = {}, const OrbitAverageOptions& orbit = {});
// The same with (b) from a given transient of the scene over [0, scene.T] (throws InvalidArgument("transient", ...)
// if it is another scene's or has another horizon).
ScenePrediction predict(const Scene& scene, const ReducedTransient& transient, const SimulationResult* simulated,
                        const PredictorOptions& options = {}, const OrbitAverageOptions& orbit = {});
ScenePrediction predict(const ValidScene& scene, const ReducedTransient& transient, const SimulationResult* simulated,
                        const PredictorOptions& options = {}, const OrbitAverageOptions& orbit = {});

}  // namespace rbcstab
