#include "rbcstab/integrate/work_precision.hpp"

#include <algorithm>
#include <cmath>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void WorkPrecisionOptions::validate() const {
  require(!levels.empty(), "levels", 0, "a non-empty list of full, modal, reduced");
  require(!steppers.empty(), "steppers", 0, "a non-empty list");
  require(!rtols.empty(), "rtols", 0, "a non-empty list");
  for (double r : rtols) require(std::isfinite(r) && r >= 1e-14 && r <= 0.1, "rtols", r, "in [1e-14, 0.1]");
  require(std::isfinite(atol_ratio) && atol_ratio >= 0 && atol_ratio <= 1, "atol_ratio", atol_ratio, "in [0, 1]");
  require(std::isfinite(max_seconds) && max_seconds > 0, "max_seconds", max_seconds, "finite and > 0");
  require(std::isfinite(reference_rtol) && reference_rtol >= 1e-14 && reference_rtol <= 1e-10, "reference_rtol",
          reference_rtol, "in [1e-14, 1e-10]");
}

namespace {
SimulationResult run(Scene s, ModelLevel level, Stepper stepper, double rtol, double atol, double max_seconds) {
  s.model = level;
  s.dt = s.T;  // only the final state and the tail are compared
  SimulationOptions o;
  o.integrator.stepper = stepper;
  o.integrator.rtol = rtol;
  o.integrator.atol = atol;
  o.integrator.max_seconds = max_seconds;
  o.record_trajectory = false;
  return simulate(s, o);
}

double relative_error(const std::vector<double>& D, const std::vector<double>& ref, double Delta) {
  double e = 0;
  for (std::size_t k = 0; k < ref.size() && k < D.size(); ++k)
    if (ref[k] > 1e-8 * Delta) e = std::max(e, std::abs(D[k] - ref[k]) / ref[k]);
  return e;
}
}  // namespace

WorkPrecisionTable work_precision(const Scene& scene, const WorkPrecisionOptions& options) {
  options.validate();
  scene.validate();
  // Every level x stepper within the dense steppers' bound before the first run (the references take longest).
  const InitialState init = initial_state(scene);
  for (ModelLevel level : options.levels)
    for (Stepper stepper : options.steppers) {
      if (dense_matrices(stepper) == 0) continue;
      Scene s = scene;
      s.model = level;
      const LevelChoice c = choose_level(s, init);  // refuses a level that cannot hold the scene, as the run would
      require_dense_dimension(stepper, make_system(scene.parameters, init, c.level)->dimension(),
                              "the " + to_string(level) + " level at L = " + std::to_string(scene.L));
    }
  WorkPrecisionTable table;
  table.scene_name = scene.name;
  table.reference_rtol = options.reference_rtol;
  const double ref_atol = options.reference_rtol * 1e-3;
  // Reference: the full level (a different formulation from the modal one); the modal level at the same
  // tolerance gives the spread that bounds the reference's own error.
  const SimulationResult ref = run(scene, ModelLevel::full, Stepper::rk8pd, options.reference_rtol, ref_atol, 600);
  table.reference_status = ref.status;
  table.reference_reason = ref.reason;
  // Without a reference no error can be measured: a failed computation, not bad input.
  if (ref.status != IntegrationStatus::success) return table;
  const double runs = 2.0 + double(options.levels.size() * options.steppers.size() * options.rtols.size());
  double done = 1;
  auto progress = [&] {
    if (options.on_progress) options.on_progress(done++, runs);
  };
  progress();
  const SimulationResult alt = run(scene, ModelLevel::modal, Stepper::rk8pd, options.reference_rtol, ref_atol, 600);
  progress();
  table.reference_Delta = ref.Delta_final;
  table.reference_sigma = ref.sigma_final;
  table.reference_l_Delta = ref.l_Delta;
  table.reference_spread = relative_error(alt.Delta_final, ref.Delta_final, scene.parameters.Delta);
  for (ModelLevel level : options.levels)
    for (Stepper stepper : options.steppers)
      for (double rtol : options.rtols) {
        const SimulationResult r = run(scene, level, stepper, rtol, rtol * options.atol_ratio, options.max_seconds);
        table.rows.push_back({level, stepper, rtol, r.status, r.counters.rhs_evaluations,
                              r.counters.jacobian_evaluations, r.counters.steps, r.seconds,
                              relative_error(r.Delta_final, ref.Delta_final, scene.parameters.Delta),
                              std::abs(r.sigma_final - ref.sigma_final) / std::max(1.0, std::abs(ref.sigma_final)),
                              r.l_Delta, r.status == IntegrationStatus::success && r.l_Delta != ref.l_Delta, r.reason});
        progress();
      }
  return table;
}

}  // namespace rbcstab
