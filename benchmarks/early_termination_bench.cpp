// The diagram's exact savings (certified early termination, verdict/certified_run.hpp; no tail-window samples
// under the final classifier; reduced transients and in-plane periodic orbits shared across B) against the
// full-horizon runs, in the same process: the paper's panels at 64 x 64 (scenes/*.toml, 2 threads: run_diagram
// with and without run.full_horizon), the finite-horizon and asymptotic predictors of their agreement, and one
// run of the default scene. Counters: wall and CPU times, their ratio, points stopped early, verdicts or l_Delta
// that differ (must be 0), oscillation flags that differ, and the work (RHS evaluations of the runs and of the
// certification).
// docs/benchmarks.md records the numbers.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "integrate/rk8pd_fixtures.hpp"
#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/verdict/asymptotic.hpp"
#include "rbcstab/verdict/certified_run.hpp"

namespace {

const char* const kPanels[] = {"fig4a_op", "fig4b_op", "fig4c_op", "appE_a_ip", "appE_b_ip", "appE_c_ip"};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
// CPU time of the whole process (every thread): less sensitive than wall time to other load on the machine.
double cpu_since(std::clock_t start) { return double(std::clock() - start) / CLOCKS_PER_SEC; }

// range(0): the panel (kPanels), range(1): points per axis, range(2): threads.
void BM_PanelEarlyVsFull(benchmark::State& state) {
  const rbcstab::SceneFile sf =
      rbcstab::load_scene(std::string(RBCSTAB_SCENES_DIR) + "/" + kPanels[state.range(0)] + ".toml");
  rbcstab::DiagramSpec spec = rbcstab::diagram_spec(sf);
  spec.x.count = spec.y.count = int(state.range(1));
  rbcstab::DiagramOptions o;
  o.threads = int(state.range(2));
  rbcstab::SimulationOptions full_options = sf.options;
  full_options.full_horizon = true;
  double full_s = 0, early_s = 0, full_cpu = 0, early_cpu = 0;
  std::size_t terminated = 0, differing = 0, oscillation = 0, full_rhs = 0, early_rhs = 0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    std::clock_t cpu = std::clock();
    const rbcstab::DiagramRun full = rbcstab::run_diagram(sf.scene, full_options, spec, o);
    full_s += seconds_since(start);
    full_cpu += cpu_since(cpu);
    start = std::chrono::steady_clock::now();
    cpu = std::clock();
    const rbcstab::DiagramRun early = rbcstab::run_diagram(sf.scene, sf.options, spec, o);
    early_s += seconds_since(start);
    early_cpu += cpu_since(cpu);
    for (std::size_t k = 0; k < early.points.size(); ++k) {
      const rbcstab::PointResult& a = early.points[k];
      const rbcstab::PointResult& b = full.points[k];
      terminated += std::isfinite(a.terminated_at) ? 1 : 0;
      differing += a.verdict != b.verdict || a.l_Delta != b.l_Delta ? 1 : 0;
      oscillation += a.oscillating != b.oscillating ? 1 : 0;
      early_rhs += a.rhs_evaluations;
      full_rhs += b.rhs_evaluations;
    }
  }
  state.SetLabel(kPanels[state.range(0)]);
  state.counters["full_s"] = full_s;
  state.counters["early_s"] = early_s;
  state.counters["speedup"] = full_s / early_s;
  state.counters["full_cpu_s"] = full_cpu;
  state.counters["early_cpu_s"] = early_cpu;
  state.counters["terminated"] = double(terminated);
  state.counters["differing"] = double(differing);
  state.counters["oscillation_differing"] = double(oscillation);
  state.counters["rhs_ratio"] = double(full_rhs) / double(early_rhs);
}
BENCHMARK(BM_PanelEarlyVsFull)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {64}, {2}})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

// A panel's grid with every point simulated stable (the agreement's disagreements are then the points predicted
// unstable); range(0): the panel (kPanels), range(1): points per axis.
struct AgreementPanel {
  rbcstab::SceneFile sf;
  rbcstab::DiagramSpec spec;
  std::vector<rbcstab::PointResult> points;
};
AgreementPanel agreement_panel(const benchmark::State& state) {
  AgreementPanel p{
      rbcstab::load_scene(std::string(RBCSTAB_SCENES_DIR) + "/" + kPanels[state.range(0)] + ".toml"), {}, {}};
  p.spec = rbcstab::diagram_spec(p.sf);
  p.spec.x.count = p.spec.y.count = int(state.range(1));
  p.points.resize(p.spec.size());
  for (std::size_t i = 0; i < p.points.size(); ++i) p.points[i].index = i;
  return p;
}
// f(i) for every point on two threads (strided), adding its wall and process CPU seconds.
void per_point_on_two_threads(std::size_t n, const std::function<void(std::size_t)>& f, double& wall, double& cpu) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  std::vector<std::thread> pool;
  for (std::size_t w = 0; w < 2; ++w)
    pool.emplace_back([&, w] {
      for (std::size_t i = w; i < n; i += 2) f(i);
    });
  for (std::thread& t : pool) t.join();
  wall += seconds_since(start);
  cpu += cpu_since(cpu_start);
}
void comparison_counters(benchmark::State& state, double per_point_s, double shared_s, double per_point_cpu,
                         double shared_cpu) {
  state.SetLabel(kPanels[state.range(0)]);
  state.counters["per_point_s"] = per_point_s;
  state.counters["shared_s"] = shared_s;
  state.counters["per_point_cpu_s"] = per_point_cpu;
  state.counters["shared_cpu_s"] = shared_cpu;
  state.counters["cpu_ratio"] = per_point_cpu / shared_cpu;
}

