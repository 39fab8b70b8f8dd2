// Sweep scaling: a Fig. 4(b)-type out-of-plane panel (L = 10, T = 500, rtol 1e-8, rk8pd) on a small
// grid with 1 and 2 threads, and tracing the same plane's boundary. Counters record work (rhs
// evaluations per point, criterion evaluations) beside the time; docs/sweeps.md has the full-panel numbers.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

// The boundary of a Fig. 4 plane traced by continuation (trace_boundary): range(0) selects the panel
// (0: Fig. 4(b), lambda = 5, Delta = 1, one l = 3 piece; 1: Fig. 4(a), lambda = 1, seven pieces and six
// corners), range(1) the criterion (0 asymptotic, 1 finite horizon T = 500). Counters: criterion
// evaluations, curve points, curve points per second, corners, and the largest |criterion| at a traced
// point (the error: 0 on the exact boundary).
void BM_TraceFig4(benchmark::State& state) {
  rbcstab::Scene scene = fig4b();
  if (state.range(0) == 1) scene.parameters.lambda = 1;
  rbcstab::DiagramSpec plane;
  rbcstab::TraceOptions o;
  o.criterion = state.range(1) == 0 ? rbcstab::TraceCriterion::asymptotic : rbcstab::TraceCriterion::finite_horizon;
  std::size_t evaluations = 0, points = 0, corners = 0;
  double worst = 0;
  for (auto _ : state) {
    const rbcstab::TraceResult t = rbcstab::trace_boundary(scene, plane, o);
    evaluations += t.evaluations;
    corners += t.corners.size();
    for (const auto& c : t.curves) {
      points += c.points.size();
      for (const auto& p : c.points) worst = std::max(worst, std::abs(p.mu));
    }
  }
  const double n = double(state.iterations());
  state.counters["evaluations"] = double(evaluations) / n;
  state.counters["curve_points"] = double(points) / n;
  state.counters["points_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  state.counters["corners"] = double(corners) / n;
  state.counters["max_abs_criterion"] = worst;
}
BENCHMARK(BM_TraceFig4)->Args({0, 0})->Args({1, 0})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TraceFig4)->Args({0, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// One in-plane asymptotic criterion evaluation (asymptotic_sigma_R) on the Appendix E(a) plane
// (lambda = 1, Delta = 1, beta = pi/2, ln B = 3) at 8 values of ln C in [-5, 2]: range(0) = 1 the periodic-
// orbit average, 0 the former time average (PredictorOptions transient 500, window 2000, tracing rtol 1e-12).
// Counters: evaluations per second and, for the orbit, the largest |orbit - time average| over the 8 points
// relative to (1 + |sigma_R|) (the error of the slower method bounds it).
void BM_InPlaneSigma(benchmark::State& state) {
  const bool orbit = state.range(0) == 1;
  rbcstab::PredictorOptions po = rbcstab::TraceOptions::tracing_predictor();
  rbcstab::OrbitAverageOptions oo, off;
  oo.enabled = orbit;
  off.enabled = false;
  std::vector<rbcstab::Scene> scenes;
  for (int k = 0; k < 8; ++k) {
    rbcstab::Scene s;
    s.parameters.lambda = 1;
    s.parameters.B = std::exp(3.0);
    s.parameters.C = std::exp(-5.0 + 7.0 * k / 7.0);
    s.beta = 1.5707963267948966;
    s.L = 5;
    scenes.push_back(s);
  }
  std::size_t evaluations = 0;
  for (auto _ : state)
    for (const auto& s : scenes) {
      benchmark::DoNotOptimize(rbcstab::asymptotic_sigma_R(s, po, oo).sigma_R);
      ++evaluations;
    }
  double worst = 0;
  if (orbit)
    for (const auto& s : scenes) {
      const double a = rbcstab::asymptotic_sigma_R(s, po, oo).sigma_R,
                   b = rbcstab::asymptotic_sigma_R(s, po, off).sigma_R;
      worst = std::max(worst, std::abs(a - b) / (1 + std::abs(b)));
    }
  state.counters["evaluations_per_s"] = benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
  state.counters["rel_diff_to_time_average"] = worst;
}
BENCHMARK(BM_InPlaneSigma)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
