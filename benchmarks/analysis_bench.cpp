// Analysis costs with work and error counters (docs/theory.md, section Analysis): the closed-form equilibrium,
// the finite-horizon quadrature (work-precision against a tight reference), and the full predictor set.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/verdict/physical_map.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace {

rbcstab::Scene fig3(double beta) {
  rbcstab::Scene s;
  s.beta = beta;
  return s;
}

void BM_OutOfPlaneEquilibrium(benchmark::State& state) {
  rbcstab::Parameters p;  // Fig. 3: lambda = 5, C = 0.04
  double residual = 0;
  for (auto _ : state) {
    const rbcstab::OutOfPlaneEquilibrium eq = rbcstab::out_of_plane_equilibrium(p);
    residual = eq.residual;
    benchmark::DoNotOptimize(eq.sigma_R);
  }
  state.counters["residual"] = residual;
}
BENCHMARK(BM_OutOfPlaneEquilibrium);

// Work-precision of G_l(T = 500) (in-plane Fig. 3 scene) against rtol = 1e-13.
void BM_FiniteHorizon(benchmark::State& state) {
  const rbcstab::Scene s = fig3(std::numbers::pi / 2);
  rbcstab::PredictorOptions ref_options;
  ref_options.integrator.rtol = 1e-13;
  const rbcstab::FiniteHorizon ref = rbcstab::finite_horizon_growth(s, 500, ref_options);
  rbcstab::PredictorOptions o;
  o.integrator.rtol = std::pow(10.0, -double(state.range(0)));
  rbcstab::FiniteHorizon h;
  for (auto _ : state) h = rbcstab::finite_horizon_growth(s, 500, o);
  double err = 0;
  for (std::size_t k = 0; k < h.G.size(); ++k) err = std::max(err, std::abs(h.G[k] - ref.G[k]));
  state.counters["rhs"] = double(h.counters.rhs_evaluations);
  state.counters["max_G_error"] = err;
}
BENCHMARK(BM_FiniteHorizon)->DenseRange(6, 12, 2);

// Predictors (a) + (b) + regime, as run by `rbcstab summary` (the simulation is timed in simulate_bench).
void BM_Predict(benchmark::State& state) {
  const rbcstab::Scene s = fig3(state.range(0) == 0 ? 1e-3 : std::numbers::pi / 2);
  for (auto _ : state) {
    const rbcstab::ScenePrediction pr = rbcstab::predict(s, nullptr);
    benchmark::DoNotOptimize(pr.asymptotic.l_Delta);
  }
}
BENCHMARK(BM_Predict)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_PostInstability(benchmark::State& state) {
  rbcstab::Parameters p;
  for (auto _ : state) {
    const rbcstab::PostInstability post = rbcstab::post_instability(p, 10);
    benchmark::DoNotOptimize(post.integer_mode.Delta2_tilde.value);
  }
}
BENCHMARK(BM_PostInstability);

// The physical map's tumbling search (scenes/physical_map.toml's cell and grid, no onset, one thread) with the
// regime stepper explicit (0: rk8pd) or linearly implicit (1: rosenbrock; 2: rosenbrock at rtol 1e-6, atol 1e-9):
// the reduced regime is stiff at small C (docs/units.md, "Cost"). Counters: the boundaries found, the regime
// evaluations and the first boundary's rate.
void BM_PhysicalMapTumbling(benchmark::State& state) {
  const rbcstab::SceneFile sf = rbcstab::load_scene(std::string(RBCSTAB_SCENES_DIR) + "/physical_map.toml");
  rbcstab::PhysicalMapOptions o = rbcstab::physical_map_panel(sf).options;
  o.onset = false;
  o.threads = 1;
  o.regime_stepper = state.range(0) == 0 ? rbcstab::Stepper::rk8pd : rbcstab::Stepper::rosenbrock;
  if (state.range(0) == 2) {
    o.predictor.integrator.rtol = 1e-6;
    o.predictor.integrator.atol = 1e-9;
  }
  rbcstab::PhysicalMap m;
  for (auto _ : state) m = rbcstab::physical_map(sf.scene, o);
  int found = 0;
  for (const rbcstab::PhysicalMapColumn& c : m.columns) found += c.tumbling_to_swinging.found;
  state.counters["found"] = found;
  state.counters["evaluations"] = m.evaluations;
  for (const rbcstab::PhysicalMapColumn& c : m.columns)
    if (c.tumbling_to_swinging.found) {
      state.counters["first_rate"] = c.tumbling_to_swinging.rate;
      break;
    }
}
BENCHMARK(BM_PhysicalMapTumbling)->Arg(0)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
BENCHMARK_MAIN();
