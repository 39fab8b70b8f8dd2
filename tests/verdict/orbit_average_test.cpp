// The in-plane asymptotic criterion from the exact periodic orbit (verdict/asymptotic.hpp orbit_sigma_average,
// asymptotic_sigma_R): against long time averages, the trapezoid rule's convergence, out-of-plane
// invariance, the fallback path, and traced points.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <thread>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Appendix E(a): in plane, lambda = 1, Delta = 1, beta = pi/2.
Scene appE_a(double lnB, double lnC) {
  Scene s;
  s.parameters.lambda = 1;
  s.parameters.Delta = 1;
  s.parameters.B = std::exp(lnB);
  s.parameters.C = std::exp(lnC);
  s.beta = 1.5707963267948966;
  s.L = 5;
  return s;
}

// The orbit average equals a converged long time average. Oracle: time_averaged_sigma_R (an independent
// method: one long run with the integrator's own quadrature of sigma_R) over a window of exactly 320
// forcing periods after 80 periods of transient, so on an exactly periodic attractor the window holds whole
// periods and the only differences are the decayed transient and the run's integration error. That error is
// estimated by the time average's own halves difference; the measured |orbit - time| is 1.5x it (rtol 1e-10
// run), so the tolerance is 4x it plus 1e-11 relative (the orbit side: Newton 1e-12, trapezoid spectral).
TEST(OrbitAverage, EqualsLongTimeAverage) {
  for (double lnB : {-1.0, 3.0})
    for (double lnC : {-5.0, -2.0, 0.0, 2.0}) {
      const Scene s = appE_a(lnB, lnC);
      const OrbitSigmaAverage a = orbit_sigma_average(s);
      ASSERT_TRUE(a.ok) << a.reason;
      EXPECT_LT(a.max_multiplier, 1.0);
      PredictorOptions po;
      po.transient = kTwoPi * 80;
      po.window = kTwoPi * 320;
      po.regime_sample_dt = 0.5 * po.window;
      const SigmaAverage ta = time_averaged_sigma_R(s, po);
      ASSERT_TRUE(ta.mean.valid()) << ta.mean.reason;
      const double tol = 4 * std::abs(ta.first_half - ta.second_half) + 1e-11 * (1 + std::abs(a.sigma_R));
      EXPECT_NEAR(a.sigma_R, ta.mean.value, tol) << "lnB " << lnB << " lnC " << lnC;
      // And asymptotic_sigma_R uses it.
      const AsymptoticSigma as = asymptotic_sigma_R(s);
      EXPECT_EQ(as.source, SigmaSource::periodic_orbit);
      EXPECT_EQ(as.sigma_R, a.sigma_R);
    }
}

// Spectral convergence of the periodic trapezoid rule: sigma_R(t) is smooth and 2 pi-periodic on the orbit,
// so 64 and 128 samples agree to rounding (1e-12 relative; the quadrature run is at rtol 1e-12), while a
// non-periodic rule would leave O(h^2) ~ 1e-3 differences.
TEST(OrbitAverage, TrapezoidRuleConvergesSpectrally) {
  for (double lnC : {-5.0, 0.0, 2.0}) {
    const Scene s = appE_a(3.0, lnC);
    OrbitAverageOptions o64, o128, o16;
    o64.samples = 64;
    o128.samples = 128;
    o16.samples = 16;
    const OrbitSigmaAverage a = orbit_sigma_average(s, o64), b = orbit_sigma_average(s, o128),
                            c = orbit_sigma_average(s, o16);
    ASSERT_TRUE(a.ok && b.ok && c.ok);
    EXPECT_NEAR(a.sigma_R, b.sigma_R, 1e-12 * (1 + std::abs(b.sigma_R))) << lnC;
    std::cout << "lnC " << lnC << ": |16 - 128| = " << std::abs(c.sigma_R - b.sigma_R)
              << ", |64 - 128| = " << std::abs(a.sigma_R - b.sigma_R) << "\n";
  }
}

