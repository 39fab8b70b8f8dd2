#include "rbcstab/analysis/predictors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rbcstab/analysis/detail/reduced_quadrature.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

IntegratorOptions PredictorOptions::default_integrator() {
  IntegratorOptions o;
  o.stepper = Stepper::rk8pd;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  return o;
}

void PredictorOptions::validate() const {
  integrator.validate();
  require(std::isfinite(transient) && transient >= 0, "transient", transient, "finite and >= 0");
  require(std::isfinite(window) && window > 0, "window", window, "finite and > 0");
  require(std::isfinite(average_tolerance) && average_tolerance > 0, "average_tolerance", average_tolerance,
          "finite and > 0");
  require(std::isfinite(out_of_plane_r0) && out_of_plane_r0 >= 0 && out_of_plane_r0 < 1, "out_of_plane_r0",
          out_of_plane_r0, "in [0, 1)");
  require(std::isfinite(regime_sample_dt) && regime_sample_dt > 0 && regime_sample_dt <= 0.5 * window,
          "regime_sample_dt", regime_sample_dt, "in (0, window/2]");
}

double stress_free_r0(const Scene& scene) {
  const InitialState init = initial_state(scene);
  const double Delta0 = init.g.excess_area(2);
  if (Delta0 <= 0) return 0;
  const double a2 = 2;
  const double z = std::abs(init.g.at(2, 2)) * std::sqrt(2 * a2 / Delta0);
  const double w = std::abs(init.g.at(2, 0).real()) * std::sqrt(a2 / Delta0);
  return z / std::sqrt(z * z + w * w);
}

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;

double initial_r(const Scene& scene) {
  const InitialState init = initial_state(scene);
  const double Delta2 = init.f.excess_area(2);
  const double a2 = 2;
  const double z = std::abs(init.f.at(2, 2)) * std::sqrt(2 * a2 / Delta2);
  const double w = std::abs(init.f.at(2, 0).real()) * std::sqrt(a2 / Delta2);
  return z / std::sqrt(z * z + w * w);
}

// One reduced run over [0, transient + window]: sigma_R integral at the window's start, middle and end,
// and r, unwrapped Psi on the regime grid.
struct ReducedRun {
  IntegrationResult result;
  std::vector<double> t, I, r, Psi;  // on the window grid; I = int_0^t sigma_R
};

ReducedRun run_reduced(const Scene& scene, const PredictorOptions& options) {
  options.validate();
  const detail::ReducedWithQuadrature sys(scene.parameters, initial_state(scene));
  const double t0 = options.transient, t1 = options.transient + options.window;
  std::vector<double> grid;
  const auto n = static_cast<std::size_t>(std::ceil(options.window / options.regime_sample_dt));
  grid.reserve(n + 1);
  for (std::size_t k = 0; k <= n; ++k) grid.push_back(t0 + (t1 - t0) * double(k) / double(n));
  ReducedRun run;
  double Psi = 0;
  bool first = true;
  auto on_sample = [&](double t, std::span<const double> y) {
    run.t.push_back(t);
    run.I.push_back(y[3]);
    const std::complex<double> z(y[0], y[1]);
    const double raw = -std::arg(z);
    Psi = first ? raw : raw + kTwoPi * std::round((Psi - raw) / kTwoPi);
    first = false;
    run.r.push_back(std::abs(z) / std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]));
    run.Psi.push_back(Psi);
  };
  const std::vector<double> y0 = sys.initial_state();
  run.result = integrate(sys, y0, 0.0, grid, options.integrator, on_sample);
  return run;
}

SigmaAverage average_from(const ReducedRun& run, const PredictorOptions& options) {
  SigmaAverage a;
  a.counters = run.result.counters;
  if (run.result.status != IntegrationStatus::success || run.t.size() < 3) {
    a.mean = Quantity::outside("reduced run failed: " + to_string(run.result.status) + ": " + run.result.reason);
    return a;
  }
  const std::size_t m = run.t.size() / 2, e = run.t.size() - 1;
  a.first_half = (run.I[m] - run.I[0]) / (run.t[m] - run.t[0]);
  a.second_half = (run.I[e] - run.I[m]) / (run.t[e] - run.t[m]);
  const double mean = (run.I[e] - run.I[0]) / (run.t[e] - run.t[0]);
  if (std::abs(a.first_half - a.second_half) > options.average_tolerance * (1 + std::abs(mean)))
    a.mean = Quantity::outside("time average of sigma_R not converged: halves " + format_value(a.first_half) + " and " +
                               format_value(a.second_half) + " differ by more than average_tolerance");
  else
    a.mean = Quantity::of(mean);
  return a;
}

