// A start you can trust (scene_continuation.hpp find_start, orbit.hpp relax): orbit starts relax period
// by period to a periodicity tolerance before Newton, and an orbit certified unstable is refused unless
// allowed; equilibrium starts report their stability. The wrong-start case is verified against a long
// direct simulation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "continuation/wrong_start_fixture.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_start.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;

double max_modulus(const Eigen::VectorXcd& mu) { return mu.cwiseAbs().maxCoeff(); }

// The wrong-start case: the start is now the attracting orbit. Physics: Newton from the state relaxed
// for T = 200 (32 periods) lands on the repelling orbit (|mu| = 1.024, certified unstable); relaxed on to
// the default periodicity tolerance 1e-6 (578 more periods, measured) it lands on the attracting one
// (|mu| = 0.97659). Verified by direct simulation: the ReducedModel integrated from the scene's shape for
// 3000 periods (0.977^3000 ~ 1e-31: on the attractor to its integration tolerance) is at the start
// orbit's state to 1e-7.
TEST(OrbitStart, WrongStartCaseNowStartsOnTheAttractingOrbit) {
  const BranchSpec spec = test::wrong_start_spec();
  const StartPoint s = find_start(spec);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_FALSE(s.refused);
  EXPECT_TRUE(s.relaxed);
  EXPECT_LT(s.periodicity_defect, spec.relax_tol);
  EXPECT_EQ(s.periodicity_tol, spec.relax_tol);
  EXPECT_GT(s.relaxation_periods, 32 + 100);
  EXPECT_TRUE(s.message.empty()) << s.message;
  EXPECT_EQ(s.stability, Stability::stable);
  EXPECT_TRUE(s.stable);
  EXPECT_EQ(s.n_unstable, 0);
  EXPECT_GT(s.margin, s.margin_error);

  const ReducedForcedSystem sys(spec.scene, P::Lambda);
  const PeriodicOrbitProblem pr(sys, spec.orbit);
  const Eigen::VectorXcd mu = pr.spectrum(s.x, s.p);
  EXPECT_LT(max_modulus(mu), 1.0);
  EXPECT_NEAR(max_modulus(mu), 0.97659, 1e-5);
  EXPECT_NEAR(s.margin, 1 - max_modulus(mu), 1e-15);
  const Eigen::VectorXd simulated = sys.relaxed_state(2 * M_PI * 3000);
  EXPECT_LT((simulated - pr.state_at_zero(s.x)).norm(), 1e-7);
  std::printf(
      "wrong-start case: %d periods relaxed (defect %.3e), max |mu| = %.8f, margin %.6e +- %.2e, "
      "|start - 3000-period simulation| = %.2e\n",
      s.relaxation_periods, s.periodicity_defect, max_modulus(mu), s.margin, s.margin_error,
      (simulated - pr.state_at_zero(s.x)).norm());

  // What the old start (Newton from the 32-period state) found: the repelling orbit, certified unstable,
  // 6e-3 from the attracting one.
  const double p = s.p;
  const NewtonResult old = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(200), p), p);
  ASSERT_TRUE(old.converged);
  const Eigen::VectorXcd mu_old = pr.spectrum(old.x, p);
  EXPECT_NEAR(max_modulus(mu_old), 1.02397, 1e-5);
  const StabilityCertificate c = certify_solution(pr, old.x, p);
  EXPECT_EQ(c.stability, Stability::unstable);
  EXPECT_GT((pr.state_at_zero(old.x) - pr.state_at_zero(s.x)).norm(), 1e-3);
  std::printf("old start: max |mu| = %.8f (%s, margin %.6e +- %.2e)\n", max_modulus(mu_old),
              to_string(c.stability).c_str(), c.margin, c.margin_error);

  // The branch from the new start: every point stable (the attracting family over Lambda in [1.1, 1.3]).
  const SceneBranch r = continue_scene(spec);
  ASSERT_GT(r.branch.branch.points.size(), 5u);
  for (const BranchPoint& pt : r.branch.branch.points) {
    EXPECT_EQ(pt.stability, Stability::stable) << "Lambda = " << pt.p;
    EXPECT_LT(max_modulus(pt.spectrum), 1.0) << "Lambda = " << pt.p;
  }
}

