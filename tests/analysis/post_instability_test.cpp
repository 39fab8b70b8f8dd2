// Post-instability Delta~2: Eq. rss_postinst and Eq. ss re-derived, the root selection, exactness of the integer
// variant as a steady state of the modal model, and both variants against long simulations (agreement measured).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "rbcstab/analysis/post_instability.hpp"
#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

Parameters fig6(double lambda, double B = 2, double C = 0.04) {
  Parameters p;  // Delta = 1, Delta0 = 0.01
  p.lambda = lambda;
  p.B = B;
  p.C = C;
  return p;
}

// Eq. rss_postinst as printed: K = 16 (9C - 6 sqrt(CB) + B)/((23 lambda + 32) C B), Psi~ = arctan K,
// r~ = (K^2 + 1)^(-1/2) / Lambda~.
TEST(PostInstability, PrintedRssPostinstIsTheZSteadyState) {
  for (double lambda : {1.0, 5.0})
    for (double B : {1.0, 2.0, 10.0}) {
      const Parameters p = fig6(lambda, B);
      const PostInstability post = post_instability(p, 10);
      const Delta2Prediction& d = post.continuous;
      const double C = p.C;
      const double K = 16 * (9 * C - 6 * std::sqrt(C * B) + B) / ((23 * lambda + 32) * C * B);
      EXPECT_NEAR(K, -d.mu_tilde, 1e-13 * std::abs(K));
      EXPECT_NEAR(d.Psi_tilde.value, std::atan(K), 1e-15);
      if (!d.Delta2_tilde.valid()) {  // e.g. B = 1 (alpha = 25): Delta~2 > Delta, no post-instability state
        EXPECT_FALSE(d.Delta2_tilde.reason.empty());
        continue;
      }
      const double Lambda_t =
          std::sqrt(d.Delta2_tilde.value) * (23 * lambda + 32) / (8 * std::sqrt(30 * std::numbers::pi));
      EXPECT_NEAR(d.r_tilde.value, 1 / (std::sqrt(K * K + 1) * Lambda_t), 1e-14);
      // z~ = r~ e^{-i Psi~} is the fixed point of z' = (i + mu~) z - i / Lambda~ (Eq. ssr with r0 = 0).
      const std::complex<double> z = std::polar(d.r_tilde.value, -d.Psi_tilde.value);
      const std::complex<double> I(0, 1);
      EXPECT_LT(std::abs((I + d.mu_tilde) * z - I / Lambda_t), 1e-14);
    }
}

// The quadratic's roots are c (w~ = 0) and c + K2^2; the kept root satisfies the f_{2,0} balance mu~ w~ = -kappa~ w0.
TEST(PostInstability, RootSelection) {
  for (double lambda : {1.0, 5.0})
    for (double C : {0.01, 0.04}) {
      const Parameters p = fig6(lambda, 2, C);
      const Delta2Prediction d = post_instability(p, 10).integer_mode;
      ASSERT_TRUE(d.Delta2_tilde.valid()) << d.Delta2_tilde.reason;
      EXPECT_NEAR(d.K1, d.c, 1e-14 * d.c);  // derived identity (docs/theory.md)
      EXPECT_NEAR(d.roots[0], d.c, 1e-12 * d.c);
      EXPECT_NEAR(d.roots[1], d.c + d.K2 * d.K2, 1e-12 * d.roots[1]);
      EXPECT_EQ(d.Delta2_tilde.value, d.roots[1]);
      const double D = d.Delta2_tilde.value;
      const double w = std::sqrt(1 - d.r_tilde.value * d.r_tilde.value);
      const double kappa = 16 * std::sqrt(p.Delta0 / D) / (d_lambda_l(p.lambda, 2) * p.C);
      EXPECT_NEAR(d.mu_tilde * w, -kappa, 1e-12 * kappa);
    }
}

// The printed Eq. ss (with the Gammas of the integer mode) evaluated at the selected state returns Delta~2.
TEST(PostInstability, PrintedEqSsHolds) {
  const Parameters p = fig6(5);
  const PostInstability post = post_instability(p, 10);
  const Delta2Prediction& d = post.integer_mode;
  const int l = post.surviving_mode;
  const double a = p.alpha(), lam = p.lambda;
  const double G12 = Gamma1(lam, 2), G22 = Gamma2(lam, 2), G32 = Gamma3(lam, 2);
  const double G1l = Gamma1(lam, l), G2l = Gamma2(lam, l), G3l = Gamma3(lam, l);
  const double prefactor = 2 * G2l / (G22 * G1l - G2l * G12 + a * G22 * G3l - a * G2l * G32);
  const double D = d.Delta2_tilde.value;
  // Re sum_m S_{2,m} conj(f~_{2,m}) with f~ of Eq. subs_ss and g (out of plane): g_{2,0} = -sqrt(Delta0/2).
  const std::complex<double> f22 = std::sqrt(D) / 2 * std::polar(d.r_tilde.value, -d.Psi_tilde.value);
  const double f20 = -std::sqrt(D / 2 * (1 - d.r_tilde.value * d.r_tilde.value));
  const double g20 = -std::sqrt(p.Delta0 / 2);
  const std::complex<double> S22 = shear_drive(lam, 2, 2);
  const double S20 = -G32 / p.C * g20;
  const double sum = S20 * f20 + 2 * (S22 * std::conj(f22)).real();
  EXPECT_NEAR(prefactor * p.B * sum, D, 1e-12 * D);
}

