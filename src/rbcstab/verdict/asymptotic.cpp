#include "rbcstab/verdict/asymptotic.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

void OrbitAverageOptions::validate() const {
  require(relaxation_periods >= 0 && relaxation_periods <= 100000, "relaxation_periods", relaxation_periods,
          "an integer in [0, 100000]");
  require(samples >= 4 && samples <= 1000000, "samples", samples, "an integer in [4, 1000000]");
  require(std::isfinite(max_multiplier) && max_multiplier > 0 && max_multiplier <= 1, "max_multiplier", max_multiplier,
          "(0, 1]");
  require(std::isfinite(newton_tol) && newton_tol >= 1e-15 && newton_tol <= 1e-6, "newton_tol", newton_tol,
          "[1e-15, 1e-6]");
  require(max_iterations >= 1 && max_iterations <= 1000, "max_iterations", max_iterations, "an integer in [1, 1000]");
  shooting.validate();
}

OrbitSigmaAverage orbit_sigma_average(const Scene& scene, const OrbitAverageOptions& o) {
  o.validate();
  scene.validate();
  OrbitSigmaAverage a;
  a.flow = ReducedTransient::flow(scene.parameters, scene.beta);
  // The free parameter is irrelevant at fixed p; B is defined for every valid scene.
  const ReducedForcedSystem sys(scene, ContinuationParameter::B);
  const PeriodicOrbitProblem orbit(sys, o.shooting);
  const double p = sys.start_parameter();
  const ReducedModel& model = sys.model(p);
  Eigen::VectorXd x0;
  if (o.relaxation_periods > 0) {
    x0 = sys.relaxed_state(kTwoPi * o.relaxation_periods);
  } else {
    const std::vector<double> y0 = model.initial_state();
    x0 = Eigen::Map<const Eigen::VectorXd>(y0.data(), 3);
  }
  if (!x0.allFinite()) {
    a.reason = "relaxation run failed";
    return a;
  }
  const NewtonResult nr = solve_fixed_parameter(orbit, orbit.shooting_guess(x0, p), p, o.newton_tol, o.max_iterations);
  a.newton_iterations = nr.iterations;
  a.newton_residual = nr.residual_norm;
  if (!nr.converged) {
    a.integrations = orbit.integrations();
    a.reason = "periodic-orbit Newton did not converge in " + std::to_string(nr.iterations) + " iterations (residual " +
               format_value(nr.residual_norm) + ")";
    return a;
  }
  const Floquet fl = orbit.floquet(nr.x, p);
  a.max_multiplier = fl.multipliers.size() > 0 ? fl.multipliers.cwiseAbs().maxCoeff() : 0.0;
  a.x0 = orbit.state_at_zero(nr.x);
  if (!(a.max_multiplier < o.max_multiplier)) {
    a.integrations = orbit.integrations();
    a.reason = "the periodic orbit is not attracting (largest nontrivial Floquet multiplier modulus " +
               format_value(a.max_multiplier) + ")";
    return a;
  }
  // Periodic trapezoid rule on t_k = 2 pi k / K of mu(t) (B-free; sigma_R follows at the end, affine in mu).
  const int K = o.samples;
  std::vector<double> grid;
  grid.reserve(static_cast<std::size_t>(K));
  for (int k = 1; k < K; ++k) grid.push_back(kTwoPi * k / K);
  double sum = model.mu(0.0, std::span<const double>(a.x0.data(), 3));
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = o.shooting.rtol;
  io.atol = o.shooting.atol;
  const IntegrationResult r = integrate(model, std::span<const double>(a.x0.data(), 3), 0.0, grid, io,
                                        [&](double t, std::span<const double> y) { sum += model.mu(t, y); });
  a.integrations = orbit.integrations() + 1;
  if (r.status != IntegrationStatus::success) {
    a.reason = "one-period run failed: " + r.reason;
    return a;
  }
  a.mean_mu = sum / K;
  a.ok = std::isfinite(a.mean_mu);
  if (!a.ok) a.reason = "non-finite period average";
  return orbit_sigma_average_at_B(a, scene);
}

OrbitSigmaAverage orbit_sigma_average_at_B(const OrbitSigmaAverage& solved, const Scene& scene) {
  if (ReducedTransient::flow(scene.parameters, scene.beta) != solved.flow)
    throw InvalidArgument("orbit", "the periodic orbit was solved for another flow (parameters other than B, or beta)");
  OrbitSigmaAverage a = solved;
  a.sigma_R = a.ok ? Upsilon_l(scene.parameters, 2).sigma_at(a.mean_mu) : 0.0;
  return a;
}

bool is_out_of_plane(const Scene& scene, const PredictorOptions& options) {
  return is_out_of_plane(validated(scene), options);
}

bool is_out_of_plane(const ValidScene& scene, const PredictorOptions& options) {
  return stress_free_r0(scene) < options.out_of_plane_r0;
}

