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

#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/two_parameter.hpp"

namespace {

using namespace rbcstab;

Scene scene(int L) {
  Scene s;
  s.name = "zbp_bench";
  s.parameters.lambda = 1;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.01;
  s.parameters.B = 2;
  s.parameters.C = 0.07;
  s.beta = M_PI / 2;
  s.L = L;
  s.model = ModelLevel::modal;
  return s;
}

ContinuationOptions curve_options() {
  ContinuationOptions o;
  o.p_min = 1.8;
  o.p_max = 2.2;
  o.direction = Direction::both;
  o.initial_step = 0.05;
  o.max_step = 0.05;
  return o;
}

// The reduced curve's start near C at B: reduced orbit, then Newton on the curve system.
Eigen::VectorXd reduced_point(const ModalOrbitBranchPointCurve& curve, const Scene& s, double C, double B, bool& ok) {
  const Scene at = with_parameter(with_parameter(s, ContinuationParameter::B, B), ContinuationParameter::C, C);
  const ReducedForcedSystem red(at, ContinuationParameter::C);
  const PeriodicOrbitProblem rp(red);
  const NewtonResult rn = solve_fixed_parameter(rp, rp.shooting_guess(red.relaxed_state(200), C), C);
  Eigen::VectorXd X(curve.dimension());
  X << rn.x, C;
  const NewtonResult n = solve_fixed_parameter(curve, X, B);
  ok = rn.converged && n.converged;
  return n.x;
}

void BM_ReducedEllipsoidalOrbitBPCurve(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  const ModalOrbitBranchPointCurve curve(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  bool ok = false;
  const Eigen::VectorXd X0 = reduced_point(curve, s, 0.06, 2.0, ok);
  if (!ok) {
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
  const SliceProblem slice(base, 2.0);
  const ModalOrbitBranchPointCurve reduced(s, ContinuationParameter::C, ContinuationParameter::B, 3);
  bool ok = false;
  const Eigen::VectorXd R0 = reduced_point(reduced, s, 0.07, 2.0, ok);  // converges to the BP's C
  const Eigen::Index nr = reduced.dimension() - 1;
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(sys2.dimension());
  x0.head(3) = R0.head(3);
  const double C0 = R0[nr] * 1.05;  // on the stable side of the BP
  const PeriodicOrbitProblem mp(sys2.at(2.0), oo);
  const NewtonResult mn = solve_fixed_parameter(slice, mp.shooting_guess(x0, C0), C0);
  ContinuationOptions o;
  o.p_min = 0.055;
  o.direction = Direction::backward;
  o.initial_step = 0.002;
  o.max_step = 0.005;
  const Branch one = continue_branch(slice, mn.x, C0, o);
  const SpecialPoint* bp = nullptr;
  for (const auto& sp : one.special_points)
    if (sp.type == SpecialPointType::BP && sp.status == LocationStatus::located) bp = &sp;
  if (!ok || !mn.converged || bp == nullptr) {
    state.SkipWithError("no located BP");
    return;
  }
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
      bool pok = false;
      const Eigen::VectorXd X = reduced_point(reduced, s, pt.parameters[0], pt.parameters[1], pok);
      err = std::max(err, pok ? std::abs(X[nr] - pt.parameters[0]) : 1.0);
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
