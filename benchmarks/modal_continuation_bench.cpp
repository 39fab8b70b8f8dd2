// Modal-model equilibria (docs/continuation.md): the ellipsoidal branch in C with its BPs (location
// error against the closed-form threshold), branch switching to the post-instability state (error
// against its closed form), and Ipopt's complementarity solve for the surviving modes (iterations,
// error against the closed form). Scene: lambda = 1, B = 1, Delta = 1, Delta0 = 0.01, L = 10.
#include <benchmark/benchmark.h>

#include <cmath>

#include "continuation/modal_fixtures.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/complementarity.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

// The test suite's scene and closed forms (tests/continuation/modal_fixtures.hpp) at L = 10.
Scene modal_scene() { return modal_fixtures::scene(0.08, 10); }

void BM_ModalEllipsoidalBranchAndBPs(benchmark::State& state) {
  const Scene s = modal_scene();
  const ModalEquilibriumProblem pr(s, ContinuationParameter::C);
  ContinuationOptions o;
  o.p_min = 0.01;
  o.p_max = 0.08;
  o.direction = Direction::backward;
  std::size_t points = 0, bps = 0;
  double err = 0;
  for (auto _ : state) {
    const Branch b = continue_branch(pr, pr.ellipsoidal_state(0.08), 0.08, o);
    points += b.points.size();
    state.PauseTiming();
    bps = 0;
    for (const auto& sp : b.special_points) {
      if (sp.type != SpecialPointType::BP) continue;
      ++bps;
      const int l = critical_mode(pr, sp.x, sp.p);
      err = std::max(err, std::abs(sp.p - modal_fixtures::threshold_root(s.parameters, ContinuationParameter::C, l,
                                                                         sp.p_lo - 1e-3, sp.p_hi + 1e-3)));
    }
    state.ResumeTiming();
  }
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
  state.counters["BPs"] = static_cast<double>(bps);
  state.counters["max_BP_error"] = err;
}
BENCHMARK(BM_ModalEllipsoidalBranchAndBPs)->Unit(benchmark::kMillisecond);

void BM_ModalBranchSwitch(benchmark::State& state) {
  const Scene s = modal_scene();
  const ModalEquilibriumProblem pr(s, ContinuationParameter::C);
  ContinuationOptions o;
  o.p_min = 0.01;
  o.p_max = 0.08;
  o.direction = Direction::backward;
  const Branch b = continue_branch(pr, pr.ellipsoidal_state(0.08), 0.08, o);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  if (!bp) {
    state.SkipWithError("no BP");
    return;
  }
  const int l = critical_mode(pr, bp->x, bp->p);
  BranchSwitchOptions so;
  so.continuation = o;
  std::size_t points = 0;
  double err = 0;
  for (auto _ : state) {
    const BranchSwitchResult sw = switch_branch(pr, b, *bp, so);
    points += sw.branch.points.size();
    state.PauseTiming();
    for (const auto& pt : sw.branch.points) {
      const Parameters q = with_parameter(s.parameters, ContinuationParameter::C, pt.p);
      err = std::max(err, std::abs(pr.observe(pt.x, pt.p).Delta_l[0] - modal_fixtures::exact_post_state(q, l).Delta2));
    }
    state.ResumeTiming();
  }
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
  state.counters["max_Delta2_error"] = err;
}
BENCHMARK(BM_ModalBranchSwitch)->Unit(benchmark::kMillisecond);

void BM_IpoptSurvivingModes(benchmark::State& state) {
  Scene s = modal_scene();
  s.parameters.C = static_cast<double>(state.range(0)) / 1000;
  const ModalEquilibriumProblem pr(s, ContinuationParameter::C);
  int iterations = 0;
  double err = 0;
  int l = 0;
  for (auto _ : state) {
    const ComplementarityResult r = solve_surviving_modes(pr, s.parameters.C);
    iterations = r.iterations;
    l = r.surviving.empty() ? 2 : r.surviving.front();
    state.PauseTiming();
    err = l == 2 ? std::abs(r.Delta_l[0] - s.parameters.Delta)
                 : std::abs(r.Delta_l[0] - modal_fixtures::exact_post_state(s.parameters, l).Delta2);
    state.ResumeTiming();
  }
  state.counters["ipopt_iterations"] = iterations;
  state.counters["surviving_l"] = l;
  state.counters["Delta2_error"] = err;
}
BENCHMARK(BM_IpoptSurvivingModes)->Arg(60)->Arg(25)->Arg(15)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rbcstab
BENCHMARK_MAIN();
