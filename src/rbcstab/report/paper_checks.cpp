// The checks of the paper's claims (paper_checks.hpp): each measures its explicit inputs with paper_measure and
// states the value and the condition as the page prints them.
#include "rbcstab/report/paper_checks.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/report/paper.hpp"

namespace rbcstab::paper_check {

namespace text {
std::string num(double v, int digits = 4) {
  std::ostringstream ss;
  ss << std::setprecision(digits) << v;
  return ss.str();
}
std::string pct(double v) { return num(100 * v, 3) + "%"; }
std::string list(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + std::to_string(v[k]);
  return s;
}
}  // namespace text

using namespace paper_measure;
using text::num;
using text::pct;

const std::vector<std::string>& names() {
  static const std::vector<std::string> all = {"lower_at_long_times",
                                               "steady",
                                               "swings",
                                               "tumbles",
                                               "redistributes",
                                               "grows_then_decays",
                                               "takes_share",
                                               "settles_at",
                                               "follows",
                                               "settles_near",
                                               "damped_more_slowly",
                                               "swings_more",
                                               "tank_treads",
                                               "steady_state",
                                               "grows_then_suppressed",
                                               "marginal",
                                               "same_signs",
                                               "modes_differ",
                                               "fraction_at_least",
                                               "more_than",
                                               "none",
                                               "increasing",
                                               "at_least_each",
                                               "unstable_in_mode",
                                               "close",
                                               "median_below",
                                               "falls_with",
                                               "stomatocyte",
                                               "lobed"};
  return all;
}

Check lower_at_long_times(const Series& t_high, const Series& x_high, const Series& t_low, const Series& x_low,
                          double window) {
  const double hi = tail_mean(t_high, x_high, window), lo = tail_mean(t_low, x_low, window);
  return {"lower_at_long_times", lo < hi, "mean " + num(lo) + " against " + num(hi), num(lo) + " < " + num(hi)};
}

Check steady(const Series& t, const Series& r, const Series& Psi, double window, double tol) {
  const double rr = tail_range(t, r, window), rp = tail_range(t, Psi, window);
  return {"steady", rr < tol && rp < tol, "tail range of r = " + num(rr, 3) + ", of Psi = " + num(rp, 3),
          "both < " + num(tol)};
}

Check swings(const Series& t, const Series& Psi, double window) {
  const double T = t.back() - t.front();
  const double drift = Psi.back() - tail_mean(t, Psi, T / 2);
  const double range = tail_range(t, Psi, window);
  return {"swings", range > 1e-3 && std::abs(drift) < kPi / 2,
          "tail range of Psi = " + num(range, 3) + ", Psi(T) minus its second-half mean = " + num(drift, 3),
          "range > 1e-3 (oscillates) and |drift| < pi/2 (no rotation)"};
}

Check tumbles(const Series& Psi) {
  const double turn = net_turn(Psi);
  return {"tumbles", turn < -2 * kPi, "net turn of Psi = " + num(turn), "< -2 pi (at least one tumble)"};
}

Check redistributes(const Series& D2, const Series& D3, const Series& D4) {
  const double g3 = *std::max_element(D3.begin(), D3.end()) / D3.front();
  const double g4 = *std::max_element(D4.begin(), D4.end()) / D4.front();
  return {"redistributes", D2.back() < D2.front() && g3 > 1 && g4 > 1,
          "Delta_2: " + num(D2.front()) + " -> " + num(D2.back()) + "; max Delta_3 / Delta_3(0) = " + num(g3) +
              ", max Delta_4 / Delta_4(0) = " + num(g4),
          "Delta_2(T) < Delta_2(0); both ratios > 1"};
}

Check grows_then_decays(const Series& x, double min_growth, double drop) {
  const auto peak = std::max_element(x.begin(), x.end());
  const double growth = *peak / x.front();
  return {"grows_then_decays", paper_measure::grows_then_decays(x, drop) && growth >= min_growth,
          "max / start = " + num(growth, 3) + " at sample " + std::to_string(peak - x.begin()) + " of " +
              std::to_string(x.size()) + ", end / max = " + num(x.back() / *peak, 3),
          "interior maximum >= " + num(min_growth) + " times the start, end < " + num(drop) + " max"};
}

Check takes_share(const Series& t, const Series& x, const Series& total, double window, double min_share) {
  const double share = tail_mean(t, x, window) / tail_mean(t, total, window);
  return {"takes_share", share >= min_share, "share = " + pct(share), ">= " + pct(min_share)};
}

Check settles_at(const Series& t, const Series& x, double target, double window, double rel_tol) {
  const double T = t.back();
  const double last = tail_mean(t, x, window);
  Series t2, x2;  // the run truncated at T - window: the window before the last
  for (std::size_t k = 0; k < t.size() && t[k] <= T - window; ++k) t2.push_back(t[k]), x2.push_back(x[k]);
  const double before = t2.size() > 1 ? tail_mean(t2, x2, window) : x.front();
  const double gap = std::abs(last - target) / std::abs(target), drift = std::abs(last - before) / std::abs(target);
  return {"settles_at", gap < rel_tol && drift < rel_tol / 4,
          "mean over the last " + num(window) + " = " + num(last) + " (gap to " + num(target) + ": " + pct(gap) +
              "); change from the window before: " + pct(drift),
          "gap < " + pct(rel_tol) + ", change < " + pct(rel_tol / 4)};
}

Check follows(const Series& t, const Series& x, const Series& y, double t_max, double rel_tol) {
  std::size_t n = 0;
  while (n < t.size() && t[n] <= t_max) ++n;
  const double gap = max_relative_gap(t, x, y, t_max);
  return {"follows", n >= 10 && gap < rel_tol,
          "max relative gap = " + pct(gap) + " over " + std::to_string(n) + " samples to t = " + num(t_max),
          "< " + pct(rel_tol) + " over >= 10 samples"};
}

namespace {
// Settled before the last fifth of the run: the settle time (tol) is earlier than 0.8 T.
bool settled_early(const Series& t, double ts) { return ts < t.front() + 0.8 * (t.back() - t.front()); }
}  // namespace

Check settles_near(const Series& t, const Series& x, double tol, double paper_time) {
  const double ts = settle_time(t, x, tol);
  return {"settles_near", settled_early(t, ts) && ts > paper_time / 2 && ts < 2 * paper_time,
          "within " + num(tol) + " of its final value after t = " + num(ts, 3) + " (T = " + num(t.back()) + ")",
          "settled before 0.8 T, within a factor 2 of t = " + num(paper_time)};
}

namespace {
struct Damping {
  double rate = 0, fall = 1;  // mean decay rate of the amplitude, A_last / A_first
};
Damping damping(const Series& t, const Series& x, double window) {
  std::vector<std::pair<double, double>> amp;  // (window start, range)
  for (double a = t.front(); a + window <= t.back() + 1e-9 * window; a += window) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] >= a && t[k] < a + window) lo = std::min(lo, x[k]), hi = std::max(hi, x[k]);
    if (hi < lo) continue;
    amp.push_back({a, hi - lo});
    if (hi - lo < 1e-6) break;
  }
  if (amp.size() < 2 || amp.front().second <= 0) return {};
  std::size_t last = amp.size() - 1;
  if (amp[last].second < 1e-6 && last > 1) --last;
  const double fall = amp[last].second / amp.front().second;
  return {-std::log(fall) / (amp[last].first - amp.front().first), fall};
}
}  // namespace

