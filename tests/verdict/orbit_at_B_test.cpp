// The in-plane orbit average across B (verdict/asymptotic.hpp orbit_sigma_average_at_B, AsymptoticSigmaMemo):
// the reduced flow holds no B, so one orbit per flow gives <sigma_R> and the asymptotic verdict at every B.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <set>
#include <vector>

#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The App. E in-plane scenes' flows: (a) lambda = 1, Delta = 1; (b) lambda = 5, Delta = 1; (c) lambda = 5,
// Delta = 0.1; Delta0 = 0.01, beta = pi/2.
Scene appE(double lambda, double Delta, double lnB, double lnC) {
  Scene s;
  s.parameters.lambda = lambda;
  s.parameters.Delta = Delta;
  s.parameters.Delta0 = 0.01;
  s.parameters.B = std::exp(lnB);
  s.parameters.C = std::exp(lnC);
  s.beta = 1.5707963267948966;
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

// The memo (one orbit per flow, in any order of B) gives asymptotic_sigma_R's bits, and solves each in-plane
// flow once; out of plane it solves none.
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
}

}  // namespace
}  // namespace rbcstab
