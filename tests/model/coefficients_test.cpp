// Mode coefficients (paper Appendix B, Eq. gammas) against closed-form identities.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameters.hpp"

namespace rbcstab {
namespace {

// Each coefficient is a ratio of integer polynomials in l (< 1e13 for l <= 100) evaluated in
// double: a handful of roundings, so identities hold to a few ulps. 1e-13 relative leaves margin.
constexpr double kRel = 1e-13;

TEST(Coefficients, GammaRatiosAreExactForEveryModeUpTo100) {
  for (double lambda : {0.0, 1.0, 5.0, 123.4}) {
    for (int l = 2; l <= 100; ++l) {
      const double Pi = double(l) * (l + 1);
      const double G1 = Gamma1(lambda, l), G2 = Gamma2(lambda, l), G3 = Gamma3(lambda, l);
      ASSERT_LT(G2, 0) << "l = " << l;
      EXPECT_NEAR(G1 / G2, Pi, kRel * Pi) << "l = " << l << ", lambda = " << lambda;
      EXPECT_NEAR(G3 / G2, 4 / Pi, kRel * 4 / Pi) << "l = " << l << ", lambda = " << lambda;
      EXPECT_DOUBLE_EQ(Pi_l(l), Pi);
      EXPECT_DOUBLE_EQ(a_l(l), (l + 2.0) * (l - 1.0) / 2);
    }
  }
}

TEST(Coefficients, DLambdaTwoIs32Plus23Lambda) {
  for (double lambda : {0.0, 0.5, 1.0, 5.0, 1e3})
    EXPECT_NEAR(d_lambda_l(lambda, 2), 32 + 23 * lambda, 1e-15 * (32 + 23 * lambda));
  // Independent check of the general formula at l = 3: (54 + 27 + 4) + lambda (54 + 27 - 5).
  EXPECT_DOUBLE_EQ(d_lambda_l(2.0, 3), 85 + 2 * 76);
}

// C_{l,m} from Appendix B: d^-1 [c0 sqrt(l(l+1)) (2l+1) + c2 (4l^3 + 6l^2 - 4l - 3)] with the
// shear values c_{2,+-2,0} = -+ i sqrt(pi/5), c_{2,+-2,2} = -+ i sqrt(2 pi/15).
std::complex<double> appendix_b_drive(double lambda, int m) {
  const int l = 2;
  const double sgn = m > 0 ? 1.0 : -1.0;
  const std::complex<double> c0(0, -sgn * std::sqrt(kPi / 5)), c2(0, -sgn * std::sqrt(2 * kPi / 15));
  const double d = (2.0 * l * l * l + 3 * l * l + 4) + lambda * (2.0 * l * l * l + 3 * l * l - 5);
  return (c0 * std::sqrt(l * (l + 1.0)) * (2.0 * l + 1) + c2 * (4.0 * l * l * l + 6 * l * l - 4 * l - 3)) / d;
}

TEST(Coefficients, ShearDriveMatchesClosedFormAndAppendixB) {
  for (double lambda : {0.0, 1.0, 5.0, 40.0}) {
    const double mag = 4 * std::sqrt(30 * kPi) / (32 + 23 * lambda);
    for (int m : {2, -2}) {
      const std::complex<double> c = shear_drive(lambda, 2, m);
      const std::complex<double> closed(0, m > 0 ? -mag : mag);
      const std::complex<double> appb = appendix_b_drive(lambda, m);
      // A few roundings of O(1) numbers: 1e-14 relative.
      EXPECT_NEAR(std::abs(c - closed), 0, 1e-14 * mag) << "m = " << m << ", lambda = " << lambda;
      EXPECT_NEAR(std::abs(c - appb), 0, 1e-14 * mag) << "m = " << m << ", lambda = " << lambda;
    }
    // Every other component vanishes in shear.
    for (int l = 2; l <= 6; ++l)
      for (int m = -l; m <= l; ++m)
        if (!(l == 2 && std::abs(m) == 2)) {
          EXPECT_EQ(shear_drive(lambda, l, m), std::complex<double>(0, 0));
        }
  }
}

TEST(Coefficients, UpsilonMatchesEqEomSupAndVanishesAtSigmaCritical) {
  Parameters p;
  for (double C : {0.04, 1.0, 7.5}) {
    p.C = C;
    p.B = 2.0;
    p.lambda = 5.0;
    const double alpha = p.alpha();
    for (int l = 2; l <= 100; ++l) {
      const double sc = sigma_c(l, alpha);
      EXPECT_DOUBLE_EQ(sc, -(l * (l + 1.0) + 4 * alpha / (l * (l + 1.0))));
      // Upsilon_l(sigma_c) is a difference of terms of size |Gamma2| |sigma_c| / B: relative 1e-14 of that.
      const double scale = std::abs(Gamma2(p.lambda, l)) / p.B * std::abs(sc);
      EXPECT_NEAR(Upsilon_l(p, l, sc), 0, 1e-14 * scale) << "l = " << l;
      // Eq. eom_sup_ups directly, at a generic sigma.
      const double sigma = -17.3;
      const double direct = (Gamma1(p.lambda, l) + sigma * Gamma2(p.lambda, l)) / p.B + Gamma3(p.lambda, l) / p.C;
      const double size = (std::abs(Gamma1(p.lambda, l)) + std::abs(sigma * Gamma2(p.lambda, l))) / p.B +
                          std::abs(Gamma3(p.lambda, l) / p.C);
      EXPECT_NEAR(Upsilon_l(p, l, sigma), direct, 1e-14 * size) << "l = " << l;
      // Sign: mode l grows iff sigma < sigma_l^c.
      EXPECT_GT(Upsilon_l(p, l, sc - 1), 0);
      EXPECT_LT(Upsilon_l(p, l, sc + 1), 0);
    }
  }
  // Vesicle limit C = inf: Gamma3 drops out, finite.
  p.C = INFINITY;
  EXPECT_EQ(p.alpha(), 0);
  EXPECT_NEAR(Upsilon_l(p, 3, -12.0), 0, 1e-15);
  EXPECT_TRUE(std::isfinite(Upsilon_l(p, 50, -3.0)));
}

TEST(Coefficients, ModeBelowTwoIsRefused) {
  EXPECT_THROW(Gamma1(1.0, 1), InvalidArgument);
  EXPECT_THROW(Gamma2(1.0, 0), InvalidArgument);
  try {
    Gamma3(1.0, 1);
    FAIL() << "l = 1 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "l");
    EXPECT_NE(std::string(e.what()).find(">= 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbcstab
