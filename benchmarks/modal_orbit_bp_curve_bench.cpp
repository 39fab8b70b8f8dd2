// The BP curve of the in-plane ellipsoidal modal orbit (lambda = 1, Delta = 1, Delta0 = 0.01, the l = 3
// pitchfork of cycles) in (C, B) over B in [1.8, 2.2], both ways, max arclength step 0.05:
//  - Generic: BranchPointCurveProblem over the modal shooting problem (2 segments, 2 n + 2 unknowns,
//    central-difference Jacobian), at L = 4 and 6;
//  - Reduced: ModalOrbitBranchPointCurve (reduced shooting, 8 segments, + sigma_bar = sigma_3^c), at
//    L = 4 and 6 (L enters only the reported multipliers).
// Counters: points, points_per_s, newton iterations; generic: max |C - C_reduced(B)| at its points.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "continuation/ellipsoidal_orbit_bp_fixture.hpp"
#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"
#include "rbcstab/continuation/two_parameter.hpp"

namespace {

using namespace rbcstab;

Scene scene(int L) { return test::in_plane_modal(1, 2, 0.07, L); }

ContinuationOptions curve_options() {
  ContinuationOptions o;
  o.p_min = 1.8;
  o.p_max = 2.2;
  o.direction = Direction::both;
  o.initial_step = 0.05;
  o.max_step = 0.05;
  return o;
}

void BM_ReducedEllipsoidalOrbitBPCurve(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  const ModalOrbitBranchPointCurve curve(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  const NewtonResult start = test::curve_point(curve, s, 0.06, 2.0);
  const Eigen::VectorXd& X0 = start.x;
  if (!start.converged) {
    state.SkipWithError("no start");
    return;
  }
  double points = 0, newton = 0;
  for (auto _ : state) {
    const Branch c = continue_branch(curve, X0, 2.0, curve_options());
    points += static_cast<double>(c.points.size());
    newton += static_cast<double>(c.counters.newton_iterations);
  }
  state.counters["points"] = benchmark::Counter(points, benchmark::Counter::kAvgIterations);
  state.counters["points_per_s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  state.counters["newton"] = benchmark::Counter(newton, benchmark::Counter::kAvgIterations);
  state.counters["unknowns"] = static_cast<double>(curve.dimension());
}
BENCHMARK(BM_ReducedEllipsoidalOrbitBPCurve)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_GenericEllipsoidalOrbitBPCurve(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  OrbitOptions oo;
  oo.segments = 2;
  const ModalForcedSystem2 sys2(s, ContinuationParameter::C, ContinuationParameter::B);
  const OrbitTwoParameterProblem base(sys2, oo);
  const ModalOrbitBranchPointCurve reduced(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  const Eigen::Index nr = reduced.dimension() - 1;
  const test::EllipsoidalOrbitBP located = test::locate_ellipsoidal_orbit_bp(sys2, s, 0.055, oo);
  if (!located.bp) {
    state.SkipWithError("no located BP");
    return;
  }
  const SpecialPoint* bp = &*located.bp;
  double points = 0, newton = 0, err = 0;
  Eigen::Index unknowns = 0;
  for (auto _ : state) {
    const BranchPointCurveProblem curve(base, *bp, 2.0);
    unknowns = curve.dimension();
    const Branch c = continue_branch(curve, curve.start(), 2.0, curve_options());
    points += static_cast<double>(c.points.size());
    newton += static_cast<double>(c.counters.newton_iterations);
    state.PauseTiming();
    for (const auto& pt : c.points) {
      const NewtonResult r = test::curve_point(reduced, s, pt.parameters[0], pt.parameters[1]);
      err = std::max(err, r.converged ? std::abs(r.x[nr] - pt.parameters[0]) : 1.0);
    }
    state.ResumeTiming();
  }
  state.counters["points"] = benchmark::Counter(points, benchmark::Counter::kAvgIterations);
  state.counters["points_per_s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  state.counters["newton"] = benchmark::Counter(newton, benchmark::Counter::kAvgIterations);
  state.counters["unknowns"] = static_cast<double>(unknowns);
  state.counters["max_err_C_vs_reduced"] = err;
}
BENCHMARK(BM_GenericEllipsoidalOrbitBPCurve)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
