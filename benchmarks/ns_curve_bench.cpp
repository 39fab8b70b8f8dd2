// NS curve of a forced orbit with a closed-form answer (the Focus system of ns_curve_test.cpp):
// continuation over p2 in [-0.8, 0.8] both ways; work (points, Newton iterations, integrations) and
// error (max |p1 - p2^2|, max |kappa - cos 2 pi omega|) in counters, for N shooting segments.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/ns_curve.hpp"

namespace {

using namespace rbcstab;
constexpr double kOmega = 0.3, kC = 0.7;

// x' = A e + xp' + c |e|^2 e_1, e = x - xp, A = [[a, -omega, 0], [omega, a, 0], [0, 0, -1]], a = p1 - p2^2.
class Focus final : public ForcedSystem2 {
 public:
  Eigen::Index dimension() const override { return 3; }
  static Eigen::Matrix3d A(double p1, double p2) {
    const double a = p1 - p2 * p2;
    Eigen::Matrix3d M;
    M << a, -kOmega, 0, kOmega, a, 0, 0, 0, -1;
    return M;
  }
  static Eigen::Vector3d xp(double t, double p1, double p2) {
    return {std::cos(t) + p1 * std::sin(2 * t), std::sin(t) + p2 * std::cos(2 * t), 0.5 * std::sin(t)};
  }
  static Eigen::Vector3d xp_dot(double t, double p1, double p2) {
    return {-std::sin(t) + 2 * p1 * std::cos(2 * t), std::cos(t) - 2 * p2 * std::sin(2 * t), 0.5 * std::cos(t)};
  }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    const Eigen::Vector3d e = Eigen::Vector3d(x[0], x[1], x[2]) - xp(t, p1, p2);
    const Eigen::Vector3d F = A(p1, p2) * e + xp_dot(t, p1, p2) + Eigen::Vector3d(kC * e.squaredNorm(), 0, 0);
    for (int i = 0; i < 3; ++i) f[static_cast<std::size_t>(i)] = F[i];
  }
  void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const override {
    const Eigen::Vector3d e = Eigen::Vector3d(x[0], x[1], x[2]) - xp(t, p1, p2);
    J = A(p1, p2);
    J.row(0) += 2 * kC * e.transpose();
  }
  void parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                            std::span<double> fp) const override {
    const Eigen::Vector3d e = Eigen::Vector3d(x[0], x[1], x[2]) - xp(t, p1, p2);
    const Eigen::Vector3d dxp(std::sin(2 * t), 0, 0), dxp_dot(2 * std::cos(2 * t), 0, 0);
    const Eigen::Vector3d F =
        Eigen::Vector3d(e[0], e[1], 0) - A(p1, p2) * dxp + dxp_dot - Eigen::Vector3d(2 * kC * e.dot(dxp), 0, 0);
    for (int i = 0; i < 3; ++i) fp[static_cast<std::size_t>(i)] = F[i];
  }
};

void BM_NeimarkSackerCurve(benchmark::State& state) {
  const Focus sys;
  OrbitOptions oo;
  oo.segments = static_cast<int>(state.range(0));
  const double p2 = 0.4, p1 = p2 * p2 - 0.1;
  const ForcedSlice slice(sys, p2);
  const PeriodicOrbitProblem pr(slice, oo);
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(Focus::xp(0, p1, p2), p1), p1);
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
