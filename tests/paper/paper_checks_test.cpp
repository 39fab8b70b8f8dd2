// Every check of the paper's claims (paper_checks.hpp) can fail: each is fed a right input, which passes, and
// deliberately wrong ones (a perturbed series, a flipped sign, a truncated transient, a wrong mode), which fail.
// The table covers every name of paper_check::names(); paper_quick_test checks that every claim of the page
// names one of them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "rbcstab/analysis/thresholds.hpp"
#include "rbcstab/report/paper_checks.hpp"

// Its own namespace: paper_test.cpp shares this unity batch (and uses paper_measure, whose names overlap).
namespace rbcstab::paper_check_test {
using namespace paper_check;
constexpr double pi = std::numbers::pi;

struct Case {
  std::string name;
  Check right;
  std::vector<Check> wrong;  // each a deliberately wrong input
};

Series sampled(double T, int n) {
  Series t;
  for (int k = 0; k <= n; ++k) t.push_back(T * k / n);
  return t;
}
template <class F>
Series of(const Series& t, F f) {
  Series x;
  for (double v : t) x.push_back(f(v));
  return x;
}

std::vector<Case> cases() {
  const Series t = sampled(100, 2000);
  const Series relax = of(t, [](double s) { return 0.5 + 0.3 * std::exp(-s / 5); });   // settles by t ~ 30
  const Series lower = of(t, [](double s) { return 0.4 + 0.3 * std::exp(-s / 5); });   // settles lower
  const Series slow = of(t, [](double s) { return 0.5 + 0.3 * std::exp(-s / 10); });   // settles by t ~ 60
  const Series never = of(t, [](double s) { return 0.5 + 0.3 * std::exp(-s / 40); });  // still moving at T
  // Damped oscillations (rates 0.03 and 0.25, the App. C runs'), and an undamped one.
  const Series ring_slow = of(t, [](double s) { return 0.7 + 0.5 * std::exp(-0.03 * s) * std::cos(2 * s); });
  const Series ring_fast = of(t, [](double s) { return 0.7 + 0.5 * std::exp(-0.25 * s) * std::cos(2 * s); });
  const Series ring_none = of(t, [](double s) { return 0.7 + 0.5 * std::cos(2 * s); });
  const Series wobble = of(t, [](double s) { return 0.5 + 0.01 * std::sin(s); });
  const Series swing = of(t, [](double s) { return 0.3 + 0.2 * std::sin(s); });
  const Series tumble = of(t, [](double s) { return -0.2 * s; });  // Psi falling: a tumble every 10 pi
  const Series flipped = of(t, [](double s) { return 0.2 * s; });  // the sign flipped: turning the wrong way
  const Series flat(t.size(), 0.3);
  // Fig. 3(b): Delta_2 falls, Delta_3 grows and saturates, Delta_4 grows by e^2 then decays.
  const Series D2 = of(t, [](double s) { return 1 - 0.5 * (1 - std::exp(-s / 10)); });
  const Series D3 = of(t, [](double s) { return 1e-4 + 0.45 * (1 - std::exp(-s / 10)); });
  const Series D4 = of(t, [](double s) { return 1e-4 * std::exp(2 * s / 10 * std::exp(1 - s / 10)); });
  const Series D4_small = of(t, [](double s) { return 1e-4 * (1 + 0.007 * s / 10 * std::exp(1 - s / 10)); });
  Series D4_truncated;  // the transient cut before its peak: no interior maximum
  for (std::size_t k = 0; k < t.size() / 20; ++k) D4_truncated.push_back(D4[k]);
  const Series above = of(t, [&](double s) { return 0.47 * (1 - std::exp(-s / 10)) + 2e-4; });
  // sigma settling at -20 (the target), one settling 5% off, one still drifting through the target at T.
  const Series sig = of(t, [](double s) { return -20 - 10 * std::exp(-s / 5) + 0.1 * std::sin(3 * s); });
  const Series sig_off = of(t, [](double s) { return -21 - 10 * std::exp(-s / 5); });
  const Series sig_drift = of(t, [](double s) { return -20 + 0.02 * (s - 95); });
  const Series sigR = of(sig, [](double v) { return v * (1 + 1e-3); });
  const Series sigR_off = of(sig, [](double v) { return v * 1.1; });
  // App. F: every mode grows by e then falls below its start; the wrong one grows by 0.7%.
  const Series bump = of(t, [](double s) { return 1e-3 * std::exp(s / 5 * std::exp(1 - s / 5)) * std::exp(-s / 50); });
  const Series bump_small =
      of(t, [](double s) { return 1e-3 * (1 + 0.007 * s * std::exp(1 - s)) * std::exp(-s / 50); });
  const Series fall = of(t, [](double s) { return 2e-3 * std::exp(-s / 50); });
  const Series rise = of(t, [](double s) { return 2e-3 * (1 + s / 100); });
  const double alpha = 25;
  const Series stomato_end{0.995, 0.003, 0.002, 0}, stomato_start{0.999, 0.001, 0, 0};
  const Series tri_end{0, 0.37, 0, 0.63}, tri_start{0, 0.375, 0, 0.625};
  const Series spread{0.3, 0.3, 0.2, 0.2};
  return {
      {"lower_at_long_times",
       lower_at_long_times(t, relax, t, lower, 20),
       {lower_at_long_times(t, lower, t, relax, 20)}},
      {"steady",
       steady(t, relax, relax, 20, 1e-3),
       {steady(t, relax, swing, 20, 1e-3), steady(t, wobble, relax, 20, 1e-3)}},
      {"swings", swings(t, swing, 20), {swings(t, tumble, 20), swings(t, flat, 20)}},
      {"tumbles", tumbles(tumble), {tumbles(swing), tumbles(flipped)}},
      {"redistributes", redistributes(D2, D3, D4), {redistributes(D3, D2, D4), redistributes(D2, D3, fall)}},
      {"grows_then_decays",
       grows_then_decays(D4, 2, 0.5),
       {grows_then_decays(D4_small, 2, 0.5), grows_then_decays(D4_truncated, 2, 0.5), grows_then_decays(D3, 2, 0.5)}},
      {"takes_share", takes_share(t, D3, above, 20, 0.9), {takes_share(t, D4, above, 20, 0.9)}},
      {"settles_at",
       settles_at(t, sig, -20, 20, 0.02),
       {settles_at(t, sig_off, -20, 20, 0.02), settles_at(t, sig_drift, -20, 20, 0.02),
        settles_at(t, sig, 20, 20, 0.02)}},
      {"follows",
       follows(t, sig, sigR, 10, 0.05),
       {follows(t, sig, sigR_off, 10, 0.05), follows(t, sig, sigR, 0.1, 0.05)}},
      {"settles_near",
       settles_near(t, relax, 1e-3, 30),
       {settles_near(t, never, 1e-3, 30), settles_near(t, relax, 1e-3, 5)}},
      {"damped_more_slowly",
       damped_more_slowly(t, ring_slow, t, ring_fast, 10),
       {damped_more_slowly(t, ring_fast, t, ring_slow, 10), damped_more_slowly(t, ring_none, t, ring_fast, 10)}},
      {"swings_more",
       swings_more(t, swing, t, wobble, 20),
       {swings_more(t, wobble, t, swing, 20), swings_more(t, flat, t, flat, 20)}},
      {"tank_treads",
       tank_treads({&t, &t}, {&relax, &relax}, {&flat, &flat}, 0.3, 20, 0.05, 1e-3),
       {tank_treads({&t, &t}, {&relax, &relax}, {&flat, &flat}, pi / 2, 20, 0.05, 1e-3),
        tank_treads({&t, &t}, {&relax, &swing}, {&flat, &flat}, 0.3, 20, 0.05, 1e-3)}},
      {"steady_state",
       steady_state({&t}, {&relax}, {&flat}, {0.3}, 0.5, 20, 0.02, 0.01),
       {steady_state({&t}, {&relax}, {&flat}, {-0.3}, 0.5, 20, 0.02, 0.01),
        steady_state({&t}, {&lower}, {&flat}, {0.3}, 0.5, 20, 0.02, 0.01)}},
      {"grows_then_suppressed",
       grows_then_suppressed({bump, bump}, fall, 2),
       {grows_then_suppressed({bump_small, bump_small}, fall, 2), grows_then_suppressed({bump, bump}, rise, 2)}},
      {"marginal",
       marginal(alpha, sigma_star(alpha), l_star(alpha)),
       {marginal(alpha, 1.01 * sigma_star(alpha), l_star(alpha)), marginal(alpha, -4 * alpha, l_star(alpha)),
        marginal(alpha, sigma_star(alpha), l_star(alpha) + 0.01)}},
      {"same_signs", same_signs({1, -2, 3}, {0.5, -1, 9}, "l"), {same_signs({1, -2, 3}, {0.5, 1, 9}, "l")}},
      {"modes_differ", modes_differ(3, 4, "l_c, fastest"), {modes_differ(3, 3, "l_c, fastest")}},
      {"fraction_at_least",
       fraction_at_least(95, 100, 0.9, "agreement"),
       {fraction_at_least(89, 100, 0.9, "agreement"), fraction_at_least(0, 0, 0.9, "agreement")}},
      {"more_than", more_than(5, 3, "unstable"), {more_than(3, 5, "unstable"), more_than(3, 3, "unstable")}},
      {"none", none(0, "unstable"), {none(1, "unstable")}},
      {"increasing",
       increasing({1, 4, 9}, "unstable"),
       {increasing({1, 9, 4}, "unstable"), increasing({3, 3, 3}, "u")}},
      {"at_least_each", at_least_each({3, 5, 9}, {3, 4, 8}, "u"), {at_least_each({3, 5, 9}, {3, 6, 8}, "u")}},
      {"unstable_in_mode", unstable_in_mode(true, 3, 3), {unstable_in_mode(true, 4, 3), unstable_in_mode(false, 3, 3)}},
      {"close",
       close({1, -20}, {1.01, -20.5}, 0.05, "x"),
       {close({1, -20}, {1.1, -20}, 0.05, "x"), close({1}, {std::nan("")}, 0.05, "x")}},
      {"median_below",
       median_below({0.01, -0.05, 0.3}, 0.1, "rows"),
       {median_below({0.2, 0.05, 0.3}, 0.1, "rows"), median_below({}, 0.1, "rows")}},
      {"falls_with",
       falls_with({{1, 0.3}, {2, 0.2}, {3, 0.05}, {4, 0.01}}, "dev"),
       {falls_with({{1, 0.01}, {2, 0.05}, {3, 0.2}, {4, 0.3}}, "dev"), falls_with({{1, 0.3}}, "dev")}},
      {"stomatocyte",
       stomatocyte(3, stomato_end, stomato_start),
       {stomatocyte(4, stomato_end, stomato_start), stomatocyte(3, spread, stomato_start),
        stomatocyte(3, tri_end, tri_start)}},
      {"lobed",
       lobed(3, tri_end, tri_start, 3),
       {lobed(4, {0, 0.3, 0, 0.2, 0.5}, {0, 0.3, 0, 0.2, 0.5}, 3), lobed(3, stomato_end, stomato_start, 3),
        lobed(3, {0, 0.6, 0, 0.4}, tri_start, 3)}},
  };
}

TEST(PaperChecks, EachPassesOnTheRightInputAndFailsOnEveryWrongOne) {
  for (const Case& c : cases()) {
    EXPECT_EQ(c.right.name, c.name);
    EXPECT_TRUE(c.right.passed) << c.name << ": measured " << c.right.measured << "; expected " << c.right.expected;
    EXPECT_FALSE(c.right.measured.empty()) << c.name;
    EXPECT_FALSE(c.right.expected.empty()) << c.name;
    ASSERT_FALSE(c.wrong.empty()) << c.name;
    for (std::size_t k = 0; k < c.wrong.size(); ++k) {
      EXPECT_EQ(c.wrong[k].name, c.name);
      EXPECT_FALSE(c.wrong[k].passed) << c.name << ", wrong input " << k << ": measured " << c.wrong[k].measured;
    }
  }
}

TEST(PaperChecks, TheTableCoversEveryCheck) {
  std::set<std::string> tested;
  for (const Case& c : cases()) EXPECT_TRUE(tested.insert(c.name).second) << c.name << " twice";
  const std::set<std::string> all(names().begin(), names().end());
  EXPECT_EQ(all.size(), names().size());
  EXPECT_EQ(tested, all);
}

}  // namespace rbcstab::paper_check_test
