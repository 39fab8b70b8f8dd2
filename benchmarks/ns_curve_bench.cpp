// NS curve of a forced orbit with a closed-form answer (the focus case of ns_curve_test.cpp's Forced3):
// continuation over p2 in [-0.8, 0.8] both ways; work (points, Newton iterations, integrations) and
// error (max |p1 - p2^2|, max |kappa - cos 2 pi omega|) in counters, for N shooting segments.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "continuation/ns_fixtures.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/ns_curve.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"

namespace {

using namespace rbcstab;
constexpr double kOmega = 0.3;
using ns_fixtures::Forced3;

void BM_NeimarkSackerCurve(benchmark::State& state) {
  const Forced3 sys(-kOmega * kOmega);  // multipliers e^{2 pi (p1 - p2^2 +- i omega)}, e^{-2 pi}
  OrbitOptions oo;
  oo.segments = static_cast<int>(state.range(0));
  const double p2 = 0.4, p1 = p2 * p2 - 0.1;
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(Forced3::xp(0, p1, p2), p1), p1);
  ContinuationOptions o;
  o.p_max = p2 * p2 + 0.1;
  o.max_step = 0.05;
  const Branch b = continue_branch(pr, nr.x, p1, o);
  if (b.special_points.size() != 1 || b.special_points[0].type != SpecialPointType::NS) {
    state.SkipWithError("no NS point");
    return;
  }
  ContinuationOptions co;
  co.direction = Direction::both;
  co.p_min = -0.8;
  co.p_max = 0.8;
  co.max_step = 0.1;
  double points = 0, newton = 0, integrations = 0, err_p1 = 0, err_kappa = 0;
  for (auto _ : state) {
    const NeimarkSackerCurveProblem curve(sys, oo, b.special_points[0], p2);
    const Branch c = continue_branch(curve, curve.start(), p2, co);
    const Eigen::Index m = curve.dimension() - 2;
    for (const auto& pt : c.points) {
      err_p1 = std::max(err_p1, std::abs(pt.x[m] - pt.p * pt.p));
      err_kappa = std::max(err_kappa, std::abs(pt.x[m + 1] - std::cos(2 * M_PI * kOmega)));
    }
    points += static_cast<double>(c.points.size());
    newton += static_cast<double>(c.counters.newton_iterations);
    integrations += static_cast<double>(curve.integrations());
  }
  state.counters["points"] = benchmark::Counter(points, benchmark::Counter::kAvgIterations);
  state.counters["points_per_s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  state.counters["newton"] = benchmark::Counter(newton, benchmark::Counter::kAvgIterations);
  state.counters["integrations"] = benchmark::Counter(integrations, benchmark::Counter::kAvgIterations);
  state.counters["max_err_p1"] = err_p1;
  state.counters["max_err_kappa"] = err_kappa;
}
BENCHMARK(BM_NeimarkSackerCurve)->Arg(3)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
