// The full model's rotating waves at its l >= 3 onset (model/rotating_wave.hpp) against simulation: the project's
// integrator on FullModel, an independent method (no continuation code in the check). The waves are built from a
// point of the branch born at the l = 3 BP (full continuation in C, L = 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include <Eigen/Eigenvalues>
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"

#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/scene_continuation.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/rotating_wave.hpp"

namespace rbcstab {
namespace {

using cd = std::complex<double>;

// Past the l = 3 onset (C = 0.03617), before the ellipsoidal state's l = 4 onset (0.02629): Upsilon_3 > 0 there.
constexpr double kC = 0.03;

// The ellipsoidal state and the state of the branch born at the l = 3 BP, both at C = kC, as FullModel states.
struct OnsetPoints {
  Scene scene = modal_fixtures::scene(0.08, 4);
  FullEquilibriumProblem problem{scene, ContinuationParameter::C};
  std::vector<double> ellipsoidal, branch;
  double bp_C = 0;
  OnsetPoints() {
    const Branch b =
        continue_scene(test::spec_of(scene, ProblemKind::full, ContinuationParameter::C, kC, 0.08, Direction::backward))
            .branch.branch;
    for (const SpecialPoint& sp : b.special_points)
      if (sp.type == SpecialPointType::BP && sp.mode_l == 3) {
        BranchSwitchOptions o;
        o.continuation.p_min = kC;
        o.continuation.p_max = 0.08;
        o.continuation.max_step = 0.05;
        const BranchSwitchResult sw = switch_branch(problem, b, sp, o);
        if (!sw.switched || sw.branch.points.back().p != kC) continue;
        bp_C = sp.p;
        branch = problem.to_full_state(sw.branch.points.back().x, kC);
      }
    if (b.points.back().p == kC) ellipsoidal = problem.to_full_state(b.points.back().x, kC);
  }
  const FullModel& model() const { return problem.model(kC); }
};

const OnsetPoints& onset() {
  static const OnsetPoints o;
  return o;
}

IntegratorOptions tight() {
  IntegratorOptions o;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  return o;
}

// The FullModel state at each grid time from y0 at t = 0.
std::vector<std::vector<double>> simulate_to(const FullModel& model, const std::vector<double>& y0,
                                             const std::vector<double>& grid) {
  std::vector<std::vector<double>> out;
  const IntegrationResult r = integrate(
      model, y0, 0, grid, tight(), [&](double, std::span<const double> y) { out.emplace_back(y.begin(), y.end()); });
  EXPECT_EQ(r.status, IntegrationStatus::success) << r.reason;
  return out;
}

double max_distance(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

cd amplitude(const std::vector<double>& y, int l, int m) {
  const std::size_t k = 2 * ModeAmplitudes::index(l, m);
  return {y[k], y[k + 1]};
}

double block_area(const std::vector<double>& y, int l) {
  double s = 0;
  for (int m = -l; m <= l; ++m) s += std::norm(amplitude(y, l, m));
  return a_l(l) * s;
}

// Tolerance of the periodicity checks: the integrator's local tolerance 1e-11 (relative, on states of size ~1)
// summed over the ~10^3 steps of a period at most, with margin: 1e-7. The wrong inputs below miss by > 1e-4.
constexpr double kPeriodTol = 1e-7;

// Periodicity defect |y(T) - y(0)| and the defect at T/4 against the exact rotation e^{i M t/2}.
std::pair<double, double> defects(const RotatingWave& w, const std::vector<double>& y0) {
  const auto ys = simulate_to(onset().model(), y0, {0.25 * w.period, w.period});
  if (ys.size() != 2) return {1, 1};
  return {max_distance(ys[1], y0), max_distance(ys[0], rotating_wave_at(w, 0.25 * w.period))};
}

TEST(RotatingWave, EveryModeIsAnExactPeriodicOrbitOfTheFullModel) {
  const OnsetPoints& o = onset();
  ASSERT_FALSE(o.branch.empty());
  ASSERT_GT(block_area(o.branch, 3), 0.05);
  for (int m = 1; m <= 3; ++m) {
    const RotatingWave w = rotating_wave(o.model(), o.branch, 3, m);
    EXPECT_NEAR(w.period, 4 * kPi / m, 1e-15);
    EXPECT_NEAR(block_area(w.y, 3), block_area(o.branch, 3), 1e-15);
    EXPECT_NEAR(o.model().sigma(0, w.y), o.model().sigma(0, o.branch), 1e-12);
    const auto [back, quarter] = defects(w, w.y);
    std::printf("m = %d: |y(T) - y(0)| = %.1e, |y(T/4) - rotation| = %.1e\n", m, back, quarter);
    EXPECT_LT(back, kPeriodTol) << "m = " << m;
    EXPECT_LT(quarter, kPeriodTol) << "m = " << m;
  }
  // A mixture of all m (and m = 0): period 4 pi; m = 2 with 3 ... gcd: m = 2 alone with m = 0 is 2 pi.
  const std::vector<cd> mix = {0.3, cd(0.5, -0.2), cd(0, 0.2), cd(-0.4, 0.1)};
  const RotatingWave w = rotating_wave(o.model(), o.branch, 3, mix);
  EXPECT_NEAR(w.period, 4 * kPi, 1e-15);
  const auto [back, quarter] = defects(w, w.y);
  std::printf("mixture: |y(T) - y(0)| = %.1e, |y(T/4) - rotation| = %.1e\n", back, quarter);
  EXPECT_LT(back, kPeriodTol);
  EXPECT_LT(quarter, kPeriodTol);
  const std::vector<cd> even = {0.3, 0, cd(0.5, 0.5), 0};
  EXPECT_NEAR(rotating_wave(o.model(), o.branch, 3, even).period, 2 * kPi, 1e-15);
}

// The checks above fail on wrong inputs: the block's magnitude 1 % off at the same excess area Delta (not on the
// branch: it relaxes back) and the wrong frequency (e^{i M t} instead of e^{i M t/2}, and a period 1 % long).
// The magnitude alone 1 % off is no wrong input: Delta is conserved and Upsilon_3(sigma_3^c) = 0 leaves sigma
// unchanged, so that state is the branch's equilibrium of another Delta and its wave is periodic too.
TEST(RotatingWave, PeriodicityCheckFailsOnWrongAmplitudeOrFrequency) {
  const OnsetPoints& o = onset();
  ASSERT_FALSE(o.branch.empty());
  const RotatingWave w = rotating_wave(o.model(), o.branch, 3, 1);
  std::vector<double> big = w.y;
  for (int m = -3; m <= 3; ++m) {
    const std::size_t k = 2 * ModeAmplitudes::index(3, m);
    big[k] *= 1.01, big[k + 1] *= 1.01;
  }
  const double other_delta = defects(w, big).first;
  std::printf("amplitude x 1.01 (another Delta): |y(T) - y(0)| = %.1e\n", other_delta);
  EXPECT_LT(other_delta, kPeriodTol);  // another Delta's wave
  const double area = block_area(big, 2) + block_area(big, 3) + block_area(big, 4);
  for (double& v : big) v *= std::sqrt(o.scene.parameters.Delta / area);  // back on the scene's Delta
  const double back = defects(w, big).first;
  std::printf("amplitude x 1.01 at the same Delta: |y(T) - y(0)| = %.1e\n", back);
  EXPECT_GT(back, 1e3 * kPeriodTol);
  RotatingWave fast = w;
  fast.y = rotating_wave_at(w, 0.5 * w.period);  // e^{i m t}: at T/4 the block turned by m T/2
  const auto ys = simulate_to(o.model(), w.y, {0.25 * w.period, 1.01 * w.period});
  ASSERT_EQ(ys.size(), 2u);
  std::printf("wrong frequency: at T/4 %.1e, at 1.01 T %.1e\n", max_distance(ys[0], fast.y), max_distance(ys[1], w.y));
  EXPECT_GT(max_distance(ys[0], fast.y), 1e3 * kPeriodTol);
  EXPECT_GT(max_distance(ys[1], w.y), 1e3 * kPeriodTol);
}

// From the ellipsoidal state at C past the onset with a small m = 1 (then m = 2) disturbance of the l = 3 block: the
// simulation settles on the rotating wave of the branch's state. Oracles: the branch's Delta_3 and sigma at that C
// (and the closed form's), the rotation rate m/2 (period 4 pi / m) measured from the unwrapped phase of f_{3,m}.
// Tolerance 1e-8: the integrator's error (1e-11 a step) plus what is left of the approach by t = 400 (measured
// 4e-11 in Delta_3, 1e-10 in the period).
TEST(RotatingWave, SimulationFromADisturbedEllipsoidSettlesOnTheWave) {
  const OnsetPoints& o = onset();
  ASSERT_FALSE(o.ellipsoidal.empty());
  ASSERT_FALSE(o.branch.empty());
  const FullModel& model = o.model();
  const modal_fixtures::PostState exact =
      modal_fixtures::exact_post_state(with_parameter(o.scene.parameters, ContinuationParameter::C, kC), 3);
  EXPECT_NEAR(block_area(o.branch, 3), exact.Delta_l, 1e-10);
  for (int m = 1; m <= 2; ++m) {
    std::vector<double> y0 = o.ellipsoidal;
    const cd f = 1e-3, g = (m % 2 == 0 ? 1.0 : -1.0) * std::conj(f);
    y0[2 * ModeAmplitudes::index(3, m)] = f.real();
    y0[2 * ModeAmplitudes::index(3, -m)] = g.real();
    double area = 0;
    for (int l = 2; l <= 4; ++l) area += block_area(y0, l);
    for (double& v : y0) v *= std::sqrt(o.scene.parameters.Delta / area);  // on the scene's area sphere
    constexpr double t_end = 400, window = 40;
    std::vector<double> grid;
    for (double t = t_end - window; t <= t_end + 1e-9; t += 0.05) grid.push_back(t);
    const auto ys = simulate_to(model, y0, grid);
    ASSERT_EQ(ys.size(), grid.size());
    const std::vector<double>& y = ys.back();
    // The phase of f_{3,m}, unwrapped over the window: its mean rate.
    double turned = 0;
    for (std::size_t i = 1; i < ys.size(); ++i) turned += std::arg(amplitude(ys[i], 3, m) / amplitude(ys[i - 1], 3, m));
    const double period = 2 * kPi / (turned / window);
    std::printf("m = %d: Delta_3 %.12f, off the branch's by %.1e; sigma off by %.1e; period off 4 pi / m by %.1e\n", m,
                block_area(y, 3), block_area(y, 3) - block_area(o.branch, 3),
                model.sigma(0, y) - model.sigma(0, o.branch), period - 4 * kPi / m);
    EXPECT_NEAR(block_area(y, 3), block_area(o.branch, 3), 1e-8);
    EXPECT_NEAR(model.sigma(0, y), model.sigma(0, o.branch), 1e-8 * std::abs(model.sigma(0, o.branch)));
    EXPECT_NEAR(period, 4 * kPi / m, 1e-8);
    // The wave through the simulated end state's phase: the whole state matches it.
    std::vector<cd> c(4, 0.0);
    c[static_cast<std::size_t>(m)] = amplitude(y, 3, m);
    EXPECT_LT(max_distance(y, rotating_wave(model, o.branch, 3, c).y), 1e-6) << "m = " << m;
  }
}

// Stability: in the frame that turns the l = 3 block back (F_rot = F - R y, R the block's e^{i M t/2} generator) the
// wave is an equilibrium, and F_rot commutes with any rotation of the block (sigma sees |f_3| only), so its
// linearisation has the spectrum of J_rot = DF(y_bp) - R at the BP branch's state. For m = 1, e^{R T} = 1 at T = 4 pi:
// the monodromy is exp(T J_rot). Check: the moduli of the multipliers of a finite-difference monodromy (the
// integrator, central differences h = 1e-6: error ~1e-6) against exp(T Re lambda(J_rot)) (J by central differences of
// the right-hand side), sorted, to 1e-5; none outside the unit circle. Failing case: the same prediction from the
// ellipsoidal state at that C (unstable to l = 3: a multiplier e^{T Upsilon_3} > 1) misses by far more.
TEST(RotatingWave, FloquetMultipliersAreTheBranchStatesRotatingFrameSpectrum) {
  const OnsetPoints& o = onset();
  ASSERT_FALSE(o.branch.empty());
  const FullModel& model = o.model();
  const RotatingWave w = rotating_wave(model, o.branch, 3, 1);
  const double T = w.period;
  const auto n = static_cast<Eigen::Index>(w.y.size());
  Eigen::MatrixXd phi(n, n);
  const double h = 1e-6;
  for (Eigen::Index j = 0; j < n; ++j) {
    std::vector<double> up = w.y, down = w.y;
    up[static_cast<std::size_t>(j)] += h;
    down[static_cast<std::size_t>(j)] -= h;
    const auto a = simulate_to(model, up, {T}), b = simulate_to(model, down, {T});
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    for (Eigen::Index i = 0; i < n; ++i)
      phi(i, j) = (a[0][static_cast<std::size_t>(i)] - b[0][static_cast<std::size_t>(i)]) / (2 * h);
  }
  const auto jacobian = [&](const std::vector<double>& y) {
    Eigen::MatrixXd D(n, n);
    std::vector<double> Fu(y.size()), Fd(y.size());
    for (Eigen::Index j = 0; j < n; ++j) {
      std::vector<double> up = y, down = y;
      up[static_cast<std::size_t>(j)] += 1e-7;
      down[static_cast<std::size_t>(j)] -= 1e-7;
      model.rhs(0, up, Fu);
      model.rhs(0, down, Fd);
      for (Eigen::Index i = 0; i < n; ++i)
        D(i, j) = (Fu[static_cast<std::size_t>(i)] - Fd[static_cast<std::size_t>(i)]) / 2e-7;
    }
    return D;
  };
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(n, n);
  for (int m = -3; m <= 3; ++m) {
    const auto k = static_cast<Eigen::Index>(2 * ModeAmplitudes::index(3, m));
    R(k, k + 1) = -0.5 * m;
    R(k + 1, k) = 0.5 * m;
  }
  const Eigen::VectorXcd mu = Eigen::EigenSolver<Eigen::MatrixXd>(phi, false).eigenvalues();
  std::vector<double> measured;
  for (Eigen::Index i = 0; i < n; ++i) measured.push_back(std::abs(mu[i]));
  std::sort(measured.begin(), measured.end());
  // The sorted moduli exp(T Re lambda) of the rotating-frame spectrum at y, against the measured ones.
  const auto miss = [&](const std::vector<double>& y) {
    const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(jacobian(y) - R, false).eigenvalues();
    std::vector<double> predicted;
    for (Eigen::Index i = 0; i < n; ++i) predicted.push_back(std::exp(T * lambda[i].real()));
    std::sort(predicted.begin(), predicted.end());
    double worst = 0;
    for (std::size_t i = 0; i < measured.size(); ++i) worst = std::max(worst, std::abs(measured[i] - predicted[i]));
    return worst;
  };
  const double worst = miss(o.branch), wrong = miss(o.ellipsoidal);
  int at_one = 0;
  for (Eigen::Index i = 0; i < n; ++i) at_one += std::abs(mu[i] - 1.0) < 1e-4;
  std::printf("multipliers: max |mu| %.8f, moduli vs exp(T Re lambda) %.1e (from the ellipsoid %.1e), %d at 1\n",
              measured.back(), worst, wrong, at_one);
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(wrong, 1e-2);
  EXPECT_LT(measured.back(), 1 + 1e-5);
  // Multipliers 1: the 13 directions of the block's 14 stored reals orthogonal to the wave (its time shift among
  // them) and the conserved Delta (measured 14).
  EXPECT_EQ(at_one, 14);
}

TEST(RotatingWave, BadArgumentsAreRefusedNamingThem) {
  const OnsetPoints& o = onset();
  ASSERT_FALSE(o.branch.empty());
  const FullModel& model = o.model();
  const auto refused = [](const auto& call, const std::string& name) {
    try {
      call();
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
      return;
    }
    ADD_FAILURE() << "not refused: " << name;
  };
  refused([&] { rotating_wave(model, o.branch, 2, 1); }, "l");
  refused([&] { rotating_wave(model, o.branch, 5, 1); }, "l");
  refused([&] { rotating_wave(model, o.branch, 3, 0); }, "m");
  refused([&] { rotating_wave(model, o.branch, 3, 4); }, "m");
  refused([&] { rotating_wave(model, o.branch, 3, std::vector<cd>(3, 1.0)); }, "direction");
  refused([&] { rotating_wave(model, o.branch, 3, std::vector<cd>{cd(0, 1), 1, 0, 0}); }, "direction");
  refused([&] { rotating_wave(model, o.branch, 3, std::vector<cd>{1, 0, 0, 0}); }, "direction");
  refused([&] { rotating_wave(model, o.branch, 3, 1, 0.0); }, "tol");
  refused([&] { rotating_wave(model, std::vector<double>(5, 0.0), 3, 1); }, "state");
  // Not an equilibrium (the wave itself: its block turns), and the l = 3 block zero (the ellipsoidal state).
  refused([&] { rotating_wave(model, rotating_wave(model, o.branch, 3, 1).y, 3, 1); }, "state");
  refused([&] { rotating_wave(model, o.ellipsoidal, 3, 1); }, "state");
  // l = 4 is unforced but zero here; a block with rest content is forced.
  refused([&] { rotating_wave(model, o.branch, 4, 1); }, "state");
  Scene forced = o.scene;
  forced.rest_delta_l = {{3, 1e-3}};
  const FullEquilibriumProblem fp(forced, ContinuationParameter::C);
  refused([&] { rotating_wave(fp.model(kC), o.branch, 3, 1); }, "l");
  // A rotating drive (rest content in l = 2, m = 2 at finite C): no equilibrium to turn.
  InitialState tilted{ModeAmplitudes(4), ModeAmplitudes(4)};
  tilted.g.at(2, 2) = 0.1;
  const FullModel rotating(with_parameter(o.scene.parameters, ContinuationParameter::C, kC), tilted);
  EXPECT_TRUE(rotating.unforced(3));
  EXPECT_FALSE(rotating.autonomous());
  refused([&] { rotating_wave(rotating, o.branch, 3, 1); }, "state");
}

}  // namespace
}  // namespace rbcstab
