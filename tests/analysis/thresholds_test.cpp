// Thresholds of Sec. IV / Appendix D: closed forms against their defining equations solved numerically,
// against the model's own sigma (ReducedModel), and the printed-formula corrections.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

Parameters params(double lambda, double Delta, double Delta0, double B, double C) {
  Parameters p;
  p.lambda = lambda;
  p.Delta = Delta;
  p.Delta0 = Delta0;
  p.B = B;
  p.C = C;
  return p;
}

// Bisection on [a, b] for a sign change of f: an oracle independent of the closed forms.
double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int i = 0; i < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a)); ++i) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// The paper's captions give Lambda and S to one or two digits: tolerance = half a unit of the last digit.
TEST(Thresholds, FigureCaptionValues) {
  EXPECT_NEAR(params(5, 0.01, 0.01, 2, 0.04).Lambda(), 0.19, 0.005);  // Fig. 2
  EXPECT_NEAR(params(5, 1, 0.01, 2, 0.04).Lambda(), 1.9, 0.05);       // Fig. 2, Fig. 4b
  EXPECT_NEAR(params(1, 1, 0.01, 2, 0.04).Lambda(), 0.7, 0.05);       // Fig. 4a
  EXPECT_NEAR(params(5, 0.1, 0.01, 2, 0.04).Lambda(), 0.6, 0.05);     // Fig. 4c
  EXPECT_NEAR(params(5, 1, 0.01, 2, 0.04).S(), 2, 0.5);               // Fig. 2: S ~ 2 at C = 0.04, Delta0 = 0.01
}

// sigma^c as a function of continuous l is maximal at l_* and equals sigma_* there (Eq. inst).
TEST(Thresholds, SigmaCriticalAtLStarIsSigmaStar) {
  for (double alpha : {9.0, 19.140625, 25.0, 50.0, 400.0, 1e6}) {
    const double l = l_star(alpha);
    const double Pi = l * (l + 1);
    const double sc = -(Pi + 4 * alpha / Pi);
    EXPECT_NEAR(sc, sigma_star(alpha), 1e-13 * std::abs(sigma_star(alpha))) << alpha;
    // It is the maximum over l: neighbours are lower (checked at +-1e-3 in l).
    for (double dl : {-1e-3, 1e-3}) {
      const double P2 = (l + dl) * (l + dl + 1);
      EXPECT_LT(-(P2 + 4 * alpha / P2), sc) << alpha;
    }
  }
  EXPECT_DOUBLE_EQ(alpha_for_l_star(2.5), (35.0 / 8) * (35.0 / 8));
  EXPECT_NEAR(l_star(alpha_for_l_star(2.5)), 2.5, 1e-14);
  EXPECT_TRUE(l_star_criterion(std::nextafter((35.0 / 8) * (35.0 / 8), 100.0)));
  EXPECT_FALSE(l_star_criterion(19.0));
}

// Upsilon_l vanishes at sigma_l^c (reuses model's Upsilon); tolerance: the terms are O(Pi + 4 alpha/Pi) * Gamma2/B,
// so a few ulps of that scale.
TEST(Thresholds, UpsilonVanishesAtSigmaCritical) {
  for (double alpha : {5.0, 50.0, 5000.0})
    for (int l = 2; l <= 12; ++l) {
      const Parameters p = params(5, 1, 0.01, 2, 2 / alpha);
      const double sc = sigma_c(l, alpha);
      const double scale = std::abs(Gamma2(p.lambda, l) / p.B) * std::abs(sc);
      EXPECT_NEAR(Upsilon_l(p, l, sc), 0, 1e-14 * scale) << l << " " << alpha;
      EXPECT_GT(Upsilon_l(p, l, sc - 1e-6 * std::abs(sc)), 0);
      EXPECT_LT(Upsilon_l(p, l, sc + 1e-6 * std::abs(sc)), 0);
    }
}

TEST(Thresholds, UnstableBandRootsAndModes) {
  const double alpha = 25;
  for (double sigma : {-20.5, -25.0, -60.0, -1e4}) {
    const UnstableBand b = unstable_band(sigma, alpha);
    ASSERT_TRUE(b.l_minus.valid() && b.l_plus.valid() && b.l_c.valid());
    for (const Quantity& l : {b.l_minus, b.l_plus}) {
      const double Pi = l.value * (l.value + 1);
      EXPECT_NEAR(Pi * Pi + sigma * Pi + 4 * alpha, 0, 1e-12 * sigma * sigma) << sigma;
    }
    // l_c: the extremum of Pi^2 + sigma Pi + 4 alpha, Pi_c = -sigma/2, lies between the roots.
    EXPECT_NEAR(b.l_c.value * (b.l_c.value + 1), -sigma / 2, 1e-12 * std::abs(sigma));
    EXPECT_LT(b.l_minus.value, b.l_c.value);
    EXPECT_GT(b.l_plus.value, b.l_c.value);
    // Integer unstable modes are exactly the integers in (l_-, l_+) with l >= 3, and those with Upsilon > 0.
    const Parameters p = params(5, 1, 0.01, 2, 2 / alpha);
    const std::vector<int> modes = unstable_modes(sigma, alpha, 200);
    for (int l = 3; l <= 200; ++l) {
      const bool in = std::find(modes.begin(), modes.end(), l) != modes.end();
      EXPECT_EQ(in, Upsilon_l(p, l, sigma) > 0) << l;
      EXPECT_EQ(in, l > b.l_minus.value && l < b.l_plus.value) << l;
    }
  }
  // Above sigma_*: no band, an explicit reason, no NaN.
  const UnstableBand none = unstable_band(-19.0, 25);
  EXPECT_FALSE(none.l_plus.valid());
  EXPECT_FALSE(none.l_plus.reason.empty());
  EXPECT_EQ(none.l_plus.value, 0.0);
}

