// Stability certificates (continuation.hpp certify, problem.hpp certified_eigenvalues): the margin of every
// branch point and special point against independent oracles, with the measured ratio of the actual error
// to the estimate: matrices with exactly known eigenvalues, the reduced out-of-plane equilibrium's
// closed-form eigenvalues, the modal ellipsoidal branch's spectrum (Upsilon_l(sigma) in closed form),
// the in-plane orbit's complex pair against Liouville's formula and the ellipsoidal modal orbit's
// multipliers exp(2 pi Upsilon_l(sigma_bar)); points located on the stability boundary are uncertain.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "continuation/ellipsoidal_orbit_bp_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/periodic_quadrature.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "continuation/wrong_start_fixture.hpp"
#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Worst ratio of actual error to estimate over a run (printed for docs/continuation.md).
struct Ratio {
  double worst = 0, actual = 0, estimate = 0;
  void add(double a, double e) {
    if (a / e > worst) worst = a / e, actual = a, estimate = e;
  }
};

// ---- the bound itself ----

// Block upper-triangular matrices, permuted: their eigenvalues are the diagonal blocks' exactly (1 x 1:
// the entry; 2 x 2 [a b; -b a]: a +- ib), and the matrix is exact in floating point, so every computed
// eigenvalue must lie within its bound of the exact one (eta = 0: only the solver's backward error).
TEST(CertifiedEigenvalues, BoundsHoldWhereTheEigenvaluesAreKnownExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Ratio ratio;
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 3 + trial % 6;
    const double coupling = trial < 10 ? 0.3 : 3.0;  // the second half is strongly non-normal
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, n);
    std::vector<std::complex<double>> exact;
    for (int i = 0; i < n;) {
      if (i + 1 < n && trial % 2 == 0) {
        const double a = u(rng), b = 0.5 + std::abs(u(rng));
        T(i, i) = T(i + 1, i + 1) = a;
        T(i, i + 1) = b;
        T(i + 1, i) = -b;
        exact.push_back({a, b});
        exact.push_back({a, -b});
        i += 2;
      } else {
        T(i, i) = u(rng) + 2.0 * i;  // well separated
        exact.push_back(T(i, i));
        ++i;
      }
    }
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (T(j, i) == 0 && T(i, j) == 0) T(i, j) = coupling * u(rng);
    Eigen::PermutationMatrix<Eigen::Dynamic> perm(n);
    perm.setIdentity();
    std::shuffle(perm.indices().data(), perm.indices().data() + n, rng);
    const Eigen::MatrixXd A = perm * T * perm.transpose();  // exact: a permutation of entries
    const CertifiedSpectrum c = certified_eigenvalues(A, 0.0);
    EXPECT_TRUE(c.values == Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues()) << "bit for bit";
    for (Eigen::Index i = 0; i < c.values.size(); ++i) {
      double d = 1e300;
      for (const auto& e : exact) d = std::min(d, std::abs(c.values[i] - e));
      EXPECT_LE(d, c.errors[i]) << "trial " << trial << " value " << c.values[i];
      EXPECT_LT(c.errors[i], 1e-11) << "trial " << trial;  // informative, not just true
      ratio.add(d, c.errors[i]);
    }
  }
  std::printf("exact matrices: worst actual/estimate %.3g (%.3g / %.3g)\n", ratio.worst, ratio.actual, ratio.estimate);
}

// A Jordan block has no first-order bound: its eigenvalue is uncertain however small the residual.
TEST(CertifiedEigenvalues, DefectiveEigenvaluesAreUncertain) {
  Eigen::MatrixXd J(2, 2);
  J << -1e-3, 1, 0, -1e-3;
  const CertifiedSpectrum c = certified_eigenvalues(J, 0.0);
  const StabilityCertificate s = certify(c, StabilityKind::eigenvalues);
  EXPECT_EQ(s.stability, Stability::uncertain);
  EXPECT_GT(s.margin_error, 1e-3);
}