// The finite-horizon predictor of a panel's agreement (what `rbcstab diagram` writes beside the points): one
// reduced run per point, as before, against the reduced transients shared across B (predictor_agreements, which
// integrates one per flow), both on 2 threads. Counters: both wall and process CPU times and their ratios.
void BM_FiniteHorizonAgreement(benchmark::State& state) {
  const AgreementPanel p = agreement_panel(state);
  rbcstab::AgreementOptions with, without;
  with.threads = without.threads = 2;
  with.trace = without.trace = false;
  without.finite_horizon = false;
  double per_point_s = 0, shared_s = 0, per_point_cpu = 0, shared_cpu = 0;
  for (auto _ : state) {
    per_point_on_two_threads(
        p.points.size(),
        [&](std::size_t i) {
          const rbcstab::Scene s = rbcstab::point_scene(p.sf.scene, p.spec, i);
          benchmark::DoNotOptimize(rbcstab::finite_horizon_growth(s, s.T).G);
        },
        per_point_s, per_point_cpu);
    // The predictor's share of predictor_agreements: with it minus without it.
    auto start = std::chrono::steady_clock::now();
    std::clock_t cpu = std::clock();
    benchmark::DoNotOptimize(rbcstab::predictor_agreements(p.sf.scene, p.spec, p.points, with));
    shared_s += seconds_since(start);
    shared_cpu += cpu_since(cpu);
    start = std::chrono::steady_clock::now();
    cpu = std::clock();
    benchmark::DoNotOptimize(rbcstab::predictor_agreements(p.sf.scene, p.spec, p.points, without));
    shared_s -= seconds_since(start);
    shared_cpu -= cpu_since(cpu);
  }
  comparison_counters(state, per_point_s, shared_s, per_point_cpu, shared_cpu);
}
BENCHMARK(BM_FiniteHorizonAgreement)
    ->ArgsProduct({{1, 4}, {64}})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

// The asymptotic predictor of a panel's agreement: asymptotic_verdict per point (in plane: a periodic-orbit solve
// each), against predictor_agreements without the finite-horizon predictor and the trace (one orbit per flow,
// mapped across B; the analytic predictors it also evaluates are closed forms), both on 2 threads. Counters:
// wall and process CPU times, their ratio, and the points whose verdict or mode differ (must be 0).
void BM_AsymptoticAgreement(benchmark::State& state) {
  const AgreementPanel p = agreement_panel(state);
  rbcstab::AgreementOptions o;
  o.threads = 2;
  o.trace = false;
  o.finite_horizon = false;
  double per_point_s = 0, shared_s = 0, per_point_cpu = 0, shared_cpu = 0;
  std::size_t differing = 0;
  for (auto _ : state) {
    std::vector<int> direct(p.points.size(), 2), shared(p.points.size(), 2);  // 2: stable, -1: not classified
    per_point_on_two_threads(
        p.points.size(),
        [&](std::size_t i) {
          try {
            const rbcstab::AsymptoticVerdict v =
                rbcstab::asymptotic_verdict(rbcstab::point_scene(p.sf.scene, p.spec, i));
            direct[i] = v.unstable ? v.l : 2;
          } catch (const rbcstab::InvalidArgument&) {
            direct[i] = -1;
          }
        },
        per_point_s, per_point_cpu);
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu = std::clock();
    const std::vector<rbcstab::Agreement> a = rbcstab::predictor_agreements(p.sf.scene, p.spec, p.points, o);
    shared_s += seconds_since(start);
    shared_cpu += cpu_since(cpu);
    for (const rbcstab::Disagreement& d : a[0].verdict_disagreements) shared[d.index] = d.l_predicted;
    std::size_t not_classified = 0;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      not_classified += direct[i] == -1;
      differing += direct[i] != -1 && direct[i] != shared[i];
    }
    differing += not_classified != a[0].not_classified;
  }
  comparison_counters(state, per_point_s, shared_s, per_point_cpu, shared_cpu);
  state.counters["differing"] = double(differing);
}
BENCHMARK(BM_AsymptoticAgreement)
    ->ArgsProduct({{3, 4, 5}, {64}})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

