#pragma once
// Text on the report's and the paper's HTML pages: numbers, maths and the hover script (module-private).
#include <string>

namespace rbcstab::detail {

// A number as HTML with `digits` significant digits; a power of ten is written "×10<sup>−125</sup>", so two numbers
// side by side never run together ("1.96507e-1259.43813e-124" in a plain table). "n/a" when not finite.
std::string html_number(double v, int digits);
// Text as HTML: < > & " escaped, every number with an exponent ("9.4e-124") written as html_number writes it, and
// each $...$ segment written as MathML (mathml()). A lone $ stays as it is.
std::string html_text(const std::string& text);
// The same text for Markdown and terminals: $ dropped, Greek names as Greek letters ("$sigma_l^c$" -> "σ_l^c").
std::string plain_text(const std::string& text);
// One expression in the pages' maths notation as a <math> element. Notation: names (Greek ones such as sigma, Delta,
// Upsilon become letters; ln, sqrt, exp are functions), numbers, x_s subscripts and x^s superscripts (s: one name,
// number or *, or {a group}), ~x a tilde accent, sqrt(...) a root, operators + - = < > / ( ) , |.
std::string mathml(const std::string& expr);
// The script that shows, under the pointer, the values of the nearest point of a figure that carries them
// (<img data-hover="ID"> with <script type="application/json" id="ID">: axes_px, x, y, columns, points).
// Self-contained: no network at view time.
const char* hover_script();

}  // namespace rbcstab::detail
