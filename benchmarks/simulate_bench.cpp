// Work-precision of one T = 500 run of the paper's Fig. 3 scenes for each model level and stepper
// (and of the Fig. 2 scenes, where the reduced level is exact too).
// Counters: RHS and Jacobian evaluations, steps, and the achieved error at T against a reference
// computed at rtol 1e-13 by a different level (full model, rk8pd) -- so the modal level's error
// includes any error of the reduction itself.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "rbcstab/integrate/simulation.hpp"

namespace {
using namespace rbcstab;

Scene fig3(bool in_plane) {
  Scene s;  // defaults: B = 2, C = 0.04, lambda = 5, Delta = 1, Delta0 = 0.01, delta = 1e-3, L = 10, T = 500
  s.name = in_plane ? "fig3_ip" : "fig3_op";
  s.beta = in_plane ? std::numbers::pi / 2 : 0.001;
  s.dt = 500;  // only the final state matters here
  return s;
}

// Fig. 2 scenes (delta = 0, Delta = 1): the reduced level is exact there.
Scene fig2(bool in_plane) {
  Scene s = fig3(in_plane);
  s.name = in_plane ? "fig2_ip" : "fig2_op";
  s.beta = in_plane ? std::numbers::pi / 2 : 0.0;
  s.delta = 0;
  s.L = 2;
  return s;
}

struct Reference {
  std::vector<double> Delta;
  double sigma;
};

const Reference& reference(const Scene& scene) {
  static std::map<std::string, Reference> cache;
  auto it = cache.find(scene.name);
  if (it != cache.end()) return it->second;
  Scene s = scene;
  s.model = ModelLevel::full;
  SimulationOptions o;
  o.integrator.rtol = 1e-13;
  o.integrator.atol = 1e-16;
  o.integrator.stepper = Stepper::rk8pd;
  const SimulationResult r = simulate(s, o);
  return cache[scene.name] = Reference{r.Delta_final, r.sigma_final};
}

void run(benchmark::State& state, Scene scene, ModelLevel level, Stepper stepper, double rtol) {
  const Reference& ref = reference(scene);
  scene.model = level;
  SimulationOptions o;
  o.integrator.stepper = stepper;
  o.integrator.rtol = rtol;
  o.integrator.atol = rtol * 1e-4;
  o.record_trajectory = false;
  SimulationResult r;
  for (auto _ : state) {
    r = simulate(scene, o);
    benchmark::DoNotOptimize(r);
  }
  double err = 0;
  for (std::size_t k = 0; k < ref.Delta.size(); ++k) err = std::max(err, std::abs(r.Delta_final[k] - ref.Delta[k]));
  state.counters["rhs_evals"] = double(r.counters.rhs_evaluations);
  state.counters["jac_evals"] = double(r.counters.jacobian_evaluations);
  state.counters["steps"] = double(r.counters.steps);
  state.counters["err_Delta"] = err / scene.parameters.Delta;  // max_l |Delta_l(T) - ref| / Delta
  state.counters["err_sigma"] = std::abs(r.sigma_final - ref.sigma) / std::abs(ref.sigma);
  state.counters["ok"] = r.status == IntegrationStatus::success ? 1 : 0;
  state.SetLabel(to_string(level) + "/" + to_string(stepper));
}

void register_all() {
  const Stepper steppers[] = {Stepper::rk8pd, Stepper::rkck, Stepper::rosenbrock, Stepper::msbdf};
  auto add = [](const Scene& s, ModelLevel level, Stepper st, double rtol) {
    const std::string name = "simulate/" + s.name + "/" + to_string(level) + "/" + to_string(st) +
                             "/rtol:" + std::to_string(int(std::round(-std::log10(rtol))));
    benchmark::RegisterBenchmark(name.c_str(), run, s, level, st, rtol)->Unit(benchmark::kMillisecond);
  };
  for (bool ip : {false, true})
    for (ModelLevel level : {ModelLevel::modal, ModelLevel::full})
      for (Stepper st : steppers)
        for (double rtol : {1e-6, 1e-8, 1e-10})
          if (!(level == ModelLevel::full && st == Stepper::msbdf && rtol < 1e-8)) add(fig3(ip), level, st, rtol);
  for (bool ip : {false, true})
    for (ModelLevel level : {ModelLevel::reduced, ModelLevel::modal})
      for (double rtol : {1e-6, 1e-8, 1e-10}) add(fig2(ip), level, Stepper::rk8pd, rtol);
}
}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
