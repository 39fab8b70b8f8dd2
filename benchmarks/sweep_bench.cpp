// Sweep scaling: a Fig. 4(b)-type out-of-plane panel (L = 10, T = 500, rtol 1e-8, rk8pd) on a small
// grid with 1 and 2 threads, and tracing the same plane's boundary. Counters record work (rhs
// evaluations per point, criterion evaluations) beside the time; docs/sweeps.md has the full-panel numbers.
#include <benchmark/benchmark.h>

#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace {

rbcstab::Scene fig4b() {
  rbcstab::Scene s;  // lambda = 5, Delta = 1, Delta0 = 0.01, beta = 0.001, L = 10, T = 500
  s.dt = s.T;        // a diagram keeps no trajectory
  return s;
}

void BM_DiagramPanel(benchmark::State& state) {
  const int n = int(state.range(0));
  rbcstab::DiagramSpec spec;
  spec.x.count = n;
  spec.y.count = n;
  spec.classifier = rbcstab::Classifier::final;
  rbcstab::DiagramOptions o;
  o.threads = int(state.range(1));
  std::size_t rhs = 0, points = 0, unstable = 0;
  for (auto _ : state) {
    const rbcstab::DiagramRun r = rbcstab::run_diagram(fig4b(), {}, spec, o);
    for (const auto& p : r.points) {
      rhs += p.rhs_evaluations;
      unstable += p.verdict == rbcstab::Verdict::unstable;
    }
    points += r.points.size();
  }
  state.counters["points_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  state.counters["rhs_per_point"] = double(rhs) / double(points);
  state.counters["unstable_fraction"] = double(unstable) / double(points);
}
BENCHMARK(BM_DiagramPanel)->Args({8, 1})->Args({8, 2})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_TraceFig4b(benchmark::State& state) {
  rbcstab::DiagramSpec plane;
  rbcstab::TraceOptions o;
  o.lines = int(state.range(0));
  std::size_t evaluations = 0, points = 0;
  for (auto _ : state) {
    const rbcstab::TraceResult t = rbcstab::trace_boundary(fig4b(), plane, o);
    evaluations += t.evaluations;
    for (const auto& c : t.curves) points += c.points.size();
  }
  state.counters["evaluations"] = double(evaluations) / double(state.iterations());
  state.counters["curve_points"] = double(points) / double(state.iterations());
}
BENCHMARK(BM_TraceFig4b)->Arg(64)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
