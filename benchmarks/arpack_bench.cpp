// ARPACK against dense Eigen on the full model's Jacobian (n = 2((L+1)^2 - 4)) at the out-of-plane
// ellipsoidal equilibrium, and matrix-free Floquet multipliers around an in-plane orbit
// (docs/benchmarks.md, docs/continuation.md). Counters: operator applications (or integrations),
// n, and the error of the leading eigenvalue against the closed form Upsilon_4(sigma) (l = 4 leads).
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/eigen_arpack.hpp"
#include "rbcstab/continuation/monodromy.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/full_model.hpp"
#include "rbcstab/model/reduced_model.hpp"

#include "../tests/continuation/in_plane_orbit.hpp"  // the in-plane orbit and its exact monodromy (oracle)

namespace rbcstab {
namespace {

struct Setup {
  Parameters p;
  InitialState init;
  std::vector<double> y;
  double sigma = 0;
  StructuredJacobian J;
};

// The exact reduced out-of-plane equilibrium embedded in the full model with f_{l>=3} = 0.
Setup out_of_plane(int L) {
  Scene s;
  s.beta = 0;
  s.delta = 0;
  s.L = L;
  Setup st;
  st.p = s.parameters;
  st.init = initial_state(s);
  const ReducedModel red(st.p, st.init);
  const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(st.p);
  st.init.f = red.amplitudes(0, std::vector<double>{eq.r * std::cos(eq.Psi), -eq.r * std::sin(eq.Psi), eq.w});
  const FullModel full(st.p, st.init);
  st.y = full.initial_state();
  st.sigma = full.sigma(0, st.y);
  std::vector<double> dfdt(st.y.size());
  full.jacobian(0, st.y, st.J, dfdt);
  return st;
}

// Shift-invert around s = 1.5 (to the right of the spectrum): the 16 eigenvalues nearest it.
void BM_ArpackShiftInvert(benchmark::State& state) {
  const Setup st = out_of_plane(static_cast<int>(state.range(0)));
  ArpackOptions o;
  o.k = 16;
  o.which = ArpackWhich::nearest_shift;
  o.shift = 1.5;
  const LinearOperator A = [&st](std::span<const double> x, std::span<double> y) { st.J.apply(x, y); };
  std::size_t apps = 0;
  double err = 0;
  for (auto _ : state) {
    const ArpackResult r = arpack_eigenvalues(st.J.size(), A, shifted_inverse(st.J, o.shift), o);
    apps = r.applications;
    err = r.eigenvalues.size() ? std::abs(r.eigenvalues(0) - Upsilon_l(st.p, 4, st.sigma)) : 1.0;
  }
  state.counters["n"] = static_cast<double>(st.J.size());
  state.counters["applications"] = static_cast<double>(apps);
  state.counters["error"] = err;
}
BENCHMARK(BM_ArpackShiftInvert)->Arg(10)->Arg(20)->Arg(40)->Arg(60)->Unit(benchmark::kMillisecond);

// Regular mode, largest real part: the stiff spread of Upsilon_l ~ -l^3 makes it slow (and at L = 60
// it does not converge in 3000 restarts), which is why shift-invert is the default advice.
void BM_ArpackLargestReal(benchmark::State& state) {
  const Setup st = out_of_plane(static_cast<int>(state.range(0)));
  ArpackOptions o;
  o.k = 9;
  o.which = ArpackWhich::largest_real;
  const LinearOperator A = [&st](std::span<const double> x, std::span<double> y) { st.J.apply(x, y); };
  std::size_t apps = 0;
  double err = 0;
  for (auto _ : state) {
    const ArpackResult r = arpack_eigenvalues(st.J.size(), A, {}, o);
    apps = r.applications;
    err = r.eigenvalues.size() ? std::abs(r.eigenvalues(0).real() - Upsilon_l(st.p, 4, st.sigma)) : 1.0;
  }
  state.counters["n"] = static_cast<double>(st.J.size());
  state.counters["applications"] = static_cast<double>(apps);
  state.counters["error"] = err;
}
BENCHMARK(BM_ArpackLargestReal)->Arg(10)->Arg(16)->Unit(benchmark::kMillisecond);

void BM_DenseEigen(benchmark::State& state) {
  const Setup st = out_of_plane(static_cast<int>(state.range(0)));
  const auto n = static_cast<Eigen::Index>(st.J.size());
  std::vector<double> d(st.J.size() * st.J.size());
  st.J.to_dense(d);
  const Eigen::MatrixXd D = Eigen::Map<Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(d.data(), n, n);
  double err = 0;
  for (auto _ : state) {
    const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(D, false).eigenvalues();
    const std::vector<std::complex<double>> v(e.data(), e.data() + e.size());
    double lead = -1e300;
    for (const auto& x : v) lead = std::max(lead, x.real());
    err = std::abs(lead - Upsilon_l(st.p, 4, st.sigma));
  }
  state.counters["n"] = static_cast<double>(n);
  state.counters["error"] = err;
}
BENCHMARK(BM_DenseEigen)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

// Floquet: in-plane orbit state (the reduced model relaxed over 30 periods, embedded), 12 leading
// multipliers by ARPACK on the monodromy action vs the dense monodromy (n integrations).
void BM_Floquet(benchmark::State& state) {
  const int L = static_cast<int>(state.range(0));
  const bool dense = state.range(1) != 0;
  Scene s;
  s.beta = std::numbers::pi / 2;
  s.delta = 0;
  s.L = L;
  InitialState init = initial_state(s);
  const ReducedModel red(s.parameters, init);
  const double t0 = 60 * std::numbers::pi;
  const double grid[1] = {t0};
  IntegratorOptions io;
  io.rtol = 1e-11;
  io.atol = 1e-13;
  init.f = red.amplitudes(t0, integrate(red, red.initial_state(), 0.0, grid, io, {}).y);
  const FullModel full(s.parameters, init);
  std::size_t integrations = 0, steps = 0;
  double lead = 0;
  for (auto _ : state) {
    if (dense) {
      const MonodromyAction a(full, full.initial_state(), t0, {});
      const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(a.dense(), false).eigenvalues();
      const std::vector<std::complex<double>> v(e.data(), e.data() + e.size());
      for (const auto& x : v) lead = std::max(lead, std::abs(x));
      integrations = a.applications();
      steps = a.counters().steps;
    } else {
      ArpackOptions o;
      o.k = 12;
      o.tol = 1e-10;
      const FloquetResult r = leading_floquet_multipliers(full, full.initial_state(), t0, {}, o);
      const Eigen::VectorXcd& e = r.arpack.eigenvalues;
      const std::vector<std::complex<double>> v(e.data(), e.data() + e.size());
      for (const auto& x : v) lead = std::max(lead, std::abs(x));
      integrations = r.integrations;
      steps = r.counters.steps;
    }
  }
  state.counters["n"] = static_cast<double>(full.dimension());
  state.counters["integrations"] = static_cast<double>(integrations);
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["leading_abs_mu"] = lead;
}
BENCHMARK(BM_Floquet)
    ->Args({6, 0})
    ->Args({6, 1})
    ->Args({12, 0})
    ->Args({12, 1})
    ->Args({20, 0})
    ->Unit(benchmark::kMillisecond);

// One monodromy action Phi v (v a fixed pseudo-random unit vector) on the in-plane orbit, explicit
// rk8pd vs the implicit rosenbrock variational integration, against the exact block-diagonal Phi
// (test::ExactInPlaneMonodromy): error against cost. Args: L, stepper (0 rk8pd, 1 rosenbrock), -log10 rtol.
// Counters: actions/s, accepted steps per action, relative error |Phi v - exact| / |exact|.
void BM_FloquetAction(benchmark::State& state) {
  const int L = static_cast<int>(state.range(0));
  const test::InPlaneOrbit o = test::in_plane_orbit(L);
  const FullModel full(o.p, o.init);
  const test::ExactInPlaneMonodromy exact = test::exact_in_plane_monodromy(o, L);
  const std::vector<double> v = test::test_vector(full.dimension());
  std::vector<double> want(v.size()), got(v.size());
  exact.apply(v, want);
  MonodromyOptions mo;
  mo.implicit_from_L = 0;  // exactly the stepper asked for
  mo.integrator.stepper = state.range(1) ? Stepper::rosenbrock : Stepper::rk8pd;
  mo.integrator.rtol = std::pow(10.0, -static_cast<double>(state.range(2)));
  mo.integrator.atol = 1e-2 * mo.integrator.rtol;
  const MonodromyAction action(full, full.initial_state(), o.t0, mo);
  for (auto _ : state) benchmark::DoNotOptimize(action.apply(v, got));
  double d = 0, w = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    d += (got[i] - want[i]) * (got[i] - want[i]);
    w += want[i] * want[i];
  }
  state.counters["n"] = static_cast<double>(full.dimension());
  state.counters["actions"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["steps"] = static_cast<double>(action.counters().steps) / static_cast<double>(action.applications());
  state.counters["error"] = std::sqrt(d / w);
}
BENCHMARK(BM_FloquetAction)
    ->ArgsProduct({{6, 12, 20, 30, 40}, {0}, {11}})
    ->ArgsProduct({{6, 12, 20, 30, 40, 60}, {1}, {8, 10}})
    ->Args({60, 0, 11})
    ->Unit(benchmark::kMillisecond);

// The 12 leading multipliers by ARPACK on the action with the default MonodromyOptions (rk8pd below
// implicit_from_L, rosenbrock from it) against the exact multiset (test::multiset_distance, relative
// to 1 + |mu|). Args: L, -log10 of the implicit rtol (default 10; 8 keeps L = 60 at ~2 min).
// Counters: actions, steps per action, error.
void BM_FloquetLeading(benchmark::State& state) {
  const int L = static_cast<int>(state.range(0));
  const test::InPlaneOrbit o = test::in_plane_orbit(L);
  const FullModel full(o.p, o.init);
  const auto exact = test::exact_in_plane_monodromy(o, L).multipliers();
  ArpackOptions ao;
  ao.k = 12;
  ao.tol = 1e-10;
  MonodromyOptions mo;
  mo.implicit.rtol = std::pow(10.0, -static_cast<double>(state.range(1)));
  mo.implicit.atol = 1e-2 * mo.implicit.rtol;
  FloquetResult r;
  for (auto _ : state) r = leading_floquet_multipliers(full, full.initial_state(), o.t0, mo, ao);
  const Eigen::VectorXcd& e = r.arpack.eigenvalues;
  state.counters["n"] = static_cast<double>(full.dimension());
  state.counters["integrations"] = static_cast<double>(r.integrations);
  state.counters["steps"] =
      static_cast<double>(r.counters.steps) / static_cast<double>(std::max<std::size_t>(1, r.integrations));
  state.counters["error"] = test::multiset_distance({e.data(), e.data() + e.size()}, exact);
}
BENCHMARK(BM_FloquetLeading)->Args({20, 10})->Args({30, 10})->Args({60, 8})->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace rbcstab

BENCHMARK_MAIN();