TEST(StabilityCertificate, LabelsFromTheMarginAndItsError) {
  auto spectrum = [](std::vector<std::complex<double>> v, std::vector<double> e) {
    CertifiedSpectrum c;
    c.values = Eigen::Map<Eigen::VectorXcd>(v.data(), static_cast<Eigen::Index>(v.size()));
    c.errors = Eigen::Map<Eigen::VectorXd>(e.data(), static_cast<Eigen::Index>(e.size()));
    return c;
  };
  StabilityCertificate s = certify(spectrum({-1.0, {-0.5, 2.0}}, {1e-12, 1e-12}), StabilityKind::eigenvalues);
  EXPECT_EQ(s.stability, Stability::stable);
  EXPECT_DOUBLE_EQ(s.margin, 0.5);
  EXPECT_NEAR(s.margin_error, 1e-12, 1e-16);
  EXPECT_EQ(s.uncertain_because, CertificateTerm::none);
  s = certify(spectrum({-1.0, 1e-13}, {1e-12, 1e-12}), StabilityKind::eigenvalues);
  EXPECT_EQ(s.stability, Stability::uncertain);
  EXPECT_EQ(s.uncertain_because, CertificateTerm::spectral_error);
  s = certify(spectrum({-1.0, 2e-12}, {1e-12, 1e-12}), StabilityKind::eigenvalues);
  EXPECT_EQ(s.stability, Stability::unstable);
  // A value whose error reaches past the critical one widens the margin's range.
  s = certify(spectrum({-0.1, -0.2}, {1e-3, 0.5}), StabilityKind::eigenvalues);
  EXPECT_DOUBLE_EQ(s.margin, 0.1);
  EXPECT_DOUBLE_EQ(s.margin_error, 0.4);  // -0.2 + 0.5 lies 0.4 above the critical -0.1
  EXPECT_EQ(s.stability, Stability::uncertain);
  s = certify(spectrum({-1.0}, {std::nan("")}), StabilityKind::eigenvalues);
  EXPECT_EQ(s.stability, Stability::uncertain);
  EXPECT_EQ(s.uncertain_because, CertificateTerm::error_bound);
  s = certify(spectrum({-1.0}, {INFINITY}), StabilityKind::eigenvalues);  // a defective value: no bound
  EXPECT_EQ(s.uncertain_because, CertificateTerm::error_bound);
  s = certify(spectrum({{NAN, 0}}, {1e-12}), StabilityKind::eigenvalues);
  EXPECT_EQ(s.uncertain_because, CertificateTerm::spectrum);
  s = certify(spectrum({{0.6, 0.6}, 0.3}, {1e-9, 1e-9}), StabilityKind::multipliers);
  EXPECT_NEAR(s.margin, 1 - std::sqrt(0.72), 1e-15);
  EXPECT_EQ(s.stability, Stability::stable);
  EXPECT_EQ(certify({}, StabilityKind::multipliers).stability, Stability::uncertain);
  EXPECT_EQ(to_string(Stability::uncertain), "uncertain");
}

// ---- equilibria ----

// The reduced out-of-plane branch in lambda: the two tangent-plane eigenvalues against the closed-form
// equilibrium's (analysis/steady_states: its own 2 x 2 trace/determinant at the exact state). Each margin
// is within its error of the oracle's, up to the oracle's own rounding (4 eps per unit).
TEST(Certificate, ReducedEquilibriumAgainstTheClosedFormEigenvalues) {
  const BranchSpec spec =
      test::spec_of(modal_fixtures::scene(0.08, 2), ProblemKind::equilibrium, P::lambda, 0.5, 3, Direction::both);
  const SceneBranch r = continue_scene(spec);
  const auto& pts = r.branch.branch.points;
  ASSERT_GT(pts.size(), 5u);
  Ratio ratio;
  for (const BranchPoint& pt : pts) {
    const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(with_parameter(spec.scene.parameters, P::lambda, pt.p));
    const double oracle = -std::max(eq.eigenvalues[0].real(), eq.eigenvalues[1].real());
    const double oracle_error = 4 * kEps * (1 + std::abs(eq.eigenvalues[0]));
    EXPECT_LE(std::abs(pt.margin - oracle), pt.margin_error + oracle_error) << "lambda = " << pt.p;
    EXPECT_LT(pt.margin_error, 1e-13) << "lambda = " << pt.p;
    EXPECT_EQ(pt.stability, Stability::stable);
    ratio.add(std::abs(pt.margin - oracle), pt.margin_error);
  }
  std::printf("reduced equilibria (%zu points): worst |margin - oracle| / margin_error %.3g (%.3g / %.3g)\n",
              pts.size(), ratio.worst, ratio.actual, ratio.estimate);
}

