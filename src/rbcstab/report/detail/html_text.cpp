#include "rbcstab/report/detail/html_text.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "rbcstab/report/detail/report_pages.hpp"

namespace rbcstab::detail {

namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_word(char c) { return is_digit(c) || is_alpha(c) || c == '_'; }

const std::map<std::string, std::string>& greek();
std::string mathml_of(const std::string& expr);

// An ASCII symbol in running text, at s[i] (a word start): a Greek name, or a Greek name or single letter with
// sub/superscripts that are each a Greek name, one letter, digits, * or a {group} ("Delta_3", "sigma_l^c",
// "l_Delta", "f_{l,0}"). Its length, or 0 when the word is not one ("phase_diagram", "sigma_initial", "a").
std::size_t symbol_length(const std::string& s, std::size_t i) {
  auto letters = [&](std::size_t k) {
    std::size_t j = k;
    while (j < s.size() && is_alpha(s[j])) ++j;
    return j;
  };
  const std::size_t base_end = letters(i);
  const std::string base = s.substr(i, base_end - i);
  const bool base_greek = greek().count(base) != 0;
  if (!base_greek && base.size() != 1) return 0;
  std::size_t k = base_end;
  int scripts = 0;
  while (scripts < 2 && k + 1 < s.size() && (s[k] == '_' || s[k] == '^')) {
    const std::size_t a = k + 1;
    std::size_t e = a;
    if (s[a] == '{') {
      e = s.find('}', a);
      if (e == std::string::npos) return 0;
      ++e;
    } else if (s[a] == '*') {
      e = a + 1;
    } else if (is_digit(s[a])) {
      while (e < s.size() && is_digit(s[e])) ++e;
    } else if (is_alpha(s[a])) {
      e = letters(a);
      if (e - a != 1 && greek().count(s.substr(a, e - a)) == 0) return 0;
    } else {
      return 0;
    }
    k = e;
    ++scripts;
  }
  if (k < s.size() && (is_word(s[k]) || s[k] == '^')) return 0;
  return (base_greek || scripts > 0) ? k - i : 0;
}

// A number written with an exponent: its mantissa as written, then x10 and the exponent raised, U+2212 for minus.
std::string with_power(const std::string& mantissa, const std::string& exponent) {
  const bool negative = exponent[0] == '-';
  std::size_t k = (exponent[0] == '-' || exponent[0] == '+') ? 1 : 0;
  while (k + 1 < exponent.size() && exponent[k] == '0') ++k;  // e-05 -> 10^-5
  return mantissa + "\u2009\u00d7\u200910<sup>" + (negative ? "\u2212" : "") + exponent.substr(k) + "</sup>";
}

// Escaped text with every number that carries an exponent raised and every ASCII symbol (symbol_length) as MathML,
// in one pass: a number or a symbol starts after a non-word character and ends before one, so "fig_3e2" and
// "phase_diagram" are left alone.
std::string text_html(const std::string& s) {
  std::string o;
  std::size_t i = 0;
  while (i < s.size()) {
    if (is_alpha(s[i]) && (i == 0 || !is_word(s[i - 1]))) {
      const std::size_t n = symbol_length(s, i);
      if (n > 0) {
        o += mathml_of(s.substr(i, n));
        i += n;
        continue;
      }
      while (i < s.size() && is_word(s[i])) o += s[i++];  // a plain word, whole (no number read inside it)
      continue;
    }
    const bool starts = is_digit(s[i]) && (i == 0 || (!is_word(s[i - 1]) && s[i - 1] != '.'));
    if (starts) {
      std::size_t j = i;
      while (j < s.size() && is_digit(s[j])) ++j;
      if (j + 1 < s.size() && s[j] == '.' && is_digit(s[j + 1])) {
        ++j;
        while (j < s.size() && is_digit(s[j])) ++j;
      }
      std::size_t e = j;
      if (e < s.size() && (s[e] == 'e' || s[e] == 'E')) {
        std::size_t k = e + 1;
        if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
        const std::size_t digits0 = k;
        while (k < s.size() && is_digit(s[k])) ++k;
        if (k > digits0 && (k == s.size() || !is_word(s[k]))) {
          o += with_power(s.substr(i, j - i), s.substr(e + 1, k - e - 1));
          i = k;
          continue;
        }
      }
      o += s.substr(i, j - i);
      i = j;
      continue;
    }
    o += html_escape(std::string(1, s[i]));
    ++i;
  }
  return o;
}

const std::map<std::string, std::string>& greek() {
  static const std::map<std::string, std::string> g{
      {"alpha", "α"}, {"beta", "β"},  {"gamma", "γ"},  {"delta", "δ"},  {"epsilon", "ε"}, {"eta", "η"},
      {"theta", "θ"}, {"kappa", "κ"}, {"lambda", "λ"}, {"mu", "μ"},     {"nu", "ν"},      {"pi", "π"},
      {"rho", "ρ"},   {"sigma", "σ"}, {"tau", "τ"},    {"phi", "φ"},    {"psi", "ψ"},     {"omega", "ω"},
      {"Gamma", "Γ"}, {"Delta", "Δ"}, {"Theta", "Θ"},  {"Lambda", "Λ"}, {"Pi", "Π"},      {"Sigma", "Σ"},
      {"Phi", "Φ"},   {"Psi", "Ψ"},   {"Omega", "Ω"},  {"Upsilon", "Υ"}};
  return g;
}

// A recursive-descent reader of the notation mathml() documents.
struct MathReader {
  const std::string& s;
  std::size_t i = 0;

