// The claim measures of `rbcstab paper` against closed forms, the paper scenes it runs, and its option checks.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/report/paper.hpp"

namespace rbcstab {
namespace {
namespace fs = std::filesystem;
using namespace paper_measure;

std::vector<double> grid(double T, int n) {
  std::vector<double> t;
  for (int k = 0; k <= n; ++k) t.push_back(T * k / n);
  return t;
}

TEST(PaperMeasure, TailMeanAndRangeMatchClosedForms) {
  const std::vector<double> t = grid(100, 1000);
  std::vector<double> lin, s;
  for (double v : t) lin.push_back(2 * v + 1), s.push_back(std::sin(v));
  // The trapezoid rule is exact on a line: the mean of 2t + 1 over [90, 100] is 2 * 95 + 1.
  EXPECT_NEAR(tail_mean(t, lin, 10), 191, 1e-12);
  EXPECT_NEAR(tail_range(t, lin, 10), 20, 1e-12);
  // sin over [50, 100] (about 8 periods): range 2 to within the sampling (dt = 0.1: 1 - cos(0.05) ~ 1.3e-3).
  EXPECT_NEAR(tail_range(t, s, 50), 2, 2e-3);
  // Mean of sin over [50, 100]: (cos 50 - cos 100) / 50, trapezoidal error O(dt^2 / 12).
  EXPECT_NEAR(tail_mean(t, s, 50), (std::cos(50.0) - std::cos(100.0)) / 50, 1e-4);
}

TEST(PaperMeasure, SettleTimeOfAnExponential) {
  const std::vector<double> t = grid(100, 10000);
  std::vector<double> x;
  for (double v : t) x.push_back(std::exp(-v));
  // |e^{-t} - ~0| > 1e-3 until t = ln 1000 (the final value is ~1e-40): the last sample before it.
  EXPECT_NEAR(settle_time(t, x, 1e-3), std::log(1000.0), 0.011);
  std::vector<double> flat(t.size(), 3.0);
  EXPECT_EQ(settle_time(t, flat, 1e-3), 0.0);
}

TEST(PaperMeasure, GrowsThenDecays) {
  const std::vector<double> t = grid(20, 2000);
  std::vector<double> bump, decay, growth;
  for (double v : t) bump.push_back(0.1 + v * std::exp(-v)), decay.push_back(std::exp(-v)), growth.push_back(v);
  // 0.1 + t e^{-t}: peak 0.1 + 1/e at t = 1, end ~0.1 < 0.5 (0.1 + 1/e)? yes; start 0.1 < peak.
  EXPECT_TRUE(grows_then_decays(bump, 0.5));
  EXPECT_FALSE(grows_then_decays(bump, 0.2));    // 0.1 > 0.2 (0.1 + 1/e) = 0.094: has not fallen that far
  EXPECT_FALSE(grows_then_decays(decay, 0.5));   // maximum at the start
  EXPECT_FALSE(grows_then_decays(growth, 0.5));  // maximum at the end
}

TEST(PaperMeasure, NetTurnIgnoresTheHalfTurnJumpsOfRThroughZero) {
  // A sawtooth: Psi falls from pi/2 to -pi/2 over 100 samples, then jumps back by pi (r through 0), 5 times:
  // a turn of -5 pi. A continuous fall by 7 (no jumps) is -7; a swing of amplitude 0.4 turns by 0 net.
  std::vector<double> saw, fall, swing;
  for (int cycle = 0; cycle < 5; ++cycle)
    for (int k = 0; k < 100; ++k) saw.push_back(std::numbers::pi / 2 - std::numbers::pi * (k + 0.5) / 100);
  for (int k = 0; k <= 700; ++k) fall.push_back(-0.01 * k), swing.push_back(0.4 * std::sin(0.05 * k));
  EXPECT_NEAR(net_turn(saw), -5 * std::numbers::pi + std::numbers::pi / 100, 1e-12);
  EXPECT_NEAR(net_turn(fall), -7, 1e-12);
  EXPECT_NEAR(net_turn(swing), 0.4 * std::sin(35.0), 1e-12);
}

TEST(PaperMeasure, MaxRelativeGapUpToATime) {
  const std::vector<double> t{0, 1, 2, 3};
  const std::vector<double> y{1, 2, 4, 8}, x{1.1, 2, 4, 16};
  EXPECT_NEAR(max_relative_gap(t, x, y, 2.5), 0.1, 1e-12);
  EXPECT_NEAR(max_relative_gap(t, x, y, 3), 1.0, 1e-12);
}

// Oracle: the in-plane start puts Delta_3 into f_{3,m} ~ d^3_{m,0}(pi/2), and |d^3_{m,0}(pi/2)|^2 =
// (l-m)!/(l+m)! P_3^m(0)^2 by hand: P_3^1(0) = -3/2, P_3^3(0) = -15, P_3^0(0) = P_3^2(0) = 0, so |m| = 1 holds
// 2 (1/12)(9/4) = 3/8 and |m| = 3 holds 2 (1/720)(225) = 5/8. The out-of-plane start (beta = 0) is all m = 0.
TEST(PaperMeasure, AzimuthalSharesOfTheInPlaneAndOutOfPlaneStarts) {
  Scene s;
  s.L = 4;
  s.beta = std::numbers::pi / 2;
  const std::vector<double> ip = azimuthal_shares(initial_state(s).f, 3);
  ASSERT_EQ(ip.size(), 4u);
  EXPECT_NEAR(ip[0], 0, 1e-14);
  EXPECT_NEAR(ip[1], 3.0 / 8, 1e-12);
  EXPECT_NEAR(ip[2], 0, 1e-14);
  EXPECT_NEAR(ip[3], 5.0 / 8, 1e-12);
  s.beta = 0;
  const std::vector<double> op = azimuthal_shares(initial_state(s).f, 4);
  ASSERT_EQ(op.size(), 5u);
  EXPECT_NEAR(op[0], 1, 1e-14);
  // Hand-set amplitudes: |f_{3,-2}|^2 = 1 and |f_{3,2}|^2 = 4 both count as |m| = 2; an empty mode has no shares.
  ModeAmplitudes f(3);
  f.at(3, -2) = {0, 1};
  f.at(3, 2) = {2, 0};
  f.at(3, 0) = {-5, 0};
  EXPECT_EQ(azimuthal_shares(f, 3), (std::vector<double>{25.0 / 30, 0, 5.0 / 30, 0}));
  EXPECT_EQ(azimuthal_shares(ModeAmplitudes(3), 3), (std::vector<double>{0, 0, 0, 0}));
}

TEST(PaperScenes, NewScenesHoldTheCaptionsParameters) {
  EXPECT_EQ(find_scene_dir(""), std::string(RBCSTAB_SCENES_DIR));
  const auto dir = fs::path(RBCSTAB_SCENES_DIR);
  // App. F (the suppressed initial instability): Delta = 0.1, Delta0 = 0.01, lambda = 5, B = e^4, C = e^-2.7, e^-1.
  for (auto [name, lnC] : {std::pair{"appF_a", -2.7}, std::pair{"appF_b", -1.0}}) {
    const SceneFile sf = load_scene((dir / (std::string(name) + ".toml")).string());
    EXPECT_NO_THROW(sf.scene.validate());
    EXPECT_EQ(sf.scene.parameters.Delta, 0.1);
    EXPECT_EQ(sf.scene.parameters.Delta0, 0.01);
    EXPECT_EQ(sf.scene.parameters.lambda, 5.0);
    EXPECT_NEAR(std::log(sf.scene.parameters.B), 4, 1e-15);
    EXPECT_NEAR(std::log(sf.scene.parameters.C), lnC, 1e-15);
  }
  // Fig. 3(a): alpha = 25.
  EXPECT_EQ(load_scene((dir / "fig3a_criterion.toml").string()).scene.parameters.alpha(), 25.0);
  // App. C: three cells at lambda = 1, 3, 5, each orientation; C = 1e6 for the vesicle-like cell, C = 1 otherwise,
  // Delta = Delta0 for the unstressed cell only; unperturbed reduced runs.
  int n = 0;
  for (const char* o : {"op", "ip"})
    for (int lam : {1, 3, 5})
      for (const char* c : {"vesicle", "unstressed", "enucleated"}) {
        const std::string name = std::string("appC_") + o + "_lambda" + std::to_string(lam) + "_" + c;
        const SceneFile sf = load_scene((dir / (name + ".toml")).string());
        EXPECT_NO_THROW(sf.scene.validate()) << name;
        EXPECT_EQ(sf.scene.name, name);
        const Parameters& p = sf.scene.parameters;
        EXPECT_EQ(p.lambda, double(lam)) << name;
        EXPECT_EQ(p.C, std::string(c) == "vesicle" ? 1e6 : 1.0) << name;
        EXPECT_EQ(p.Delta == p.Delta0, std::string(c) == "unstressed") << name;
        EXPECT_EQ(sf.scene.beta, std::string(o) == "ip" ? std::numbers::pi / 2 : 0.001) << name;
        EXPECT_EQ(sf.scene.model, ModelLevel::reduced) << name;
        ++n;
      }
  EXPECT_EQ(n, 18);
}

TEST(PaperOptions, BadInputNamesTheField) {
  PaperOptions o;
  try {
    o.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "output");
  }
  o.output = "x";
  o.threads = -1;
  try {
    o.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "threads");
  }
  o.threads = 1;
  o.scene_dir = "/nonexistent";
  try {
    build_paper(o);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "scene_dir");
  }
}

}  // namespace
}  // namespace rbcstab