namespace {
// flow_orbit: the orbit of the scene's flow if already solved (else solved here when needed).
AsymptoticSigma asymptotic_sigma(const ValidScene& valid, const PredictorOptions& options,
                                 const OrbitAverageOptions& orbit, const OrbitSigmaAverage* flow_orbit) {
  const Scene& scene = *valid;
  options.validate();
  orbit.validate();
  AsymptoticSigma out;
  out.out_of_plane = is_out_of_plane(valid, options);
  if (out.out_of_plane) {
    out.equilibrium = out_of_plane_equilibrium(scene.parameters);
    if (out.equilibrium.stable) {
      out.sigma_R = out.equilibrium.sigma_R;
      out.exact = true;
      out.source = SigmaSource::equilibrium;
      return out;
    }
    out.note = out.equilibrium.stability_known() ? "the out-of-plane equilibrium is not stable"
                                                 : "the out-of-plane equilibrium's eigenvalues are not finite";
  } else if (orbit.enabled) {
    // In plane the attractor is (mostly) a 2 pi-periodic orbit of the forced reduced system.
    const OrbitSigmaAverage a =
        flow_orbit ? orbit_sigma_average_at_B(*flow_orbit, scene) : orbit_sigma_average(scene, orbit);
    out.max_multiplier = a.max_multiplier;
    out.newton_iterations = a.newton_iterations;
    if (a.ok) {
      out.sigma_R = a.sigma_R;
      out.source = SigmaSource::periodic_orbit;
      return out;
    }
    out.note = a.reason;
  }
  // The time average (the needed sigma_R integral at three times only: no dense regime sampling, 10x cheaper).
  PredictorOptions o = options;
  o.regime_sample_dt = 0.5 * o.window;
  const SigmaAverage avg = time_averaged_sigma_R(scene, o);
  out.source = SigmaSource::time_average;
  if (!avg.mean.valid()) {
    out.status = DomainStatus::outside_domain;
    out.reason = out.note.empty() ? avg.mean.reason : avg.mean.reason + " (" + out.note + ")";
    return out;
  }
  out.sigma_R = avg.mean.value;
  return out;
}
}  // namespace

AsymptoticSigma asymptotic_sigma_R(const Scene& scene, const PredictorOptions& options,
                                   const OrbitAverageOptions& orbit) {
  return asymptotic_sigma(validated(scene), options, orbit, nullptr);
}

AsymptoticSigma asymptotic_sigma_R(const ValidScene& scene, const PredictorOptions& options,
                                   const OrbitAverageOptions& orbit) {
  return asymptotic_sigma(scene, options, orbit, nullptr);
}

AsymptoticSigma asymptotic_sigma_R(const Scene& scene, const OrbitSigmaAverage& flow_orbit,
                                   const PredictorOptions& options, const OrbitAverageOptions& orbit) {
  return asymptotic_sigma(validated(scene), options, orbit, &flow_orbit);
}

AsymptoticVerdict asymptotic_verdict(const Scene& scene, double sigma_R) {
  AsymptoticVerdict v;
  v.sigma_R = sigma_R;
  if (scene.L < 3) {  // no mode l >= 3 to destabilise
    v.active_mode = 2;
    v.margin = std::numeric_limits<double>::infinity();
    return v;
  }
  const double alpha = scene.parameters.alpha();
  v.active_mode = surviving_mode(alpha, scene.L);
  v.margin = v.sigma_R - sigma_c(v.active_mode, alpha);
  v.unstable = v.margin < 0;
  v.l = v.unstable ? v.active_mode : 2;
  return v;
}

namespace {
AsymptoticVerdict verdict_of(const Scene& scene, const AsymptoticSigma& a) {
  if (!a.valid()) throw InvalidArgument("criterion", a.reason);
  return asymptotic_verdict(scene, a.sigma_R);
}
}  // namespace

AsymptoticSigmaMemo::AsymptoticSigmaMemo(const PredictorOptions& options, const OrbitAverageOptions& orbit)
    : options_(options), orbit_(orbit) {
  options_.validate();
  orbit_.validate();
}

AsymptoticSigma AsymptoticSigmaMemo::operator()(const Scene& scene) {
  const ValidScene valid = validated(scene);
  if (!orbit_.enabled || is_out_of_plane(valid, options_)) return asymptotic_sigma(valid, options_, orbit_, nullptr);
  const auto flow = ReducedTransient::flow(scene.parameters, scene.beta);
  const OrbitSigmaAverage* known = nullptr;
  {
    const std::lock_guard lock(mutex_);
    const auto it = orbits_.find(flow);
    if (it != orbits_.end()) known = &it->second;
  }
  if (known) return asymptotic_sigma(valid, options_, orbit_, known);
  const OrbitSigmaAverage solved = orbit_sigma_average(scene, orbit_);  // outside the lock: the slow part
  {
    const std::lock_guard lock(mutex_);
    orbits_.emplace(flow, solved);
  }
  return asymptotic_sigma(valid, options_, orbit_, &solved);
}

std::size_t AsymptoticSigmaMemo::orbits_solved() const {
  const std::lock_guard lock(mutex_);
  return orbits_.size();
}

AsymptoticVerdict AsymptoticSigmaMemo::verdict(const Scene& scene) { return verdict_of(scene, (*this)(scene)); }

AsymptoticVerdict asymptotic_verdict(const Scene& scene, const PredictorOptions& options,
                                     const OrbitAverageOptions& orbit) {
  return verdict_of(scene, asymptotic_sigma_R(scene, options, orbit));
}

AsymptoticVerdict asymptotic_verdict(const Scene& scene, const OrbitSigmaAverage& flow_orbit,
                                     const PredictorOptions& options, const OrbitAverageOptions& orbit) {
  return verdict_of(scene, asymptotic_sigma_R(scene, flow_orbit, options, orbit));
}

}  // namespace rbcstab