// The surviving mode changes from l to l+1 where sigma_l^c = sigma_{l+1}^c: alpha = Pi_l Pi_{l+1}/4.
TEST(Thresholds, SurvivingModeChangesAtAlphaModeChange) {
  EXPECT_DOUBLE_EQ(alpha_mode_change(2), 18.0);
  EXPECT_DOUBLE_EQ(alpha_mode_change(3), 60.0);
  for (int l = 3; l <= 9; ++l) {
    const double a = alpha_mode_change(l);
    EXPECT_NEAR(sigma_c(l, a), sigma_c(l + 1, a), 1e-12 * a);
    EXPECT_EQ(surviving_mode(a * (1 - 1e-9), 20), l);
    EXPECT_EQ(surviving_mode(a * (1 + 1e-9), 20), l + 1);
  }
  // The paper's dashed lines use half-integer l_* instead: a different alpha (62.0 vs 60 for 3 -> 4).
  EXPECT_GT(alpha_for_l_star(3.5), alpha_mode_change(3));
}

// sigma_R(0) against the ReducedModel's own multiplier at t = 0 (out of plane and in plane), and alpha_*^init
// solving sigma_R(0) = sigma_*.
TEST(Thresholds, InitialTensionAndAlphaInit) {
  for (double beta : {0.0, std::numbers::pi / 2})
    for (double Delta : {0.1, 1.0}) {
      Scene s;
      s.parameters = params(5, Delta, 0.01, 3, 0.05);
      s.beta = beta;
      s.L = 2;
      const ReducedModel m(s.parameters, initial_state(s));
      const std::vector<double> y0 = m.initial_state();
      EXPECT_NEAR(m.observe(0, y0).sigma, sigma_R_initial(s.parameters), 1e-12 * 60) << beta;
    }
  for (double Delta0 : {0.0, 0.001, 0.01, 0.5}) {
    const Parameters p0 = params(5, 1, Delta0, 1, 1);
    const Quantity a = alpha_init(p0);
    ASSERT_TRUE(a.valid());
    Parameters p = p0;
    p.C = p.B / a.value;
    EXPECT_NEAR(sigma_R_initial(p), sigma_star(a.value), 1e-12 * a.value) << Delta0;
  }
  EXPECT_DOUBLE_EQ(alpha_init(params(5, 1, 0, 1, 1)).value, 9.0);  // Delta0 -> 0 limit
  const Quantity none = alpha_init(params(5, 1, 1, 1, 1));         // Delta0 = Delta: infinite
  EXPECT_FALSE(none.valid());
  EXPECT_FALSE(none.reason.empty());
}

// C_*^- (Eq. c_crit) is the root in C of <sigma_R^->(C) = sigma_*(B/C) with the instability below it.
TEST(Thresholds, CStarMinusSolvesItsDefinition) {
  for (double B : {0.5, 2.0, 20.0})
    for (double Delta : {1.0, 0.1}) {
      const Parameters p = params(1, Delta, 0.01, B, 1);  // Lambda ~ 0.71 / 0.22 < 1
      const Quantity Cs = C_star_minus(p);
      ASSERT_TRUE(Cs.valid());
      auto g = [&](double lnC) {
        Parameters q = p;
        q.C = std::exp(lnC);
        return mean_sigma_R_minus(q).value - sigma_star(q.alpha());
      };
      // Bracket on the branch alpha > 9 (sqrt(alpha) > 3 + ...): C in (C_*/100, B/9).
      const double root = std::exp(bisect(g, std::log(Cs.value / 100), std::log(B / 9)));
      EXPECT_NEAR(Cs.value, root, 1e-12 * root) << B << " " << Delta;
      EXPECT_LT(g(std::log(Cs.value * 0.99)), 0);  // unstable below C_*
      EXPECT_GT(g(std::log(Cs.value * 1.01)), 0);
    }
  // Edge Lambda -> 1: A^- -> 0, C_*^- -> B/9 (finite); Lambda > 1: outside with a reason.
  Parameters edge = params(1, 1, 0.01, 2, 1);
  edge.lambda = (8 * std::sqrt(30 * std::numbers::pi) - 32) / 23 * (1 - 1e-14);  // Lambda = 1 - O(1e-15)
  ASSERT_LE(edge.Lambda(), 1.0);
  // A^- ~ sqrt(30 pi (1 - Lambda^2))/3 ~ 3e-7, so C_* = B/9 (1 - O(sqrt(B A^-))) with sqrt(B A^-) ~ 1e-3.
  EXPECT_NEAR(C_star_minus(edge).value, 2.0 / 9, 2e-3 * 2.0 / 9);
  EXPECT_FALSE(C_star_minus(params(5, 1, 0.01, 2, 1)).valid());
}

