// Output where the user asks: t_eval (the integrator stops at each time) and dense output (DenseOutput: a
// polynomial through the nearest accepted steps), against closed forms and a tight-tolerance run.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "continuation/invalid_argument_fixture.hpp"
#include "model/test_scenes.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/dense_output.hpp"
#include "rbcstab/integrate/simulation.hpp"

namespace rbcstab {
namespace {

// sin and exp on irregular nodes of spacing ~h: the largest error at the midpoints between nodes.
double interpolation_error(double h) {
  DenseOutput d(2);
  std::vector<double> mid;
  double t = 0;
  for (int k = 0; t < 4; ++k) {
    d.add(t, {std::sin(t), std::exp(-t)});
    const double step = h * (1 + 0.5 * std::sin(3.0 * k));  // steps vary by a factor 3, as adaptive ones do
    mid.push_back(t + step / 2);
    t += step;
  }
  mid.pop_back();
  double err = 0;
  for (double m : mid) {
    const std::vector<double> v = d(m);
    err = std::max({err, std::abs(v[0] - std::sin(m)), std::abs(v[1] - std::exp(-m))});
  }
  return err;
}

// Degree 7: the error falls as h^8 (2^8 = 256 per halving; asked > 100, below that the order is lost) and is
// at the scale of the bound max|f^(8)| prod |t - t_i| / 8!: steps up to 1.5 h = 0.3, at a midpoint the product
// is (0.5 1.5 2.5 3.5)^2 0.3^8 = 7e-4, over 8! = 4e4: 1.7e-8 (measured 2.0e-8, asked < 5e-8).
TEST(DenseOutput, InterpolatesToEighthOrder) {
  const double coarse = interpolation_error(0.2), fine = interpolation_error(0.1);
  std::cout << "interpolation error h = 0.2: " << coarse << ", h = 0.1: " << fine << "\n";
  EXPECT_LT(coarse, 5e-8);
  EXPECT_GT(coarse / fine, 100.0);
}

// Exact at the nodes; NaN in the gap between segments and outside the run; a segment's nodes only.
TEST(DenseOutput, NodesExactAndNothingAcrossAGap) {
  DenseOutput d(1);
  for (int k = 0; k <= 10; ++k) d.add(0.125 * k, {double(k * k)});  // t = k / 8: nodes exact in binary
  d.start_segment();
  for (int k = 20; k <= 30; ++k) d.add(0.125 * k, {-1.0});
  EXPECT_EQ(d(0.375)[0], 9.0);
  EXPECT_NEAR(d(0.4375)[0], 12.25, 1e-12);  // (8 t)^2: a polynomial of degree < 8 is reproduced
  EXPECT_TRUE(std::isnan(d(1.875)[0]));     // the skip between the segments
  EXPECT_TRUE(std::isnan(d(-0.1)[0]));
  EXPECT_TRUE(std::isnan(d(3.9)[0]));
  EXPECT_NEAR(d(2.5625)[0], -1.0, 1e-12);  // only the second segment's nodes
  EXPECT_EQ(test::invalid_parameter([] { DenseOutput(2, {0.0, 1.0}, {1.0, 2.0, 3.0}, {0}); }), "values");
  EXPECT_EQ(test::invalid_parameter([] { DenseOutput(1, {0.0, 1.0}, {1.0, 2.0}, {1}); }), "segment_starts");
}

Scene fig3() {
  Scene s = testing::fig3_scene(0.0);
  s.T = 60;  // past Delta_4's rise: the modes move on several time scales
  return s;
}

SimulationOptions options(double rtol) {
  SimulationOptions o;
  o.integrator.rtol = rtol;
  o.integrator.atol = rtol * 1e-4;
  return o;
}

// t_eval: one sample at each time asked, at the integrator's error (against an rtol 1e-13 run at the same
// times: within 100 rtol of Delta, the global error of rk8pd at rtol 1e-10 over this run measured ~1e-9).
TEST(SimulationOutput, TEvalSamplesWhereAsked) {
  const std::vector<double> times{0.0, 0.37, 1.5, 2.25, 17.3, 41.0, 59.99};
  SimulationOptions o = options(1e-10);
  o.t_eval = times;
  const SimulationResult r = simulate(fig3(), o);
  o = options(1e-13);
  o.t_eval = times;
  const SimulationResult ref = simulate(fig3(), o);
  ASSERT_EQ(r.trajectory.t, times);
  double err = 0;
  for (std::size_t k = 0; k < times.size(); ++k)
    for (std::size_t j = 0; j < 3; ++j)
      err = std::max(err, std::abs(r.trajectory.Delta_l[k][j] - ref.trajectory.Delta_l[k][j]));
  std::cout << "t_eval samples against rtol 1e-13: max |Delta_l error| " << err << "\n";
  EXPECT_LT(err, 100 * 1e-10 * fig3().parameters.Delta);
  EXPECT_EQ(r.t_reached, fig3().T);  // T is integrated to (its state is reported) though not asked for
}

// Dense output at off-grid times against an rtol 1e-13 run stopped there (t_eval): largest error in Delta_l
// (absolute) and sigma (relative).
std::pair<double, double> dense_error(double rtol) {
  std::vector<double> off;
  for (double t = 0.123; t < 60; t += 3.7) off.push_back(t);
  SimulationOptions o = options(rtol);
  o.dense_output = true;
  const SimulationResult r = simulate(fig3(), o);
  o = options(1e-13);
  o.t_eval = off;
  const SimulationResult ref = simulate(fig3(), o);
  double err = 0, err_sigma = 0;
  for (std::size_t k = 0; k < off.size(); ++k) {
    const std::vector<double> v = r.dense(off[k]);
    for (std::size_t j = 0; j < 9; ++j) err = std::max(err, std::abs(v[j] - ref.trajectory.Delta_l[k][j]));
    err_sigma = std::max(err_sigma, std::abs(v[9] - ref.trajectory.sigma[k]) / std::abs(ref.trajectory.sigma[k]));
  }
  // The columns Delta_2..Delta_10, sigma, r, Psi; at a step the run's own values.
  EXPECT_EQ(r.dense.columns(), 12u);
  EXPECT_EQ(r.dense(fig3().T)[9], r.sigma_final);
  return {err, err_sigma};
}

// The interpolation's error is of the integrator's order: rk8pd's steps h ~ rtol^(1/9) make it fall as
// h^8 ~ rtol^(8/9) (asked: by > 30 from rtol 1e-8 to 1e-10, 100^(8/9) = 60). Its constant is the 8-node
// stencil's, (0.5 1.5 2.5 3.5)^2 / 8! of h^8 |y^(8)|: measured ~5e3 rtol in Delta_l at rtol 1e-10, asked
// < 2e4 rtol (Delta = 1).
TEST(SimulationOutput, DenseOutputConvergesWithRtolOffGrid) {
  const auto [coarse, coarse_sigma] = dense_error(1e-8);
  const auto [fine, fine_sigma] = dense_error(1e-10);
  std::cout << "dense output against rtol 1e-13: rtol 1e-8 " << coarse << " (sigma " << coarse_sigma << "), rtol 1e-10 "
            << fine << " (sigma " << fine_sigma << ")\n";
  EXPECT_GT(coarse / fine, 30.0);
  EXPECT_GT(coarse_sigma / fine_sigma, 30.0);
  EXPECT_LT(fine, 2e4 * 1e-10);
}

TEST(SimulationOutput, TEvalRejectsBadTimes) {
  for (const std::vector<double>& bad : std::vector<std::vector<double>>{
           {0.0, 2.0, 1.0}, {0.0, 61.0}, {-1.0}, {0.0, std::numeric_limits<double>::quiet_NaN()}, {1.0, 1.0}}) {
    SimulationOptions o;
    o.t_eval = bad;
    EXPECT_EQ(test::invalid_parameter([&] { (void)simulate(fig3(), o); }), "t_eval");
  }
}

}  // namespace
}  // namespace rbcstab
