// Continuation throughput and accuracy (docs/continuation.md): the out-of-plane equilibrium branch
// of the reduced system over lambda in [0, 20] against the closed form (docs/theory.md), and
// the location precision of a fold (x' = p - x^2, LP at p = 0) and a Hopf point; the in-plane
// periodic-orbit branch of Fig. 2 in Delta (multiple shooting) with its swinging -> tumbling UZ point.
#include <benchmark/benchmark.h>

#include <cmath>

#include "continuation/fig2_fixture.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/orbit.hpp"

namespace rbcstab {
namespace {

PolarState closed_form(const Parameters& p) {
  const double L = p.Lambda(), iS = 1 / p.S();
  const double b = 1 + L * L + iS * iS;
  const double u = 2 / (b + std::sqrt(b * b - 4 * L * L));
  return {std::sqrt(u), std::atan2(iS / std::sqrt(1 - u), L)};
}

void BM_OutOfPlaneBranchLambda(benchmark::State& state) {
  Scene s;
  s.beta = 0;
  s.parameters.lambda = 0;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.01;
  s.parameters.C = 0.04;
  const ReducedEquilibriumProblem pr(s, ContinuationParameter::lambda);
  const PolarState c0 = closed_form(s.parameters);
  Eigen::VectorXd y(3);
  y << c0.r * std::cos(c0.Psi), -c0.r * std::sin(c0.Psi), std::sqrt(1 - c0.r * c0.r);
  ContinuationOptions o;
  o.p_min = 0;
  o.p_max = 20;
  o.max_step = static_cast<double>(state.range(0)) / 100;
  std::size_t points = 0, newton = 0;
  double err = 0;
  for (auto _ : state) {
    const Branch b = continue_branch(pr, y, 0.0, o);
    points += b.points.size();
    newton += b.counters.newton_iterations;
    state.PauseTiming();
    for (const auto& pt : b.points) {
      const PolarState c = closed_form(with_parameter(s.parameters, ContinuationParameter::lambda, pt.p));
      const PolarState g = polar(pt.x);
      err = std::max({err, std::abs(g.r - c.r), std::abs(g.Psi - c.Psi)});
    }
    state.ResumeTiming();
  }
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
  state.counters["points"] = static_cast<double>(points) / static_cast<double>(state.iterations());
  state.counters["newton_per_point"] = static_cast<double>(newton) / static_cast<double>(points);
  state.counters["max_error_vs_closed_form"] = err;
}
BENCHMARK(BM_OutOfPlaneBranchLambda)->Arg(50)->Arg(200)->Unit(benchmark::kMillisecond);

class Fold final : public ContinuationProblem {
 public:
  Eigen::Index dimension() const override { return 1; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override { F[0] = p - x[0] * x[0]; }
};

void BM_FoldLocation(benchmark::State& state) {
  const Fold pr;
  ContinuationOptions o;
  o.p_max = 1;
  o.direction = Direction::backward;
  Eigen::VectorXd x(1);
  x << 1;
  double err = 0, precision = 0;
  std::size_t iters = 0;
  for (auto _ : state) {
    const Branch b = continue_branch(pr, x, 1.0, o);
    for (const auto& sp : b.special_points) {
      err = std::max(err, std::abs(sp.p));
      precision = std::max(precision, sp.precision);
    }
    iters += b.counters.location_iterations;
  }
  state.counters["LP_error"] = err;
  state.counters["LP_precision"] = precision;
  state.counters["location_iterations"] = static_cast<double>(iters) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_FoldLocation)->Unit(benchmark::kMillisecond);

// Fig. 2's in-plane scene (lambda = 5, Delta0 = 0.01, B = 2, C = 0.04): the swinging orbit branch
// from Delta = 0.05 through the swinging -> tumbling transition to 0.5, with N = range(0) segments.
// Precision of the UZ point: its bracket, and its distance to the same point located with N = 32.
Scene fig2_in_plane(double Delta) { return test::fig2_in_plane(Delta); }

Branch in_plane_branch(const PeriodicOrbitProblem& pr, const ReducedForcedSystem& sys, bool event = true) {
  const double p0 = sys.start_parameter();
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(300), p0), p0);
  ContinuationOptions o;
  o.direction = Direction::forward;
  o.p_max = 0.5;
  if (event) o.events.push_back(pr.transition_event());
  return continue_branch(pr, nr.x, p0, o);
}

void BM_InPlaneOrbitBranchDelta(benchmark::State& state) {
  const ReducedForcedSystem sys(fig2_in_plane(0.05), ContinuationParameter::Delta);
  static const double reference = [&] {
    OrbitOptions ro;
    ro.segments = 32;
    const PeriodicOrbitProblem pr(sys, ro);
    const Branch b = in_plane_branch(pr, sys);
    return b.special_points.empty() ? std::nan("") : b.special_points[0].p;
  }();
  OrbitOptions oo;
  oo.segments = static_cast<int>(state.range(0));
  const PeriodicOrbitProblem pr(sys, oo);
  std::size_t points = 0, integrations = 0;
  double precision = 0, err = 0, trivial = 0;
  for (auto _ : state) {
    const std::size_t i0 = pr.integrations();
    const Branch b = in_plane_branch(pr, sys);
    points += b.points.size();
    integrations += pr.integrations() - i0;
    state.PauseTiming();
    if (b.special_points.size() != 1) state.SkipWithError("expected one UZ point");
    for (const auto& sp : b.special_points) {
      precision = std::max(precision, sp.precision);
      err = std::max(err, std::abs(sp.p - reference));
    }
    for (const auto& pt : b.points) trivial = std::max(trivial, std::abs(*pr.floquet(pt.x, pt.p).trivial - 1));
    state.ResumeTiming();
  }
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
  state.counters["points"] = static_cast<double>(points) / static_cast<double>(state.iterations());
  state.counters["integrations_per_point"] = static_cast<double>(integrations) / static_cast<double>(points);
  state.counters["UZ_precision"] = precision;
  state.counters["UZ_vs_N32"] = err;
  state.counters["max_trivial_multiplier_error"] = trivial;
}
BENCHMARK(BM_InPlaneOrbitBranchDelta)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);

// The same branch without the UZ event: the work AUTO-07p does per point (Newton, tangent, multipliers), for
// benchmarks/auto/compare.py, with N = range(0) segments at rtol = 10^-range(1). The start (relaxation and the
// first Newton) is timed too, as AUTO's start is.
void BM_InPlaneOrbitBranchNoEvent(benchmark::State& state) {
  const ReducedForcedSystem sys(fig2_in_plane(0.05), ContinuationParameter::Delta);
  OrbitOptions oo;
  oo.segments = static_cast<int>(state.range(0));
  oo.rtol = std::pow(10.0, -static_cast<double>(state.range(1)));
  oo.atol = oo.rtol / 10;
  const PeriodicOrbitProblem pr(sys, oo);
  std::size_t points = 0;
  for (auto _ : state) points += in_plane_branch(pr, sys, false).points.size();
  state.counters["points"] = static_cast<double>(points) / static_cast<double>(state.iterations());
  state.counters["points_per_second"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_InPlaneOrbitBranchNoEvent)
    ->Args({4, 12})
    ->Args({8, 12})
    ->Args({16, 12})
    ->Args({4, 10})
    ->Args({4, 8})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rbcstab

BENCHMARK_MAIN();