// C_*^+ (corrected) is the root in C of the corrected <sigma_R^+>(C) = sigma_*(B/C). Its agreement with the exact
// finite-S equilibrium, and the printed form's disagreement, are in steady_states_test.cpp.
TEST(Thresholds, CStarPlusSolvesItsDefinition) {
  for (double r0 : {0.0, std::sqrt(3.0) / 2})
    for (double B : {1.0, 10.0}) {
      const Parameters p = params(5, 1, 0.01, B, 1);  // Lambda ~ 1.89
      const Quantity Cs = C_star_plus(p, r0);
      ASSERT_TRUE(Cs.valid());
      auto g = [&](double lnC) {
        Parameters q = p;
        q.C = std::exp(lnC);
        return mean_sigma_R_plus(q, r0).value - sigma_star(q.alpha());
      };
      const double root = std::exp(bisect(g, std::log(Cs.value / 100), std::log(B / 9)));
      EXPECT_NEAR(Cs.value, root, 1e-12 * root);
    }
  // The printed <sigma_R^+> has (1 - Lambda^2)(1 - r0^2) < 0 under its root for every Lambda > 1.
  EXPECT_FALSE(mean_sigma_R_plus_printed(params(5, 1, 0.01, 2, 0.04), 0).valid());
  EXPECT_TRUE(mean_sigma_R_plus(params(5, 1, 0.01, 2, 0.04), 0).valid());
  // Lambda -> 1+: w_ss -> 0, sqrt(A^+) -> inf: explicitly outside (never unstable at S >> 1), no NaN.
  Parameters edge = params(1, 1, 0.01, 2, 1);
  edge.lambda = (8 * std::sqrt(30 * std::numbers::pi) - 32) / 23 * (1 + 1e-12);
  ASSERT_GT(edge.Lambda(), 1.0);
  EXPECT_FALSE(C_star_plus(edge, 0).valid());
  EXPECT_FALSE(std::isnan(mean_sigma_R_plus(edge, 0).value));
}

// lambda_*^- (Eq. ss_lambda_red) is the root in lambda of <sigma_R^->(lambda) = sigma_* at fixed alpha, C, Delta,
// with the instability above it: the printed formula is confirmed.
TEST(Thresholds, LambdaStarMinusSolvesItsDefinition) {
  int checked = 0;
  for (double alpha : {40.0, 100.0, 500.0})
    for (double C : {0.05, 0.2, 1.0})
      for (double Delta : {1.0, 0.1}) {
        const Quantity ls = lambda_star_minus(alpha, C, Delta);
        if (!ls.valid()) {
          EXPECT_FALSE(ls.reason.empty());
          continue;
        }
        ++checked;
        auto g = [&](double lambda) {
          Parameters q = params(lambda, Delta, 0.01, alpha * C, C);
          return mean_sigma_R_minus(q).value - sigma_star(alpha);
        };
        // lambda with Lambda = 1: the upper end of the Lambda < 1 domain.
        const double lambda_max = (8 * std::sqrt(30 * std::numbers::pi / Delta) - 32) / 23 * (1 - 1e-12);
        const double root = bisect(g, 0, lambda_max);
        EXPECT_NEAR(ls.value, root, 1e-9 * std::max(1.0, root)) << alpha << " " << C << " " << Delta;
        EXPECT_LT(g(std::min(lambda_max, root * 1.01 + 1e-6)), 0);  // unstable above
      }
  EXPECT_GE(checked, 6);
}

// No NaN anywhere over a grid that includes the domain edges.
TEST(Thresholds, NeverNaN) {
  for (double lambda : {0.0, 1.0, 5.0, 1e3})
    for (double Delta : {1e-6, 0.1, 1.0, 12.0})
      for (double Delta0 : {0.0, 1e-6, Delta})
        for (double C : {1e-6, 0.04, 1e6, std::numeric_limits<double>::infinity()}) {
          const Parameters p = params(lambda, Delta, Delta0, 2, C);
          for (const Quantity& q : {alpha_init(p), mean_sigma_R_minus(p), mean_sigma_R_plus(p, 0), C_star_minus(p),
                                    C_star_plus(p, 0), C_star_plus(p, 1)}) {
            EXPECT_FALSE(std::isnan(q.value));
            EXPECT_EQ(q.valid(), q.reason.empty() || q.status == DomainStatus::limit);
          }
        }
  EXPECT_THROW(lambda_star_minus(-1, 1, 1), InvalidArgument);
  EXPECT_FALSE(std::isnan(lambda_star_minus(9, 1, 1).value));
}

}  // namespace
}  // namespace rbcstab
