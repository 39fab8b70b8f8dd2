// The in-plane asymptotic criterion from the exact periodic orbit (verdict/asymptotic.hpp orbit_sigma_average,
// asymptotic_sigma_R): against long time averages, the trapezoid rule's convergence, out-of-plane
// invariance, the fallback path, traced points, and the mapping of one flow's orbit across B.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <set>
#include <thread>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {
namespace {

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

// The orbit average across B (orbit_sigma_average_at_B, AsymptoticSigmaMemo): the reduced flow holds no B, so one
// orbit per flow gives <sigma_R> and the asymptotic verdict at every B.
// The App. E in-plane flows: (a) lambda = 1, Delta = 1; (b) lambda = 5, Delta = 1; (c) lambda = 5, Delta = 0.1.
Scene appE(double lambda, double Delta, double lnB, double lnC) {
  Scene s = appE_a(lnB, lnC);
  s.parameters.lambda = lambda;
  s.parameters.Delta = Delta;
  s.L = 10;
  return s;
}

// Oracle for <sigma_R> at B: the periodic trapezoid rule of sigma_R(t) as the model at B observes it
// (ReducedModel::observe, i.e. Upsilon_2^{-1}(mu) pointwise), along a fresh one-period run from the orbit
// state that the direct solve at B found. It differs from Upsilon_2^{-1}(<mu>) only by the rounding of
// 128-term sums of O(|sigma_R|) terms (~128 eps |sigma_R| ~ 3e-14 |sigma_R|); 1e-12 (1 + |sigma_R|) is far
// below the orbit solver's own accuracy (Newton 1e-12, rtol 1e-12) that either value carries.
double trapezoid_sigma(const Scene& s, const Eigen::VectorXd& x0, const OrbitAverageOptions& o) {
  const ReducedModel model(s.parameters, initial_state(s));
  const int K = o.samples;
  std::vector<double> grid;
  for (int k = 1; k < K; ++k) grid.push_back(kTwoPi * k / K);
  double sum = model.observe(0.0, std::span<const double>(x0.data(), 3)).sigma;
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = o.shooting.rtol;
  io.atol = o.shooting.atol;
  const IntegrationResult r = integrate(model, std::span<const double>(x0.data(), 3), 0.0, grid, io,
                                        [&](double t, std::span<const double> y) { sum += model.observe(t, y).sigma; });
  EXPECT_EQ(r.status, IntegrationStatus::success);
  return sum / K;
}

OrbitKind kind_of(const Scene& s, const OrbitSigmaAverage& a) {
  const ReducedForcedSystem sys(s, ContinuationParameter::B);
  const PeriodicOrbitProblem orbit(sys);
  return orbit.summary(orbit.shooting_guess(a.x0, sys.start_parameter()), sys.start_parameter()).kind;
}

// One orbit per flow, solved at ln B = 2, mapped to ln B in [-1, 6]: the orbit, its multipliers and <mu> are
// the direct solve's bits at every B, <sigma_R> and the verdict (unstable, mode, margin) equal the direct ones
// bit for bit and the independent trapezoid of sigma_R to rounding. Swinging and tumbling orbits, stable and
// unstable verdicts all occur.
TEST(OrbitAtB, MapsExactlyAcrossB) {
  const OrbitAverageOptions o;
  std::set<OrbitKind> kinds;
  int unstable = 0, stable = 0, flows = 0;
  double worst = 0;  // largest |mapped - oracle| / (1 + |oracle|)
  for (const auto& [lambda, Delta] : std::vector<std::pair<double, double>>{{1, 1}, {5, 1}, {5, 0.1}})
    for (double lnC : {-5.0, -2.0, 0.5, 2.0}) {
      const Scene base = appE(lambda, Delta, 2.0, lnC);
      const OrbitSigmaAverage solved = orbit_sigma_average(base, o);
      if (!solved.ok) {
        std::cout << "lambda " << lambda << " Delta " << Delta << " lnC " << lnC << ": no orbit (" << solved.reason
                  << ")\n";
        continue;
      }
      ++flows;
      kinds.insert(kind_of(base, solved));
      for (double lnB : {-1.0, 0.5, 2.5, 4.0, 6.0}) {
        const Scene s = appE(lambda, Delta, lnB, lnC);
        const OrbitSigmaAverage mapped = orbit_sigma_average_at_B(solved, s), direct = orbit_sigma_average(s, o);
        ASSERT_TRUE(direct.ok) << direct.reason;
        EXPECT_EQ(direct.x0, solved.x0);
        EXPECT_EQ(direct.mean_mu, solved.mean_mu);
        EXPECT_EQ(direct.max_multiplier, solved.max_multiplier);
        EXPECT_EQ(mapped.sigma_R, direct.sigma_R);
        const double oracle = trapezoid_sigma(s, direct.x0, o);
        worst = std::max(worst, std::abs(mapped.sigma_R - oracle) / (1 + std::abs(oracle)));
        EXPECT_NEAR(mapped.sigma_R, oracle, 1e-12 * (1 + std::abs(oracle)))
            << "lambda " << lambda << " Delta " << Delta << " lnB " << lnB << " lnC " << lnC;
        const AsymptoticVerdict vd = asymptotic_verdict(s), vm = asymptotic_verdict(s, solved);
        EXPECT_EQ(vm.unstable, vd.unstable);
        EXPECT_EQ(vm.l, vd.l);
        EXPECT_EQ(vm.margin, vd.margin);
        EXPECT_EQ(asymptotic_sigma_R(s, solved).source, SigmaSource::periodic_orbit);
        (vd.unstable ? unstable : stable)++;
      }
    }
  std::cout << flows << " flows x 5 B: " << unstable << " unstable, " << stable << " stable, " << kinds.size()
            << " orbit kinds; max |mapped - trapezoid of sigma_R| / (1 + |sigma_R|) = " << worst << "\n";
  EXPECT_GE(flows, 10);
  EXPECT_EQ(kinds.size(), 2u) << "both swinging and tumbling orbits";
  EXPECT_GT(unstable, 0);
  EXPECT_GT(stable, 0);
}

// A flow whose orbit does not attract gives no average at any B: the mapped result carries the same reason, and
// the verdict falls back to the time average at the scene's own B exactly as without the solved orbit.
TEST(OrbitAtB, NonAttractingOrbitFallsBackAtEachB) {
  const Scene base = appE(3, 1, 2.0, 1.0);  // lambda = 3: a repelling orbit (OrbitAverage.UnstableOrbitFalls...)
  const OrbitSigmaAverage solved = orbit_sigma_average(base);
  ASSERT_FALSE(solved.ok);
  for (double lnB : {0.0, 4.0}) {
    Scene s = base;
    s.parameters.B = std::exp(lnB);
    const OrbitSigmaAverage mapped = orbit_sigma_average_at_B(solved, s);
    EXPECT_FALSE(mapped.ok);
    EXPECT_EQ(mapped.reason, solved.reason);
    try {
      const AsymptoticSigma d = asymptotic_sigma_R(s), m = asymptotic_sigma_R(s, solved);
      EXPECT_EQ(m.source, d.source);
      EXPECT_EQ(m.sigma_R, d.sigma_R);
      EXPECT_EQ(m.note, d.note);
    } catch (const InvalidArgument&) {
      EXPECT_THROW(asymptotic_sigma_R(s, solved), InvalidArgument);
    }
  }
}

// Another flow (C, lambda, Delta, Delta0 or beta) is refused, naming the parameter.
TEST(OrbitAtB, OtherFlowIsRefused) {
  const OrbitSigmaAverage solved = orbit_sigma_average(appE(1, 1, 2.0, 0.0));
  Scene other = appE(1, 1, 2.0, 0.1);
  EXPECT_THROW(orbit_sigma_average_at_B(solved, other), InvalidArgument);
  other = appE(1, 1, 3.0, 0.0);
  other.beta = 1.5;
  try {
    orbit_sigma_average_at_B(solved, other);
    ADD_FAILURE() << "another beta was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("orbit"), std::string::npos) << e.what();
  }
}

// The memo (one orbit per flow, in any order of B and from any thread) gives asymptotic_sigma_R's bits, and
// solves each in-plane flow once; out of plane it solves none.
TEST(OrbitAtB, MemoEqualsDirectInAnyOrder) {
  AsymptoticSigmaMemo memo;
  for (double lnB : {5.0, -1.0, 2.0})
    for (double lnC : {-3.0, 1.0}) {
      const Scene s = appE(1, 1, lnB, lnC);
      const AsymptoticSigma m = memo(s), d = asymptotic_sigma_R(s);
      EXPECT_EQ(m.sigma_R, d.sigma_R);
      EXPECT_EQ(m.source, d.source);
    }
  EXPECT_EQ(memo.orbits_solved(), 2u);
  Scene op = appE(1, 1, 2.0, 0.0);
  op.beta = 0.001;
  EXPECT_EQ(memo(op).sigma_R, asymptotic_sigma_R(op).sigma_R);
  EXPECT_EQ(memo.orbits_solved(), 2u);
  // Shared by two threads over 3 flows x 4 B (each thread its own order): the direct values, bit for bit.
  AsymptoticSigmaMemo shared;
  std::vector<Scene> scenes;
  for (double lnC : {-4.0, -1.0, 1.5})
    for (double lnB : {-1.0, 1.0, 3.0, 6.0}) scenes.push_back(appE(5, 1, lnB, lnC));
  std::vector<double> a(scenes.size()), b(scenes.size());
  std::thread t1([&] {
    for (std::size_t i = 0; i < scenes.size(); ++i) a[i] = shared(scenes[i]).sigma_R;
  });
  std::thread t2([&] {
    for (std::size_t i = scenes.size(); i-- > 0;) b[i] = shared.verdict(scenes[i]).sigma_R;
  });
  t1.join();
  t2.join();
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const double d = asymptotic_sigma_R(scenes[i]).sigma_R;
    EXPECT_EQ(a[i], d) << i;
    EXPECT_EQ(b[i], d) << i;
  }
  EXPECT_EQ(shared.orbits_solved(), 3u);
}

}  // namespace
}  // namespace rbcstab
