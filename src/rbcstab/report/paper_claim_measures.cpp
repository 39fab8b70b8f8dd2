// The measures the paper's claim checks apply to the runs' series (paper_measure in paper.hpp): tail means and
// ranges, settling times, net turns of Psi, azimuthal shares of a mode.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "rbcstab/report/paper.hpp"

#include "rbcstab/core/constants.hpp"

namespace rbcstab {

namespace paper_measure {
namespace {
std::size_t window_start(const std::vector<double>& t, double window) {
  const double t0 = t.back() - window;
  return std::size_t(std::lower_bound(t.begin(), t.end(), t0) - t.begin());
}
}  // namespace

double tail_mean(const std::vector<double>& t, const std::vector<double>& x, double window) {
  if (t.empty() || t.size() != x.size()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t k0 = window_start(t, window);
  if (k0 + 1 >= t.size()) return x.back();
  double area = 0;
  for (std::size_t k = k0 + 1; k < t.size(); ++k) area += (t[k] - t[k - 1]) * (x[k] + x[k - 1]) / 2;
  return area / (t.back() - t[k0]);
}

double tail_range(const std::vector<double>& t, const std::vector<double>& x, double window) {
  if (t.empty() || t.size() != x.size()) return std::numeric_limits<double>::quiet_NaN();
  const auto [lo, hi] = std::minmax_element(x.begin() + std::ptrdiff_t(window_start(t, window)), x.end());
  return *hi - *lo;
}

double settle_time(const std::vector<double>& t, const std::vector<double>& x, double tol) {
  if (t.empty() || t.size() != x.size()) return std::numeric_limits<double>::quiet_NaN();
  const double end = tail_mean(t, x, 0.05 * (t.back() - t.front()));
  for (std::size_t k = t.size(); k-- > 0;)
    if (std::abs(x[k] - end) > tol) return t[k];
  return t.front();
}

bool grows_then_decays(const std::vector<double>& x, double drop) {
  if (x.size() < 3) return false;
  const std::size_t k = std::size_t(std::max_element(x.begin(), x.end()) - x.begin());
  return k > 0 && k + 1 < x.size() && x[k] > x.front() && x.back() < drop * x[k];
}

double net_turn(const std::vector<double>& Psi) {
  double turn = 0;
  for (std::size_t k = 1; k < Psi.size(); ++k) {
    const double d = Psi[k] - Psi[k - 1];
    turn += d - kPi * std::round(d / kPi);
  }
  return turn;
}

std::vector<double> azimuthal_shares(const ModeAmplitudes& f, int l) {
  std::vector<double> share(std::size_t(l + 1), 0.0);
  double total = 0;
  for (int m = -l; m <= l; ++m) {
    const double a = std::norm(f.at(l, m));
    share[std::size_t(std::abs(m))] += a;
    total += a;
  }
  for (double& s : share) s = total > 0 ? s / total : 0.0;
  return share;
}

double max_relative_gap(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y,
                        double t_max) {
  double gap = 0;
  for (std::size_t k = 0; k < std::min({t.size(), x.size(), y.size()}) && t[k] <= t_max; ++k)
    gap = std::max(gap, std::abs(x[k] - y[k]) / std::max(std::abs(y[k]), 1e-300));
  return gap;
}
}  // namespace paper_measure

}  // namespace rbcstab
