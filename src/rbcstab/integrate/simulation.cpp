#include "rbcstab/integrate/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/quadrature.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

void SimulationOptions::validate() const {
  integrator.validate();
  require(std::isfinite(tail_window) && tail_window > 0, "tail_window", tail_window, "finite and > 0");
  require(to_string(tail_means) != "?", "tail_means", double(static_cast<int>(tail_means)),
          "one of grid, quadrature, none");
  if (tail_means == TailMeans::quadrature && is_implicit(integrator.stepper))
    throw InvalidArgument("tail_means",
                          "tail_means = quadrature needs an explicit stepper (the quadrature rows have "
                          "no Jacobian), not stepper = " +
                              to_string(integrator.stepper) + ": use tail_means = grid");
}

ModeAmplitudes final_amplitudes(const Scene& scene, const SimulationResult& result) {
  return make_system(scene.parameters, initial_state(scene), result.level.level)
      ->amplitudes(result.t_reached, result.y_final);
}

double SkippedSamples::time(std::size_t k) const { return times.empty() ? sampling_time(k, dt) : times[k - first]; }

namespace {
// The output grid with room for `spare` more times, so that adding them does not copy it (80 MB at T = 1e7).
std::vector<double> sampling_grid(double T, double dt, std::size_t spare) {
  std::vector<double> g;
  const auto n = static_cast<std::size_t>(std::floor(T / dt * (1 + 1e-12)));
  g.reserve(n + 2 + spare);
  for (std::size_t k = 0; k <= n; ++k) g.push_back(std::min(T, sampling_time(k, dt)));
  if (T - g.back() > 1e-12 * T) g.push_back(T);
  g.back() = T;
  return g;
}

std::vector<double> output_grid(const Scene& scene, const SimulationOptions& options, std::size_t spare) {
  if (options.t_eval.empty()) return sampling_grid(scene.T, scene.dt, spare);
  const std::vector<double>& g = options.t_eval;
  for (std::size_t k = 0; k < g.size(); ++k) {
    const std::string at = "t_eval[" + std::to_string(k) + "]";
    if (!(std::isfinite(g[k]) && g[k] >= 0 && g[k] <= scene.T))
      throw InvalidArgument("t_eval", at + " = " + format_value(g[k]) +
                                          " is out of range: must be finite and in [0, T = " + format_value(scene.T) +
                                          "]");
    if (k > 0 && !(g[k] - g[k - 1] > 1e-12 * scene.T))
      throw InvalidArgument("t_eval", at + " = " + format_value(g[k]) + " does not follow t_eval[" +
                                          std::to_string(k - 1) + "] = " + format_value(g[k - 1]) +
                                          ": the times must increase (by more than 1e-12 T)");
  }
  std::vector<double> out;
  out.reserve(g.size() + spare);
  out.assign(g.begin(), g.end());
  return out;
}
}  // namespace

std::vector<double> sampling_grid(double T, double dt) { return sampling_grid(T, dt, 0); }

std::vector<double> output_grid(const Scene& scene, const SimulationOptions& options) {
  return output_grid(scene, options, 0);
}

double trajectory_bytes(const Scene& scene, const SimulationOptions& options) {
  if (!options.record_trajectory) return 0;
  const double samples = options.t_eval.empty() ? std::floor(scene.T / scene.dt) + 2 : double(options.t_eval.size()),
               L = scene.L;
  return samples * (8 * (L + 8) + (options.trajectory_text ? 25 * (L + 4) : 0));
}

