// The pages' numbers and maths (report/detail/html_text): no two numbers run together, maths as MathML.
#include "rbcstab/report/detail/html_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace rbcstab {
namespace {

// The oracle: reads an HTML number back (mantissa, then thin space, times sign, thin space, "10<sup>", an optional
// minus sign U+2212, the exponent, "</sup>"; or nothing), independently of the formatter; false when the text is not
// exactly one number (two run together, or a bare exponent left over). A hand-written scanner, not std::regex:
// GCC 12's <regex> trips -Wmaybe-uninitialized in the sanitized build.
bool read_back(const std::string& html, double& value) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < html.size() && html[i] >= '0' && html[i] <= '9') ++i;
    return i > start;
  };
  auto take = [&](const std::string& literal) {
    if (html.compare(i, literal.size(), literal) != 0) return false;
    i += literal.size();
    return true;
  };
  if (i < html.size() && html[i] == '-') ++i;
  if (!digits()) return false;
  if (take(".") && !digits()) return false;
  const std::string mantissa = html.substr(0, i);
  int e = 0;
  if (take(" × 10<sup>")) {
    const bool negative = take("−");
    const std::size_t start = i;
    if (!digits()) return false;
    e = std::stoi(html.substr(start, i - start)) * (negative ? -1 : 1);
    if (!take("</sup>")) return false;
  }
  if (i != html.size()) return false;
  value = std::strtod((mantissa + "e" + std::to_string(e)).c_str(), nullptr);  // subnormals too
  return true;
}

TEST(HtmlNumber, ThreeDigitExponentsAreRaisedAndReadBack) {
  EXPECT_EQ(detail::html_number(1.96507e-125, 6), "1.96507\u2009\u00d7\u200910<sup>\u2212125</sup>");
  EXPECT_EQ(detail::html_number(9.43813e-124, 6), "9.43813\u2009\u00d7\u200910<sup>\u2212124</sup>");
  EXPECT_EQ(detail::html_number(2.5e+300, 6), "2.5\u2009\u00d7\u200910<sup>300</sup>");
  EXPECT_EQ(detail::html_number(3e-5, 6), "3\u2009\u00d7\u200910<sup>\u22125</sup>");  // e-05: no leading zero
  EXPECT_EQ(detail::html_number(0.125, 6), "0.125");
  EXPECT_EQ(detail::html_number(std::nan(""), 6), "n/a");
  // Round trip to the digits asked for, from the smallest subnormal to the largest double.
  for (double v : {4.9406564584124654e-324, 1.96507e-125, -7.25e-100, 1e-5, 0.5, -42.0, 123456.0, 6.02e23,
                   1.7976931348623157e308}) {
    double back = 0;
    ASSERT_TRUE(read_back(detail::html_number(v, 6), back)) << detail::html_number(v, 6);
    EXPECT_NEAR(back, v, 5e-6 * std::abs(v)) << v;
  }
}

TEST(HtmlNumber, TheOracleRejectsNumbersRunTogether) {
  // What a plain table cell held before: two numbers, three-digit exponents, side by side. The oracle must see
  // that it is not one number; html_text of the same cell text splits them.
  double back = 0;
  EXPECT_FALSE(read_back("1.96507e-1259.43813e-124", back));
  EXPECT_FALSE(read_back("1.96507e-125", back));  // an exponent left in ASCII is not accepted either
  const std::string two = detail::html_text("1.96507e-125 9.43813e-124");
  EXPECT_EQ(two, detail::html_number(1.96507e-125, 6) + " " + detail::html_number(9.43813e-124, 6));
}

TEST(HtmlText, RaisesOnlyWholeNumbersAndEscapes) {
  EXPECT_EQ(detail::html_text("a < b & 2e3"), "a &lt; b &amp; 2\u2009\u00d7\u200910<sup>3</sup>");
  EXPECT_EQ(detail::html_text("fig_3e2 x1e5 v2.0e"), "fig_3e2 x1e5 v2.0e");  // names, not numbers
  EXPECT_EQ(detail::html_text("costs $5"), "costs $5");                      // a lone $ stays
}

TEST(MathML, SymbolsOfThePages) {
  EXPECT_EQ(detail::mathml("sigma_l^c"), "<math><msubsup><mi>σ</mi><mi>l</mi><mi>c</mi></msubsup></math>");
  EXPECT_EQ(detail::mathml("~Delta_2"),
            "<math><msub><mover accent=\"true\"><mi mathvariant=\"normal\">Δ</mi><mo>\u02dc</mo></mover><mn>2</mn>"
            "</msub></math>");
  EXPECT_EQ(detail::mathml("Upsilon_l"), "<math><msub><mi mathvariant=\"normal\">Υ</mi><mi>l</mi></msub></math>");
  EXPECT_EQ(detail::mathml("ln B"), "<math><mi>ln</mi><mo>\u2061</mo><mi>B</mi></math>");
  EXPECT_EQ(detail::mathml("sigma_* = -4 sqrt(alpha)"),
            "<math><msub><mi>σ</mi><mo>\u2217</mo></msub><mo>=</mo><mo>\u2212</mo><mn>4</mn><msqrt><mi>α</mi></msqrt>"
            "</math>");
  EXPECT_EQ(detail::mathml("Delta_{l+1}"),
            "<math><msub><mi mathvariant=\"normal\">Δ</mi><mrow><mi>l</mi><mo>+</mo><mn>1</mn></mrow></msub></math>");
  // In text: the segment between $ becomes MathML, no ASCII maths left; plain text keeps it readable.
  const std::string t = detail::html_text("mode $l$ grows while $sigma < sigma_l^c$");
  EXPECT_EQ(t.find("sigma"), std::string::npos) << t;
  EXPECT_NE(t.find("<mo>&lt;</mo>"), std::string::npos) << t;
  EXPECT_EQ(detail::plain_text("mode $l$ grows while $sigma < sigma_l^c$"), "mode l grows while σ < σ_l^c");
}

TEST(HtmlText, AsciiSymbolsInRunningTextBecomeMathML) {
  // The paper's claims and the parameter table's meanings are plain text: their symbols are found as words.
  EXPECT_EQ(detail::html_text("max Delta_3 / Delta_3(0)"),
            "max " + detail::mathml("Delta_3") + " / " + detail::mathml("Delta_3") + "(0)");
  EXPECT_EQ(detail::html_text("l_Delta = 4, alpha"), detail::mathml("l_Delta") + " = 4, " + detail::mathml("alpha"));
  EXPECT_EQ(detail::html_text("in f_{l,0} at sigma_l^c."),
            "in " + detail::mathml("f_{l,0}") + " at " + detail::mathml("sigma_l^c") + ".");
  // Not symbols: names of fields and files, plain words, single letters without scripts, a Greek prefix.
  for (const char* plain :
       {"sigma_initial", "phase_diagram.csv", "l_Delta_final", "a tail mean", "Delta0", "alphabet", "x_min"})
    EXPECT_EQ(detail::html_text(plain), plain) << plain;
}

}  // namespace
}  // namespace rbcstab
