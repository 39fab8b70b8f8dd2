// Wigner column D^(l)_{m,0}(beta) (paper Appendix A) against identities, Appendix A's l = 2 table,
// a closed form at beta = pi/2, and GSL's normalised associated Legendre functions.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_legendre.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

// Required accuracy of the column for every l <= 100.
constexpr double kTol = 1e-12;
const double kBetas[] = {0.0, 1e-3, 0.3, 1.0, kPi / 2, 2.2, kPi - 1e-3, kPi};

TEST(Wigner, ColumnIsAUnitVector) {
  // Unitarity of D^(l): sum_m |D_{m,0}|^2 = 1. Rounding accumulates over ~l^2 recursion steps.
  for (int l = 0; l <= 100; ++l)
    for (double beta : kBetas) {
      const auto col = wigner_column(l, beta);
      ASSERT_EQ(col.size(), std::size_t(2 * l + 1));
      double s = 0;
      for (double d : col) s += d * d;
      EXPECT_NEAR(s, 1.0, kTol) << "l = " << l << ", beta = " << beta;
    }
}

TEST(Wigner, AppendixAEntriesForLTwo) {
  for (double beta : kBetas) {
    const auto D = wigner_column(2, beta);
    const double c = std::cos(beta), s = std::sin(beta);
    // D_{0,0} = (3 cos 2b + 1)/4, D_{+-1,0} = +-sqrt(3/2) cos b sin b, D_{+-2,0} = sqrt(3/2) sin^2 b / 2.
    EXPECT_NEAR(D[2], (3 * std::cos(2 * beta) + 1) / 4, 1e-15) << beta;
    EXPECT_NEAR(D[3], std::sqrt(1.5) * c * s, 1e-15) << beta;
    EXPECT_NEAR(D[1], -std::sqrt(1.5) * c * s, 1e-15) << beta;
    EXPECT_NEAR(D[4], 0.5 * std::sqrt(1.5) * s * s, 1e-15) << beta;
    EXPECT_NEAR(D[0], 0.5 * std::sqrt(1.5) * s * s, 1e-15) << beta;
  }
}

TEST(Wigner, BetaZeroIsKroneckerDelta) {
  for (int l = 0; l <= 100; ++l) {
    const auto D = wigner_column(l, 0.0);
    for (int m = -l; m <= l; ++m) EXPECT_EQ(D[m + l], m == 0 ? 1.0 : 0.0) << "l = " << l << ", m = " << m;
  }
}

// Closed form at beta = pi/2 (P_l^m(0) without the Condon-Shortley phase):
// D_{m,0}(pi/2) = 0 if l + m is odd, else (-1)^((l-m)/2) sqrt((l-m)! (l+m)!) / (2^l ((l+m)/2)! ((l-m)/2)!)
// for m >= 0, and D_{-m,0} = (-1)^m D_{m,0}. Evaluated through lgamma (no overflow); its relative
// error is ~1e-16 times the size of the log-factorials (<= 500), i.e. < 1e-13.
double closed_form_half_pi(int l, int m) {
  const int am = std::abs(m);
  if ((l + am) % 2) return 0.0;
  const double logv = 0.5 * (std::lgamma(l - am + 1.0) + std::lgamma(l + am + 1.0)) - l * std::log(2.0) -
                      std::lgamma((l + am) / 2 + 1.0) - std::lgamma((l - am) / 2 + 1.0);
  double v = std::exp(logv);
  if (((l - am) / 2) % 2) v = -v;
  if (m < 0 && am % 2) v = -v;
  return v;
}

TEST(Wigner, HalfPiAgainstClosedForm) {
  for (int l = 0; l <= 100; ++l) {
    const auto D = wigner_column(l, kPi / 2);
    // cos(pi/2) = 6e-17 in double, so odd-parity entries are O(1e-16 l) instead of 0.
    for (int m = -l; m <= l; ++m)
      EXPECT_NEAR(D[m + l], closed_form_half_pi(l, m), kTol) << "l = " << l << ", m = " << m;
  }
}

// GSL's gsl_sf_legendre_sphPlm(l, m, x) = sqrt((2l+1)/(4 pi)) sqrt((l-m)!/(l+m)!) P_l^m(x) for m >= 0,
// where GSL's P_l^m carries the Condon-Shortley phase (-1)^m (GSL: P_1^1(x) = -sqrt(1-x^2)).
// Our (the paper's) column is sqrt((l-m)!/(l+m)!) P_l^m(cos b) without that phase, e.g.
// D^(2)_{1,0} = +sqrt(3/2) cos b sin b. Hence, for m >= 0,
//   D_{m,0}(b) = (-1)^m sqrt(4 pi/(2l+1)) sphPlm(l, m, cos b),   D_{-m,0} = (-1)^m D_{m,0}.
// GSL evaluates sphPlm by its own stable recursion in l (started from P_m^m in log form), to ~1e-15.
double gsl_column_entry(int l, int m, double beta) {
  const int am = std::abs(m);
  double v = std::sqrt(4 * kPi / (2 * l + 1)) * gsl_sf_legendre_sphPlm(l, am, std::cos(beta));
  if (am % 2) v = -v;           // remove the Condon-Shortley phase
  if (m < 0 && am % 2) v = -v;  // D_{-m,0} = (-1)^m D_{m,0}
  return v;
}

TEST(Wigner, LargeLAgainstGsl) {
  gsl_set_error_handler_off();
  for (int l : {2, 3, 7, 10, 25, 50, 77, 99, 100})
    for (double beta : kBetas) {
      const auto D = wigner_column(l, beta);
      for (int m = -l; m <= l; ++m)
        ASSERT_NEAR(D[m + l], gsl_column_entry(l, m, beta), kTol)
            << "l = " << l << ", m = " << m << ", beta = " << beta;
    }
}

TEST(Wigner, ConventionSignAgainstGslForLTwo) {
  // The conversion above reproduces Appendix A's sign: D^(2)_{1,0}(0.4) = +sqrt(3/2) cos sin > 0.
  EXPECT_GT(gsl_column_entry(2, 1, 0.4), 0);
  EXPECT_NEAR(gsl_column_entry(2, 1, 0.4), std::sqrt(1.5) * std::cos(0.4) * std::sin(0.4), 1e-15);
}

TEST(Wigner, BadInputRefused) {
  EXPECT_THROW(wigner_column(-1, 0.1), InvalidArgument);
  EXPECT_THROW(wigner_column(3, NAN), InvalidArgument);
  EXPECT_THROW(wigner_column(3, INFINITY), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
