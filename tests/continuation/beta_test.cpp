// beta (the rest shape's orientation) as a continuation parameter: the exact df/dbeta of the forced
// systems, the in-plane orbit continued down to the out-of-plane equilibrium (closed form), the
// mirror symmetry beta <-> pi - beta, the swinging <-> tumbling point in beta cross-checked by a
// continuation in Delta, and the equilibria's one-point domain in beta.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "continuation/fig2_fixture.hpp"
#include "continuation/periodic_quadrature.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

Scene fig2(double Delta, double beta = M_PI / 2) { return test::fig2_in_plane(Delta, beta); }

// The ladder identity against central differences of wigner_column itself. h = 1e-5: truncation
// h^2 |D'''| / 6 <= 1e-10 l^3 / 6 and rounding eps / h ~ 2e-11, so 1e-8 holds up to l = 6.
TEST(Beta, WignerColumnDerivativeMatchesDifferences) {
  const double h = 1e-5;
  for (int l = 2; l <= 6; ++l) {
    for (double beta : {0.1, 0.7, M_PI / 2, 2.2, 3.0}) {
      const std::vector<double> d = wigner_column_derivative(l, beta);
      const std::vector<double> p = wigner_column(l, beta + h), m = wigner_column(l, beta - h);
      for (std::size_t k = 0; k < d.size(); ++k)
        EXPECT_NEAR(d[k], (p[k] - m[k]) / (2 * h), 1e-8) << "l = " << l << " beta = " << beta << " m = " << int(k) - l;
    }
  }
  // Closed forms of Appendix A: D^(2)_{2,0} = (1/2) sqrt(3/2) sin^2, so its slope is sqrt(3/2) sin cos.
  const double b = 0.9;
  EXPECT_NEAR(wigner_column_derivative(2, b)[4], std::sqrt(1.5) * std::sin(b) * std::cos(b), 1e-15);
  EXPECT_NEAR(wigner_column_derivative(2, b)[2], -3 * std::sin(b) * std::cos(b), 1e-15);
}

// df/dbeta (exact: only the rest direction g(beta) moves) against ForcedSystem's central differences of
// the rhs in beta, reduced and modal, at states off and on the sphere and several times. 1e-7 relative:
// truncation ~h^2 with h ~ 6e-6 and rounding ~eps/h ~ 4e-11 (as for the other parameters).
TEST(Beta, ForcedSystemsDerivativeInBetaMatchesDifferences) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (double beta : {0.3, 0.7, 1.2, 2.5}) {
    const ReducedForcedSystem red(fig2(1.0, beta), ContinuationParameter::beta);
    EXPECT_EQ(red.start_parameter(), beta);
    Scene ms = fig2(1.0, beta);
    ms.L = 5;
    ms.delta = 1e-3;
    ms.model = ModelLevel::automatic;
    const ModalForcedSystem modal(total_area_scene(ms), ContinuationParameter::beta);
    for (double t : {0.0, 1.3, 4.0}) {
      for (int trial = 0; trial < 2; ++trial) {
        const Eigen::Vector3d y(u(gen), u(gen), u(gen));
        double a[3], f[3];
        red.parameter_derivative(t, std::span<const double>(y.data(), 3), beta, a);
        red.ForcedSystem::parameter_derivative(t, std::span<const double>(y.data(), 3), beta, f);
        const double scale = std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2]), 1e-3});
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], f[i], 1e-7 * scale) << "reduced beta = " << beta << " i = " << i;

        const Eigen::Index n = modal.dimension();
        const auto nn = static_cast<std::size_t>(n);
        Eigen::VectorXd x(n), am(n), dm(n);
        for (Eigen::Index i = 0; i < n; ++i) x[i] = u(gen);
        modal.parameter_derivative(t, std::span<const double>(x.data(), nn), beta, std::span<double>(am.data(), nn));
        modal.ForcedSystem::parameter_derivative(t, std::span<const double>(x.data(), nn), beta,
                                                 std::span<double>(dm.data(), nn));
        const double ds = std::max(1e-3, dm.cwiseAbs().maxCoeff());
        for (Eigen::Index i = 0; i < n; ++i)
          EXPECT_NEAR(am[i], dm[i], 1e-7 * ds) << "modal beta = " << beta << " i = " << i;
      }
    }
  }
}

