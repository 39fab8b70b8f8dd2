// unit_phasor against long double sinl/cosl: within one ulp of the exact value on its fast range, std::polar
// beyond it; the fast range's reduction is exercised where it is hardest (near multiples of pi/2, large x).
#include "rbcstab/core/phasor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace rbcstab {
namespace {

// |approx - exact| in ulps of the larger of |exact| and 2^-53 (an absolute ulp near 1 for values near 0: the
// phasor's components are used as a unit vector, whose error is absolute).
double ulps(double approx, long double exact) {
  const double scale = std::max(std::abs(static_cast<double>(exact)), 0x1p-53);
  const double ulp = std::nextafter(scale, 2 * scale) - scale;
  return static_cast<double>(std::abs(static_cast<long double>(approx) - exact)) / ulp;
}

void expect_within_one_ulp(double x) {
  const std::complex<double> e = unit_phasor(x);
  const long double lx = x;
  EXPECT_LE(ulps(e.real(), std::cos(lx)), 1.0) << "cos at x = " << x;
  EXPECT_LE(ulps(e.imag(), std::sin(lx)), 1.0) << "sin at x = " << x;
}

TEST(UnitPhasor, WithinOneUlpOverTheTimesOfARun) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> small(-10.0, 10.0), run(0.0, 5e6), big(-823549.0, 823549.0);
  for (int k = 0; k < 200000; ++k) {
    expect_within_one_ulp(small(rng));
    expect_within_one_ulp(run(rng) * 1e-1);
    expect_within_one_ulp(big(rng));
  }
}

TEST(UnitPhasor, WithinOneUlpNearMultiplesOfHalfPi) {
  // Where the reduced argument cancels most: the nearest doubles to k pi/2 and their neighbours.
  for (long k = -200000; k <= 200000; k += 997)
    for (double x = std::nextafter(static_cast<double>(k) * 1.5707963267948966, -1e300), n = 0; n < 5;
         ++n, x = std::nextafter(x, 1e300))
      expect_within_one_ulp(x);
}

TEST(UnitPhasor, TinyArgumentsAreExact) {
  for (double x : {0.0, -0.0, 1e-300, -1e-20, 1e-9}) {
    const std::complex<double> e = unit_phasor(x);
    EXPECT_EQ(e.real(), 1.0);
    EXPECT_EQ(e.imag(), x);  // sin x = x to double precision below ~1e-8
  }
}

TEST(UnitPhasor, BeyondTheFastRangeIsStdPolar) {
  for (double x : {823550.0, -1e6, 5e6, 1e300}) EXPECT_EQ(unit_phasor(x), std::polar(1.0, x)) << x;
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {inf, -inf, std::numeric_limits<double>::quiet_NaN()}) {
    const std::complex<double> e = unit_phasor(x);
    EXPECT_TRUE(std::isnan(e.real()) && std::isnan(e.imag())) << x;
  }
}

}  // namespace
}  // namespace rbcstab
