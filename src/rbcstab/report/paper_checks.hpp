#pragma once
// The checks of the paper's claims (`rbcstab paper`), each a function of explicit inputs so that a test can feed
// it a wrong input (a perturbed series, a flipped sign, a truncated transient, a wrong mode) and see it fail
// (tests/paper/paper_checks_test.cpp). The figure files (paper_fig*.cpp, paper_app*.cpp) gather the inputs from
// the runs and the independent side (another run, another level, a closed form, the paper's printed value); the
// thresholds are justified in docs/paper.md.
#include <string>
#include <vector>

namespace rbcstab::paper_check {

using Series = std::vector<double>;

// A check's verdict: the value measured and the condition it had to meet, as the page prints them.
struct Check {
  std::string name;  // the check (one of names())
  bool passed = false;
  std::string measured, expected;
};

// Every check below by name, in declaration order.
const std::vector<std::string>& names();

// --- Time series (t ascending, same length as x) ---
// The long-time mean of x_low (last `window`) below that of x_high.
Check lower_at_long_times(const Series& t_high, const Series& x_high, const Series& t_low, const Series& x_low,
                          double window);
// r and Psi constant over the last `window`: both tail ranges below tol.
Check steady(const Series& t, const Series& r, const Series& Psi, double window, double tol);
// Psi oscillates (tail range > 1e-3) about a fixed angle (|Psi(T) - mean of the second half| < pi/2).
Check swings(const Series& t, const Series& Psi, double window);
// Psi turns by less than -2 pi over the run (at least one tumble; steps taken modulo pi).
Check tumbles(const Series& Psi);
// Delta_2 falls (Delta_2(T) < Delta_2(0)) while Delta_3 and Delta_4 rise above their start.
Check redistributes(const Series& D2, const Series& D3, const Series& D4);
// x peaks at an interior sample at least `min_growth` times its start, and ends below `drop` times the peak.
Check grows_then_decays(const Series& x, double min_growth, double drop);
// x's share of `total` (means over the last `window`) at least `min_share`.
Check takes_share(const Series& t, const Series& x, const Series& total, double window, double min_share);
// The run settles at `target`: the mean of x over the last window is within rel_tol |target| of it, and the means
// over the last two windows differ by less than rel_tol |target| / 4 (no drift left at T).
Check settles_at(const Series& t, const Series& x, double target, double window, double rel_tol);
// x follows y (same samples) up to t_max: max |x - y| / |y| < rel_tol; t_max after at least 10 samples.
Check follows(const Series& t, const Series& x, const Series& y, double t_max, double rel_tol);
// x settles within tol of its final value at a time within a factor 2 of `paper_time`, and the last fifth of
// the run stays within tol (the run settles before T, not at it).
Check settles_near(const Series& t, const Series& x, double tol, double paper_time);
// Oscillations damped more slowly: the amplitude of x (its range over consecutive windows of width `window`)
// falls by at least a factor e over the run for both, and its mean decay rate ln(A_first / A_last) / time is
// smaller for `slow` (A_last: the last window above 1e-6, the runs' noise floor).
Check damped_more_slowly(const Series& t_slow, const Series& slow, const Series& t_fast, const Series& fast,
                         double window);
// Swinging amplitude: the tail range of Psi_a above 1e-3 and above that of Psi_b.
Check swings_more(const Series& t_a, const Series& Psi_a, const Series& t_b, const Series& Psi_b, double window);
// Tank-treading at a fixed angle: |<Psi> - Psi_target| < psi_tol and tail range of r < r_tol for every run.
Check tank_treads(const std::vector<const Series*>& t, const std::vector<const Series*>& r,
                  const std::vector<const Series*>& Psi, double Psi_target, double window, double psi_tol,
                  double r_tol);
// The steady state r = r_target, Psi = Psi_target[k] of each run k: |<Psi> - target| < psi_tol, |<r> - r| < r_tol.
Check steady_state(const std::vector<const Series*>& t, const std::vector<const Series*>& r,
                   const std::vector<const Series*>& Psi, const Series& Psi_target, double r_target, double window,
                   double psi_tol, double r_tol);
// A transient growth then suppression (App. F): the largest max_t Delta_l / Delta_l(0) over l >= 3 at least
// min_growth, and sum_{l>=3} Delta_l at T below its start. Delta[k] is Delta_{k+3}(t).
Check grows_then_suppressed(const std::vector<Series>& Delta, const Series& above2, double min_growth);

// --- Formulas (Fig. 3(a)) ---
// The criterion -Pi^2 - sigma Pi - 4 alpha maximised numerically over continuous l in [1, 8]: at sigma_star its
// maximum is 0 (|max| < 1e-6 4 alpha) at l_star (within 1e-3), and at 1.01 sigma_star it is positive.
Check marginal(double alpha, double sigma_star, double l_star);
// a and b have the same sign at every index (the roots coincide).
Check same_signs(const Series& a, const Series& b, const std::string& what);
// Two integer modes differ.
Check modes_differ(int a, int b, const std::string& what);

// --- Counts and fractions ---
// matches / points at least `min_fraction` (points > 0).
Check fraction_at_least(std::size_t matches, std::size_t points, double min_fraction, const std::string& what);
// more > less.
Check more_than(std::size_t more, std::size_t less, const std::string& what);
// count == 0.
Check none(std::size_t count, const std::string& what);
// counts non-decreasing and last > first.
Check increasing(const std::vector<std::size_t>& counts, const std::string& what);
// a[k] >= b[k] for every k.
Check at_least_each(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b, const std::string& what);
// A point's verdict and mode: unstable with l_Delta the mode the paper names.
Check unstable_in_mode(bool unstable, int l_Delta, int named_l);

// --- Values ---
// |a - b| / |a| < rel_tol for each pair (a[k], b[k]).
Check close(const Series& a, const Series& b, double rel_tol, const std::string& what);
// The median of |dev| below tol (some rows required).
Check median_below(const Series& dev, double tol, const std::string& what);
// (x, dev) pairs sorted by x: the mean dev of the lower half of x above that of the upper half (>= 2 pairs).
Check falls_with(std::vector<std::pair<double, double>> x_dev, const std::string& what);

// --- Shapes (final azimuthal shares of the dominant l >= 3 mode about the vorticity axis, at t = 0 and T) ---
// A stomatocyte: odd dominant l, |m| = 0 share >= 99%, shares within 1 point of t = 0.
Check stomatocyte(int l, const Series& end, const Series& start);
// A multi-lobed shape with `named_l` lobes (3: the trilobe): dominant l = named_l, |m| = 0 share < 1%, |m| = l the
// largest share, shares within 1 point of t = 0.
Check lobed(int l, const Series& end, const Series& start, int named_l);

}  // namespace rbcstab::paper_check