// The forcing vanishes as z0 ~ sin^2 beta: at beta = 0 the orbit is the out-of-plane equilibrium.
// The reduced system at beta and pi - beta is the same (D^(2)_{m,0}(pi - beta) = (-1)^m D^(2)_{m,0}(beta)
// and the reduced model has no m = 1 content).
struct BetaRun {
  Scene scene = fig2(1.0);
  ReducedForcedSystem sys{scene, ContinuationParameter::beta};
  PeriodicOrbitProblem pr{sys};
  Eigen::VectorXd start;
  BetaRun() {
    const double p0 = sys.start_parameter();
    const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(300), p0), p0);
    EXPECT_TRUE(nr.converged);
    start = nr.x;
  }
  Branch run(Direction d, double lo, double hi) const {
    ContinuationOptions o;
    o.direction = d;
    o.p_min = lo;
    o.p_max = hi;
    o.events.push_back(pr.transition_event());
    return continue_branch(pr, start, sys.start_parameter(), o);
  }
};

// Largest deviation of the orbit's segment states from the constant state e.
double deviation(const Eigen::VectorXd& X, const Eigen::Vector3d& e) {
  double d = 0;
  for (Eigen::Index j = 0; j < X.size() / 3; ++j) d = std::max(d, (X.segment<3>(3 * j) - e).cwiseAbs().maxCoeff());
  return d;
}