namespace {
// The memory bounds of simulate(), checked once the level and so the system's dimension are known.
void require_memory(const Scene& scene, const SimulationOptions& options, ModelLevel level, std::size_t dimension) {
  require_dense_dimension(options.integrator.stepper, dimension,
                          "the " + to_string(level) + " level at L = " + std::to_string(scene.L));
  const double bytes = trajectory_bytes(scene, options);
  if (bytes <= kMaxTrajectoryBytes) return;
  if (!options.t_eval.empty())
    throw InvalidArgument("t_eval", "t_eval has " + std::to_string(options.t_eval.size()) + " times: about " +
                                        format_bytes(bytes) + " of trajectory, more than the limit " +
                                        format_bytes(kMaxTrajectoryBytes) + ": give fewer times");
  const double samples = std::floor(scene.T / scene.dt) + 2;
  throw InvalidArgument("dt", "dt = " + format_value(scene.dt) + " gives T/dt = " + format_value(scene.T / scene.dt) +
                                  " output samples of about " + format_bytes(bytes / samples) + " each at L = " +
                                  std::to_string(scene.L) + (options.trajectory_text ? " with their CSV text" : "") +
                                  ": about " + format_bytes(bytes) + " of trajectory, more than the limit " +
                                  format_bytes(kMaxTrajectoryBytes) + ": raise dt, or lower T or L");
}

constexpr int kTailIntervals =
    160;  // Simpson on the tail window: measured error ~1e-8 relative on the in-plane Fig. 3 scene

// Delta_2 rises and falls over its samples by more than rounding.
bool oscillates(const std::vector<double>& Delta2, double Delta) {
  if (Delta2.size() < 2) return false;
  bool up = false, down = false;
  double lo = Delta2[0], hi = lo;
  for (std::size_t k = 1; k < Delta2.size(); ++k) {
    const double d = Delta2[k] - Delta2[k - 1];
    up = up || d > 0;
    down = down || d < 0;
    lo = std::min(lo, Delta2[k]);
    hi = std::max(hi, Delta2[k]);
  }
  return up && down && (hi - lo) > 1e-9 * Delta;
}

int argmax_growth(const std::vector<double>& X, const std::vector<double>& X0) {
  int best = 0;
  for (std::size_t j = 1; j < X.size(); ++j)
    if (X[j] - X0[j] > X[best] - X0[best]) best = int(j);
  return best + 2;
}

// The limits of a run whose first part took `done`, for the part that continues it: they hold for the whole run.
IntegratorOptions remaining(const IntegratorOptions& options, const IntegrationResult& done) {
  IntegratorOptions io = options;
  io.max_steps = io.max_steps > done.counters.steps ? io.max_steps - done.counters.steps : 1;
  if (io.max_seconds > 0) io.max_seconds = std::max(io.max_seconds - done.seconds, 1e-9);
  return io;
}

// `run` continued by `next`: the end of next, the work of both.
void append(IntegrationResult& run, IntegrationResult next) {
  run.status = next.status;
  run.reason = std::move(next.reason);
  run.t_reached = next.t_reached;
  run.y = std::move(next.y);
  run.seconds += next.seconds;
  run.counters += next.counters;
}
}  // namespace

SimulationResult simulate(const Scene& scene, const SimulationOptions& options, AttractorCertifier* certifier) {
  return simulate(validated(scene), options, certifier);
}