  void skip() {
    while (i < s.size() && s[i] == ' ') ++i;
  }
  // Elements up to `close` (consumed) or the end.
  std::string row(char close) {
    std::string o;
    skip();
    while (i < s.size() && s[i] != close) {
      o += scripted();
      skip();
    }
    if (i < s.size()) ++i;
    return o;
  }
  std::string scripted() {
    std::string base = atom();
    std::string sub, sup;
    for (int k = 0; k < 2 && i < s.size() && (s[i] == '_' || s[i] == '^'); ++k) {
      const char c = s[i++];
      (c == '_' ? sub : sup) = script_atom();
    }
    if (!sub.empty() && !sup.empty()) return "<msubsup>" + base + sub + sup + "</msubsup>";
    if (!sub.empty()) return "<msub>" + base + sub + "</msub>";
    if (!sup.empty()) return "<msup>" + base + sup + "</msup>";
    return base;
  }
  std::string script_atom() {
    if (i < s.size() && s[i] == '*') {
      ++i;
      return "<mo>\u2217</mo>";
    }
    return atom();
  }
  std::string atom() {
    if (i >= s.size()) return "<mrow></mrow>";
    const char c = s[i];
    if (c == '{') {
      ++i;
      return "<mrow>" + row('}') + "</mrow>";
    }
    if (c == '~') {
      ++i;
      return "<mover accent=\"true\">" + atom() + "<mo>\u02dc</mo></mover>";
    }
    if (is_digit(c) || (c == '.' && i + 1 < s.size() && is_digit(s[i + 1]))) {
      const std::size_t j = i;
      while (i < s.size() && (is_digit(s[i]) || s[i] == '.')) ++i;
      return "<mn>" + s.substr(j, i - j) + "</mn>";
    }
    if (is_alpha(c)) {
      const std::size_t j = i;
      while (i < s.size() && is_alpha(s[i])) ++i;
      const std::string w = s.substr(j, i - j);
      if (w == "sqrt" && i < s.size() && s[i] == '(') {
        ++i;
        return "<msqrt>" + row(')') + "</msqrt>";
      }
      if (w == "ln" || w == "exp" || w == "log" || w == "sin" || w == "cos") return "<mi>" + w + "</mi><mo>\u2061</mo>";
      const auto g = greek().find(w);
      if (g != greek().end())
        return std::isupper(static_cast<unsigned char>(w[0])) ? "<mi mathvariant=\"normal\">" + g->second + "</mi>"
                                                              : "<mi>" + g->second + "</mi>";
      return "<mi>" + w + "</mi>";
    }
    ++i;
    if (c == '-') return "<mo>\u2212</mo>";
    if (c == '*') return "<mo>\u2217</mo>";
    return "<mo>" + html_escape(std::string(1, c)) + "</mo>";
  }
};

std::string mathml_of(const std::string& expr) {
  MathReader r{expr};
  return "<math>" + r.row('\0') + "</math>";
}

}  // namespace