Check damped_more_slowly(const Series& t_slow, const Series& slow, const Series& t_fast, const Series& fast,
                         double window) {
  const Damping s = damping(t_slow, slow, window), f = damping(t_fast, fast, window);
  return {"damped_more_slowly", s.fall < std::exp(-1.0) && f.fall < std::exp(-1.0) && s.rate < f.rate,
          "amplitude decay rates " + num(s.rate, 3) + " against " + num(f.rate, 3) + " (amplitude falls to " +
              pct(s.fall) + ", " + pct(f.fall) + " of its first window)",
          "both fall below 1/e, the first rate smaller"};
}

Check swings_more(const Series& t_a, const Series& Psi_a, const Series& t_b, const Series& Psi_b, double window) {
  const double ra = tail_range(t_a, Psi_a, window), rb = tail_range(t_b, Psi_b, window);
  return {"swings_more", ra > 1e-3 && ra > rb, "tail range of Psi: " + num(ra, 3) + " against " + num(rb, 3),
          "first > 1e-3 and > second"};
}

Check tank_treads(const std::vector<const Series*>& t, const std::vector<const Series*>& r,
                  const std::vector<const Series*>& Psi, double Psi_target, double window, double psi_tol,
                  double r_tol) {
  double worst = 0, worst_r = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    worst = std::max(worst, std::abs(tail_mean(*t[k], *Psi[k], window) - Psi_target));
    worst_r = std::max(worst_r, tail_range(*t[k], *r[k], window));
  }
  return {"tank_treads", worst < psi_tol && worst_r < r_tol,
          "max |<Psi> - " + num(Psi_target, 4) + "| = " + num(worst, 3) + ", max tail range of r = " + num(worst_r, 3),
          "< " + num(psi_tol) + " and < " + num(r_tol)};
}