TEST(Beta, InPlaneOrbitCollapsesOntoTheOutOfPlaneEquilibriumAtBetaZero) {
  const BetaRun r;
  const Branch b = r.run(Direction::backward, 0.0, M_PI / 2);
  ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
  ASSERT_EQ(b.points.back().p, 0.0) << "the engine lands on the bound exactly";
  // The closed form (analysis/steady_states.hpp): z = r e^{-i Psi}, w = sqrt(1 - r^2).
  const OutOfPlaneEquilibrium c = out_of_plane_equilibrium(r.scene.parameters);
  const Eigen::Vector3d e(c.r * std::cos(c.Psi), -c.r * std::sin(c.Psi), c.w);
  // At beta = 0 exactly the forcing is zero: every segment state is the equilibrium, to the shooting
  // Newton's tolerance (1e-12 on the states) and the integration's (rtol 1e-12) -> 1e-10.
  EXPECT_LT(deviation(b.points.back().x, e), 1e-10);
  EXPECT_TRUE(b.points.back().stable);
  // Near beta = 0 the orbit is the equilibrium plus the linear response to the forcing's change
  // kappa P dg(t), P = I - e e^T, dg(t) = Re(z0(beta) (1, -i, 0) e^{it}) with z0 = -sqrt(2) D_{2,0} / |u| ~ beta^2
  // (w0 moves only at O(beta^4)): x(t) = e + Re(R e^{it}), R = (iI - J)^{-1} kappa P (1, -i, 0) z0, J the
  // (time-independent) Jacobian at the equilibrium. Its neglected terms are O(beta^2) relative (the
  // response's square and w0's shift), so 1e-3 relative at beta = 0.01, 0.02 (measured: see the print);
  // the distance scales as beta^2 (ratio 4 for beta halved, to O(beta^2) relative: +-0.01).
  Eigen::MatrixXd J;
  r.sys.jacobian(0.0, std::span<const double>(e.data(), 3), 0.0, J);
  const double kappa = r.scene.parameters.inv_Lambda_S();
  double d[2];
  const double betas[2] = {0.02, 0.01};
  for (int k = 0; k < 2; ++k) {
    const NewtonResult nr = solve_fixed_parameter(r.pr, b.points.back().x, betas[k]);
    ASSERT_TRUE(nr.converged);
    d[k] = deviation(nr.x, e);
    const std::vector<double> D = wigner_column(2, betas[k]);
    const double z0 = -std::sqrt(2.0) * D[4] / std::hypot(std::sqrt(2.0) * D[4], D[2]);
    const Eigen::Vector3cd g(z0, std::complex<double>(0, -z0), 0);
    const Eigen::Matrix3cd P = (Eigen::Matrix3d::Identity() - e * e.transpose()).cast<std::complex<double>>();
    const Eigen::Matrix3cd A =
        std::complex<double>(0, 1) * Eigen::Matrix3cd::Identity() - J.cast<std::complex<double>>();
    const Eigen::Vector3cd R = A.partialPivLu().solve(kappa * (P * g));
    double err = 0;
    for (int j = 0; j < r.pr.segments(); ++j) {
      const Eigen::Vector3d lin = e + (R * std::polar(1.0, kTwoPi * j / r.pr.segments())).real();
      err = std::max(err, (nr.x.segment<3>(3 * j) - lin).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(err, 1e-3 * R.cwiseAbs().maxCoeff()) << "beta = " << betas[k];
    std::printf("beta = %.2f: |orbit - equilibrium| = %.4e, linear response |R| = %.4e, misfit %.2e\n", betas[k], d[k],
                R.cwiseAbs().maxCoeff(), err);
  }
  EXPECT_NEAR(d[0] / d[1], 4.0, 0.01) << d[0] << " " << d[1];
  EXPECT_GT(d[1], 0.0);
}

TEST(Beta, BranchOnUpperHalfMirrorsLowerHalfAndSwingTumblePointsToo) {
  const BetaRun r;
  const Branch lo = r.run(Direction::backward, 0.0, M_PI / 2);
  const Branch hi = r.run(Direction::forward, M_PI / 2, M_PI);
  ASSERT_EQ(lo.status, ContinuationStatus::completed) << lo.message;
  ASSERT_EQ(hi.status, ContinuationStatus::completed) << hi.message;
  EXPECT_EQ(hi.points.back().p, M_PI);
  // Each point of the upper half solves the problem at the mirrored beta: Newton from it at pi - beta
  // stays put (1e-10: Newton's tolerance 1e-12 and the sin(pi - beta) rounding ~1e-16 amplified by the
  // O(1) sensitivity of the orbit).
  for (const auto& pt : hi.points) {
    const NewtonResult nr = solve_fixed_parameter(r.pr, pt.x, M_PI - pt.p);
    ASSERT_TRUE(nr.converged) << pt.p;
    EXPECT_LT((nr.x - pt.x).cwiseAbs().maxCoeff(), 1e-10) << "beta = " << pt.p;
  }
  // The lower half's end at beta = 0 and the upper half's at pi are the same equilibrium.
  EXPECT_LT((lo.points.back().x - hi.points.back().x).cwiseAbs().maxCoeff(), 1e-10);
  // Exactly one swinging <-> tumbling UZ on each half, mirrored (location tolerance 1e-11 -> 1e-9).
  auto uz = [](const Branch& b) {
    std::vector<double> v;
    for (const auto& sp : b.special_points) {
      EXPECT_EQ(sp.type, SpecialPointType::UZ) << "no bifurcation along beta: " << sp.name << " at " << sp.p;
      if (sp.type == SpecialPointType::UZ) {
        EXPECT_EQ(sp.status, LocationStatus::located);
        v.push_back(sp.p);
      }
    }
    return v;
  };
  const std::vector<double> ulo = uz(lo), uhi = uz(hi);
  ASSERT_EQ(ulo.size(), 1u);
  ASSERT_EQ(uhi.size(), 1u);
  EXPECT_NEAR(uhi[0], M_PI - ulo[0], 1e-9);
  std::printf("swing <-> tumble in beta (Fig. 2 in plane, Delta = 1): beta = %.12f and %.12f\n", ulo[0], uhi[0]);
  // Every point is stable (the multipliers stay inside the unit circle, as along Delta).
  for (const auto& pt : lo.points) EXPECT_TRUE(pt.stable) << pt.p;
}

// The UZ found in beta is the UZ found in Delta at that beta: two continuations in different
// parameters through the same point. The transition function r_min is refined to the integration
// tolerance (~1e-12), and both locations to 1e-11 in (x, p), so the two agree to ~1e-8 in Delta.
TEST(Beta, SwingTumblePointInBetaAgreesWithTheOneInDelta) {
  const BetaRun r;
  const Branch lo = r.run(Direction::backward, 0.0, M_PI / 2);
  const SpecialPoint* uz = find_special_point(lo, SpecialPointType::UZ);
  ASSERT_NE(uz, nullptr);
  EXPECT_LT(r.pr.summary(uz->x, uz->p).r_min, 1e-7);
  // The same scene at beta = beta_UZ, continued in Delta through Delta = 1 from the UZ's orbit.
  const Scene at = with_parameter(r.scene, ContinuationParameter::beta, uz->p);
  const ReducedForcedSystem sys(at, ContinuationParameter::Delta);
  const PeriodicOrbitProblem pr(sys);
  ContinuationOptions o;
  o.direction = Direction::forward;
  o.p_min = 0.8;
  o.p_max = 1.2;
  o.events.push_back(pr.transition_event());
  // Start a little below Delta = 1 (on the swinging side) so the crossing is inside the run.
  const NewtonResult s = solve_fixed_parameter(pr, uz->x, 0.9);
  ASSERT_TRUE(s.converged);
  const Branch b = continue_branch(pr, s.x, 0.9, o);
  std::vector<double> found;
  for (const auto& sp : b.special_points)
    if (sp.type == SpecialPointType::UZ) found.push_back(sp.p);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0], 1.0, 1e-8);
  std::printf("UZ at beta = %.12f (Delta = 1); continued in Delta at that beta: Delta = %.12f\n", uz->p, found[0]);
}