std::string html_number(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream ss;
  ss.precision(digits);
  ss << v;
  return text_html(ss.str());
}

std::string mathml(const std::string& expr) { return mathml_of(expr); }

std::string html_text(const std::string& text) {
  std::string o;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('$', i);
    const std::size_t close = open == std::string::npos ? open : text.find('$', open + 1);
    if (close == std::string::npos) {
      o += text_html(text.substr(i));
      break;
    }
    o += text_html(text.substr(i, open - i)) + mathml(text.substr(open + 1, close - open - 1));
    i = close + 1;
  }
  return o;
}

std::string plain_text(const std::string& text) {
  std::string o;
  std::size_t i = 0;
  bool in_math = false;
  while (i < text.size()) {
    if (text[i] == '$' && (in_math || text.find('$', i + 1) != std::string::npos)) {
      in_math = !in_math;
      ++i;
      continue;
    }
    if (in_math && is_alpha(text[i]) && (i == 0 || !is_alpha(text[i - 1]))) {
      std::size_t j = i;
      while (j < text.size() && is_alpha(text[j])) ++j;
      const auto g = greek().find(text.substr(i, j - i));
      o += g != greek().end() ? g->second : text.substr(i, j - i);
      i = j;
      continue;
    }
    o += text[i++];
  }
  return o;
}

const char* hover_script() {
  // Each point is placed once in the image's pixels (axes_px: left, top, right, bottom; linear or log axes), then
  // the nearest one to the pointer is shown. textContent only: the data cannot inject markup.
  return R"JS((function () {
  function frac(v, a) {
    var lo = a.lim[0], hi = a.lim[1];
    if (a.scale === "log") { v = Math.log(v); lo = Math.log(lo); hi = Math.log(hi); }
    return (v - lo) / (hi - lo);
  }
  function show(v) { return typeof v === "number" ? String(Number(v.toPrecision(6))) : String(v); }
  var tip = document.createElement("div");
  tip.className = "hover-tip";
  tip.hidden = true;
  document.body.appendChild(tip);
  document.querySelectorAll("img[data-hover]").forEach(function (img) {
    var d = JSON.parse(document.getElementById(img.dataset.hover).textContent), b = d.axes_px;
    var at = d.points.map(function (p) {
      return [b[0] + frac(p[0], d.x) * (b[2] - b[0]), b[3] - frac(p[1], d.y) * (b[3] - b[1])];
    });
    img.addEventListener("mousemove", function (e) {
      var r = img.getBoundingClientRect(), k = img.naturalWidth / r.width;
      var mx = (e.clientX - r.left) * k, my = (e.clientY - r.top) * k, best = -1, bd = Infinity;
      if (mx < b[0] || mx > b[2] || my < b[1] || my > b[3]) { tip.hidden = true; return; }
      at.forEach(function (q, n) {
        var dd = (q[0] - mx) * (q[0] - mx) + (q[1] - my) * (q[1] - my);
        if (dd < bd) { bd = dd; best = n; }
      });
      if (best < 0) { tip.hidden = true; return; }
      tip.textContent = d.columns.map(function (c, n) { return c + " = " + show(d.points[best][n]); }).join(", ");
      tip.style.left = (e.clientX + 14) + "px";
      tip.style.top = (e.clientY + 14) + "px";
      tip.hidden = false;
    });
    img.addEventListener("mouseleave", function () { tip.hidden = true; });
  });
})();
)JS";
}

}  // namespace rbcstab::detail
