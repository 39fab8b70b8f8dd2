// beta as a continuation parameter (docs/continuation.md, "beta"): the in-plane orbit of Fig. 2
// (Delta = 1) continued from beta = pi/2 down to beta = 0, with its swinging <-> tumbling UZ, the
// collapse onto the out-of-plane closed form at beta = 0 (error counter, arg 2), and the cost of the
// exact df/dbeta (arg 0) against ForcedSystem's default central differences of the rhs (arg 1).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "continuation/fig2_fixture.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/orbit.hpp"

namespace rbcstab {
namespace {

Scene fig2_in_plane_Delta1() { return test::fig2_in_plane(1); }

// The same system with df/dbeta left to ForcedSystem's central differences of the rhs.
class DifferencedBeta final : public ForcedSystem {
 public:
  explicit DifferencedBeta(const ReducedForcedSystem& s) : s_(s) {}
  Eigen::Index dimension() const override { return 3; }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override { s_.rhs(t, x, p, f); }
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    s_.jacobian(t, x, p, J);
  }
  bool conserves_norm() const override { return true; }
  std::string parameter_name() const override { return "beta"; }

 private:
  const ReducedForcedSystem& s_;
};

// Arg 0: the exact df/dbeta; arg 1: central differences of the rhs (which cannot reach beta = 0: the
// difference steps to beta < 0, outside the domain), both down to beta = 0.05; arg 2: the exact one
// down to beta = 0, landed on exactly, where the orbit is compared with the closed form.
void BM_InPlaneOrbitBranchBeta(benchmark::State& state) {
  const Scene scene = fig2_in_plane_Delta1();
  const ReducedForcedSystem exact(scene, ContinuationParameter::beta);
  const DifferencedBeta differenced(exact);
  const ForcedSystem& sys = state.range(0) == 1 ? static_cast<const ForcedSystem&>(differenced) : exact;
  const PeriodicOrbitProblem pr(sys);
  const double p0 = M_PI / 2;
  const NewtonResult start = solve_fixed_parameter(pr, pr.shooting_guess(exact.relaxed_state(300), p0), p0);
  const OutOfPlaneEquilibrium c = out_of_plane_equilibrium(scene.parameters);
  const Eigen::Vector3d e(c.r * std::cos(c.Psi), -c.r * std::sin(c.Psi), c.w);
  ContinuationOptions o;
  o.direction = Direction::backward;
  o.p_min = state.range(0) == 2 ? 0.0 : 0.05;
  o.events.push_back(pr.transition_event());
  std::size_t points = 0, integrations = 0;
  double err = 0, uz = 0;
  bool ok = true;
  for (auto _ : state) {
    const std::size_t i0 = pr.integrations();
    const Branch b = continue_branch(pr, start.x, p0, o);
    points += b.points.size();
    integrations += pr.integrations() - i0;
    ok = ok && b.points.back().p == o.p_min && b.special_points.size() == 1;
    if (o.p_min == 0.0)
      for (Eigen::Index j = 0; j < pr.segments(); ++j)
        err = std::max(err, (b.points.back().x.segment<3>(3 * j) - e).cwiseAbs().maxCoeff());
    if (!b.special_points.empty()) uz = b.special_points[0].p;
  }
  if (!ok) state.SkipWithError("expected the bound and one UZ");
  state.counters["points"] = static_cast<double>(points) / static_cast<double>(state.iterations());
  state.counters["integrations_per_point"] = static_cast<double>(integrations) / static_cast<double>(points);
  state.counters["beta0_vs_closed_form"] = err;
  state.counters["UZ_beta"] = uz;
}
BENCHMARK(BM_InPlaneOrbitBranchBeta)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rbcstab

BENCHMARK_MAIN();