// Equilibria: beta is a valid parameter, but a pulling rest shape (Delta0 > 0, C finite) leaves them
// only beta = 0; without elastic memory (Delta0 = 0 or C = inf) the branch is constant in beta.
TEST(Beta, EquilibriaEndAtBetaZeroWhenTheRestShapePullsAndAreConstantOtherwise) {
  ContinuationOptions o;
  o.direction = Direction::forward;
  o.p_min = 0;
  o.p_max = M_PI;
  {
    const Scene s = fig2(1.0, 0.0);
    const ReducedEquilibriumProblem pr(s, ContinuationParameter::beta);
    const Branch b = continue_branch(pr, pr.relaxed_state(300), 0.0, o);
    EXPECT_EQ(b.status, ContinuationStatus::outside_domain);
    EXPECT_NE(b.message.find("beta"), std::string::npos) << b.message;
    ASSERT_EQ(b.points.size(), 1u);
    EXPECT_TRUE(b.points[0].x.allFinite());
    Scene m = s;
    m.L = 4;
    m.model = ModelLevel::automatic;
    const ModalEquilibriumProblem mp(m, ContinuationParameter::beta);
    const Branch mb = continue_branch(mp, mp.ellipsoidal_state(0.0), 0.0, o);
    EXPECT_EQ(mb.status, ContinuationStatus::outside_domain);
    EXPECT_NE(mb.message.find("beta"), std::string::npos) << mb.message;
    ASSERT_EQ(mb.points.size(), 1u);
    const FullEquilibriumProblem fp(m, ContinuationParameter::beta);
    const Branch fb = continue_branch(fp, fp.ellipsoidal_state(0.0), 0.0, o);
    EXPECT_EQ(fb.status, ContinuationStatus::outside_domain);
    EXPECT_NE(fb.message.find("beta"), std::string::npos) << fb.message;
    ASSERT_EQ(fb.points.size(), 1u);
    // A forced scene is refused up front, naming beta.
    EXPECT_THROW(ReducedEquilibriumProblem(fig2(1.0, 0.3), ContinuationParameter::beta), InvalidArgument);
    // beta outside [0, pi] names beta.
    try {
      with_parameter(s, ContinuationParameter::beta, -0.1);
      ADD_FAILURE() << "no throw";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "beta");
    }
  }
  for (int variant = 0; variant < 2; ++variant) {
    Scene s = fig2(1.0, 0.0);
    if (variant == 0)
      s.parameters.Delta0 = 0;
    else
      s.parameters.C = INFINITY;
    const ReducedEquilibriumProblem pr(s, ContinuationParameter::beta);
    const Branch b = continue_branch(pr, pr.relaxed_state(300), 0.0, o);
    EXPECT_EQ(b.status, ContinuationStatus::completed) << b.message;
    EXPECT_EQ(b.points.back().p, M_PI);
    if (variant == 1) {
      // The full level too (C = inf: no rest-shape term at all): every point is the start's closed form
      // (ellipsoidal_state(p) itself picks w's sign from the rest shape's orientation at p, which
      // flips at cos^2 beta = 1/3 — immaterial at C = inf, where w -> -w is a symmetry).
      Scene m = s;
      m.L = 3;
      m.model = ModelLevel::automatic;
      const FullEquilibriumProblem fp(m, ContinuationParameter::beta);
      const Branch fb = continue_branch(fp, fp.ellipsoidal_state(0.0), 0.0, o);
      EXPECT_EQ(fb.status, ContinuationStatus::completed) << fb.message;
      EXPECT_EQ(fb.points.back().p, M_PI);
      for (const auto& pt : fb.points)
        EXPECT_LT((pt.x - fp.ellipsoidal_state(0.0)).cwiseAbs().maxCoeff(), 1e-10) << pt.p;
    }
    // The closed form does not know beta: every point is it (Newton tolerance 1e-12 -> 1e-10).
    const OutOfPlaneEquilibrium c = out_of_plane_equilibrium(s.parameters);
    for (const auto& pt : b.points) {
      const PolarState ps = polar(pt.x);
      EXPECT_NEAR(ps.r, c.r, 1e-10) << pt.p;
      EXPECT_NEAR(std::remainder(ps.Psi - c.Psi, kTwoPi), 0.0, 1e-10) << pt.p;
    }
  }
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {

// Why the reduced in-plane orbits have no NS (nor LPC, PD) point: on the unit sphere the field is
// f = P_y c(t) + (rotation), c = -e_y/Lambda + kappa g(t), i.e. the gradient of the l = 1 harmonic c.y
// plus a Killing field: a conformal field, so the period map is a Moebius transformation and its
// derivative at a fixed point is a complex number k: the nontrivial multipliers are k and conj(k)
// (equal moduli), and div_S f = -2 c.y = 2 mu gives |k|^2 = exp(2 int_0^{2 pi} mu dt). A multiplier on
// the unit circle therefore needs int mu dt = 0 (an elliptic period map, every orbit neutral). Checked
// here against mu(t) = Upsilon_2 integrated along the orbit by ReducedModel directly (not through the
// shooting code): 1e-9 relative (periodic trapezoid on 512 samples, rtol 1e-13 integration).
TEST(Beta, ReducedMultipliersAreAConformalPairWithModulusExpOfTheMeanGrowthRate) {
  for (double beta : {M_PI / 2, 0.9, 0.4}) {
    for (double C : {0.04, 1.0}) {
      Scene s = fig2(1.0, beta);
      s.parameters.C = C;
      const ReducedForcedSystem sys(s, ContinuationParameter::beta);
      const PeriodicOrbitProblem pr(sys);
      const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(300), beta), beta);
      ASSERT_TRUE(nr.converged);
      const Eigen::VectorXcd mu = pr.spectrum(nr.x, beta);
      ASSERT_EQ(mu.size(), 2);
      EXPECT_NEAR(std::abs(mu[0]), std::abs(mu[1]), 1e-9 * std::abs(mu[0]));
      const ReducedModel& m = sys.model(beta);
      const Eigen::Vector3d y0 = nr.x.head<3>();
      const double integral = test::period_integral(m, std::span<const double>(y0.data(), 3),
                                                    [&](double t, std::span<const double> y) { return m.mu(t, y); });
      EXPECT_NEAR(std::abs(mu[0]), std::exp(integral), 1e-9 * std::exp(integral)) << "beta " << beta << " C " << C;
      EXPECT_LT(integral, 0.0);
      std::printf("beta = %.3f, C = %.2f: |k| = %.12e, exp(int mu dt) = %.12e\n", beta, C, std::abs(mu[0]),
                  std::exp(integral));
    }
  }
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {

// ModalForcedSystem2 (for two-parameter cycle curves of the modal model) is
// ModalForcedSystem at p2, bit for bit (the same computation through the scene), here with beta as
// the second parameter, and its d/dp1 matches central differences of its rhs (h = 1e-5: truncation
// ~h^2 f''' ~ 1e-10, rounding eps/h ~ 1e-11, so 1e-8 relative).
TEST(ModalForcedSystem2, IsTheOneParameterSystemAtP2WithBetaSecond) {
  Scene s = fig2(1.0, M_PI / 2);
  s.L = 5;
  s.delta = 1e-3;
  s.model = ModelLevel::automatic;
  const Scene total = total_area_scene(s);
  const ModalForcedSystem2 sys2(total, ContinuationParameter::lambda, ContinuationParameter::beta);
  EXPECT_EQ(sys2.start_parameter2(), M_PI / 2);
  EXPECT_EQ(sys2.dimension(), 8);
  Scene t = total;
  t.beta = 0.8;
  const ModalForcedSystem sys1(t, ContinuationParameter::lambda);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> x(8), f1(8), f2(8), fp(8), fa(8), fb(8);
  for (double time : {0.0, 1.3, 4.0}) {
    for (double& v : x) v = u(gen);
    sys1.rhs(time, x, 4.5, f1);
    sys2.rhs(time, x, 4.5, 0.8, f2);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(f1[i], f2[i]) << i;
    sys2.parameter_derivative(time, x, 4.5, 0.8, fp);
    const double h = 1e-5;
    sys2.rhs(time, x, 4.5 + h, 0.8, fa);
    sys2.rhs(time, x, 4.5 - h, 0.8, fb);
    double scale = 1;
    for (std::size_t i = 0; i < 8; ++i) scale = std::max(scale, std::abs(fa[i]));
    for (std::size_t i = 0; i < 8; ++i) EXPECT_NEAR(fp[i], (fa[i] - fb[i]) / (2 * h), 1e-8 * scale) << i;
  }
  EXPECT_TRUE(sys2.conserves_norm());
  EXPECT_EQ(sys2.name1(), "lambda");
  EXPECT_EQ(sys2.name2(), "beta");
  // beta outside [0, pi] as the second parameter names beta.
  try {
    sys2.rhs(0.0, x, 4.5, 3.5, f2);
    ADD_FAILURE() << "no throw";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "beta");
  }
}

}  // namespace
}  // namespace rbcstab