// The integer variant is an exact steady state of the modal model holding l = 2 and l_s.
TEST(PostInstability, IntegerVariantIsAModalSteadyState) {
  for (double lambda : {1.0, 5.0}) {
    Scene s;
    s.parameters = fig6(lambda);
    const PostInstability post = post_instability(s.parameters, s.L);
    const Delta2Prediction& d = post.integer_mode;
    s.delta = 0;
    s.delta_l = {{post.surviving_mode, 1e-3}};
    s.beta = 0;
    const ModalModel m(s.parameters, initial_state(s));
    ASSERT_EQ(m.active_modes(), std::vector<int>{post.surviving_mode});
    const double D = d.Delta2_tilde.value;
    const std::complex<double> f22 = std::sqrt(D) / 2 * std::polar(d.r_tilde.value, -d.Psi_tilde.value);
    const double f20 = -std::sqrt(D / 2 * (1 - d.r_tilde.value * d.r_tilde.value));
    const std::vector<double> y = {f20, 0, 0, f22.real(), f22.imag(), std::log(s.parameters.Delta - D)};
    std::vector<double> f(y.size());
    m.rhs(0, y, f);
    for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i], 0, 1e-12) << lambda << " component " << i;
    EXPECT_NEAR(m.sigma(0, y), d.sigma_s, 1e-11 * std::abs(d.sigma_s));
  }
}

// Both variants against the simulated long-time Delta-bar_2 of the paper's Fig. 6 scenes (T = 500, tail mean).
TEST(PostInstability, AgainstSimulation) {
  for (double lambda : {1.0, 5.0})
    for (double beta : {1e-3, std::numbers::pi / 2}) {
      Scene s;
      s.parameters = fig6(lambda);
      s.beta = beta;
      s.T = 1000;
      SimulationOptions so;
      so.record_trajectory = false;
      so.tail_window = 100;
      const SimulationResult r = simulate(s, so);
      ASSERT_EQ(r.status, IntegrationStatus::success);
      const PostInstability post = post_instability(s.parameters, s.L, beta < 0.1 ? 0.0 : std::sqrt(3.0) / 2);
      const PostInstability post0 = post_instability(s.parameters, s.L, 0.0);  // out-of-plane g for comparison
      const double bar = r.Delta_tail_mean[0];
      const double e_int = post.integer_mode.Delta2_tilde.value / bar - 1;
      const double e_cont = post.continuous.Delta2_tilde.value / bar - 1;
      std::printf(
          "lambda %g beta %g: Delta-bar_2 %.6g, integer (l = %d) %.6g (%+.3g), continuous (l_* = %.3f) %.6g "
          "(%+.3g), l_Delta %d\n",
          lambda, beta, bar, post.surviving_mode, post.integer_mode.Delta2_tilde.value, e_int, post.continuous.l,
          post.continuous.Delta2_tilde.value, e_cont, r.l_Delta);
      if (beta > 0.1)
        std::printf("    in plane with the out-of-plane g (w0 = 1): integer %+.3g, continuous %+.3g\n",
                    post0.integer_mode.Delta2_tilde.value / bar - 1, post0.continuous.Delta2_tilde.value / bar - 1);
      // Measured (docs/theory.md): OP integer 1e-9 (an exact steady state, reached to the tail's precision),
      // OP continuous -4.5 % / -6.0 %; IP with the out-of-plane g: integer +1.2 % / +2.4 %, continuous -4.9 % / -2.2 %.
      // Bounds keep those measurements from regressing silently.
      if (beta < 0.1) {
        EXPECT_LT(std::abs(e_int), 1e-6);
        EXPECT_LT(std::abs(e_cont), 0.08);
      } else {
        EXPECT_LT(std::abs(post0.integer_mode.Delta2_tilde.value / bar - 1), 0.04);
        EXPECT_LT(std::abs(post0.continuous.Delta2_tilde.value / bar - 1), 0.07);
      }
    }
}

TEST(PostInstability, DomainEdges) {
  // alpha = 9: Upsilon_2(sigma_*) = 0, no steady state, explicit reason.
  const Delta2Prediction d = post_instability_Delta2(fig6(5, 0.36, 0.04), sigma_star(9.0));
  EXPECT_FALSE(d.Delta2_tilde.valid());
  EXPECT_FALSE(d.Delta2_tilde.reason.empty());
  // Delta0 = 0: K2 = 0, a double root at c, still finite.
  Parameters p = fig6(5);
  p.Delta0 = 0;
  const PostInstability post = post_instability(p, 10);
  EXPECT_FALSE(std::isnan(post.integer_mode.Delta2_tilde.value));
}

}  // namespace
}  // namespace rbcstab