Check steady_state(const std::vector<const Series*>& t, const std::vector<const Series*>& r,
                   const std::vector<const Series*>& Psi, const Series& Psi_target, double r_target, double window,
                   double psi_tol, double r_tol) {
  double worst = 0, worst_r = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    worst = std::max(worst, std::abs(tail_mean(*t[k], *Psi[k], window) - Psi_target[k]));
    worst_r = std::max(worst_r, std::abs(tail_mean(*t[k], *r[k], window) - r_target));
  }
  return {"steady_state", worst < psi_tol && worst_r < r_tol,
          "max |<Psi> - Psi_ss| = " + num(worst, 3) + ", max |<r> - " + num(r_target) + "| = " + num(worst_r, 3),
          "< " + num(psi_tol) + " and < " + num(r_tol)};
}

Check grows_then_suppressed(const std::vector<Series>& Delta, const Series& above2, double min_growth) {
  int grown = 3;
  double factor = 0;
  for (std::size_t k = 0; k < Delta.size(); ++k) {
    const double f = *std::max_element(Delta[k].begin(), Delta[k].end()) / Delta[k].front();
    if (f > factor) factor = f, grown = int(k) + 3;
  }
  return {"grows_then_suppressed", factor >= min_growth && above2.back() < above2.front(),
          "largest max_t Delta_l / Delta_l(0) = " + num(factor, 4) + " (l = " + std::to_string(grown) +
              "); sum_{l>=3} Delta_l: start " + num(above2.front(), 3) + ", end " + num(above2.back(), 3),
          "growth factor >= " + num(min_growth) + " and the sum at T below its start"};
}

Check marginal(double alpha, double sigma_star, double l_star) {
  // Maximum over continuous l of the criterion: a grid, then a refinement around the best grid point.
  auto maximum = [&](double s) {
    auto crit = [&](double l) { return -l * (l + 1) * l * (l + 1) - s * l * (l + 1) - 4 * alpha; };
    double best = -1e300, best_l = 1;
    for (int i = 0; i <= 7000; ++i)
      if (const double l = 1 + 7.0 * i / 7000; crit(l) > best) best = crit(l), best_l = l;
    const double c = best_l;
    for (int i = 0; i <= 20000; ++i)
      if (const double l = c - 1e-3 + 2e-3 * i / 20000; crit(l) > best) best = crit(l), best_l = l;
    return std::pair{best, best_l};
  };
  const auto [best, best_l] = maximum(sigma_star);
  const double below = maximum(1.01 * sigma_star).first;
  return {"marginal", std::abs(best) < 4e-6 * alpha && std::abs(best_l - l_star) < 1e-3 && below > 0,
          "max = " + num(best, 3) + " at l = " + num(best_l, 5) + " (l_* = " + num(l_star, 5) +
              "); max at 1.01 sigma_* = " + num(below, 3),
          "|max| < 1e-6 4 alpha, |l - l_*| < 1e-3, positive below sigma_*"};
}

Check same_signs(const Series& a, const Series& b, const std::string& what) {
  std::size_t mismatches = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) mismatches += (a[k] > 0) != (b[k] > 0);
  return {"same_signs", mismatches == 0 && a.size() == b.size() && !a.empty(),
          std::to_string(mismatches) + " sign mismatches over " + std::to_string(a.size()) + " " + what, "0"};
}

Check modes_differ(int a, int b, const std::string& what) {
  return {"modes_differ", a != b, what + ": " + std::to_string(a) + " and " + std::to_string(b), "different"};
}

Check fraction_at_least(std::size_t matches, std::size_t points, double min_fraction, const std::string& what) {
  const double f = points ? double(matches) / double(points) : 0.0;
  return {"fraction_at_least", points > 0 && f >= min_fraction,
          what + ": " + pct(f) + " of " + std::to_string(points) + " points", ">= " + pct(min_fraction)};
}

Check more_than(std::size_t more, std::size_t less, const std::string& what) {
  return {"more_than", more > less, what + ": " + std::to_string(more) + " against " + std::to_string(less),
          "first > second"};
}

Check none(std::size_t count, const std::string& what) {
  return {"none", count == 0, what + ": " + std::to_string(count), "0"};
}