// Near an attracting orbit the periodicity defect shrinks by the leading multiplier's modulus per period
// (a complex pair: on average), the relaxation's stopping rule in terms of the Floquet data: over 100
// periods (d_200 / d_100)^(1/100) = |mu| to 1e-3.
TEST(OrbitRelaxation, DefectShrinksByTheLeadingMultiplierPerPeriod) {
  const BranchSpec spec = test::wrong_start_spec();
  const StartPoint s = find_start(spec);
  ASSERT_TRUE(s.converged);
  const ReducedForcedSystem sys(spec.scene, P::Lambda);
  const PeriodicOrbitProblem pr(sys, spec.orbit);
  const OrbitRelaxation a = pr.relax(sys.relaxed_state(2 * M_PI * 300), s.p, 1e-300, 100);
  const OrbitRelaxation b = pr.relax(a.x, s.p, 1e-300, 100);
  EXPECT_EQ(a.periods, 100);
  EXPECT_FALSE(a.converged);
  EXPECT_TRUE(a.failure.empty());
  EXPECT_NEAR(std::pow(b.defect / a.defect, 0.01), max_modulus(pr.spectrum(s.x, s.p)), 1e-3);
  // Stops at the first period below tol: here at once (tol above the first defect).
  const OrbitRelaxation c = pr.relax(a.x, s.p, 1.0, 100);
  EXPECT_TRUE(c.converged);
  EXPECT_EQ(c.periods, 1);
}

// The in-plane ellipsoidal modal orbit (delta = 0 keeps every l >= 3 amplitude exactly 0, so the
// relaxation stays on it) is unstable to l = 3 at lambda = 5 (multiplier 695): refused unless allowed.
TEST(OrbitStart, AnUnstableOrbitIsRefusedUnlessAllowed) {
  Scene sc = test::fig2_in_plane(1.0);
  sc.L = 5;
  sc.model = ModelLevel::automatic;
  BranchSpec spec = test::spec_of(sc, ProblemKind::modal_orbit, P::lambda, 4.9, 5.1, Direction::both);
  spec.relax_T = 600;
  spec.engine.max_points = 3;
  const StartPoint s = find_start(spec);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_TRUE(s.refused);
  EXPECT_EQ(s.stability, Stability::unstable);
  EXPECT_FALSE(s.stable);
  EXPECT_EQ(s.n_unstable, 2);  // the l = 3 and l = 4 multipliers
  EXPECT_NE(s.message.find("unstable periodic orbit"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("--allow-unstable-start"), std::string::npos) << s.message;
  const SceneBranch refused = continue_scene(spec);
  EXPECT_TRUE(refused.branch.branch.points.empty());
  EXPECT_EQ(refused.branch.branch.status, ContinuationStatus::start_failed);
  EXPECT_EQ(refused.branch.branch.message, s.message);

  spec.allow_unstable_start = true;
  const SceneBranch r = continue_scene(spec);
  EXPECT_FALSE(r.start.refused);
  EXPECT_EQ(r.start.stability, Stability::unstable);
  EXPECT_NE(r.start.message.find("allowed"), std::string::npos) << r.start.message;
  ASSERT_GE(r.branch.branch.points.size(), 3u);
  for (const BranchPoint& pt : r.branch.branch.points) EXPECT_EQ(pt.stability, Stability::unstable);
}

// Equilibria: the modal kind starts on the ellipsoidal branch by design; past its first BP (C = 0.03617)
// that start is unstable: reported, certified, and continued.
TEST(EquilibriumStart, AnUnstableStartIsReportedAndContinued) {
  const StartPoint stable = find_start(test::modal_spec(6, 0.05));
  EXPECT_EQ(stable.stability, Stability::stable);
  EXPECT_TRUE(stable.message.empty()) << stable.message;

  BranchSpec spec = test::modal_spec(6, 0.015);
  spec.scene.parameters.C = 0.02;
  spec.engine.p_max = 0.03;
  const StartPoint s = find_start(spec);
  EXPECT_FALSE(s.refused);
  EXPECT_EQ(s.stability, Stability::unstable);
  EXPECT_GE(s.n_unstable, 1);
  EXPECT_LT(s.margin, -s.margin_error);
  EXPECT_NE(s.message.find("unstable equilibrium"), std::string::npos) << s.message;
  const SceneBranch r = continue_scene(spec);
  EXPECT_GT(r.branch.branch.points.size(), 3u);
  EXPECT_EQ(r.start.message, s.message);
}

TEST(StartSpec, ValidateNamesTheField) {
  auto field = [](BranchSpec spec) {
    try {
      spec.validate();
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return std::string();
  };
  BranchSpec spec = test::wrong_start_spec();
  EXPECT_EQ(field(spec), "");
  spec.relax_tol = 0;
  EXPECT_EQ(field(spec), "relax_tol");
  spec.relax_tol = NAN;
  EXPECT_EQ(field(spec), "relax_tol");
  spec = test::wrong_start_spec();
  spec.relax_max_periods = 0;
  EXPECT_EQ(field(spec), "relax_max_periods");
  spec = test::wrong_start_spec();
  spec.engine.certificate_refine_margin = -1;
  EXPECT_EQ(field(spec), "certificate_refine_margin");
}

}  // namespace
}  // namespace rbcstab