// Out of plane nothing changes: the exact equilibrium, bit for bit, with or without the orbit option.
TEST(OrbitAverage, OutOfPlaneUnchanged) {
  Scene s = appE_a(3.0, -1.0);
  s.beta = 1e-3;
  OrbitAverageOptions off;
  off.enabled = false;
  const AsymptoticSigma on = asymptotic_sigma_R(s), without = asymptotic_sigma_R(s, {}, off);
  const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(s.parameters);
  ASSERT_TRUE(eq.stable);
  EXPECT_EQ(on.source, SigmaSource::equilibrium);
  EXPECT_TRUE(on.exact);
  EXPECT_EQ(on.sigma_R, eq.sigma_R);
  EXPECT_EQ(without.sigma_R, eq.sigma_R);
}

// A scene where Newton from the relaxed state lands on an unstable periodic orbit (found by a scan:
// lambda = 3, Delta = 1, ln C = 1, largest multiplier ~1.03): the orbit is rejected and the time average is
// used, with the reason recorded; with the orbit option off the same time average results.
TEST(OrbitAverage, UnstableOrbitFallsBackToTheTimeAverage) {
  Scene s = appE_a(2.0, 1.0);
  s.parameters.lambda = 3;
  const OrbitSigmaAverage a = orbit_sigma_average(s);
  EXPECT_FALSE(a.ok);
  EXPECT_GT(a.max_multiplier, 1.0);
  EXPECT_NE(a.reason.find("not attracting"), std::string::npos) << a.reason;
  OrbitAverageOptions off;
  off.enabled = false;
  try {
    const AsymptoticSigma as = asymptotic_sigma_R(s);
    EXPECT_EQ(as.source, SigmaSource::time_average);
    EXPECT_NE(as.note.find("not attracting"), std::string::npos) << as.note;
    EXPECT_EQ(as.sigma_R, asymptotic_sigma_R(s, {}, off).sigma_R);
    std::cout << "fallback: time average " << as.sigma_R << " (unstable orbit's average not used): " << as.note << "\n";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("not attracting"), std::string::npos) << e.what();
    std::cout << "fallback: " << e.what() << "\n";
  }
  // Newton that cannot converge (one iteration allowed) falls back too, saying so.
  OrbitAverageOptions one;
  one.max_iterations = 1;
  one.relaxation_periods = 0;
  const OrbitSigmaAverage b = orbit_sigma_average(appE_a(3.0, 0.0), one);
  EXPECT_FALSE(b.ok);
  EXPECT_NE(b.reason.find("did not converge"), std::string::npos) << b.reason;
}

// Deterministic for any thread count and evaluation order: each value depends on its scene only (no warm
// starts, no shared caches), so two threads in reverse order give the serial values bit for bit.
TEST(OrbitAverage, BitIdenticalAcrossThreadsAndOrder) {
  std::vector<Scene> scenes;
  for (int k = 0; k < 8; ++k) scenes.push_back(appE_a(0.5 * k, -5.0 + k));
  std::vector<double> serial, parallel(scenes.size());
  for (const Scene& s : scenes) serial.push_back(asymptotic_sigma_R(s).sigma_R);
  std::vector<std::thread> pool;
  for (int w = 0; w < 2; ++w)
    pool.emplace_back([&, w] {
      for (std::size_t i = scenes.size(); i-- > 0;)
        if (int(i % 2) == w) parallel[i] = asymptotic_sigma_R(scenes[i]).sigma_R;
    });
  for (auto& t : pool) t.join();
  for (std::size_t i = 0; i < scenes.size(); ++i) EXPECT_EQ(serial[i], parallel[i]) << i;
}

TEST(OrbitAverage, OptionsValidateNamingTheField) {
  OrbitAverageOptions o;
  o.samples = 2;
  try {
    o.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("samples"), std::string::npos);
  }
}

}  // namespace
}  // namespace rbcstab
