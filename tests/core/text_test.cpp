// TextStream: NaN reads "n/a" at the stream's width and adjustment; every other number is untouched.
#include <gtest/gtest.h>

#include <complex>
#include <iomanip>
#include <limits>
#include <sstream>

#include "rbcstab/core/text.hpp"

namespace rbcstab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(TextStream, NotANumberReadsNa) {
  TextStream s;
  s << kNaN << ' ' << -kNaN << ' ' << static_cast<long double>(kNaN);
  EXPECT_EQ(s.str(), "n/a n/a n/a");
}

TEST(TextStream, NaIsPaddedLikeANumber) {
  TextStream s;
  s << '[' << std::setw(6) << kNaN << ']' << '[' << std::left << std::setw(5) << kNaN << ']' << '[' << std::setw(2)
    << kNaN << ']' << '[' << std::setw(4) << 1.5 << ']';
  EXPECT_EQ(s.str(), "[   n/a][n/a  ][n/a][1.5 ]");
}

TEST(TextStream, EveryOtherValueIsTheClassicText) {
  for (double v : {0.0, -0.0, 1.0, -2.5e-300, 6.02e23, kInf, -kInf, std::numeric_limits<double>::denorm_min()}) {
    TextStream s;
    std::ostringstream classic;
    classic.imbue(std::locale::classic());
    s << std::setprecision(17) << v << ' ' << std::scientific << v;
    classic << std::setprecision(17) << v << ' ' << std::scientific << v;
    EXPECT_EQ(s.str(), classic.str()) << v;
  }
}

TEST(TextStream, ComplexNumbersUseTheStreamsLocale) {
  TextStream s;
  s << std::complex<double>(kNaN, 1.0);
  EXPECT_EQ(s.str(), "(n/a,1)");
}

}  // namespace
}  // namespace rbcstab