RegimeResult regime_from(const ReducedRun& run, bool out_of_plane) {
  RegimeResult g;
  if (run.result.status != IntegrationStatus::success || run.r.empty()) {
    g.reason = "reduced run failed: " + run.result.reason;
    return g;
  }
  const auto [rmin, rmax] = std::minmax_element(run.r.begin(), run.r.end());
  const auto [pmin, pmax] = std::minmax_element(run.Psi.begin(), run.Psi.end());
  g.r_range = *rmax - *rmin;
  g.Psi_range = *pmax - *pmin;
  // Steady when r and Psi move less than 1e-4 over the window: above the O(kappa r0) ripple of the paper's
  // beta = 1e-3 start (measured 2.6e-6 at Fig. 2's Delta = 1) and far below swinging amplitudes (Fig. 2: ~0.1).
  constexpr double kSteady = 1e-4;
  if (g.Psi_range > kTwoPi) {
    g.regime = Regime::tumbling;
    g.reason = "Psi rotates by " + format_value(run.Psi.back() - run.Psi.front()) + " over the window";
  } else if (g.Psi_range > kSteady || g.r_range > kSteady) {
    g.regime = Regime::swinging;
    g.reason = "Psi oscillates within a range of " + format_value(g.Psi_range) + " (r range " +
               format_value(g.r_range) + ") without net rotation";
  } else {
    g.regime = out_of_plane ? Regime::rolling : Regime::tank_treading;
    g.reason = out_of_plane ? "out-of-plane steady state: fixed shape and angle, membrane rolling (Sec. III)"
                            : "in-plane steady state: fixed shape and angle, membrane tank-treading";
  }
  return g;
}
}  // namespace

SigmaAverage time_averaged_sigma_R(const Scene& scene, const PredictorOptions& options) {
  scene.validate();
  return average_from(run_reduced(scene, options), options);
}

RegimeResult reduced_regime(const Scene& scene, const PredictorOptions& options) {
  scene.validate();
  return regime_from(run_reduced(scene, options), initial_r(scene) < options.out_of_plane_r0);
}

FiniteHorizon finite_horizon_growth(const Scene& scene, double T, const PredictorOptions& options) {
  scene.validate();
  options.validate();
  require(std::isfinite(T) && T > 0, "T", T, "finite and > 0");
  const Parameters& p = scene.parameters;
  const detail::ReducedWithQuadrature sys(p, initial_state(scene));
  FiniteHorizon h;
  h.T = T;
  const double grid[1] = {T};
  double I = 0;
  const std::vector<double> y0 = sys.initial_state();
  const IntegrationResult res =
      integrate(sys, y0, 0.0, grid, options.integrator, [&](double, std::span<const double> y) { I = y[3]; });
  h.status = res.status;
  h.reason = res.reason;
  h.counters = res.counters;
  const double Tr = res.status == IntegrationStatus::success ? T : res.t_reached;
  if (res.status != IntegrationStatus::success) I = res.y.size() > 3 ? res.y[3] : 0.0;
  h.T = Tr;
  h.mean_sigma_R = Tr > 0 ? I / Tr : 0.0;
  // Upsilon_l is affine in sigma: int_0^T Upsilon_l(sigma_R) dt = T Upsilon_l(<sigma_R>_T).
  for (int l = 2; l <= scene.L; ++l) h.G.push_back(Tr * Upsilon(p, l, h.mean_sigma_R));
  return h;
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

ScenePrediction predict(const Scene& scene, const SimulationResult* simulated, const PredictorOptions& options) {
  scene.validate();
  options.validate();
  const Parameters& p = scene.parameters;
  const double alpha = p.alpha();
  ScenePrediction out;
  out.out_of_plane = initial_r(scene) < options.out_of_plane_r0;
  const ReducedRun run = run_reduced(scene, options);
  out.regime = regime_from(run, out.out_of_plane);

  // (a) asymptotic
  bool use_equilibrium = false;
  if (out.out_of_plane) {
    out.equilibrium = out_of_plane_equilibrium(p);
    use_equilibrium = out.equilibrium.stable;
  }
  if (use_equilibrium) {
    out.sigma_R_asymptotic = Quantity::of(out.equilibrium.sigma_R);
    out.asymptotic_source = "exact out-of-plane equilibrium";
  } else {
    const SigmaAverage avg = average_from(run, options);
    out.sigma_R_asymptotic = avg.mean;
    out.asymptotic_source = "time average of sigma_R over t in [" + format_value(options.transient) + ", " +
                            format_value(options.transient + options.window) + "] of the reduced model";
  }
  ModePrediction& a = out.asymptotic;
  a.predictor = "asymptotic";
  if (out.sigma_R_asymptotic.valid()) {
    const double s = out.sigma_R_asymptotic.value;
    for (int l = 2; l <= scene.L; ++l) a.rate.push_back(Upsilon(p, l, s));
    a.unstable = unstable_modes(s, alpha, scene.L);
    // Once modes grow, sigma rises until only the mode with the largest sigma_l^c stays: it takes the area.
    a.l_Delta = a.unstable.empty() ? 2 : surviving_mode(alpha, scene.L);
  } else {
    a.status = DomainStatus::outside_domain;
    a.reason = out.sigma_R_asymptotic.reason;
  }

  // (b) finite horizon
  out.horizon = finite_horizon_growth(scene, scene.T, options);
  out.finite_horizon = finite_horizon_prediction(scene, out.horizon);

  // (c) simulation
  ModePrediction& c = out.simulation;
  c.predictor = "simulation";
  if (simulated) {
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
  } else {
    c.status = DomainStatus::outside_domain;
    c.reason = "no simulation supplied";
  }
  return out;
}

}  // namespace rbcstab
