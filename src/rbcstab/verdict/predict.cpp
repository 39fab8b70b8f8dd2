#include "rbcstab/verdict/predict.hpp"

#include <cmath>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

namespace {
std::string source_in_words(const AsymptoticSigma& a, const PredictorOptions& options) {
  switch (a.source) {
    case SigmaSource::equilibrium:
      return "exact out-of-plane equilibrium";
    case SigmaSource::periodic_orbit:
      return "period average of sigma_R over the attracting 2 pi-periodic orbit of the reduced model (largest "
             "nontrivial Floquet multiplier modulus " +
             format_value(a.max_multiplier) + ")";
    case SigmaSource::time_average:
      break;
  }
  std::string s = "time average of sigma_R over t in [" + format_value(options.transient) + ", " +
                  format_value(options.transient + options.window) + "] of the reduced model";
  if (!a.note.empty()) s += "; " + a.note;
  return s;
}
}  // namespace

ModePrediction asymptotic_prediction(const Scene& scene, const AsymptoticSigma& sigma) {
  const Parameters& p = scene.parameters;
  ModePrediction a;
  a.predictor = "asymptotic";
  if (!sigma.valid()) {
    a.status = DomainStatus::outside_domain;
    a.reason = sigma.reason;
    return a;
  }
  const double s = sigma.sigma_R;
  for (int l = 2; l <= scene.L; ++l) a.rate.push_back(Upsilon_l(p, l, s));
  a.unstable = unstable_modes(s, p.alpha(), scene.L);
  a.l_Delta = asymptotic_verdict(scene, s).l;
  return a;
}

ModePrediction finite_horizon_prediction(const Scene& scene, const FiniteHorizon& horizon) {
  ModePrediction b;
  b.predictor = "finite_horizon";
  b.rate = horizon.G;
  if (horizon.status != IntegrationStatus::success) {
    b.status = DomainStatus::outside_domain;
    b.reason = "reduced run stopped at t = " + format_value(horizon.T) + ": " + horizon.reason;
  }
  double best = 0;
  for (int l = 3; l <= scene.L && std::size_t(l - 2) < horizon.G.size(); ++l) {
    const double G = horizon.G[std::size_t(l - 2)];
    const double d = scene.perturbation(l);
    if (G > 0) b.unstable.push_back(l);
    // linear growth of the excess area of mode l: d (exp(2 G) - 1), compared in logs to avoid overflow
    if (G > 0 && d > 0) {
      const double score = std::log(d) + 2 * G + std::log1p(-std::exp(-2 * G));
      if (b.l_Delta == 2 || score > best) {
        best = score;
        b.l_Delta = l;
      }
    }
  }
  return b;
}

ModePrediction simulation_prediction(const SimulationResult* simulated) {
  ModePrediction c;
  c.predictor = "simulation";
  if (!simulated) {
    c.status = DomainStatus::outside_domain;
    c.reason = "no simulation supplied";
    return c;
  }
  const SimulationResult& r = *simulated;
  const std::vector<double>& X = r.oscillating ? r.Delta_tail_mean : r.Delta_final;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const double d0 = r.Delta_initial[k];
    c.rate.push_back(d0 > 0 && X[k] > 0 ? 0.5 * std::log(X[k] / d0) : 0.0);
    if (k >= 1 && X[k] > d0 && d0 > 0) c.unstable.push_back(int(k) + 2);
  }
  c.l_Delta = r.l_Delta;
  if (r.status != IntegrationStatus::success) {
    c.status = DomainStatus::outside_domain;
    c.reason = "simulation stopped at t = " + format_value(r.t_reached) + ": " + r.reason;
  }
  return c;
}

ScenePrediction predict(const Scene& scene, const SimulationResult* simulated, const PredictorOptions& options,
                        const OrbitAverageOptions& orbit) {
  return predict(validated(scene), simulated, options, orbit);
}

ScenePrediction predict(const ValidScene& valid, const SimulationResult* simulated, const PredictorOptions& options,
                        const OrbitAverageOptions& orbit) {
  return predict(valid, reduced_transient(valid, valid->T, 1, options), simulated, options, orbit);
}

ScenePrediction predict(const Scene& scene, const ReducedTransient& transient, const SimulationResult* simulated,
                        const PredictorOptions& options, const OrbitAverageOptions& orbit) {
  return predict(validated(scene), transient, simulated, options, orbit);
}

ScenePrediction predict(const ValidScene& valid, const ReducedTransient& transient, const SimulationResult* simulated,
                        const PredictorOptions& options, const OrbitAverageOptions& orbit) {
  const Scene& scene = *valid;
  options.validate();
  if (!transient.of(scene) || transient.T != scene.T)
    throw InvalidArgument("transient",
                          "the reduced transient must be the scene's over [0, T = " + format_value(scene.T) + "]");
  ScenePrediction out;
  out.asymptotic_sigma = asymptotic_sigma_R(valid, options, orbit);
  const AsymptoticSigma& a = out.asymptotic_sigma;
  out.out_of_plane = a.out_of_plane;
  out.equilibrium = a.equilibrium;
  out.sigma_R_asymptotic = a.valid() ? Quantity::of(a.sigma_R) : Quantity::outside(a.reason);
  out.asymptotic_source = source_in_words(a, options);
  out.asymptotic = asymptotic_prediction(scene, a);
  out.horizon = finite_horizon_growth(valid, transient);
  out.finite_horizon = finite_horizon_prediction(scene, out.horizon);
  out.simulation = simulation_prediction(simulated);
  out.regime = reduced_regime(valid, options);
  return out;
}

}  // namespace rbcstab