Check increasing(const std::vector<std::size_t>& counts, const std::string& what) {
  bool ok = counts.size() >= 2 && counts.back() > counts.front();
  for (std::size_t k = 1; k < counts.size(); ++k) ok = ok && counts[k - 1] <= counts[k];
  return {"increasing", ok, what + ": " + text::list(counts), "non-decreasing, last > first"};
}

Check at_least_each(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b, const std::string& what) {
  bool ok = a.size() == b.size() && !a.empty();
  for (std::size_t k = 0; ok && k < a.size(); ++k) ok = a[k] >= b[k];
  return {"at_least_each", ok, what + ": " + text::list(a) + " against " + text::list(b), "first >= second at each"};
}

Check unstable_in_mode(bool unstable, int l_Delta, int named_l) {
  return {"unstable_in_mode", unstable && l_Delta == named_l,
          std::string(unstable ? "unstable" : "stable") + ", l_Delta = " + std::to_string(l_Delta),
          "unstable with l_Delta = " + std::to_string(named_l)};
}

Check close(const Series& a, const Series& b, double rel_tol, const std::string& what) {
  double worst = a.empty() || a.size() != b.size() ? 1e300 : 0;
  std::string values;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    const double gap = std::abs(a[k] - b[k]) / std::abs(a[k]);
    worst = std::isfinite(gap) ? std::max(worst, gap) : 1e300;  // a missing value (NaN) never passes
    values += (k ? "; " : "") + num(a[k]) + " / " + num(b[k]);
  }
  return {"close", worst < rel_tol, what + ": " + values + " (largest gap " + pct(worst) + ")",
          "each gap < " + pct(rel_tol)};
}

Check median_below(const Series& dev, double tol, const std::string& what) {
  if (dev.empty()) return {"median_below", false, "no " + what, "some " + what};
  Series d;
  for (double v : dev) d.push_back(std::abs(v));
  std::sort(d.begin(), d.end());
  const double median = d[d.size() / 2];
  return {"median_below", median < tol, "median = " + pct(median) + " over " + std::to_string(d.size()) + " " + what,
          "< " + pct(tol)};
}

Check falls_with(std::vector<std::pair<double, double>> v, const std::string& what) {
  std::sort(v.begin(), v.end());
  double lo = 0, hi = 0;
  const std::size_t h = v.size() / 2;
  for (std::size_t i = 0; i < v.size(); ++i) (i < h ? lo : hi) += v[i].second;
  lo /= double(std::max<std::size_t>(h, 1));
  hi /= double(std::max<std::size_t>(v.size() - h, 1));
  return {"falls_with", v.size() >= 2 && lo > hi,
          "mean " + what + ": lower half " + pct(lo) + ", upper half " + pct(hi) + " (" + std::to_string(v.size()) +
              " rows)",
          "lower half > upper half"};
}

namespace {
std::string shares_text(int l, const Series& end, const Series& start) {
  std::string out = "dominant l >= 3 mode: l = " + std::to_string(l) + "; shares at T:";
  double moved = 0;
  for (std::size_t m = 0; m < end.size(); ++m) {
    out += (m ? ", " : " ") + std::string("|m| = ") + std::to_string(m) + ": " + pct(end[m]);
    moved = std::max(moved, std::abs(end[m] - (m < start.size() ? start[m] : 0.0)));
  }
  return out + "; largest change from t = 0: " + num(100 * moved, 3) + " points";
}
double largest_change(const Series& end, const Series& start) {
  double moved = end.size() == start.size() ? 0 : 1;
  for (std::size_t m = 0; m < std::min(end.size(), start.size()); ++m)
    moved = std::max(moved, std::abs(end[m] - start[m]));
  return moved;
}
}  // namespace

Check stomatocyte(int l, const Series& end, const Series& start) {
  return {"stomatocyte", l % 2 == 1 && !end.empty() && end[0] >= 0.99 && largest_change(end, start) < 0.01,
          shares_text(l, end, start), "odd l, |m| = 0 share >= 99%, shares within 1 point of t = 0"};
}

Check lobed(int l, const Series& end, const Series& start, int named_l) {
  const bool lobes =
      !end.empty() && std::size_t(std::max_element(end.begin(), end.end()) - end.begin()) == std::size_t(l);
  return {
      "lobed", l == named_l && lobes && end[0] < 0.01 && largest_change(end, start) < 0.01, shares_text(l, end, start),
      "l = " + std::to_string(named_l) + ", |m| = 0 share < 1%, |m| = l the largest share, within 1 point of t = 0"};
}

}  // namespace rbcstab::paper_check
