// Full-model equilibria (continuation/full_equilibrium.hpp, docs/continuation.md) at L = 4, 8, 12:
// - the ellipsoidal branch over lambda in [0, 20] (no stress-free l >= 3 content): points/s and the
//   largest error against the out-of-plane closed form (analysis/steady_states) embedded;
// - a stress-free l = 3 content (rest_delta_l = {3: 1e-3}) continued in C from 0.08 to 0.012: points/s,
//   the largest error of f_{l,m} against the constant-drive closed form (tests/continuation/
//   full_fixtures.hpp) and the located l = 4 crossing's |sigma - sigma_4^c| (Upsilon_4 = 0 there).
// Scene: lambda = 1, B = 1, Delta = 1, Delta0 = 0.01, beta = 0 (the modal benchmarks' scene).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "continuation/full_fixtures.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

void BM_FullEllipsoidalBranchLambda(benchmark::State& state) {
  const Scene s = full_fixtures::forced_scene(0.08, static_cast<int>(state.range(0)), 0);
  const FullEquilibriumProblem pr(s, ContinuationParameter::lambda);
  ContinuationOptions o;
  o.p_min = 0;
  o.p_max = 20;
  o.direction = Direction::both;
  std::size_t points = 0, newton = 0;
  double err = 0;
  for (auto _ : state) {
    const Branch b = continue_branch(pr, pr.ellipsoidal_state(1.0), 1.0, o);
    points += b.points.size();
    newton += b.counters.newton_iterations;
    state.PauseTiming();
    for (const auto& pt : b.points) err = std::max(err, (pt.x - pr.ellipsoidal_state(pt.p)).lpNorm<Eigen::Infinity>());
    state.ResumeTiming();
  }
  state.counters["n"] = static_cast<double>(pr.dimension());
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
  state.counters["newton_per_point"] =
      static_cast<double>(newton) / static_cast<double>(std::max<std::size_t>(points, 1));
  state.counters["max_error_vs_closed_form"] = err;
}
BENCHMARK(BM_FullEllipsoidalBranchLambda)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

void BM_FullForcedBranchC(benchmark::State& state) {
  const Scene s = full_fixtures::forced_scene(0.08, static_cast<int>(state.range(0)), 1e-3);
  const FullEquilibriumProblem pr(s, ContinuationParameter::C);
  const NewtonResult start = solve_fixed_parameter(pr, pr.ellipsoidal_state(0.08), 0.08);
  if (!start.converged) {
    state.SkipWithError("no start");
    return;
  }
  ContinuationOptions o;
  o.p_min = 0.012;
  o.p_max = 0.08;
  o.direction = Direction::backward;
  std::size_t points = 0, special = 0;
  double bp_err = 0, err = 0;
  for (auto _ : state) {
    const Branch b = continue_branch(pr, start.x, 0.08, o);
    points += b.points.size();
    state.PauseTiming();
    special = b.special_points.size();
    for (const auto& pt : b.points) {
      const Parameters q = with_parameter(s.parameters, ContinuationParameter::C, pt.p);
      err = std::max(err, full_fixtures::state_error(pr, pt.x, pt.p, full_fixtures::closed_form(s, q)));
    }
    for (const auto& sp : b.special_points) {
      if (sp.type != SpecialPointType::BP) continue;
      const Parameters q = with_parameter(s.parameters, ContinuationParameter::C, sp.p);
      bp_err = std::max(bp_err, std::abs(pr.observe(sp.x, sp.p).sigma - sigma_c(4, q.alpha())));
      break;
    }
    state.ResumeTiming();
  }
  state.counters["n"] = static_cast<double>(pr.dimension());
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
  state.counters["special_points"] = static_cast<double>(special);
  state.counters["max_error_vs_closed_form"] = err;
  state.counters["l4_BP_sigma_error"] = bp_err;
}
BENCHMARK(BM_FullForcedBranchC)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rbcstab

BENCHMARK_MAIN();