// The ellipsoidal modal branch in C (L = 6): its whole spectrum is closed form at the exact equilibrium:
// the reduced pair, Upsilon_2 +- i/2 (the m = 1 plane) and Upsilon_l(sigma) for l = 3..6. Margins agree
// with the oracle's within their errors; the labels change at the first BP (Upsilon_3 = 0, C = 0.036169),
// which is itself uncertain: its margin (~1e-12, the location's reach) is inside its error.
TEST(Certificate, ModalEquilibriumAgainstTheModalSpectrum) {
  const BranchSpec spec = test::modal_spec(6, 0.02);
  const SceneBranch r = continue_scene(spec);
  const Branch& b = r.branch.branch;
  ASSERT_GT(b.points.size(), 5u);
  const double C_bp = modal_fixtures::threshold_root(spec.scene.parameters, P::C, 3, 0.03, 0.04);
  Ratio ratio;
  for (const BranchPoint& pt : b.points) {
    const Parameters q = with_parameter(spec.scene.parameters, P::C, pt.p);
    const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(q);
    double top = std::max({eq.eigenvalues[0].real(), eq.eigenvalues[1].real(), eq.mu});
    for (int l = 3; l <= 6; ++l) top = std::max(top, Upsilon_l(q, l, eq.sigma_R));
    const double oracle_error = 16 * kEps * (1 + std::abs(top));
    EXPECT_LE(std::abs(pt.margin + top), pt.margin_error + oracle_error) << "C = " << pt.p;
    EXPECT_LT(pt.margin_error, 1e-11) << "C = " << pt.p;
    if (std::abs(pt.p - C_bp) > 1e-6) {
      EXPECT_EQ(pt.stability, pt.p > C_bp ? Stability::stable : Stability::unstable) << "C = " << pt.p;
    }
    ratio.add(std::abs(pt.margin + top), pt.margin_error);
  }
  std::printf("modal equilibria (%zu points): worst |margin - oracle| / margin_error %.3g (%.3g / %.3g)\n",
              b.points.size(), ratio.worst, ratio.actual, ratio.estimate);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  EXPECT_NEAR(bp->p, C_bp, 1e-9);
  EXPECT_EQ(bp->stability, Stability::uncertain);
  EXPECT_LE(std::abs(bp->margin), bp->margin_error);
  // Which quantity reaches the margin: a term of the error, never "no bound" at a regular spectrum.
  EXPECT_TRUE(bp->uncertain_because == CertificateTerm::spectral_error ||
              bp->uncertain_because == CertificateTerm::state_error ||
              bp->uncertain_because == CertificateTerm::location)
      << to_string(bp->uncertain_because);
  std::printf("modal BP at C = %.12f: margin %.3g +- %.3g (%s: %s)\n", bp->p, bp->margin, bp->margin_error,
              to_string(bp->stability).c_str(), to_string(bp->uncertain_because).c_str());
  // A branch point certified at the BP's parameter and state (certify_solution, the start's certificate):
  // deliberately near-neutral, it is uncertain too.
  const ModalEquilibriumProblem pr(with_parameter(spec.scene, P::C, bp->p), P::C);
  const StabilityCertificate at_bp = certify_solution(pr, bp->x, bp->p, spec.engine.newton_tol);
  EXPECT_EQ(at_bp.stability, Stability::uncertain) << at_bp.margin << " +- " << at_bp.margin_error;
  EXPECT_NE(at_bp.uncertain_because, CertificateTerm::none);
}

// ---- orbits ----

// The in-plane orbit's nontrivial multipliers form a complex pair on the wrong-start branch, so their
// common modulus is Liouville's: mu1 mu2 * 1 = det M = exp(int_0^{2 pi} tr J dt), |mu| = exp(int tr J / 2),
// integrated along the orbit by the periodic trapezoid rule (periodic_quadrature.hpp, independent of the
// variational equations). The cheap certificate (every point) and the refined one (certificate_refine_margin
// = inf) both hold; the refined one's cost is measured.
TEST(Certificate, InPlaneOrbitAgainstLiouville) {
  BranchSpec spec = test::wrong_start_spec();
  spec.orbit.segments = 4;
  for (bool refined : {false, true}) {
    spec.engine.certificate_refine_margin = refined ? std::numeric_limits<double>::infinity() : 1e-6;
    const auto t0 = std::chrono::steady_clock::now();
    const SceneBranch r = continue_scene(spec);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto& pts = r.branch.branch.points;
    ASSERT_GT(pts.size(), 5u);
    const ReducedForcedSystem sys(spec.scene, P::Lambda);
    const PeriodicOrbitProblem pr(sys, spec.orbit);
    Ratio ratio;
    for (const BranchPoint& pt : pts) {
      ASSERT_EQ(pt.spectrum.size(), 2);
      ASSERT_NE(pt.spectrum[0].imag(), 0.0) << "a complex pair";
      const Eigen::Vector3d y0 = pr.state_at_zero(pt.x);
      const ReducedModel& m = sys.model(pt.p);
      const double trace =
          test::period_integral(m, std::span<const double>(y0.data(), 3), [&](double t, std::span<const double> y) {
            Eigen::MatrixXd J;
            sys.jacobian(t, y, pt.p, J);
            return J.trace();
          });
      const double oracle = 1 - std::exp(trace / 2);
      EXPECT_LE(std::abs(pt.margin - oracle), pt.margin_error + 1e-13) << "Lambda = " << pt.p;
      EXPECT_LT(pt.margin_error, 1e-8) << "Lambda = " << pt.p;
      EXPECT_EQ(pt.stability, Stability::stable);
      ratio.add(std::abs(pt.margin - oracle), pt.margin_error);
    }
    std::printf(
        "in-plane orbit, %s certificates (%zu points, %.3f s): worst |margin - Liouville| / margin_error "
        "%.3g (%.3g / %.3g)\n",
        refined ? "refined" : "cheap", pts.size(), seconds, ratio.worst, ratio.actual, ratio.estimate);
  }
}

