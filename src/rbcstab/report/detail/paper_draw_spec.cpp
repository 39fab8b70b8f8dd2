// The drawing-spec pieces the paper's figures share (declared, with their defaults, in paper_draw_spec.hpp).
#include "rbcstab/report/detail/paper_draw_spec.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/report/paper.hpp"

namespace rbcstab::detail::paper {

using namespace rbcstab::paper_measure;

json series(const std::string& csv, const std::string& y, const std::string& label, const std::string& color,
            const std::string& ls, double lw) {
  return {{"data", csv}, {"x", "t"}, {"y", y}, {"label", label}, {"color", color}, {"ls", ls}, {"lw", lw}};
}
json psi_series(const Line& l, const std::string& label, const std::string& color, const std::string& ls, double lw) {
  const bool tumbles = std::abs(net_turn(l.run.trajectory.Psi)) > kPi;
  json s = series(l.csv, "Psi", tumbles ? label + " (mod $\\pi$)" : label, color, ls, lw);
  if (tumbles) s["wrap"] = kPi;
  return s;
}
json hline(double y, const std::string& label, const std::string& color, const std::string& ls, double lw) {
  return {{"y", y}, {"label", label}, {"color", color}, {"ls", ls}, {"lw", lw}};
}
json lines_panel(const std::string& title, const std::string& ylabel, json s, const std::string& xscale,
                 std::pair<double, double> xlim, const std::string& yscale) {
  return {{"kind", "lines"},
          {"title", title},
          {"xlabel", "$t$"},
          {"ylabel", ylabel},
          {"series", s},
          {"xscale", xscale},
          {"xlim", {xlim.first, xlim.second}},
          {"yscale", yscale},
          {"hlines", json::array()},
          {"vlines", json::array()}};
}

std::string time_axis(const std::vector<Curve>& curves, std::pair<double, double>& xlim) {
  double T = std::numeric_limits<double>::infinity();
  for (const Curve& c : curves) T = std::min(T, c.t->back());
  double settle = 0, band = 0;
  bool oscillates = false;
  for (const Curve& c : curves) {
    const std::vector<double>& t = *c.t;
    const std::vector<double>& x = *c.x;
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    const double swing = std::max(*hi - *lo, 1e-300);
    settle = std::max(settle, settle_time(t, x, 0.01 * swing));
    const std::size_t k0 = std::size_t(std::lower_bound(t.begin(), t.end(), 0.9 * t.back()) - t.begin());
    const auto [tlo, thi] = std::minmax_element(x.begin() + std::ptrdiff_t(k0), x.end());
    if (*thi - *tlo > 0.01 * swing) oscillates = true;
    for (std::size_t k = k0; k-- > 0;)
      if (x[k] < *tlo - 0.01 * swing || x[k] > *thi + 0.01 * swing) {
        band = std::max(band, t[k]);
        break;
      }
  }
  if (!oscillates && settle < T / 5 && T > 20) {
    xlim = {1.0, T};
    return "log";
  }
  xlim = {0.0, oscillates ? std::min(T, std::max(4 * band, 20.0)) : T};
  return "linear";
}

}  // namespace rbcstab::detail::paper
