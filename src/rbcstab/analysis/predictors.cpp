#include "rbcstab/analysis/predictors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/quadrature.hpp"
#include "rbcstab/io/units_io.hpp"
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

double stress_free_r0(const Scene& scene) { return stress_free_r0(validated(scene)); }

double stress_free_r0(const ValidScene& scene) {
  const InitialState init = initial_state(scene);
  const double Delta0 = init.g.excess_area(2);
  if (Delta0 <= 0) return 0;
  const double a2 = 2;
  const double z = std::abs(init.g.at(2, 2)) * std::sqrt(2 * a2 / Delta0);
  const double w = std::abs(init.g.at(2, 0).real()) * std::sqrt(a2 / Delta0);
  return z / std::sqrt(z * z + w * w);
}

namespace {

double initial_r(const ValidScene& scene) {
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

ReducedRun run_reduced(const ValidScene& scene, const PredictorOptions& options) {
  options.validate();
  const ReducedModel reduced(scene->parameters, initial_state(scene));
  const WithQuadratures sys(reduced, tension_integral(reduced));
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
    g.reason = "Psi rotates by " + degrees_text(run.Psi.back() - run.Psi.front()) + " over the window";
  } else if (g.Psi_range > kSteady || g.r_range > kSteady) {
    g.regime = out_of_plane ? Regime::oscillating_out_of_plane : Regime::swinging;
    g.reason = "Psi oscillates within a range of " + degrees_text(g.Psi_range) + " (r range " +
               format_value(g.r_range) + ") without net rotation" +
               (out_of_plane ? ", from an out-of-plane start" : ", from an in-plane start");
  } else {
    g.regime = out_of_plane ? Regime::rolling : Regime::tank_treading;
    g.reason = out_of_plane ? "out-of-plane steady state: fixed shape and angle, membrane rolling (Sec. III)"
                            : "in-plane steady state: fixed shape and angle, membrane tank-treading";
  }
  return g;
}
}  // namespace

SigmaAverage time_averaged_sigma_R(const Scene& scene, const PredictorOptions& options) {
  return average_from(run_reduced(validated(scene), options), options);
}

RegimeResult reduced_regime(const Scene& scene, const PredictorOptions& options) {
  return reduced_regime(validated(scene), options);
}

RegimeResult reduced_regime(const ValidScene& scene, const PredictorOptions& options) {
  return regime_from(run_reduced(scene, options), initial_r(scene) < options.out_of_plane_r0);
}

bool ReducedTransient::of(const Scene& scene) const { return of_flow(scene) && scene.parameters.B == parameters.B; }

std::array<double, 5> ReducedTransient::flow(const Parameters& p, double beta) {
  return {p.lambda, p.Delta, p.Delta0, p.C, beta};
}

bool ReducedTransient::of_flow(const Scene& scene) const {
  return flow(scene.parameters, scene.beta) == flow(parameters, beta);
}

ReducedTransient transient_at_B(const ReducedTransient& transient, const Scene& scene) {
  if (!transient.of_flow(scene))
    throw InvalidArgument("transient",
                          "the reduced transient was integrated for another flow (parameters other "
                          "than B, or beta)");
  if (transient.of(scene)) return transient;
  const GrowthRate from = Upsilon_l(transient.parameters, 2), to = Upsilon_l(scene.parameters, 2);
  // int_0^t mu = from.slope (I - from.sigma_c t), then int_0^t sigma_R = int mu / to.slope + to.sigma_c t.
  const double ratio = from.slope / to.slope;
  auto map = [&](double t, double integral) { return ratio * (integral - from.sigma_c * t) + to.sigma_c * t; };
  ReducedTransient tr = transient;
  tr.parameters = scene.parameters;
  for (std::size_t k = 0; k < tr.t.size(); ++k) tr.integral[k] = map(tr.t[k], tr.integral[k]);
  tr.integral_end = map(tr.t_end, tr.integral_end);
  return tr;
}

ReducedTransient reduced_transient(const Scene& scene, double T, int checkpoints, const PredictorOptions& options) {
  return reduced_transient(validated(scene), T, checkpoints, options);
}

ReducedIntegralSystem::ReducedIntegralSystem(const ValidScene& scene)
    : model_(scene->parameters, initial_state(scene)), with_integral_(model_, tension_integral(model_)) {}

ReducedTransient reduced_integrals(const ValidScene& valid, std::span<const double> times,
                                   const PredictorOptions& options) {
  const Scene& scene = *valid;
  options.validate();
  const ReducedIntegralSystem reduced(valid);
  const System& sys = reduced.system();
  ReducedTransient tr;
  tr.parameters = scene.parameters;
  tr.beta = scene.beta;
  auto on_sample = [&](double t, std::span<const double> y) {
    tr.t.push_back(t);
    tr.integral.push_back(y[3]);
  };
  const IntegrationResult res = integrate(sys, sys.initial_state(), 0.0, times, options.integrator, on_sample);
  tr.status = res.status;
  tr.reason = res.reason;
  tr.counters = res.counters;
  tr.t_end = res.t_reached;
  tr.integral_end = res.y.size() > 3 ? res.y[3] : 0.0;
  return tr;
}

ReducedTransient reduced_transient(const ValidScene& valid, double T, int checkpoints,
                                   const PredictorOptions& options) {
  options.validate();
  require(std::isfinite(T) && T > 0, "T", T, "finite and > 0");
  require(checkpoints >= 1 && checkpoints <= 10000, "checkpoints", checkpoints, "an integer in [1, 10000]");
  std::vector<double> grid;
  for (int k = 1; k <= checkpoints; ++k) grid.push_back(T * k / checkpoints);
  ReducedTransient tr = reduced_integrals(valid, grid, options);
  tr.T = T;
  tr.checkpoints = checkpoints;
  if (tr.status == IntegrationStatus::success) {
    tr.t_end = T;
    tr.integral_end = tr.integral.back();
  }
  return tr;
}

FiniteHorizon finite_horizon_growth(const Scene& scene, const ReducedTransient& transient) {
  return finite_horizon_growth(validated(scene), transient);
}

FiniteHorizon finite_horizon_growth(const ValidScene& valid, const ReducedTransient& transient) {
  const Scene& scene = *valid;
  if (!transient.of(scene))
    throw InvalidArgument("transient", "the reduced transient was integrated for other parameters or another beta");
  const Parameters& p = scene.parameters;
  FiniteHorizon h;
  h.status = transient.status;
  h.reason = transient.reason;
  h.counters = transient.counters;
  const double Tr = transient.t_end;
  h.T = Tr;
  h.mean_sigma_R = Tr > 0 ? transient.integral_end / Tr : 0.0;
  // Upsilon_l is affine in sigma: int_0^T Upsilon_l(sigma_R) dt = T Upsilon_l(<sigma_R>_T).
  for (int l = 2; l <= scene.L; ++l) h.G.push_back(Tr * Upsilon_l(p, l, h.mean_sigma_R));
  return h;
}

FiniteHorizon finite_horizon_growth(const Scene& scene, double T, const PredictorOptions& options) {
  const ValidScene valid = validated(scene);
  return finite_horizon_growth(valid, reduced_transient(valid, T, 1, options));
}

}  // namespace rbcstab