// The in-plane ellipsoidal orbit of the modal model (L = 4; delta = 0 keeps a_l = 0 and v~ = 0 exactly)
// continued in C past its symmetry-breaking BP: the a_l multipliers are exp(2 pi Upsilon_l(sigma_bar))
// (sigma_bar the period mean of sigma along the reduced orbit, by quadrature) and the v~ plane's
// exp(2 pi Upsilon_2(sigma_bar)) twice; where one of them is critical the margin agrees with the closed
// form within its error. The located BP (the l = 3 multiplier through 1) is uncertain.
TEST(Certificate, EllipsoidalModalOrbitAgainstTheClosedFormMultipliers) {
  Scene s = test::in_plane_modal(1, 2, 0.07, 4);
  s.delta = 0;
  BranchSpec spec = test::spec_of(s, ProblemKind::modal_orbit, P::C, 0.055, 0.07, Direction::backward);
  spec.orbit.segments = 2;
  spec.allow_unstable_start = true;
  spec.engine.initial_step = 0.002;
  spec.engine.max_step = 0.005;
  const SceneBranch r = continue_scene(spec);
  const Branch& b = r.branch.branch;
  ASSERT_GT(b.points.size(), 5u) << b.message;
  Ratio ratio;
  int compared = 0;
  for (const BranchPoint& pt : b.points) {
    const Scene at = with_parameter(r.problem_scene, P::C, pt.p);
    const ReducedForcedSystem red(at, P::C);
    const Eigen::Vector3d y0 = pt.x.head(3);
    const ReducedModel& m = red.model(pt.p);
    const double sigma_bar =
        test::period_integral(m, std::span<const double>(y0.data(), 3),
                              [&](double t, std::span<const double> y) { return m.sigma_from_mu(m.mu(t, y)); }) /
        kTwoPi;
    double top = 0;  // the largest closed-form multiplier
    for (int l = 2; l <= 4; ++l) top = std::max(top, std::exp(kTwoPi * Upsilon_l(at.parameters, l, sigma_bar)));
    const PeriodicOrbitProblem rp(red);
    const double reduced_top = rp.spectrum(rp.shooting_guess(y0, pt.p), pt.p).cwiseAbs().maxCoeff();
    if (top < reduced_top + 1e-3) continue;  // the critical multiplier is the reduced orbit's own
    ++compared;
    const double oracle = 1 - top;
    EXPECT_LE(std::abs(pt.margin - oracle), pt.margin_error + 1e-12) << "C = " << pt.p;
    EXPECT_LT(pt.margin_error, 1e-8) << "C = " << pt.p;
    ratio.add(std::abs(pt.margin - oracle), pt.margin_error);
  }
  EXPECT_GE(compared, 3);
  std::printf(
      "ellipsoidal modal orbit (%d of %zu points compared): worst |margin - closed form| / margin_error %.3g "
      "(%.3g / %.3g)\n",
      compared, b.points.size(), ratio.worst, ratio.actual, ratio.estimate);
  const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  EXPECT_EQ(bp->stability, Stability::uncertain);
  EXPECT_LE(std::abs(bp->margin), bp->margin_error);
  std::printf("ellipsoidal orbit BP at C = %.12f: margin %.3g +- %.3g (%s)\n", bp->p, bp->margin, bp->margin_error,
              to_string(bp->stability).c_str());
}

}  // namespace
}  // namespace rbcstab