// One run of the default scene (Fig. 3, out of plane, L = 10, rtol 1e-8) as `rbcstab simulate` makes it:
// range(0) = 1 early termination, 0 full horizon. Counters: the run's integration time (what the JSON's
// "seconds" reports), its RHS evaluations and the certification's.
void BM_DefaultScene(benchmark::State& state) {
  rbcstab::SimulationOptions o;
  o.full_horizon = state.range(0) == 0;
  double seconds = 0;
  std::size_t runs = 0, rhs = 0, certification = 0;
  for (auto _ : state) {
    const rbcstab::SimulationResult r = rbcstab::simulate_certified(rbcstab::Scene{}, o);
    benchmark::DoNotOptimize(r.sigma_final);
    seconds += r.seconds;
    rhs += r.counters.rhs_evaluations;
    certification += r.early.work.rhs_evaluations;
    ++runs;
  }
  state.SetLabel(state.range(0) ? "early" : "full horizon");
  state.counters["integration_ms"] = 1e3 * seconds / double(runs);
  state.counters["rhs"] = double(rhs) / double(runs);
  state.counters["certification_rhs"] = double(certification) / double(runs);
}
BENCHMARK(BM_DefaultScene)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// One uncertified run: a Fig. 4(b) point (ln B = 2, ln C = 1) whose T = 500 run reaches no certificate (it is still
// ~0.05 from its periodic orbit at T), integrated to T as a diagram integrates it, three ways in the same process:
// GSL's rk8pd on the modal state (5 + 8 unknowns, how rk8pd ran before it had a stepper of its own), the native
// rk8pd on that state (the same steps bit for bit) and on the compact form (7 unknowns: how it runs now). Counters:
// ms per run, ns per RHS evaluation, and the model's RHS alone at the run's accepted states (what no stepper can
// save).
void BM_UncertifiedRunFloor(benchmark::State& state) {
  rbcstab::SceneFile sf = rbcstab::load_scene(std::string(RBCSTAB_SCENES_DIR) + "/fig4b_op.toml");
  sf.scene.parameters.B = std::exp(2.0);
  sf.scene.parameters.C = std::exp(1.0);
  const rbcstab::SceneSystem ss = rbcstab::make_scene_system(sf.scene);
  const rbcstab::System& sys = *ss.system;
  const rbcstab::testing::FullState full(sys);
  const std::vector<double> grid = {sf.scene.T};
  const rbcstab::IntegratorOptions& io = sf.options.integrator;
  std::vector<double> times, states;
  const rbcstab::IntegrationResult probe =
      rbcstab::integrate(sys, sys.initial_state(), 0.0, grid, io, {}, [&](double t, std::span<const double> y) {
        times.push_back(t);
        states.insert(states.end(), y.begin(), y.end());
      });
  const std::size_t n = sys.dimension(), rhs_per_run = probe.counters.rhs_evaluations;
  std::vector<double> dydt(n);
  double gsl_s = 0, full_s = 0, compact_s = 0, rhs_s = 0, sink = 0;
  std::size_t runs = 0, gsl_rhs = 0, full_rhs = 0;
  auto timed = [](auto&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return seconds_since(start);
  };
  for (auto _ : state) {
    gsl_s += timed([&] {
      const rbcstab::testing::Steps r = rbcstab::testing::gsl_rk8pd(full, grid, io);
      sink += r.samples.at(0)[0];
      gsl_rhs = r.rhs;
    });
    full_s += timed([&] {
      const rbcstab::testing::Steps r = rbcstab::testing::native_rk8pd(full, grid, io);
      sink += r.samples.at(0)[0];
      full_rhs = r.rhs;
    });
    compact_s += timed([&] { sink += rbcstab::integrate(sys, sys.initial_state(), 0.0, grid, io, {}).y[0]; });
    rhs_s += timed([&] {
      for (std::size_t k = 0; k < rhs_per_run; ++k) {
        const std::size_t i = k % times.size();
        sys.rhs(times[i], {states.data() + i * n, n}, dydt);
        sink += dydt[0];
      }
    });
    ++runs;
  }
  benchmark::DoNotOptimize(sink);
  const double per = 1e3 / double(runs);
  state.counters["gsl_ms"] = gsl_s * per;
  state.counters["native_full_ms"] = full_s * per;
  state.counters["compact_ms"] = compact_s * per;
  state.counters["gsl_over_compact"] = gsl_s / compact_s;
  state.counters["compact_rhs"] = double(rhs_per_run);
  state.counters["full_rhs"] = double(full_rhs);
  state.counters["gsl_rhs"] = double(gsl_rhs);
  state.counters["ns_per_rhs_compact"] = 1e9 * compact_s / double(runs * rhs_per_run);
  state.counters["ns_per_rhs_alone"] = 1e9 * rhs_s / double(runs * rhs_per_run);
}
BENCHMARK(BM_UncertifiedRunFloor)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