SimulationResult simulate(const ValidScene& valid, const SimulationOptions& options, AttractorCertifier* certifier) {
  const Scene& scene = *valid;
  options.validate();
  SceneSystem built = make_scene_system(valid);
  SimulationResult res;
  res.scene_name = scene.name;
  res.level = built.level;
  res.warnings = std::move(built.warnings);
  const std::unique_ptr<System> system = std::move(built.system);
  require_memory(scene, options, res.level.level, system->dimension());
  res.L = scene.L;
  res.T = scene.T;

  // Output grid, plus the fine grid over the tail window for grid means or the window's start for quadrature
  // means (there the integrator switches to the system with the quadratures). Samples that are not recorded are
  // not integrated to (T is: the state there is reported).
  // The output grid is held once (at T = 1e7 it is 80 MB): the recorded samples are the grid times that are not
  // among the few the run adds (`added`, those within 1e-12 T of a sample dropped).
  const double tol = 1e-12 * scene.T;
  const std::size_t spare = kTailIntervals + 3;  // at most the times added below
  std::vector<double> grid = options.record_trajectory ? output_grid(scene, options, spare) : std::vector<double>{};
  if (!options.record_trajectory && !options.t_eval.empty()) (void)output_grid(scene, options, 0);  // checks t_eval
  const double tail_start = std::max(0.0, scene.T - options.tail_window);
  const bool grid_means = options.tail_means == TailMeans::grid;
  const bool quadrature_means = options.tail_means == TailMeans::quadrature;
  std::vector<double> added{scene.T};  // the state there is reported
  if (grid_means)
    for (int k = 0; k <= kTailIntervals; ++k) added.push_back(tail_start + (scene.T - tail_start) * k / kTailIntervals);
  if (quadrature_means) added.push_back(tail_start);
  std::sort(added.begin(), added.end());
  added.erase(std::unique(added.begin(), added.end(), [&](double a, double b) { return b - a <= tol; }), added.end());
  const auto recorded = std::ptrdiff_t(grid.size());
  std::erase_if(added, [&](double a) {
    const auto it = std::lower_bound(grid.begin(), grid.begin() + recorded, a - tol);
    return it != grid.begin() + recorded && *it <= a + tol;
  });
  // The output grid is sorted already: merge the few times added (linear in the samples).
  grid.insert(grid.end(), added.begin(), added.end());
  std::inplace_merge(grid.begin(), grid.begin() + recorded, grid.end());
  auto is_added = [&](double t) {
    const auto it = std::lower_bound(added.begin(), added.end(), t - tol);
    return it != added.end() && *it <= t + tol;
  };
  // Recorded samples before time t (exclusive of t - tol).
  auto samples_before = [&](double t) {
    const auto in_grid = std::lower_bound(grid.begin(), grid.end(), t - tol) - grid.begin();
    const auto in_added = std::lower_bound(added.begin(), added.end(), t - tol) - added.begin();
    return std::size_t(in_grid - in_added);
  };

  const std::vector<double> y0 = system->initial_state();
  const Observation o0 = system->observe(0, y0);
  res.Delta_initial = o0.Delta_l;
  res.Delta_total_initial = std::accumulate(o0.Delta_l.begin(), o0.Delta_l.end(), 0.0);
  res.sigma_initial = o0.sigma;

  // Psi in (-pi, pi] at t = 0, then unwrapped along the accepted steps.
  double Psi = o0.Psi();
  auto unwrap = [&](const Observation& o) { return Psi = o.Psi_near(Psi); };
  if (options.dense_output) res.dense = DenseOutput(o0.Delta_l.size() + 3);
  auto keep_dense = [&](double t, const Observation& o, double psi) {
    if (!options.dense_output) return;
    std::vector<double> v = o.Delta_l;
    v.insert(v.end(), {o.sigma, o.r(), psi});
    res.dense.add(t, v);
  };
  keep_dense(0, o0, Psi);

  std::size_t user_index = 0;
  std::vector<double> tail_t;
  std::vector<std::vector<double>> tail_D;
  std::vector<double> tail_sigma;
  std::vector<double> step_Delta2;  // without grid means: Delta_2 at the accepted steps in the window
  Observation last = o0;
  // The last two accepted step lengths: the first is usually cut short to end on a grid time, so the larger one
  // is the step size to carry into the window.
  double step_t = 0, step_h = 0, step_h_before = 0;
  // The observers see the base part of the state (the quadratures follow it in the window).
  const std::size_t n = system->dimension();
  auto on_step = [&](double t, std::span<const double> y) {
    step_h_before = step_h;
    step_h = t - step_t;
    step_t = t;
    const Observation o = system->observe(t, y.first(n));
    const double total = std::accumulate(o.Delta_l.begin(), o.Delta_l.end(), 0.0);
    res.excess_area_drift = std::max(res.excess_area_drift, std::abs(total - res.Delta_total_initial));
    keep_dense(t, o, unwrap(o));
    if (!grid_means && t >= tail_start - 1e-12 * scene.T) step_Delta2.push_back(o.Delta_l[0]);
    if (options.on_step) options.on_step(t, o);
    if (options.on_progress) options.on_progress(t, scene.T);
  };
  auto on_sample = [&](double t, std::span<const double> y) {
    const Observation o = system->observe(t, y.first(n));
    last = o;
    const double psi = t == 0 ? Psi : unwrap(o);
    if (options.record_trajectory && !is_added(t)) {
      ++user_index;
      res.trajectory.t.push_back(t);
      res.trajectory.Delta_l.push_back(o.Delta_l);
      res.trajectory.sigma.push_back(o.sigma);
      res.trajectory.r.push_back(o.r());
      res.trajectory.Psi.push_back(psi);
    }
    // Only the uniform tail grid feeds the averages: user samples inside the window (dt not a
    // multiple of the tail spacing) would break Simpson's rule and drop it to the trapezoid rule.
    const double tail_h = (scene.T - tail_start) / kTailIntervals;
    const double tail_k = tail_h > 0 ? (t - tail_start) / tail_h : 0.0;
    if (grid_means && t >= tail_start - 1e-12 * scene.T && std::abs(tail_k - std::round(tail_k)) <= 1e-6) {
      tail_t.push_back(t);
      tail_D.push_back(o.Delta_l);
      tail_sigma.push_back(o.sigma);
    }
  };

  // Early termination: the certifier may end the run at an accepted step before the tail window, from where
  // the run resumes on the certified attractor whole periods later (the samples in between are not taken).
  AttractorJump jump;
  StopCondition stop;
  if (certifier && options.full_horizon) res.early.note = "full horizon requested";
  if (certifier && !options.full_horizon)
    stop = [&](double t, std::span<const double> y) {
      return tail_start > t && certifier->certify(*system, t, y, tail_start, jump, res.early);
    };
  // Quadrature means: q' = (Delta_2..Delta_L, sigma) from q(tail_from) = 0, where the run reaches the window.
  Quadrature tail_quadrature;
  tail_quadrature.count = o0.Delta_l.size() + 1;
  tail_quadrature.rate = [&](double t, std::span<const double> x, std::span<const double>, std::span<double> rate) {
    const Observation o = system->observe(t, x);
    std::copy(o.Delta_l.begin(), o.Delta_l.end(), rate.begin());
    rate.back() = o.sigma;
  };
  const WithQuadratures with_tail_integrals(*system, tail_quadrature);
  double tail_from = tail_start;
  std::vector<double> tail_integrals;  // q where the run ended
  // Integrates from (t0, y) through `times`; with quadrature means, the times after tail_start on the system with
  // the quadratures, starting with the step size reached before the window (a restart from h_init = 1e-3 cost 3.5
  // more steps per run on the 64 x 64 App. E(b) panel).
  auto run = [&](double t0, std::span<const double> y, std::span<const double> times, const IntegratorOptions& io,
                 const StopCondition& until) {
    step_t = t0;
    if (!quadrature_means) return integrate(*system, y, t0, times, io, on_sample, on_step, until);
    const auto window = std::upper_bound(times.begin(), times.end(), tail_start + 1e-12 * scene.T);
    IntegrationResult r = integrate(*system, y, t0, {times.begin(), window}, io, on_sample, on_step, until);
    if (r.stopped || r.status != IntegrationStatus::success || window == times.end()) return r;
    IntegratorOptions in_window = remaining(io, r);
    if (const double h = std::max(step_h, step_h_before); h > 0) {
      in_window.h_init = h;
      in_window.h_min = std::min(in_window.h_min, h);
    }
    std::vector<double> yq = r.y;
    yq.resize(with_tail_integrals.dimension(), 0.0);
    tail_from = r.t_reached;
    IntegrationResult w =
        integrate(with_tail_integrals, yq, r.t_reached, {window, times.end()}, in_window, on_sample, on_step);
    tail_integrals.assign(w.y.begin() + std::ptrdiff_t(n), w.y.end());
    w.y.resize(n);
    append(r, std::move(w));
    return r;
  };
  IntegrationResult ir = run(0.0, y0, grid, options.integrator, stop);
  if (stop && !ir.stopped && res.early.note.empty())
    res.early.note = "no certification attempt: none could skip a whole period before the tail window";
  if (ir.stopped) {
    res.early.terminated = true;
    res.early.note.clear();
    res.early.terminated_at = ir.t_reached;
    res.early.resumed_at = jump.t;
    Psi += jump.Psi_advance;
    const std::size_t resume_index = options.record_trajectory ? samples_before(jump.t) : 0;
    // The skipped samples: described, not stored (Trajectory::skipped), so that a long skip costs nothing.
    if (options.record_trajectory && user_index < resume_index) {
      SkippedSamples& gap = res.trajectory.skipped;
      gap.first = user_index;
      gap.count = resume_index - user_index;
      gap.dt = scene.dt;
      if (!options.t_eval.empty())  // the recorded samples are t_eval's times
        gap.times.assign(options.t_eval.begin() + std::ptrdiff_t(user_index),
                         options.t_eval.begin() + std::ptrdiff_t(resume_index));
    }
    user_index = resume_index;
    const Observation resumed = system->observe(jump.t, jump.y);
    if (options.dense_output) res.dense.start_segment();
    keep_dense(jump.t, resumed, resumed.Psi_near(Psi));
    if (options.on_step) options.on_step(jump.t, resumed);
    const std::span<const double> rest(std::lower_bound(grid.begin(), grid.end(), jump.t), grid.end());
    append(ir, run(jump.t, jump.y, rest, remaining(options.integrator, ir), {}));
  }
  res.status = ir.status;
  res.reason = ir.reason;
  res.counters = ir.counters;
  res.seconds = ir.seconds;
  res.t_reached = ir.t_reached;
  res.y_final = ir.y;
  res.Delta_final = last.Delta_l;
  res.sigma_final = last.sigma;
  res.r_final = last.r();
  res.Psi_final = Psi;

  // Grid means: the trapezoid-corrected Simpson rule on the window's fine grid (falls back to the trapezoid rule
  // when the run stopped early). Quadrature means: q over the part of the window integrated.
  const std::size_t nt = tail_t.size();
  res.Delta_tail_mean = res.Delta_final;
  res.sigma_tail_mean = res.sigma_final;
  if (!tail_integrals.empty() && res.t_reached > tail_from) {
    const double span = res.t_reached - tail_from;
    for (std::size_t j = 0; j < res.Delta_tail_mean.size(); ++j) res.Delta_tail_mean[j] = tail_integrals[j] / span;
    res.sigma_tail_mean = tail_integrals.back() / span;
  }
  if (nt >= 2) {
    std::vector<double> weights(nt, 0.0);
    const bool simpson = ir.status == IntegrationStatus::success && nt == std::size_t(kTailIntervals) + 1;
    const double span = tail_t.back() - tail_t.front();
    for (std::size_t k = 0; k < nt; ++k) {
      if (simpson) {
        const double h = span / kTailIntervals;
        weights[k] = h / 3 * ((k == 0 || k == nt - 1) ? 1 : (k % 2 ? 4 : 2));
      } else {
        if (k > 0) weights[k] += 0.5 * (tail_t[k] - tail_t[k - 1]);
        if (k + 1 < nt) weights[k] += 0.5 * (tail_t[k + 1] - tail_t[k]);
      }
    }
    if (span > 0) {
      std::fill(res.Delta_tail_mean.begin(), res.Delta_tail_mean.end(), 0.0);
      res.sigma_tail_mean = 0;
      for (std::size_t k = 0; k < nt; ++k) {
        for (std::size_t j = 0; j < res.Delta_tail_mean.size(); ++j)
          res.Delta_tail_mean[j] += weights[k] * tail_D[k][j] / span;
        res.sigma_tail_mean += weights[k] * tail_sigma[k] / span;
      }
    }
    std::vector<double> Delta2(nt);
    for (std::size_t k = 0; k < nt; ++k) Delta2[k] = tail_D[k][0];
    res.oscillating = oscillates(Delta2, scene.parameters.Delta);
  }
  if (!grid_means) res.oscillating = oscillates(step_Delta2, scene.parameters.Delta);
  res.l_Delta_final = argmax_growth(res.Delta_final, res.Delta_initial);
  res.l_Delta = res.oscillating ? argmax_growth(res.Delta_tail_mean, res.Delta_initial) : res.l_Delta_final;
  return res;
}

std::string run_reason(IntegrationStatus status, const std::string& reason, const Parameters& p) {
  if (status != IntegrationStatus::non_finite_state) return reason;
  return reason + " (" + nonfinite_reason(p) + ")";
}

std::string run_reason(const SimulationResult& r, const Parameters& p) { return run_reason(r.status, r.reason, p); }

}  // namespace rbcstab
